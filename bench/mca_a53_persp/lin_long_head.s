// The aarch64 linear long head (persp_fast_inl<false>, kPre: asm/span_persp_fast.cpp) as
// bench/count.sh's hot block shows it (wt-lin3: registers as the compiler allocated them), the
// first 12 lines the compiler's (loads, the loop's end pointer: --head=12), then the asm block
// in the order bench/order_search.py found (seed 3: 132 -> 121 cycles as one block):
//   order_search.py lin_long_head.s OUT.s 3000 --head=12 --seed=3
// Registers: x4 &p, d21 zrow, d0 zix, d25 / d26 urow / vrow, d27 / d28 ux / vx, d2 P, d1 kMaxU
// (umax, vmax), v4 kMin; v20 [16, 0] then kZix, v9 [P, P] then pos23, v10 p16, v31 z01, v8 z23,
// v29 / v30 / v23 / v24 ts0 .. ts3 then samples 0 .. 3, v3 ll, v7 its second lane then kUVrow,
// v16 kUVx, v5 k16, v6 k32, v18 kOne, v19 kZrow, v22 pp.
sub w13, w0, #0x31
ldr d21, [x4]
ldp d25, d27, [x4, #16]
lsr w15, w13, #5
ldp d26, d28, [x4, #32]
lsl w1, w15, #5
add x1, x1, #0x20
ldr d2, [x4, #48]
ldr d1, [x4, #56]
add x27, x14, x1
sub w0, w0, #0x21
mov x20, x14
fmov d20, #1.600000000000000000e+01
dup v9.2d, v2.d[0]
fmov v5.2d, #1.600000000000000000e+01
dup v31.2d, v21.d[0]
fmov v18.2d, #1.000000000000000000e+00
zip1 v29.2d, v25.2d, v26.2d
dup v8.2d, v21.d[0]
fadd v10.2d, v9.2d, v20.2d
fadd v6.2d, v5.2d, v5.2d
scvtf d3, w0
zip1 v16.2d, v27.2d, v28.2d
scvtf d7, w13
zip1 v24.2d, v25.2d, v26.2d
zip1 v30.2d, v25.2d, v26.2d
fadd v9.2d, v10.2d, v6.2d
fmla v31.2d, v10.2d, v0.d[0]
zip1 v23.2d, v25.2d, v26.2d
mov v3.d[1], v7.d[0]
fmla v30.2d, v16.2d, v2.d[0]
fmla v8.2d, v9.2d, v0.d[0]
fmaxnm v31.2d, v31.2d, v4.2d
fmla v24.2d, v16.2d, v9.d[0]
fmla v23.2d, v16.2d, v9.d[1]
fmla v29.2d, v16.2d, v10.d[0]
fmaxnm v8.2d, v8.2d, v4.2d
fdiv v31.2d, v18.2d, v31.2d
dup v20.2d, v0.d[0]
fadd d22, d10, d5
dup v19.2d, v21.d[0]
fdiv v8.2d, v18.2d, v8.2d
fmul v30.2d, v30.2d, v31.d[1]
fmul v29.2d, v29.2d, v31.d[0]
fadd d10, d22, d5
fmul v24.2d, v24.2d, v8.d[0]
fcvtzu v30.2d, v30.2d, #16
fcvtzu v29.2d, v29.2d, #16
fmul v23.2d, v23.2d, v8.d[1]
zip1 v22.2d, v22.2d, v10.2d
fcvtzu v24.2d, v24.2d, #16
uqxtn v30.2s, v30.2d
uqxtn v29.2s, v29.2d
fcvtzu v23.2d, v23.2d, #16
zip1 v7.2d, v25.2d, v26.2d
umin v30.2s, v30.2s, v1.2s
umin v29.2s, v29.2s, v1.2s
uqxtn v23.2s, v23.2d
uqxtn v24.2s, v24.2d
