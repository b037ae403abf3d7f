ext v7.16b, v19.16b, v7.16b, #8
ext v0.16b, v5.16b, v19.16b, #8
ldp q23, q24, [x0, #64]
ldp q6, q17, [x1, #32]
sub v7.4s, v7.4s, v19.4s
sub v0.4s, v0.4s, v5.4s
ldp q2, q4, [x1]
saddw2 v29.2d, v6.2d, v7.4s
saddw v26.2d, v6.2d, v0.2s
saddw2 v27.2d, v6.2d, v0.4s
saddw v28.2d, v6.2d, v7.2s
ldr q25, [x0, #96]
fmul d31, d31, v1.d[1]
fsub v29.2d, v29.2d, v6.2d
fsub v26.2d, v26.2d, v6.2d
fsub v27.2d, v27.2d, v6.2d
fsub v28.2d, v28.2d, v6.2d
ldp q18, q20, [x0]
fmul v30.2d, v29.2d, v24.d[0]
fmul v26.2d, v26.2d, v3.d[0]
fmul d31, d31, v25.d[0]
fmul v27.2d, v27.2d, v3.d[1]
fmul v28.2d, v28.2d, v16.d[0]
fmov x3, d5
mov x4, v5.d[1]
fmls v29.2d, v30.2d, v24.d[1]
fcvtzs v26.2d, v26.2d
ldp q21, q22, [x0, #32]
fcvtzs v28.2d, v28.2d
sqxtn v6.2s, v26.2d
fmla v30.2d, v29.2d, v24.d[0]
fcvtzs v27.2d, v27.2d
str q19, [x2]
sqxtn v1.2s, v28.2d
sshr v28.4s, v0.4s, #31
abs v26.4s, v0.4s
sshr v29.4s, v7.4s, #31
fcvtzs v25.2d, v30.2d
fmul v30.2d, v30.2d, v31.d[0]
sqxtn2 v6.4s, v27.2d
abs v27.4s, v7.4s
mov v7.16b, v26.16b
ushr v24.4s, v26.4s, #4
abs v25.2d, v25.2d
fcvtzs v30.2d, v30.2d
ushr v31.4s, v27.4s, #4
eor v24.16b, v24.16b, v28.16b
sqxtn2 v1.4s, v30.2d
xtn2 v31.4s, v25.2d
abs v3.4s, v6.4s
mov v25.16b, v27.16b
eor v30.16b, v6.16b, v28.16b
abs v0.4s, v1.4s
cmhi v16.4s, v17.4s, v0.4s
eor v9.16b, v31.16b, v29.16b
umin v3.4s, v3.4s, v4.4s
mul v4.4s, v20.4s, v1.4s
sub v30.4s, v30.4s, v28.4s
mls v25.4s, v18.4s, v31.4s
sub v24.4s, v24.4s, v28.4s
umin v0.4s, v0.4s, v22.4s
mul v3.4s, v3.4s, v2.4s
mls v7.4s, v30.4s, v2.s[0]
sshr v22.4s, v4.4s, #1
sub v9.4s, v9.4s, v29.4s
cmhi v25.4s, v23.4s, v25.4s
shl v4.4s, v4.4s, #31
mul v0.4s, v0.4s, v21.4s
ushr v7.4s, v7.4s, #4
cmhs v3.4s, v26.4s, v3.4s
sub v21.4s, v9.4s, v22.4s
eor v25.16b, v25.16b, v29.16b
eor v7.16b, v7.16b, v28.16b
and v6.16b, v6.16b, v3.16b
cmhs v0.4s, v27.4s, v0.4s
and v25.16b, v25.16b, v4.16b
sub v7.4s, v7.4s, v28.4s
fmov x5, d6
and v0.16b, v0.16b, v16.16b
ssra v21.4s, v25.4s, #31
mov x6, v6.d[1]
bit v24.16b, v7.16b, v3.16b
and v1.16b, v1.16b, v0.16b
bit v9.16b, v21.16b, v0.16b
mov x7, v24.d[1]
fmov x8, d24
stp q9, q1, [x2, #16]
