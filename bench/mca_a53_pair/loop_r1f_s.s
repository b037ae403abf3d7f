add x0, x1, #0x58
mov x2, x1
add x4, x1, #0x10
ldr w1, [x1, #8]
str x0, [sp, #176]
ldr w0, [x0, #8]
str x2, [sp, #192]
ldp x30, x22, [sp, #184]
sbfiz x2, x1, #5, #32
ldp x25, x3, [sp, #248]
sbfiz x0, x0, #5, #32
ldr x24, [sp, #264]
add x0, x3, x0
add x2, x3, x2
add x3, x22, #0x68
ldr q18, [x25, #16]
add x12, x3, #0x30
ldr d31, [x4, #8]
add x7, x22, #0x108
ldr d2, [x2]
ldr d4, [x4]
add w5, w1, #0xf
cmp x30, x7
asr w5, w5, #4
ldr d0, [x4, #48]
add x7, x22, #0xb0
ldr d21, [x4, #16]
add x6, x4, #0x20
ldr d7, [x2, #16]
sub w27, w1, w5, lsl #4
ldr q16, [x25]
csel x7, x7, x22, hi
ld1 {v4.d}[1], [x3]
add x15, x0, #0x10
ld1 {v0.d}[1], [x12]
add x14, x0, #0x8
ld1 {v2.d}[1], [x0]
add w27, w27, #0x10
ldr d5, [x2, #8]
add x9, x3, #0x8
ld1 {v7.d}[1], [x15]
ldrb w19, [x7, #168]
fadd v6.2d, v0.2d, v16.2d
mov v1.16b, v4.16b
ldr x20, [x7, #24]
cset w16, hi
ld1 {v5.d}[1], [x14]
ld1 {v31.d}[1], [x9]
ldr x21, [x7, #112]
fadd v17.2d, v6.2d, v16.2d
mov v13.16b, v4.16b
mov v11.16b, v4.16b
fadd v8.2d, v0.2d, v2.2d
mov v10.16b, v4.16b
fadd v12.2d, v6.2d, v5.2d
fadd v14.2d, v17.2d, v7.2d
ldp q20, q9, [x25, #64]
fmla v1.2d, v31.2d, v8.2d
fmla v10.2d, v31.2d, v0.2d
fmla v11.2d, v31.2d, v6.2d
fmla v4.2d, v31.2d, v14.2d
fmla v13.2d, v31.2d, v12.2d
mov v25.16b, v18.16b
ldp q19, q3, [x25, #32]
add x11, x3, #0x28
fmaxnm v10.2d, v10.2d, v9.2d
fmaxnm v11.2d, v11.2d, v9.2d
fmaxnm v1.2d, v1.2d, v9.2d
fmaxnm v13.2d, v13.2d, v9.2d
mov v23.16b, v18.16b
fmaxnm v4.2d, v4.2d, v9.2d
frecpe v27.2d, v10.2d
frecpe v28.2d, v11.2d
mov v24.16b, v18.16b
frecpe v29.2d, v1.2d
frecpe v30.2d, v13.2d
frecpe v15.2d, v4.2d
frecps v2.2d, v10.2d, v27.2d
frecps v5.2d, v11.2d, v28.2d
mov v22.16b, v18.16b
frecps v17.2d, v1.2d, v29.2d
frecps v7.2d, v13.2d, v30.2d
frecps v9.2d, v4.2d, v15.2d
fmul v27.2d, v27.2d, v2.2d
fmul v28.2d, v28.2d, v5.2d
mov v26.16b, v18.16b
fmul v29.2d, v29.2d, v17.2d
fmul v30.2d, v30.2d, v7.2d
fmax v16.2d, v10.2d, v11.2d
fmul v15.2d, v15.2d, v9.2d
frecps v2.2d, v10.2d, v27.2d
frecps v5.2d, v11.2d, v28.2d
frecps v17.2d, v1.2d, v29.2d
frecps v7.2d, v13.2d, v30.2d
ldr w17, [x7, #8]
frecps v9.2d, v4.2d, v15.2d
fmul v27.2d, v27.2d, v2.2d
fmul v28.2d, v28.2d, v5.2d
fmax v2.2d, v1.2d, v13.2d
fmul v29.2d, v29.2d, v17.2d
fmul v30.2d, v30.2d, v7.2d
orr v7.16b, v1.16b, v19.16b
orr v17.16b, v11.16b, v19.16b
fmul v15.2d, v15.2d, v9.2d
orr v5.16b, v10.16b, v19.16b
fmax v16.2d, v16.2d, v2.2d
fmls v24.2d, v1.2d, v29.2d
fmls v23.2d, v11.2d, v28.2d
fmls v22.2d, v10.2d, v27.2d
fmls v25.2d, v13.2d, v30.2d
fmls v26.2d, v4.2d, v15.2d
orr v9.16b, v13.16b, v19.16b
fmax v16.2d, v16.2d, v4.2d
orr v2.16b, v4.16b, v19.16b
uminp v19.4s, v5.4s, v17.4s
fmla v28.2d, v28.2d, v23.2d
fmla v29.2d, v29.2d, v24.2d
fmla v30.2d, v30.2d, v25.2d
fmla v27.2d, v27.2d, v22.2d
fmla v15.2d, v15.2d, v26.2d
mov v23.16b, v18.16b
cmhs v16.2d, v16.2d, v3.2d
uminp v22.4s, v7.4s, v9.4s
mov v5.16b, v18.16b
mov v24.16b, v18.16b
mov v25.16b, v18.16b
ldr d9, [x3, #24]
add x10, x3, #0x20
ldr d17, [x3, #16]
uminp v26.4s, v2.4s, v16.4s
umax v19.4s, v19.4s, v22.4s
mov v3.16b, v18.16b
fmls v23.2d, v10.2d, v27.2d
fmls v5.2d, v4.2d, v15.2d
fmls v25.2d, v1.2d, v29.2d
fmls v24.2d, v11.2d, v28.2d
umax v19.4s, v19.4s, v26.4s
ldrb w23, [x7, #80]
ldr w18, [x7, #96]
fmls v3.2d, v13.2d, v30.2d
fmla v27.2d, v27.2d, v23.2d
fmla v29.2d, v29.2d, v25.2d
fmla v28.2d, v28.2d, v24.2d
ld1 {v17.d}[1], [x10]
add x7, x4, #0x28
ld1 {v21.d}[1], [x6]
add x13, x3, #0x38
ld1 {v9.d}[1], [x11]
ldr d7, [x4, #24]
umaxv s19, v19.4s
mov v23.16b, v17.16b
mov v2.16b, v21.16b
mov v25.16b, v17.16b
mov v16.16b, v21.16b
ld1 {v7.d}[1], [x7]
mov v18.16b, v21.16b
mov v24.16b, v17.16b
mov v22.16b, v21.16b
fmov w6, s19
mov v26.16b, v17.16b
fmla v21.2d, v7.2d, v14.d[0]
fmla v25.2d, v9.2d, v12.d[1]
fmla v15.2d, v15.2d, v5.2d
fmla v16.2d, v7.2d, v0.d[0]
fmla v2.2d, v7.2d, v6.d[0]
fmla v23.2d, v9.2d, v6.d[1]
fmla v22.2d, v7.2d, v8.d[0]
fmla v18.2d, v7.2d, v12.d[0]
fmla v24.2d, v9.2d, v8.d[1]
fmla v26.2d, v9.2d, v0.d[1]
fmla v17.2d, v9.2d, v14.d[1]
fmla v30.2d, v30.2d, v3.2d
cmn w6, #0x1
add x8, x4, #0x38
b.ne .Ltgt
