add x14, x0, #48
ld1r {v10.2d}, [x4]
sub w22, w7, #1
add x10, x4, #48
add x9, x11, x7, lsl #5
fmov v1.2d, #16.0
ld1r {v3.2d}, [x10]
add x15, x4, #16
ld1r {v9.2d}, [x10]
add x16, x0, #16
ld1r {v8.2d}, [x14]
ldr q6, [x11]
sub x7, x9, #504
ld1 {v3.d}[1], [x14]
add x12, x11, x27, lsl #5
ld2 {v16.d, v17.d}[0], [x4]
ldp q4, q5, [x9, #-528]
fadd v0.2d, v9.2d, v6.2d
fadd v3.2d, v3.2d, v1.2d
ldp q13, q14, [x12, #-528]
ldr x7, [x7]
ld1r {v2.2d}, [x0]
fadd v15.2d, v8.2d, v6.2d
zip1 v5.2d, v5.2d, v14.2d
ld2 {v22.2d, v23.2d}, [x15]
fadd v3.2d, v3.2d, v1.2d
fmov v1.2d, #1.0
ld1r {v11.2d}, [x4]
ld1r {v12.2d}, [x0]
fadd v30.2d, v15.2d, v13.2d
ld2 {v16.d, v17.d}[1], [x0]
fadd v3.2d, v3.2d, v5.2d
mov v20.16b, v22.16b
ld1r {v31.2d}, [x2]
mov v18.16b, v22.16b
fadd v7.2d, v0.2d, v4.2d
mov v21.16b, v22.16b
fmla v10.2d, v0.2d, v17.d[0]
ld2 {v28.2d, v29.2d}, [x16]
fmla v16.2d, v17.2d, v3.2d
fmla v2.2d, v30.2d, v17.d[1]
fmla v11.2d, v7.2d, v17.d[0]
fmla v12.2d, v15.2d, v17.d[1]
mov v27.16b, v28.16b
mov v26.16b, v28.16b
mov v19.16b, v22.16b
fmaxnm v10.2d, v10.2d, v31.2d
mov v25.16b, v28.16b
fmaxnm v2.2d, v2.2d, v31.2d
fmaxnm v16.2d, v16.2d, v31.2d
mov v24.16b, v28.16b
fmaxnm v12.2d, v12.2d, v31.2d
fmaxnm v11.2d, v11.2d, v31.2d
fmla v21.2d, v23.2d, v7.d[1]
fmla v28.2d, v29.2d, v3.d[1]
fmla v18.2d, v23.2d, v0.d[0]
fmla v22.2d, v23.2d, v3.d[0]
fmla v25.2d, v29.2d, v15.d[1]
fmla v20.2d, v23.2d, v7.d[0]
fmla v24.2d, v29.2d, v15.d[0]
fmla v19.2d, v23.2d, v0.d[1]
fmla v26.2d, v29.2d, v30.d[0]
fmla v27.2d, v29.2d, v30.d[1]
frecpe v4.2d, v10.2d
frecpe v5.2d, v11.2d
frecpe v13.2d, v12.2d
frecpe v14.2d, v2.2d
frecpe v6.2d, v16.2d
fmax v31.2d, v10.2d, v11.2d
frecps v9.2d, v10.2d, v4.2d
frecps v8.2d, v11.2d, v5.2d
frecps v29.2d, v12.2d, v13.2d
frecps v23.2d, v2.2d, v14.2d
frecps v17.2d, v16.2d, v6.2d
fmax v7.2d, v12.2d, v2.2d
fmul v4.2d, v4.2d, v9.2d
fmul v5.2d, v5.2d, v8.2d
fmul v13.2d, v13.2d, v29.2d
fmul v14.2d, v14.2d, v23.2d
fmul v6.2d, v6.2d, v17.2d
fmax v31.2d, v31.2d, v7.2d
frecps v9.2d, v10.2d, v4.2d
frecps v8.2d, v11.2d, v5.2d
frecps v29.2d, v12.2d, v13.2d
frecps v23.2d, v2.2d, v14.2d
frecps v17.2d, v16.2d, v6.2d
fmax v31.2d, v31.2d, v16.2d
fmul v4.2d, v4.2d, v9.2d
fmul v5.2d, v5.2d, v8.2d
fmul v13.2d, v13.2d, v29.2d
mov v29.16b, v1.16b
mov v9.16b, v1.16b
fmul v14.2d, v14.2d, v23.2d
mov v8.16b, v1.16b
mov v23.16b, v1.16b
fmul v6.2d, v6.2d, v17.2d
mov v17.16b, v1.16b
mov x14, v12.d[1]
fmov x3, d10
fmls v9.2d, v10.2d, v4.2d
fmls v8.2d, v11.2d, v5.2d
fmls v29.2d, v12.2d, v13.2d
mov x5, v10.d[1]
fmov x9, d11
mov x1, v16.d[1]
fmls v17.2d, v16.2d, v6.2d
fmls v23.2d, v2.2d, v14.2d
fmla v4.2d, v4.2d, v9.2d
fmla v5.2d, v5.2d, v8.2d
fmla v13.2d, v13.2d, v29.2d
fmov x10, d16
fmov x13, d12
mov x8, v11.d[1]
mov v8.16b, v1.16b
mov v9.16b, v1.16b
fmla v6.2d, v6.2d, v17.2d
fmla v14.2d, v14.2d, v23.2d
mov v23.16b, v1.16b
mov v29.16b, v1.16b
fmaxp d31, v31.2d
mov v17.16b, v1.16b
fmov x17, d2
mov x19, v2.d[1]
fmls v9.2d, v10.2d, v4.2d
fmls v8.2d, v11.2d, v5.2d
fmls v29.2d, v12.2d, v13.2d
fmls v23.2d, v2.2d, v14.2d
fmls v17.2d, v16.2d, v6.2d
fmov x6, d31
ldr d0, [x4, #56]
fmla v4.2d, v4.2d, v9.2d
fmla v5.2d, v5.2d, v8.2d
fmla v13.2d, v13.2d, v29.2d
fmla v14.2d, v14.2d, v23.2d
fmla v6.2d, v6.2d, v17.2d
uxtl v0.2d, v0.2s
ldr d15, [x0, #56]
add x8, x8, #1
add x14, x14, #1
add x13, x13, #1
add x9, x9, #1
add x1, x1, #1
add x5, x5, #1
add x3, x3, #1
add x10, x10, #1
lsl x3, x3, #12
clz x3, x3
lsl x13, x13, #12
lsl x9, x9, #12
lsl x5, x5, #12
lsl x10, x10, #12
lsl x1, x1, #12
lsl x14, x14, #12
add x17, x17, #1
clz x14, x14
clz x9, x9
clz x10, x10
lsl x8, x8, #12
add x19, x19, #1
clz x1, x1
clz x8, x8
clz x5, x5
clz x13, x13
lsl x17, x17, #12
lsl x19, x19, #12
lsr x6, x6, #52
orr x3, x3, x5
orr x13, x13, x14
clz x17, x17
orr x9, x9, x8
uxtl v15.2d, v15.2s
ucvtf v0.2d, v0.2d, #16
orr x10, x10, x1
add x6, x6, #25
orr x10, x10, x13
orr x3, x3, x9
clz x19, x19
ucvtf v15.2d, v15.2d, #16
orr x17, x17, x19
and w28, w22, #15
orr x3, x3, x10
cmp w28, #0
lsr x6, x6, #5
orr x17, x17, x6
orr x3, x3, x17
lsr w22, w22, #4
csinc w28, w28, wzr, ne
tbz x3, #6, 2f
fdiv v4.2d, v1.2d, v10.2d
fdiv v5.2d, v1.2d, v11.2d
fdiv v13.2d, v1.2d, v12.2d
fdiv v14.2d, v1.2d, v2.2d
fdiv v6.2d, v1.2d, v16.2d
2:
fmul v21.2d, v21.2d, v5.d[1]
fmul v24.2d, v24.2d, v13.d[0]
fmul v18.2d, v18.2d, v4.d[0]
fmul v22.2d, v22.2d, v6.d[0]
fmul v19.2d, v19.2d, v4.d[1]
fmul v20.2d, v20.2d, v5.d[0]
fmul v25.2d, v25.2d, v13.d[1]
fmul v27.2d, v27.2d, v14.d[1]
fmul v26.2d, v26.2d, v14.d[0]
fmul v28.2d, v28.2d, v6.d[1]
fmin v19.2d, v19.2d, v0.2d
fmin v22.2d, v22.2d, v0.2d
fmin v18.2d, v18.2d, v0.2d
fmin v21.2d, v21.2d, v0.2d
fmin v20.2d, v20.2d, v0.2d
fmin v26.2d, v26.2d, v15.2d
fmin v24.2d, v24.2d, v15.2d
fmin v28.2d, v28.2d, v15.2d
fmin v25.2d, v25.2d, v15.2d
fmin v27.2d, v27.2d, v15.2d
fcvtzu v20.2d, v20.2d, #16
fcvtzu v19.2d, v19.2d, #16
fcvtzu v21.2d, v21.2d, #16
fcvtzu v18.2d, v18.2d, #16
fcvtzu v25.2d, v25.2d, #16
fcvtzu v22.2d, v22.2d, #16
fcvtzu v24.2d, v24.2d, #16
fcvtzu v28.2d, v28.2d, #16
fmov x19, d20
mov x3, v20.d[1]
fmov x23, d19
fcvtzu v27.2d, v27.2d, #16
fmov x13, d18
mov x1, v18.d[1]
fcvtzu v26.2d, v26.2d, #16
mov x2, v19.d[1]
fmov x25, d21
stp q24, q25, [x26]
fmov x4, d22
mov x5, v21.d[1]
mov x6, v22.d[1]
stp q26, q27, [x26, #32]
sub w9, w23, w13
sub w12, w3, w2
sub w24, w19, w23
sub w10, w2, w1
sub w15, w5, w3
orr x23, x23, x2, lsl #32
sub w20, w25, w19
asr w8, w9, #31
asr w14, w24, #31
asr w21, w15, #31
cmp w22, #2
asr w11, w10, #31
sub w4, w4, w25
asr w16, w12, #31
sub w6, w6, w5
csel w4, w20, w4, eq
add w10, w10, w11, lsr #28
asr w17, w20, #31
add w9, w9, w8, lsr #28
sbfx x9, x9, #4, #28
csel w4, w24, w4, lt
add w24, w24, w14, lsr #28
csel w6, w15, w6, eq
csel w6, w12, w6, lt
add w15, w15, w21, lsr #28
add w20, w20, w17, lsr #28
add w12, w12, w16, lsr #28
asr w15, w15, #4
orr x19, x19, x3, lsl #32
sbfx x24, x24, #4, #28
asr w10, w10, #4
sbfiz x8, x4, #29, #32
sbfx x20, x20, #4, #28
asr w12, w12, #4
smulh x8, x8, x7
sbfiz x21, x6, #29, #32
add w4, w8, w4, lsr #31
add x24, x24, x12, lsl #32
add x9, x9, x10, lsl #32
str q28, [x26, #64]
smulh x21, x21, x7
add x20, x20, x15, lsl #32
orr x13, x13, x1, lsl #32
add w6, w21, w6, lsr #31
orr x25, x25, x5, lsl #32
lsl x6, x6, #32
add x28, x6, w4, sxtw
