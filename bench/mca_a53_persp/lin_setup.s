add x9, x11, x7, lsl #5
add x10, x4, #48
ldr q6, [x11]
fmov d1, #16.0
ld1r {v28.2d}, [x10]
sub w22, w7, #1
ld1r {v31.2d}, [x2]
and w28, w22, #15
ld2r {v16.2d, v17.2d}, [x4]
add x10, x4, #16
ld1r {v26.2d}, [x4]
ldp q4, q5, [x9, #-528]
fadd d2, d28, d1
fadd v0.2d, v28.2d, v6.2d
ld2 {v20.2d, v21.2d}, [x10]
cmp w28, #0
ld1r {v27.2d}, [x4]
fadd d3, d2, d1
ld2 {v22.2d, v23.2d}, [x10]
fadd v7.2d, v0.2d, v4.2d
fmla v26.2d, v17.2d, v0.2d
fmla v20.2d, v21.2d, v0.d[1]
fadd d3, d3, d5
ld2 {v24.2d, v25.2d}, [x10]
fmla v27.2d, v17.2d, v7.2d
fmla v22.2d, v23.2d, v7.d[0]
ld2 {v29.2d, v30.2d}, [x10]
fmaxnm v26.2d, v26.2d, v31.2d
fmadd d28, d17, d3, d16
fmla v24.2d, v25.2d, v7.d[1]
fmaxnm v27.2d, v27.2d, v31.2d
ld2 {v18.2d, v19.2d}, [x10]
frecpe v2.2d, v26.2d
fmov v1.2d, #1.0
fmaxnm d28, d28, d31
fmov x9, d27
fmov x3, d26
frecps v5.2d, v26.2d, v2.2d
frecpe v6.2d, v27.2d
mov x5, v26.d[1]
frecpe d4, d28
fmax v31.2d, v26.2d, v27.2d
mov x8, v27.d[1]
fmov x10, d28
fmul v2.2d, v2.2d, v5.2d
frecps v16.2d, v27.2d, v6.2d
frecps d17, d28, d4
fmaxp d31, v31.2d
add x10, x10, #1
add x3, x3, #1
lsl x3, x3, #12
lsl x10, x10, #12
add x8, x8, #1
fmul v6.2d, v6.2d, v16.2d
fmax d31, d31, d28
fmul d4, d4, d17
ldr d21, [x4, #56]
clz x10, x10
add x5, x5, #1
lsl x5, x5, #12
clz x3, x3
lsl x8, x8, #12
frecps v5.2d, v26.2d, v2.2d
frecps d17, d28, d4
frecps v16.2d, v27.2d, v6.2d
clz x8, x8
add x9, x9, #1
lsl x9, x9, #12
fmul v2.2d, v2.2d, v5.2d
mov v5.16b, v1.16b
fmul d4, d4, d17
fmul v6.2d, v6.2d, v16.2d
mov v16.16b, v1.16b
clz x9, x9
clz x5, x5
orr x3, x3, x5
orr x9, x9, x8
fmov x6, d31
fmsub d17, d28, d4, d1
fmls v16.2d, v27.2d, v6.2d
fmls v5.2d, v26.2d, v2.2d
uxtl v21.2d, v21.2s
orr x3, x3, x9
lsr x6, x6, #52
fmadd d4, d4, d17, d4
fmla v6.2d, v6.2d, v16.2d
fmla v2.2d, v2.2d, v5.2d
mov v5.16b, v1.16b
mov v16.16b, v1.16b
add x6, x6, #25
orr x3, x3, x10
lsr x6, x6, #5
fmla v29.2d, v30.2d, v3.d[0]
fmls v5.2d, v26.2d, v2.2d
fmls v16.2d, v27.2d, v6.2d
fmsub d17, d28, d4, d1
orr x3, x3, x6
fmla v18.2d, v19.2d, v0.d[0]
fmla v2.2d, v2.2d, v5.2d
fmla v6.2d, v6.2d, v16.2d
fmadd d4, d4, d17, d4
ucvtf v21.2d, v21.2d, #16
csinc w28, w28, wzr, ne
lsr w22, w22, #4
tbz x3, #6, 2f
fdiv v2.2d, v1.2d, v26.2d
fdiv v6.2d, v1.2d, v27.2d
fdiv d4, d1, d28
2:
fmul v18.2d, v18.2d, v2.d[0]
fmul v20.2d, v20.2d, v2.d[1]
fmul v29.2d, v29.2d, v4.d[0]
fmul v24.2d, v24.2d, v6.d[1]
fmul v22.2d, v22.2d, v6.d[0]
fmin v18.2d, v18.2d, v21.2d
fmin v20.2d, v20.2d, v21.2d
fmin v29.2d, v29.2d, v21.2d
fmin v24.2d, v24.2d, v21.2d
fmin v22.2d, v22.2d, v21.2d
fcvtzu v18.2d, v18.2d, #16
fcvtzu v20.2d, v20.2d, #16
fcvtzu v24.2d, v24.2d, #16
fcvtzu v22.2d, v22.2d, #16
fcvtzu v29.2d, v29.2d, #16
fmov x13, d18
fmov x23, d20
mov x1, v18.d[1]
mov x2, v20.d[1]
mov x5, v24.d[1]
fmov x19, d22
fmov x25, d24
mov x3, v22.d[1]
mov x6, v29.d[1]
fmov x4, d29
sub w9, w23, w13
sub w20, w25, w19
sub w15, w5, w3
sub w12, w3, w2
sub w24, w19, w23
sub w10, w2, w1
asr w14, w24, #31
cmp w22, #2
asr w8, w9, #31
asr w21, w15, #31
asr w16, w12, #31
sub w6, w6, w5
asr w11, w10, #31
sub w4, w4, w25
add w10, w10, w11, lsr #28
csel w4, w20, w4, eq
asr w17, w20, #31
add w9, w9, w8, lsr #28
sbfx x9, x9, #4, #28
csel w4, w24, w4, lt
csel w6, w15, w6, eq
add w15, w15, w21, lsr #28
csel w6, w12, w6, lt
add w24, w24, w14, lsr #28
asr w15, w15, #4
add w12, w12, w16, lsr #28
add w20, w20, w17, lsr #28
orr x19, x19, x3, lsl #32
asr w10, w10, #4
sbfx x24, x24, #4, #28
sbfx x20, x20, #4, #28
asr w12, w12, #4
add x9, x9, x10, lsl #32
sdiv w4, w4, w28
add x24, x24, x12, lsl #32
sdiv w6, w6, w28
add x20, x20, x15, lsl #32
orr x25, x25, x5, lsl #32
orr x23, x23, x2, lsl #32
orr x13, x13, x1, lsl #32
lsl x6, x6, #32
add x28, x6, w4, sxtw
