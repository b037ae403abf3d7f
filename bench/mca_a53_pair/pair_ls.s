// persp_short_inl's sample block for two spans A, B at once (asm/span_persp_a64pair.h,
// short_samples2): each vector [span A's value, span B's value] of one sample k (0 .. 4).
// x0 = &A (PerspSpan), x1 = &B, x2 = out (two ShortSamples), x3 = kPairConsts,
// x4 = kShortOffsets + 32 nA, x5 = kShortOffsets + 32 nB; x6 .. x15 scratch.
ldr d0, [x0, #48]
add x12, x1, #48
ldr q1, [x3]
ldr d2, [x4]
ldr d3, [x4, #8]
ld1 {v0.d}[1], [x12]
ldr d4, [x4, #16]
ldr d5, [x0]
add x14, x5, #8
add x15, x5, #16
fadd v6.2d, v0.2d, v1.2d
ld1 {v2.d}[1], [x5]
ld1 {v3.d}[1], [x14]
ld1 {v4.d}[1], [x15]
ld1 {v5.d}[1], [x1]
fadd v7.2d, v6.2d, v1.2d
fadd v8.2d, v0.2d, v2.2d
fadd v9.2d, v6.2d, v3.2d
mov v10.16b, v5.16b
mov v11.16b, v5.16b
mov v12.16b, v5.16b
mov v13.16b, v5.16b
fadd v14.2d, v7.2d, v4.2d
ldr d15, [x0, #8]
add x9, x1, #8
ldp q16, q17, [x3, #64]
ldr q18, [x3, #16]
ldp q19, q20, [x3, #32]
ld1 {v15.d}[1], [x9]
ldr d21, [x0, #16]
mov v22.16b, v18.16b
mov v23.16b, v18.16b
fmla v10.2d, v15.2d, v0.2d
fmla v11.2d, v15.2d, v6.2d
fmla v12.2d, v15.2d, v8.2d
fmla v13.2d, v15.2d, v9.2d
fmla v5.2d, v15.2d, v14.2d
mov v24.16b, v18.16b
mov v25.16b, v18.16b
fmaxnm v10.2d, v10.2d, v17.2d
fmaxnm v11.2d, v11.2d, v17.2d
fmaxnm v12.2d, v12.2d, v17.2d
fmaxnm v13.2d, v13.2d, v17.2d
fmaxnm v5.2d, v5.2d, v17.2d
mov v26.16b, v18.16b
frecpe v27.2d, v10.2d
frecpe v28.2d, v11.2d
frecpe v29.2d, v12.2d
frecpe v30.2d, v13.2d
frecpe v31.2d, v5.2d
fmax v1.2d, v10.2d, v11.2d
frecps v2.2d, v10.2d, v27.2d
frecps v3.2d, v11.2d, v28.2d
frecps v7.2d, v12.2d, v29.2d
frecps v4.2d, v13.2d, v30.2d
frecps v17.2d, v5.2d, v31.2d
fmul v27.2d, v27.2d, v2.2d
fmul v28.2d, v28.2d, v3.2d
fmul v29.2d, v29.2d, v7.2d
fmul v30.2d, v30.2d, v4.2d
fmul v31.2d, v31.2d, v17.2d
frecps v2.2d, v10.2d, v27.2d
frecps v3.2d, v11.2d, v28.2d
frecps v7.2d, v12.2d, v29.2d
frecps v4.2d, v13.2d, v30.2d
frecps v17.2d, v5.2d, v31.2d
fmul v27.2d, v27.2d, v2.2d
fmax v2.2d, v12.2d, v13.2d
fmul v28.2d, v28.2d, v3.2d
fmul v29.2d, v29.2d, v7.2d
fmul v30.2d, v30.2d, v4.2d
fmul v31.2d, v31.2d, v17.2d
fmls v22.2d, v10.2d, v27.2d
fmls v23.2d, v11.2d, v28.2d
fmls v24.2d, v12.2d, v29.2d
fmls v25.2d, v13.2d, v30.2d
fmls v26.2d, v5.2d, v31.2d
fmax v1.2d, v1.2d, v2.2d
orr v3.16b, v10.16b, v19.16b
orr v7.16b, v11.16b, v19.16b
orr v4.16b, v12.16b, v19.16b
orr v17.16b, v13.16b, v19.16b
orr v2.16b, v5.16b, v19.16b
fmax v1.2d, v1.2d, v5.2d
fmla v27.2d, v27.2d, v22.2d
fmla v28.2d, v28.2d, v23.2d
fmla v29.2d, v29.2d, v24.2d
fmla v30.2d, v30.2d, v25.2d
fmla v31.2d, v31.2d, v26.2d
cmhs v1.2d, v1.2d, v20.2d
uminp v19.4s, v3.4s, v7.4s
uminp v22.4s, v4.4s, v17.4s
mov v23.16b, v18.16b
mov v24.16b, v18.16b
mov v25.16b, v18.16b
uminp v26.4s, v2.4s, v1.4s
mov v20.16b, v18.16b
umax v19.4s, v19.4s, v22.4s
mov v3.16b, v18.16b
fmls v23.2d, v10.2d, v27.2d
fmls v24.2d, v11.2d, v28.2d
fmls v25.2d, v12.2d, v29.2d
fmls v20.2d, v13.2d, v30.2d
fmls v3.2d, v5.2d, v31.2d
umax v19.4s, v19.4s, v26.4s
fmla v27.2d, v27.2d, v23.2d
fmla v28.2d, v28.2d, v24.2d
fmla v29.2d, v29.2d, v25.2d
fmla v30.2d, v30.2d, v20.2d
fmla v31.2d, v31.2d, v3.2d
umaxv s19, v19.4s
ldr d7, [x1, #16]
add x6, x0, #32
add x10, x1, #32
ldr d4, [x0, #24]
ldr d17, [x1, #24]
ld1 {v21.d}[1], [x6]
fmov w6, s19
ld1 {v7.d}[1], [x10]
add x7, x0, #40
add x11, x1, #40
mov v1.16b, v21.16b
mov v2.16b, v21.16b
mov v22.16b, v21.16b
mov v18.16b, v21.16b
mov v26.16b, v7.16b
mov v23.16b, v7.16b
mov v24.16b, v7.16b
mov v25.16b, v7.16b
ld1 {v4.d}[1], [x7]
ld1 {v17.d}[1], [x11]
add x8, x0, #56
add x13, x1, #56
cmn w6, #1
fmla v1.2d, v4.2d, v0.d[0]
fmla v2.2d, v4.2d, v6.d[0]
fmla v22.2d, v4.2d, v8.d[0]
fmla v18.2d, v4.2d, v9.d[0]
fmla v21.2d, v4.2d, v14.d[0]
fmla v26.2d, v17.2d, v0.d[1]
fmla v23.2d, v17.2d, v6.d[1]
fmla v24.2d, v17.2d, v8.d[1]
fmla v25.2d, v17.2d, v9.d[1]
fmla v7.2d, v17.2d, v14.d[1]
b.ne 2f
ldr q20, [x3, #16]
fdiv v27.2d, v20.2d, v10.2d
fdiv v28.2d, v20.2d, v11.2d
fdiv v29.2d, v20.2d, v12.2d
fdiv v30.2d, v20.2d, v13.2d
fdiv v31.2d, v20.2d, v5.2d
2:
fmul v1.2d, v1.2d, v27.d[0]
fmul v22.2d, v22.2d, v29.d[0]
fmul v21.2d, v21.2d, v31.d[0]
fmul v2.2d, v2.2d, v28.d[0]
fmul v18.2d, v18.2d, v30.d[0]
fmul v26.2d, v26.2d, v27.d[1]
fcvtzu v1.2d, v1.2d, #16
fcvtzu v22.2d, v22.2d, #16
fcvtzu v21.2d, v21.2d, #16
fcvtzu v2.2d, v2.2d, #16
fcvtzu v18.2d, v18.2d, #16
fmul v24.2d, v24.2d, v29.d[1]
uqxtn v3.2s, v1.2d
uqxtn v19.2s, v22.2d
uqxtn v4.2s, v21.2d
fmul v7.2d, v7.2d, v31.d[1]
fadd v0.2d, v27.2d, v28.2d
fadd v6.2d, v28.2d, v29.2d
uqxtn2 v3.4s, v2.2d
uqxtn2 v19.4s, v18.2d
fmul v23.2d, v23.2d, v28.d[1]
fmul v25.2d, v25.2d, v30.d[1]
fcvtzu v26.2d, v26.2d, #16
fcvtzu v24.2d, v24.2d, #16
uqxtn2 v4.4s, v21.2d
fadd v8.2d, v29.2d, v30.2d
fadd v9.2d, v30.2d, v31.2d
fmul v14.2d, v15.2d, v16.2d
fcvtzu v7.2d, v7.2d, #16
trn1 v17.2d, v0.2d, v6.2d
fcvtzu v23.2d, v23.2d, #16
fcvtzu v25.2d, v25.2d, #16
uqxtn v10.2s, v26.2d
uqxtn v11.2s, v24.2d
trn1 v12.2d, v8.2d, v9.2d
uqxtn v13.2s, v7.2d
fmul v20.2d, v17.2d, v14.d[0]
trn2 v5.2d, v0.2d, v6.2d
uqxtn2 v10.4s, v23.2d
uqxtn2 v11.4s, v25.2d
fmul v1.2d, v12.2d, v14.d[0]
uqxtn2 v13.4s, v7.2d
trn2 v22.2d, v8.2d, v9.2d
fmul v27.2d, v5.2d, v14.d[1]
ld1r {v2.2d}, [x8]
ld1r {v18.2d}, [x13]
fmul v28.2d, v22.2d, v14.d[1]
umin v3.4s, v3.4s, v2.4s
umin v19.4s, v19.4s, v2.4s
umin v4.4s, v4.4s, v2.4s
umin v10.4s, v10.4s, v18.4s
umin v11.4s, v11.4s, v18.4s
umin v13.4s, v13.4s, v18.4s
stp q3, q19, [x2, #0]
stp q4, q17, [x2, #32]
stp q12, q20, [x2, #64]
str q1, [x2, #96]
stp q10, q11, [x2, #112]
stp q13, q5, [x2, #144]
stp q22, q27, [x2, #176]
str q28, [x2, #208]
