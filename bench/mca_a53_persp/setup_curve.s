// persp_short_inl's second-order sample block up to its divide branch (asm/span_persp_a64short.h),
// operands as compiled: x4 = p, w7 = n, x0 = &kMinZi, x1 t0, x8 t1, x9 t2, x10 t5, x11 t6, x12 t7,
// d8 = zc, d9 = zck; the order from order_search.py (A53 141 -> 124 cycles as a loop, --a57=1).
sub w10, w7, #1
cmp w10, #32
mov w12, #32
sub w11, w7, #17
fmov d1, #16.0
ldr d0, [x4, #48]
csel w10, w10, w12, lt
cmp w11, #32
add x1, x4, #16
ld2r {v16.2d, v17.2d}, [x4]
ld1r {v26.2d}, [x4]
csel w11, w11, w12, lt
fadd d2, d0, d1
sub w12, w7, #33
scvtf d5, w11
scvtf d4, w10
ld1r {v27.2d}, [x4]
trn1 v0.2d, v0.2d, v2.2d
fadd d3, d2, d1
ld2 {v20.2d, v21.2d}, [x1]
fmov v1.2d, #1.0
scvtf d6, w12
trn1 v4.2d, v4.2d, v5.2d
ld1r {v31.2d}, [x0]
fmla v26.2d, v17.2d, v0.2d
fadd v7.2d, v0.2d, v4.2d
fadd d3, d3, d6
ld2 {v22.2d, v23.2d}, [x1]
mov x10, #0xbfb0000000000000
ld2 {v29.2d, v30.2d}, [x1]
fmaxnm v26.2d, v26.2d, v31.2d
fmla v27.2d, v17.2d, v7.2d
fmadd d28, d17, d3, d16
fmla v20.2d, v21.2d, v0.d[1]
frecpe v2.2d, v26.2d
mov x9, v26.d[1]
fmov d9, x10
fmov x8, d26
ld2 {v24.2d, v25.2d}, [x1]
fmaxnm v27.2d, v27.2d, v31.2d
fmaxnm d28, d28, d31
fmla v22.2d, v23.2d, v7.d[0]
frecps v5.2d, v26.2d, v2.2d
frecpe v6.2d, v27.2d
frecpe d4, d28
ld2 {v18.2d, v19.2d}, [x1]
fmax v31.2d, v26.2d, v27.2d
fmov x1, d28
fmov x12, d27
fmul v2.2d, v2.2d, v5.2d
frecps v16.2d, v27.2d, v6.2d
frecps d17, d28, d4
mov x11, v27.d[1]
fmaxp d31, v31.2d
add x8, x8, #1
add x1, x1, #1
lsl x8, x8, #12
lsl x1, x1, #12
add x11, x11, #1
frecps v5.2d, v26.2d, v2.2d
fmul d4, d4, d17
fmax d31, d31, d28
fmul v6.2d, v6.2d, v16.2d
add x9, x9, #1
add x12, x12, #1
lsl x9, x9, #12
lsl x11, x11, #12
lsl x12, x12, #12
frecps d17, d28, d4
frecps v16.2d, v27.2d, v6.2d
clz x8, x8
clz x12, x12
clz x11, x11
fmul v2.2d, v2.2d, v5.2d
mov v5.16b, v1.16b
fmul d9, d8, d9
fmul d4, d4, d17
fmul v6.2d, v6.2d, v16.2d
mov v16.16b, v1.16b
fmov x10, d31
orr x12, x12, x11
clz x9, x9
orr x8, x8, x9
fmsub d17, d28, d4, d1
fmls v5.2d, v26.2d, v2.2d
fmla v29.2d, v30.2d, v3.d[0]
fmls v16.2d, v27.2d, v6.2d
orr x8, x8, x12
clz x1, x1
lsr x10, x10, #52
fmla v2.2d, v2.2d, v5.2d
fmadd d4, d4, d17, d4
fmla v6.2d, v6.2d, v16.2d
mov v5.16b, v1.16b
mov v16.16b, v1.16b
add x10, x10, #0x19
orr x8, x8, x1
lsr x10, x10, #5
fmla v18.2d, v19.2d, v0.d[0]
fmls v5.2d, v26.2d, v2.2d
fmls v16.2d, v27.2d, v6.2d
fmsub d17, d28, d4, d1
fmla v24.2d, v25.2d, v7.d[1]
orr x8, x8, x10
fmla v2.2d, v2.2d, v5.2d
fmla v6.2d, v6.2d, v16.2d
fmadd d4, d4, d17, d4
tbz w8, #6, .
