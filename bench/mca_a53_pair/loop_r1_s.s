ldr w0, [x1, #8]
add x4, x1, #0x10
ldr w1, [x1, #96]
ldp x22, x2, [sp, #232]
sbfiz x0, x0, #5, #32
ldr x24, [sp, #184]
sbfiz x1, x1, #5, #32
ldr x23, [sp, #208]
ldr x21, [sp, #248]
add x0, x2, x0
add x1, x2, x1
add x2, x24, #0x68
add x7, x24, #0x108
cmp x23, x7
ldr q16, [x22]
ldr d0, [x4, #48]
add x7, x24, #0xb0
ldr d4, [x4]
csel x7, x7, x24, hi
add x15, x1, #0x10
ldp q19, q3, [x22, #32]
add x11, x2, #0x28
add x12, x2, #0x30
cset w3, hi
ldr w5, [x7, #8]
ldr d7, [x0, #16]
add x6, x4, #0x20
ldr d15, [x4, #8]
ldrb w20, [x7, #80]
add x14, x1, #0x8
ldr w16, [x7, #96]
ldr d5, [x0, #8]
ld1 {v0.d}[1], [x12]
ldrb w17, [x7, #168]
ldr d2, [x0]
ldr x18, [x7, #24]
ldr x19, [x7, #112]
fadd v6.2d, v0.2d, v16.2d
ld1 {v5.d}[1], [x14]
add x9, x2, #0x8
ld1 {v4.d}[1], [x2]
ldr q18, [x22, #16]
add x7, x4, #0x28
ld1 {v2.d}[1], [x1]
ld1 {v7.d}[1], [x15]
ld1 {v15.d}[1], [x9]
mov v10.16b, v4.16b
fadd v17.2d, v6.2d, v16.2d
mov v13.16b, v4.16b
mov v11.16b, v4.16b
fadd v8.2d, v0.2d, v2.2d
mov v1.16b, v4.16b
fadd v12.2d, v6.2d, v5.2d
fadd v14.2d, v17.2d, v7.2d
ldp q20, q9, [x22, #64]
fmla v10.2d, v15.2d, v0.2d
fmla v11.2d, v15.2d, v6.2d
fmla v1.2d, v15.2d, v8.2d
fmla v13.2d, v15.2d, v12.2d
fmla v4.2d, v15.2d, v14.2d
mov v25.16b, v18.16b
ldr d21, [x4, #16]
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
frecpe v31.2d, v4.2d
frecps v2.2d, v10.2d, v27.2d
frecps v5.2d, v11.2d, v28.2d
frecps v17.2d, v1.2d, v29.2d
frecps v7.2d, v13.2d, v30.2d
mov v22.16b, v18.16b
frecps v9.2d, v4.2d, v31.2d
fmul v27.2d, v27.2d, v2.2d
fmul v28.2d, v28.2d, v5.2d
fmul v29.2d, v29.2d, v17.2d
fmul v30.2d, v30.2d, v7.2d
mov v26.16b, v18.16b
fmul v31.2d, v31.2d, v9.2d
frecps v2.2d, v10.2d, v27.2d
frecps v5.2d, v11.2d, v28.2d
frecps v17.2d, v1.2d, v29.2d
frecps v7.2d, v13.2d, v30.2d
fmax v16.2d, v10.2d, v11.2d
frecps v9.2d, v4.2d, v31.2d
fmul v27.2d, v27.2d, v2.2d
fmul v28.2d, v28.2d, v5.2d
fmul v29.2d, v29.2d, v17.2d
orr v5.16b, v10.16b, v19.16b
fmul v30.2d, v30.2d, v7.2d
fmul v31.2d, v31.2d, v9.2d
fmax v2.2d, v1.2d, v13.2d
orr v7.16b, v1.16b, v19.16b
fmls v22.2d, v10.2d, v27.2d
fmls v23.2d, v11.2d, v28.2d
fmls v24.2d, v1.2d, v29.2d
fmls v25.2d, v13.2d, v30.2d
fmls v26.2d, v4.2d, v31.2d
fmax v16.2d, v16.2d, v2.2d
orr v9.16b, v13.16b, v19.16b
add x10, x2, #0x20
orr v2.16b, v4.16b, v19.16b
orr v17.16b, v11.16b, v19.16b
fmax v16.2d, v16.2d, v4.2d
fmla v30.2d, v30.2d, v25.2d
fmla v31.2d, v31.2d, v26.2d
fmla v27.2d, v27.2d, v22.2d
fmla v28.2d, v28.2d, v23.2d
fmla v29.2d, v29.2d, v24.2d
uminp v22.4s, v7.4s, v9.4s
cmhs v16.2d, v16.2d, v3.2d
mov v23.16b, v18.16b
mov v3.16b, v18.16b
mov v24.16b, v18.16b
uminp v19.4s, v5.4s, v17.4s
mov v25.16b, v18.16b
uminp v26.4s, v2.4s, v16.4s
ldr d17, [x2, #16]
add x8, x4, #0x38
umax v19.4s, v19.4s, v22.4s
mov v5.16b, v18.16b
fmls v24.2d, v11.2d, v28.2d
fmls v23.2d, v10.2d, v27.2d
fmls v25.2d, v1.2d, v29.2d
umax v19.4s, v19.4s, v26.4s
ldr d9, [x2, #24]
fmls v3.2d, v13.2d, v30.2d
fmls v5.2d, v4.2d, v31.2d
fmla v28.2d, v28.2d, v24.2d
fmla v27.2d, v27.2d, v23.2d
fmla v29.2d, v29.2d, v25.2d
umaxv s19, v19.4s
ld1 {v9.d}[1], [x11]
ld1 {v21.d}[1], [x6]
ld1 {v17.d}[1], [x10]
ldr d7, [x4, #24]
fmov w6, s19
mov v2.16b, v21.16b
mov v16.16b, v21.16b
mov v18.16b, v21.16b
ld1 {v7.d}[1], [x7]
cmn w6, #0x1
mov v22.16b, v21.16b
mov v25.16b, v17.16b
mov v24.16b, v17.16b
mov v26.16b, v17.16b
mov v23.16b, v17.16b
fmla v21.2d, v7.2d, v14.d[0]
fmla v2.2d, v7.2d, v6.d[0]
fmla v17.2d, v9.2d, v14.d[1]
fmla v25.2d, v9.2d, v12.d[1]
fmla v16.2d, v7.2d, v0.d[0]
fmla v22.2d, v7.2d, v8.d[0]
fmla v26.2d, v9.2d, v0.d[1]
fmla v30.2d, v30.2d, v3.2d
fmla v23.2d, v9.2d, v6.d[1]
fmla v31.2d, v31.2d, v5.2d
fmla v18.2d, v7.2d, v12.d[0]
fmla v24.2d, v9.2d, v8.d[1]
add x13, x2, #0x38
b.ne .+4
