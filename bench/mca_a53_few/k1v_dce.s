ext v7.16b, v19.16b, v7.16b, #8
ldp q23, q24, [x0, #64]
ldp q6, q17, [x1, #32]
sub v7.4s, v7.4s, v19.4s
saddw2 v29.2d, v6.2d, v7.4s
saddw v28.2d, v6.2d, v7.2s
ldr q25, [x0, #96]
fmul d31, d31, v1.d[1]
fsub v29.2d, v29.2d, v6.2d
fsub v28.2d, v28.2d, v6.2d
ldp q18, q20, [x0]
fmul v30.2d, v29.2d, v24.d[0]
fmul d31, d31, v25.d[0]
fmul v28.2d, v28.2d, v16.d[0]
fmls v29.2d, v30.2d, v24.d[1]
ldp q21, q22, [x0, #32]
fcvtzs v28.2d, v28.2d
fmla v30.2d, v29.2d, v24.d[0]
str q19, [x2]
sqxtn v1.2s, v28.2d
sshr v29.4s, v7.4s, #31
fcvtzs v25.2d, v30.2d
fmul v30.2d, v30.2d, v31.d[0]
abs v27.4s, v7.4s
abs v25.2d, v25.2d
fcvtzs v30.2d, v30.2d
ushr v31.4s, v27.4s, #4
sqxtn2 v1.4s, v30.2d
xtn2 v31.4s, v25.2d
mov v25.16b, v27.16b
abs v0.4s, v1.4s
cmhi v16.4s, v17.4s, v0.4s
eor v9.16b, v31.16b, v29.16b
mul v4.4s, v20.4s, v1.4s
mls v25.4s, v18.4s, v31.4s
umin v0.4s, v0.4s, v22.4s
sshr v22.4s, v4.4s, #1
sub v9.4s, v9.4s, v29.4s
cmhi v25.4s, v23.4s, v25.4s
shl v4.4s, v4.4s, #31
mul v0.4s, v0.4s, v21.4s
sub v21.4s, v9.4s, v22.4s
eor v25.16b, v25.16b, v29.16b
cmhs v0.4s, v27.4s, v0.4s
and v25.16b, v25.16b, v4.16b
and v0.16b, v0.16b, v16.16b
ssra v21.4s, v25.4s, #31
and v1.16b, v1.16b, v0.16b
bit v9.16b, v21.16b, v0.16b
stp q9, q1, [x2, #16]
