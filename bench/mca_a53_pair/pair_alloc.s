// persp_short_inl's sample block for two spans A, B at once (asm/span_persp_a64pair.h,
// short_samples2): each vector [span A's value, span B's value] of one sample k (0 .. 4).
// x0 = &A (PerspSpan), x1 = &B, x2 = out (two ShortSamples), x3 = kPairConsts,
// x4 = kShortOffsets + 32 nA, x5 = kShortOffsets + 32 nB; x6 .. x15 scratch.
add x6, x0, #32
add x7, x0, #40
add x8, x0, #56
add x9, x1, #8
add x10, x1, #32
add x11, x1, #40
add x12, x1, #48
add x13, x1, #56
add x14, x5, #8
add x15, x5, #16
ldr q0, [x3]
ldr d1, [x0, #48]
ld1 {v1.d}[1], [x12]
ldr d2, [x4]
ld1 {v2.d}[1], [x5]
ldr d3, [x4, #8]
ld1 {v3.d}[1], [x14]
ldr d4, [x4, #16]
ld1 {v4.d}[1], [x15]
ldr d5, [x0, #8]
ld1 {v5.d}[1], [x9]
ldr d6, [x0]
ld1 {v6.d}[1], [x1]
ldr d7, [x0]
ld1 {v7.d}[1], [x1]
ldr d8, [x0]
ld1 {v8.d}[1], [x1]
ldr d9, [x0]
ld1 {v9.d}[1], [x1]
ldr d10, [x0]
ld1 {v10.d}[1], [x1]
ldp q11, q12, [x3, #64]
fadd v13.2d, v1.2d, v0.2d
fadd v14.2d, v1.2d, v2.2d
fmla v6.2d, v5.2d, v1.2d
fadd v15.2d, v13.2d, v0.2d
fadd v16.2d, v13.2d, v3.2d
fmla v7.2d, v5.2d, v13.2d
fmla v8.2d, v5.2d, v14.2d
fadd v17.2d, v15.2d, v4.2d
fmla v9.2d, v5.2d, v16.2d
fmla v10.2d, v5.2d, v17.2d
fmaxnm v6.2d, v6.2d, v12.2d
fmaxnm v7.2d, v7.2d, v12.2d
fmaxnm v8.2d, v8.2d, v12.2d
fmaxnm v9.2d, v9.2d, v12.2d
fmaxnm v10.2d, v10.2d, v12.2d
frecpe v18.2d, v6.2d
frecpe v19.2d, v7.2d
frecpe v20.2d, v8.2d
frecpe v21.2d, v9.2d
frecpe v22.2d, v10.2d
ldp q23, q24, [x3, #32]
orr v25.16b, v6.16b, v23.16b
orr v26.16b, v7.16b, v23.16b
frecps v27.2d, v6.2d, v18.2d
frecps v28.2d, v7.2d, v19.2d
frecps v29.2d, v8.2d, v20.2d
frecps v30.2d, v9.2d, v21.2d
frecps v31.2d, v10.2d, v22.2d
orr v2.16b, v8.16b, v23.16b
orr v0.16b, v9.16b, v23.16b
orr v3.16b, v10.16b, v23.16b
fmul v18.2d, v18.2d, v27.2d
fmul v19.2d, v19.2d, v28.2d
fmul v20.2d, v20.2d, v29.2d
fmul v21.2d, v21.2d, v30.2d
fmul v22.2d, v22.2d, v31.2d
fmax v4.2d, v6.2d, v7.2d
fmax v15.2d, v8.2d, v9.2d
fmax v4.2d, v4.2d, v15.2d
frecps v27.2d, v6.2d, v18.2d
frecps v28.2d, v7.2d, v19.2d
frecps v29.2d, v8.2d, v20.2d
frecps v30.2d, v9.2d, v21.2d
frecps v31.2d, v10.2d, v22.2d
fmax v4.2d, v4.2d, v10.2d
cmhs v4.2d, v4.2d, v24.2d
uminp v12.4s, v25.4s, v26.4s
fmul v18.2d, v18.2d, v27.2d
ldr q23, [x3, #16]
fmul v19.2d, v19.2d, v28.2d
ldr q15, [x3, #16]
fmul v20.2d, v20.2d, v29.2d
ldr q24, [x3, #16]
fmul v21.2d, v21.2d, v30.2d
ldr q25, [x3, #16]
fmul v22.2d, v22.2d, v31.2d
ldr q26, [x3, #16]
uminp v27.4s, v2.4s, v0.4s
uminp v28.4s, v3.4s, v4.4s
umax v12.4s, v12.4s, v27.4s
fmls v23.2d, v6.2d, v18.2d
fmls v15.2d, v7.2d, v19.2d
fmls v24.2d, v8.2d, v20.2d
fmls v25.2d, v9.2d, v21.2d
fmls v26.2d, v10.2d, v22.2d
umax v12.4s, v12.4s, v28.4s
umaxv s12, v12.4s
ldr d29, [x0, #24]
ld1 {v29.d}[1], [x7]
fmla v18.2d, v18.2d, v23.2d
ldr q30, [x3, #16]
fmla v19.2d, v19.2d, v15.2d
ldr q31, [x3, #16]
fmla v20.2d, v20.2d, v24.2d
ldr q2, [x3, #16]
fmla v21.2d, v21.2d, v25.2d
ldr q0, [x3, #16]
fmla v22.2d, v22.2d, v26.2d
ldr q4, [x3, #16]
ldr d3, [x0, #16]
ld1 {v3.d}[1], [x6]
fmla v3.2d, v29.2d, v1.d[0]
ldr d27, [x0, #16]
ld1 {v27.d}[1], [x6]
fmla v27.2d, v29.2d, v13.d[0]
ldr d28, [x0, #16]
ld1 {v28.d}[1], [x6]
fmla v28.2d, v29.2d, v14.d[0]
fmls v30.2d, v6.2d, v18.2d
fmls v31.2d, v7.2d, v19.2d
fmls v2.2d, v8.2d, v20.2d
fmls v0.2d, v9.2d, v21.2d
fmls v4.2d, v10.2d, v22.2d
ldr d23, [x0, #16]
ld1 {v23.d}[1], [x6]
fmla v23.2d, v29.2d, v16.d[0]
ldr d15, [x0, #16]
ld1 {v15.d}[1], [x6]
fmla v15.2d, v29.2d, v17.d[0]
ldr d24, [x1, #24]
ld1 {v24.d}[1], [x11]
fmla v18.2d, v18.2d, v30.2d
fmla v19.2d, v19.2d, v31.2d
fmla v20.2d, v20.2d, v2.2d
fmla v21.2d, v21.2d, v0.2d
fmla v22.2d, v22.2d, v4.2d
ldr d25, [x1, #16]
ld1 {v25.d}[1], [x10]
fmla v25.2d, v24.2d, v1.d[1]
ldr d26, [x1, #16]
ld1 {v26.d}[1], [x10]
fmla v26.2d, v24.2d, v13.d[1]
ldr d29, [x1, #16]
ld1 {v29.d}[1], [x10]
fmla v29.2d, v24.2d, v14.d[1]
ldr d30, [x1, #16]
ld1 {v30.d}[1], [x10]
fmla v30.2d, v24.2d, v16.d[1]
ldr d31, [x1, #16]
ld1 {v31.d}[1], [x10]
fmla v31.2d, v24.2d, v17.d[1]
fmov w6, s12
cmn w6, #1
b.ne 2f
ldr q2, [x3, #16]
fdiv v18.2d, v2.2d, v6.2d
fdiv v19.2d, v2.2d, v7.2d
fdiv v20.2d, v2.2d, v8.2d
fdiv v21.2d, v2.2d, v9.2d
fdiv v22.2d, v2.2d, v10.2d
2:
ld1r {v0.2d}, [x8]
ld1r {v4.2d}, [x13]
fmul v3.2d, v3.2d, v18.d[0]
fmul v25.2d, v25.2d, v18.d[1]
fmul v27.2d, v27.2d, v19.d[0]
fmul v26.2d, v26.2d, v19.d[1]
fmul v28.2d, v28.2d, v20.d[0]
fmul v29.2d, v29.2d, v20.d[1]
fmul v23.2d, v23.2d, v21.d[0]
fmul v30.2d, v30.2d, v21.d[1]
fmul v15.2d, v15.2d, v22.d[0]
fmul v31.2d, v31.2d, v22.d[1]
fadd v1.2d, v18.2d, v19.2d
fadd v13.2d, v19.2d, v20.2d
fadd v14.2d, v20.2d, v21.2d
fadd v16.2d, v21.2d, v22.2d
fmul v24.2d, v5.2d, v11.2d
fcvtzu v3.2d, v3.2d, #16
fcvtzu v25.2d, v25.2d, #16
fcvtzu v27.2d, v27.2d, #16
fcvtzu v26.2d, v26.2d, #16
fcvtzu v28.2d, v28.2d, #16
fcvtzu v29.2d, v29.2d, #16
fcvtzu v23.2d, v23.2d, #16
fcvtzu v30.2d, v30.2d, #16
fcvtzu v15.2d, v15.2d, #16
fcvtzu v31.2d, v31.2d, #16
trn1 v17.2d, v1.2d, v13.2d
trn2 v12.2d, v1.2d, v13.2d
trn1 v6.2d, v14.2d, v16.2d
trn2 v7.2d, v14.2d, v16.2d
uqxtn v8.2s, v3.2d
uqxtn v9.2s, v28.2d
uqxtn v10.2s, v15.2d
uqxtn v2.2s, v25.2d
uqxtn v18.2s, v29.2d
uqxtn v19.2s, v31.2d
fmul v20.2d, v17.2d, v24.d[0]
fmul v21.2d, v12.2d, v24.d[1]
fmul v22.2d, v6.2d, v24.d[0]
fmul v11.2d, v7.2d, v24.d[1]
uqxtn2 v8.4s, v27.2d
uqxtn2 v9.4s, v23.2d
uqxtn2 v10.4s, v15.2d
uqxtn2 v2.4s, v26.2d
uqxtn2 v18.4s, v30.2d
uqxtn2 v19.4s, v31.2d
umin v8.4s, v8.4s, v0.4s
umin v9.4s, v9.4s, v0.4s
umin v10.4s, v10.4s, v0.4s
umin v2.4s, v2.4s, v4.4s
umin v18.4s, v18.4s, v4.4s
umin v19.4s, v19.4s, v4.4s
stp q8, q9, [x2, #0]
stp q10, q17, [x2, #32]
stp q6, q20, [x2, #64]
str q22, [x2, #96]
stp q2, q18, [x2, #112]
stp q19, q12, [x2, #144]
stp q7, q21, [x2, #176]
str q11, [x2, #208]
