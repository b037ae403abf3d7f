fmls v5.2d, v4.2d, v15.2d
fmla v28.2d, v28.2d, v24.2d
fmla v27.2d, v27.2d, v23.2d
fmla v29.2d, v29.2d, v25.2d
umaxv s19, v19.4s
ld1 {v17.d}[1], [x10]
ld1 {v21.d}[1], [x6]
cset w16, hi
ldr d7, [x4, #24]
ld1 {v9.d}[1], [x11]
fmov w6, s19
mov v18.16b, v21.16b
mov v26.16b, v17.16b
ld1 {v7.d}[1], [x7]
mov v23.16b, v17.16b
mov v22.16b, v21.16b
mov v2.16b, v21.16b
mov v25.16b, v17.16b
mov v24.16b, v17.16b
mov v16.16b, v21.16b
fmla v17.2d, v9.2d, v14.d[1]
fmla v18.2d, v7.2d, v12.d[0]
fmla v30.2d, v30.2d, v3.2d
fmla v21.2d, v7.2d, v14.d[0]
fmla v26.2d, v9.2d, v0.d[1]
fmla v25.2d, v9.2d, v12.d[1]
fmla v22.2d, v7.2d, v8.d[0]
fmla v15.2d, v15.2d, v5.2d
fmla v23.2d, v9.2d, v6.d[1]
fmla v16.2d, v7.2d, v0.d[0]
fmla v24.2d, v9.2d, v8.d[1]
fmla v2.2d, v7.2d, v6.d[0]
cmn w6, #0x1
add x13, x3, #0x38
add x8, x4, #0x38
b.ne .Ltgt
