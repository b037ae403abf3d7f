// The long pass's set-up (gen_long_pass.py header --setup puts it before the loop): x1 = the
// span's PerspSpan (fields at the offsets the header static_asserts), w2 = n, x0 = d; input
// kMin v21 loaded here (kLongMin, its address in x30); writes kZix v16, kUVx v17, kMax4 v22, kZck v23 (dup zck, zck = zix * -1/16),
// k16 v18, k32 v19, kOne v20, the loop's state: samples 0 .. 3 (n0 = c0 x13, nA x25, nB x26,
// nC x27), run 0's chains (c1 x14, e0 x17, e1 x19, dd4 x20), pp v24, z23 v26, cc v27, zsn
// v29, and the stack slots [sp] kZrow, [sp, #16] kUVrow, [sp, #32] lim = d + 32 full,
// [sp, #48] offl = [min(lastl - 33, 32), lastl - 49] (full = (n - 49) / 32, lastl = n -
// 32 full in 49 .. 80; n > 64: full = 0 for n = 65 .. 80, one pass, the last) and x21 = full
// (the header's entry branch: full = 0 enters the loop with k32 = offl already loaded) (sp
// already lowered by 64). Reloads what it stored: order_search --mem.
add x4, x1, #40
ldr d0, [x1, #48]
mov x6, #0xbfb0000000000000
ldr d17, [x1, #24]
add x3, x1, #32
add x5, x1, #56
ldr d3, [x1, #16]
fmov v18.2d, #16.0
fmov d23, x6
ldr d16, [x1, #8]
sub w7, w2, #49
adrp x30, kLongMin
lsr w21, w7, #5
ld1 {v3.d}[1], [x3]
mov w11, #32
ld1 {v17.d}[1], [x4]
fadd d5, d0, d18
fmul d23, d16, d23
ld1r {v22.2d}, [x5]
str q3, [sp, #16]
add x8, x0, x21, lsl #5
ld1r {v1.2d}, [x1]
ldr q4, [sp, #16]
dup v16.2d, v16.d[0]
mov v0.d[1], v5.d[0]
fadd v19.2d, v18.2d, v18.2d
ldr q21, [x30, :lo12:kLongMin]
str q1, [sp]
ldr q6, [sp, #16]
sub w9, w2, w21, lsl #5
fmla v1.2d, v16.2d, v0.2d
fmla v3.2d, v17.2d, v0.d[0]
fmov v20.2d, #1.0
fadd v30.2d, v0.2d, v19.2d
ldr q2, [sp]
sub w10, w9, #33
sub w9, w9, #49
cmp w10, #32
fmaxnm v1.2d, v1.2d, v21.2d
ldr q25, [sp, #16]
csel w10, w10, w11, lt
fmla v2.2d, v16.2d, v30.2d
fmla v4.2d, v17.2d, v0.d[1]
fmla v6.2d, v17.2d, v30.d[0]
fdiv v31.2d, v20.2d, v1.2d
scvtf d7, w10
fmaxnm v2.2d, v2.2d, v21.2d
scvtf d27, w9
fmla v25.2d, v17.2d, v30.d[1]
fmul v4.2d, v4.2d, v31.d[1]
fmul v3.2d, v3.2d, v31.d[0]
fdiv v26.2d, v20.2d, v2.2d
fcvtzu v3.2d, v3.2d, #16
faddp d1, v31.2d
fcvtzu v4.2d, v4.2d, #16
uqxtn v3.2s, v3.2d
dup v23.2d, v23.d[0]
mov v7.d[1], v27.d[0]
ext v29.16b, v31.16b, v26.16b, #8
fmul v6.2d, v6.2d, v26.d[0]
uqxtn2 v3.4s, v4.2d
fmul d1, d1, v23.d[0]
fmul v25.2d, v25.2d, v26.d[1]
fadd d24, d5, d18
fcvtzu v6.2d, v6.2d, #16
umin v3.4s, v3.4s, v22.4s
fcvtzu v25.2d, v25.2d, #16
fadd d28, d24, d18
uqxtn v6.2s, v6.2d
fadd v2.2d, v29.2d, v26.2d
fmov x13, d3
mov x25, v3.d[1]
lsr x3, x25, #32
sub w2, w25, w13
sub x3, x3, x13, lsr #32
uqxtn2 v6.4s, v25.2d
scvtf d4, w2
scvtf d5, w3
sxtw x2, w2
str q7, [sp, #48]
fmul v27.2d, v2.2d, v23.d[0]
fmul d4, d4, d1
umin v6.4s, v6.4s, v22.4s
fmul d5, d5, d1
cmp x2, #0
str x8, [sp, #32]
fcvtzs w4, d4
fcvtzs w5, d5
mov v24.d[1], v28.d[0]
cneg x7, x2, lt
sbfiz x6, x4, #7, #32
sub x6, x6, w4, sxtw #3
add x8, x6, x7
cmp x8, x7, lsl #1
mov x27, v6.d[1]
csel x6, x6, xzr, ls
csel w9, w4, wzr, ls
cmp x3, #0
sub x6, x2, x6
asr x8, x6, #63
sbfiz x10, x5, #7, #32
cneg x11, x3, lt
sub x10, x10, w5, sxtw #3
add x12, x10, x11
cmp x12, x11, lsl #1
fmov x26, d6
csel x10, x10, xzr, ls
sub x10, x3, x10
csel w15, w5, wzr, ls
asr x12, x10, #63
lsl x11, x15, #32
add x10, x10, x12, lsr #60
add x6, x6, x8, lsr #60
asr x10, x10, #4
asr x6, x6, #4
add x11, x11, w9, sxtw
add x10, x6, x10, lsl #32
lsl x20, x11, #2
add x14, x13, x10
add x17, x11, x10, lsl #1
add x19, x17, x11, lsl #1
