// The linear long pass's set-up (gen_lin_pass.py header puts it before the loop): x4 = the
// span's PerspSpan (fields at the offsets the header static_asserts), w2 = n, x0 = d; the
// head of persp_fast's linear vector block (samples 0 .. 3 at [P + 16, P] and + 32 by two
// vector divides, their [u, v] converted and clamped, run 0's steps16_packed) then the loop's
// set-up: writes kZix v16, kUVx v17, k16 v18, k32 v19, kOne v20, kMin v21, kMax4 v22, pp v24,
// run 0's chains (lin_start: c0 x13, x14, x15, x16, e x17), samples 1 .. 3 (nA x25, nB x26,
// nC x27), the stack slots [sp] kZrow, [sp, #16] kUVrow, [sp, #32] lim = d + 32 full, [sp,
// #48] offl = [min(l - 33, 32), l - 49] (full = (n - 49) / 32, l = n - 32 full) and x10 =
// full (the header's entry branch). Taken from the compiler's block for the head asm and the
// set-up (its registers); reloads nothing it stores (order_search --mem keeps the stores).
ldp d1, d2, [x4]
fmov d16, #16.0
ldr d0, [x4, #48]
ldp d3, d6, [x4, #16]
adrp x30, kLinMin
ldp d5, d7, [x4, #32]
sub w9, w2, #49
dup v28.2d, v0.d[0]
fmov v30.2d, #16.0
dup v22.2d, v1.d[0]
ldr d4, [x4, #56]
zip1 v17.2d, v6.2d, v7.2d
dup v27.2d, v1.d[0]
fadd v29.2d, v28.2d, v16.2d
fadd v31.2d, v30.2d, v30.2d
fmov v6.2d, #1.0
zip1 v18.2d, v3.2d, v5.2d
zip1 v19.2d, v3.2d, v5.2d
ldr q23, [x30, :lo12:kLinMin]
zip1 v20.2d, v3.2d, v5.2d
fadd v28.2d, v29.2d, v31.2d
fmla v22.2d, v29.2d, v2.d[0]
zip1 v21.2d, v3.2d, v5.2d
fmla v19.2d, v17.2d, v29.d[0]
fmla v18.2d, v17.2d, v0.d[0]
fmla v27.2d, v28.2d, v2.d[0]
fmaxnm v22.2d, v22.2d, v23.2d
fmla v21.2d, v17.2d, v28.d[1]
fmla v20.2d, v17.2d, v28.d[0]
fmaxnm v27.2d, v27.2d, v23.2d
fdiv v22.2d, v6.2d, v22.2d
dup v16.2d, v2.d[0]
fadd d24, d29, d30
dup v25.2d, v1.d[0]
fdiv v27.2d, v6.2d, v27.2d
fmul v19.2d, v19.2d, v22.d[0]
fmul v18.2d, v18.2d, v22.d[1]
zip1 v26.2d, v3.2d, v5.2d
lsr w10, w9, #5
fcvtzu v19.2d, v19.2d, #16
fcvtzu v18.2d, v18.2d, #16
fmul v20.2d, v20.2d, v27.d[0]
fmul v21.2d, v21.2d, v27.d[1]
sub w9, w2, w10, lsl #5
uqxtn v19.2s, v19.2d
uqxtn v18.2s, v18.2d
str q25, [sp]
fcvtzu v21.2d, v21.2d, #16
fcvtzu v20.2d, v20.2d, #16
umin v19.2s, v19.2s, v4.2s
umin v18.2s, v18.2s, v4.2s
str q26, [sp, #16]
uqxtn v21.2s, v21.2d
uqxtn v20.2s, v20.2d
dup v22.2d, v4.d[0]
fmov x25, d19
fmov x13, d18
umin v0.2s, v21.2s, v4.2s
add x11, x0, x10, lsl #5
lsr x3, x25, #32
lsr x4, x13, #32
sub w3, w3, w4
sub w1, w25, w13
asr w5, w1, #31
asr w4, w3, #31
add w1, w1, w5, lsr #28
add w3, w3, w4, lsr #28
asr w3, w3, #4
sbfx x1, x1, #4, #28
add x1, x1, x3, lsl #32
mov x26, v0.d[0]
umin v0.2s, v20.2s, v4.2s
str x11, [sp, #32]
sub w11, w9, #33
mov w3, #32
cmp w11, #32
sub w9, w9, #49
add x14, x13, x1
add x12, x1, x1
add x15, x13, x12
add x16, x14, x12
csel w11, w11, w3, lt
scvtf d1, w9
mov x27, v0.d[0]
scvtf d0, w11
fadd d29, d24, d30
fmov v18.2d, #16.0
fmov v20.2d, #1.0
mov v0.d[1], v1.d[0]
zip1 v24.2d, v24.2d, v29.2d
ldr q21, [x30, :lo12:kLinMin]
fadd v19.2d, v18.2d, v18.2d
str q0, [sp, #48]
add x17, x12, x12
