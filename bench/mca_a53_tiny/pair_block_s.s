sub v0.4s, v0.4s, v24.4s
adrp x0, .Ltgt
ldr w3, [x9, #8]
ldr w1, [x12, #8]
mov w2, #0x30
add x0, x0, #0x620
saddw v2.2d, v12.2d, v0.2s
ldp q9, q28, [x9, #16]
smull x8, w1, w2
smull x2, w3, w2
add x5, x0, x8
saddw2 v1.2d, v12.2d, v0.4s
fadd v2.2d, v2.2d, v11.2d
ldr q22, [x0, x8]
ldr q23, [x0, x2]
add x4, x0, x2
adrp x0, .Ltgt
fmul v6.2d, v2.2d, v16.d[0]
ldr q13, [x0, #816]
ldr q3, [x12, #64]
ldr q8, [x12, #16]
ldr q25, [x9, #64]
fmls v2.2d, v6.2d, v14.d[0]
fadd v1.2d, v1.2d, v11.2d
zip1 v18.2d, v22.2d, v23.2d
abs v26.4s, v0.4s
zip1 v21.2d, v3.2d, v25.2d
zip1 v3.2d, v8.2d, v9.2d
mov v4.16b, v2.16b
fmul v2.2d, v1.2d, v16.d[1]
zip2 v8.2d, v8.2d, v9.2d
mov v9.16b, v3.16b
fadd v18.2d, v18.2d, v21.2d
fmla v6.2d, v4.2d, v16.d[0]
fmls v1.2d, v2.2d, v14.d[1]
fmla v9.2d, v8.2d, v21.2d
fmla v3.2d, v8.2d, v18.2d
fmul v4.2d, v6.2d, v5.d[0]
fmla v2.2d, v1.2d, v16.d[1]
fmaxnm v1.2d, v9.2d, v13.2d
fcvtzs v4.2d, v4.2d
fmaxnm v3.2d, v3.2d, v13.2d
fcvtzs v6.2d, v6.2d
fmul v9.2d, v2.2d, v5.d[1]
fcvtzs v2.2d, v2.2d
sqxtn v4.2s, v4.2d
cmlt v13.4s, v0.4s, #0
frecpe v5.2d, v1.2d
fcvtzs v9.2d, v9.2d
uzp1 v6.4s, v6.4s, v2.4s
frecpe v2.2d, v3.2d
frecps v14.2d, v1.2d, v5.2d
add v0.4s, v17.4s, v30.4s
sqxtn2 v4.4s, v9.2d
eor v20.16b, v13.16b, v6.16b
frecps v9.2d, v3.2d, v2.2d
fmul v5.2d, v5.2d, v14.2d
eor v16.16b, v13.16b, v4.16b
sub v20.4s, v20.4s, v13.4s
fmul v2.2d, v2.2d, v9.2d
mov v9.16b, v26.16b
fmov v14.2d, #1.000000000000000000e+00
frecps v27.2d, v1.2d, v5.2d
sub v16.4s, v16.4s, v13.4s
frecps v19.2d, v3.2d, v2.2d
mls v9.4s, v17.4s, v20.4s
mov v29.16b, v14.16b
mov v31.16b, v14.16b
mul v16.4s, v16.4s, v0.4s
movi v0.4s, #0x1
fmul v5.2d, v5.2d, v27.2d
shl v9.4s, v9.4s, #1
fmul v2.2d, v2.2d, v19.2d
and v0.16b, v16.16b, v0.16b
cmhi v9.4s, v17.4s, v9.4s
fmls v29.2d, v1.2d, v5.2d
fmls v31.2d, v3.2d, v2.2d
ldr q17, [x9, #48]
ldp q19, q27, [x12, #32]
and v0.16b, v9.16b, v0.16b
abs v9.4s, v4.4s
fmla v5.2d, v5.2d, v29.2d
fmla v2.2d, v2.2d, v31.2d
mov v29.16b, v14.16b
zip1 v31.2d, v19.2d, v28.2d
zip2 v19.2d, v19.2d, v28.2d
zip1 v28.2d, v27.2d, v17.2d
umin v7.4s, v9.4s, v7.4s
zip2 v17.2d, v27.2d, v17.2d
ssra v0.4s, v16.4s, #1
fmls v29.2d, v1.2d, v5.2d
mov v27.16b, v28.16b
mov v16.16b, v31.16b
fmls v14.2d, v3.2d, v2.2d
fmla v31.2d, v19.2d, v18.2d
mul v7.4s, v7.4s, v10.4s
fmla v5.2d, v5.2d, v29.2d
fmla v28.2d, v17.2d, v18.2d
fmla v16.2d, v19.2d, v21.2d
fmla v27.2d, v17.2d, v21.2d
fmla v2.2d, v2.2d, v14.2d
sub v0.4s, v20.4s, v0.4s
adrp x0, .Ltgt
fmul v16.2d, v5.2d, v16.2d
cmhi v9.4s, v9.4s, v15.4s
cmhs v7.4s, v26.4s, v7.4s
eor v10.16b, v0.16b, v13.16b
fmul v27.2d, v5.2d, v27.2d
ldr q14, [x0, #1520]
adrp x0, .Ltgt
fcvtzu v0.2d, v16.2d, #16
fmul v31.2d, v2.2d, v31.2d
bic v9.16b, v7.16b, v9.16b
fcvtzu v27.2d, v27.2d, #16
sub v10.4s, v10.4s, v13.4s
orr v17.16b, v3.16b, v14.16b
fmax v3.2d, v1.2d, v3.2d
orr v1.16b, v1.16b, v14.16b
fmul v28.2d, v2.2d, v28.2d
uqxtn v0.2s, v0.2d
ldr q14, [x0, #1536]
fcvtzu v31.2d, v31.2d, #16
uqxtn v27.2s, v27.2d
bit v6.16b, v10.16b, v9.16b
fcvtzu v28.2d, v28.2d, #16
uminp v1.4s, v1.4s, v17.4s
cmhi v3.2d, v3.2d, v14.2d
uqxtn2 v0.4s, v31.2d
movi v14.2d, #0xffffffff00000000
and v4.16b, v4.16b, v9.16b
uqxtn2 v27.4s, v28.2d
orr v1.16b, v1.16b, v3.16b
