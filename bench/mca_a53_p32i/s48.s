ldr q18, [x22, #16]
add x12, x20, #48
ldr d31, [x19, #8]
add x9, x20, #8
ldr d2, [x23]
add x7, x25, #264
ldr d4, [x19]
add w17, w27, #15
cmp x26, x7
asr w17, w17, #4
ldr d0, [x19, #48]
add x7, x25, #176
ldr d21, [x19, #16]
add x6, x19, #32
ldr d7, [x23, #16]
sub w30, w27, w17, lsl #4
ldr q16, [x22]
csel x7, x7, x25, hi
ld1 {v4.d}[1], [x20]
add x15, x24, #16
ld1 {v0.d}[1], [x12]
add x14, x24, #8
ld1 {v2.d}[1], [x24]
ldr d5, [x23, #8]
ld1 {v7.d}[1], [x15]
ldrb w4, [x7, #168]
fadd v6.2d, v0.2d, v16.2d
mov v1.16b, v4.16b
ldr x5, [x7, #24]
cset w1, hi
ld1 {v5.d}[1], [x14]
ld1 {v31.d}[1], [x9]
ldr x16, [x7, #112]
fadd v17.2d, v6.2d, v16.2d
mov v13.16b, v4.16b
mov v11.16b, v4.16b
fadd v8.2d, v0.2d, v2.2d
mov v10.16b, v4.16b
fadd v12.2d, v6.2d, v5.2d
fadd v14.2d, v17.2d, v7.2d
ldp q20, q9, [x22, #64]
fmla v1.2d, v31.2d, v8.2d
fmla v10.2d, v31.2d, v0.2d
fmla v11.2d, v31.2d, v6.2d
fmla v4.2d, v31.2d, v14.2d
fmla v13.2d, v31.2d, v12.2d
mov v25.16b, v18.16b
ldp q19, q3, [x22, #32]
add x11, x20, #40
fmaxnm v10.2d, v10.2d, v9.2d
fmaxnm v11.2d, v11.2d, v9.2d
fmaxnm v1.2d, v1.2d, v9.2d
fmaxnm v13.2d, v13.2d, v9.2d
mov v23.16b, v18.16b
fmaxnm v4.2d, v4.2d, v9.2d
frecpe v27.2d, v10.2d
frecpe v28.2d, v11.2d
frecpe v29.2d, v1.2d
frecpe v30.2d, v13.2d
mov v24.16b, v18.16b
frecps v2.2d, v10.2d, v27.2d
frecps v5.2d, v11.2d, v28.2d
mov v22.16b, v18.16b
frecps v17.2d, v1.2d, v29.2d
frecps v7.2d, v13.2d, v30.2d
fmul v27.2d, v27.2d, v2.2d
fmul v28.2d, v28.2d, v5.2d
fmul v29.2d, v29.2d, v17.2d
fmul v30.2d, v30.2d, v7.2d
fmax v16.2d, v10.2d, v11.2d
frecps v2.2d, v10.2d, v27.2d
frecps v5.2d, v11.2d, v28.2d
frecps v17.2d, v1.2d, v29.2d
frecps v7.2d, v13.2d, v30.2d
ldr w2, [x7, #8]
fmul v27.2d, v27.2d, v2.2d
fmul v28.2d, v28.2d, v5.2d
fmul v29.2d, v29.2d, v17.2d
fmax v2.2d, v1.2d, v13.2d
fmul v30.2d, v30.2d, v7.2d
orr v5.16b, v10.16b, v19.16b
orr v7.16b, v1.16b, v19.16b
orr v17.16b, v11.16b, v19.16b
fmax v16.2d, v16.2d, v2.2d
fmls v24.2d, v1.2d, v29.2d
fmls v22.2d, v10.2d, v27.2d
fmls v23.2d, v11.2d, v28.2d
fmls v25.2d, v13.2d, v30.2d
orr v9.16b, v13.16b, v19.16b
fmax v16.2d, v16.2d, v4.2d
orr v2.16b, v4.16b, v19.16b
uminp v19.4s, v5.4s, v17.4s
fmla v29.2d, v29.2d, v24.2d
fmla v28.2d, v28.2d, v23.2d
fmla v30.2d, v30.2d, v25.2d
fmla v27.2d, v27.2d, v22.2d
mov v23.16b, v18.16b
cmhs v16.2d, v16.2d, v3.2d
mov v24.16b, v18.16b
uminp v22.4s, v7.4s, v9.4s
mov v25.16b, v18.16b
ldr d9, [x20, #24]
add w30, w30, #16
add x10, x20, #32
ldr d17, [x20, #16]
mov v3.16b, v18.16b
uminp v26.4s, v2.4s, v16.4s
umax v19.4s, v19.4s, v22.4s
fmls v23.2d, v10.2d, v27.2d
fmls v25.2d, v1.2d, v29.2d
fmls v24.2d, v11.2d, v28.2d
fmls v3.2d, v13.2d, v30.2d
umax v19.4s, v19.4s, v26.4s
ld1 {v17.d}[1], [x10]
ldr w3, [x7, #96]
ldrb w28, [x7, #80]
fmla v29.2d, v29.2d, v25.2d
fmla v27.2d, v27.2d, v23.2d
fmla v28.2d, v28.2d, v24.2d
mov v24.16b, v17.16b
ld1 {v21.d}[1], [x6]
add x7, x19, #40
ld1 {v9.d}[1], [x11]
ldr d7, [x19, #24]
umaxv s19, v19.4s
mov v23.16b, v17.16b
mov v2.16b, v21.16b
mov v25.16b, v17.16b
ld1 {v7.d}[1], [x7]
mov v18.16b, v21.16b
mov v16.16b, v21.16b
fmov w6, s19
mov v22.16b, v21.16b
mov v26.16b, v17.16b
fmla v2.2d, v7.2d, v6.d[0]
fmla v25.2d, v9.2d, v12.d[1]
fmla v16.2d, v7.2d, v0.d[0]
fmla v22.2d, v7.2d, v8.d[0]
fmla v18.2d, v7.2d, v12.d[0]
fmla v23.2d, v9.2d, v6.d[1]
fmla v24.2d, v9.2d, v8.d[1]
fmla v26.2d, v9.2d, v0.d[1]
fmla v30.2d, v30.2d, v3.2d
add x13, x20, #56
cmn w6, #1
add x8, x19, #56
b.ne 2f
ldr q3, [x22, #16]
fdiv v27.2d, v3.2d, v10.2d
fdiv v28.2d, v3.2d, v11.2d
fdiv v29.2d, v3.2d, v1.2d
fdiv v30.2d, v3.2d, v13.2d
2:
fmul v18.2d, v18.2d, v30.d[0]
fmul v16.2d, v16.2d, v27.d[0]
fmul v22.2d, v22.2d, v29.d[0]
fadd v6.2d, v28.2d, v29.2d
fmul v24.2d, v24.2d, v29.d[1]
fadd v8.2d, v29.2d, v30.2d
fcvtzu v16.2d, v16.2d, #16
fmul v2.2d, v2.2d, v28.d[0]
fcvtzu v18.2d, v18.2d, #16
fadd v0.2d, v27.2d, v28.2d
fcvtzu v22.2d, v22.2d, #16
fmul v26.2d, v26.2d, v27.d[1]
fcvtzu v2.2d, v2.2d, #16
uqxtn v5.2s, v16.2d
fcvtzu v24.2d, v24.2d, #16
uqxtn v19.2s, v22.2d
mov v1.16b, v8.16b
fmul v23.2d, v23.2d, v28.d[1]
uqxtn2 v5.4s, v2.2d
fmul v25.2d, v25.2d, v30.d[1]
fcvtzu v26.2d, v26.2d, #16
trn1 v9.2d, v0.2d, v6.2d
ld1r {v2.2d}, [x8]
fcvtzu v23.2d, v23.2d, #16
uqxtn v10.2s, v26.2d
uqxtn v11.2s, v24.2d
fcvtzu v25.2d, v25.2d, #16
dup v22.2d, v8.d[1]
uqxtn2 v19.4s, v18.2d
uqxtn2 v10.4s, v23.2d
ld1r {v18.2d}, [x13]
fmul v14.2d, v31.2d, v20.2d
uqxtn2 v11.4s, v25.2d
fmov v20.2d, #0.5
umin v19.4s, v19.4s, v2.4s
trn2 v4.2d, v0.2d, v6.2d
umin v10.4s, v10.4s, v18.4s
umin v11.4s, v11.4s, v18.4s
fmul v31.2d, v31.2d, v20.2d
fmul v27.2d, v4.2d, v14.d[1]
fmul v3.2d, v9.2d, v14.d[0]
stp q10, q11, [x21, #0]
tst x5, #0x7fffffffffffffff
and w28, w28, w4
sub w3, w3, #17
str q4, [x21, #48]
sub w2, w2, #17
stp q22, q27, [x21, #64]
sub x3, x3, #32
sub x2, x2, #32
lsl x16, x16, #1
and x2, x2, x3
ccmp x16, #0, #4, ne
lsr x2, x2, #63
and w28, w28, w1
and w28, w28, w2
add x3, x25, #176
ccmp w28, #0, #4, ne
umin v5.4s, v5.4s, v2.4s
str q31, [x29]
csel x28, x3, xzr, ne
