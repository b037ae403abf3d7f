ext v7.16b, v19.16b, v7.16b, #8
ext v0.16b, v5.16b, v19.16b, #8
fmul d31, d31, v1.d[1]
fmov x13, d5
mov x23, v5.d[1]
sub v7.4s, v7.4s, v19.4s
sub v0.4s, v0.4s, v5.4s
ldp q6, q17, [x26, #32]
ldp q23, q24, [x27, #64]
ldr q25, [x27, #96]
ldp q2, q4, [x26]
saddw2 v29.2d, v6.2d, v7.4s
saddw v26.2d, v6.2d, v0.2s
saddw2 v27.2d, v6.2d, v0.4s
fmul d31, d31, v25.d[0]
saddw v28.2d, v6.2d, v7.2s
fsub v29.2d, v29.2d, v6.2d
fsub v26.2d, v26.2d, v6.2d
fsub v27.2d, v27.2d, v6.2d
fsub v28.2d, v28.2d, v6.2d
fmul v30.2d, v29.2d, v24.d[0]
fmul v26.2d, v26.2d, v3.d[0]
fmul v27.2d, v27.2d, v3.d[1]
fmul v28.2d, v28.2d, v16.d[0]
abs v16.4s, v0.4s
fmls v29.2d, v30.2d, v24.d[1]
fcvtzs v26.2d, v26.2d
fcvtzs v28.2d, v28.2d
fcvtzs v27.2d, v27.2d
ldp q18, q20, [x27]
ldp q21, q22, [x27, #32]
fmla v30.2d, v29.2d, v24.d[0]
sqxtn v6.2s, v26.2d
sqxtn v1.2s, v28.2d
abs v26.4s, v7.4s
sshr v28.4s, v7.4s, #31
mov v7.16b, v16.16b
ushr v24.4s, v16.4s, #4
fcvtzs v25.2d, v30.2d
fmul v30.2d, v30.2d, v31.d[0]
sqxtn2 v6.4s, v27.2d
sshr v27.4s, v0.4s, #31
ushr v29.4s, v26.4s, #4
abs v25.2d, v25.2d
facgt v3.2d, v17.2d, v30.2d
fcvtzs v30.2d, v30.2d
eor v17.16b, v6.16b, v27.16b
eor v24.16b, v24.16b, v27.16b
xtn2 v29.4s, v25.2d
mov v25.16b, v26.16b
and v3.16b, v30.16b, v3.16b
sub v17.4s, v17.4s, v27.4s
sub v24.4s, v24.4s, v27.4s
eor v31.16b, v29.16b, v28.16b
mls v25.4s, v18.4s, v29.4s
sqxtn2 v1.4s, v3.2d
abs v3.4s, v6.4s
mls v7.4s, v17.4s, v2.s[0]
sub v31.4s, v31.4s, v28.4s
cmhi v25.4s, v23.4s, v25.4s
eor v30.16b, v1.16b, v28.16b
abs v0.4s, v1.4s
umin v3.4s, v3.4s, v4.4s
ushr v7.4s, v7.4s, #4
str q19, [x0]
sub v30.4s, v30.4s, v28.4s
umin v0.4s, v0.4s, v22.4s
mul v3.4s, v3.4s, v2.4s
eor v7.16b, v7.16b, v27.16b
mul v4.4s, v20.4s, v30.4s
mul v0.4s, v0.4s, v21.4s
cmhs v3.4s, v16.4s, v3.4s
sub v7.4s, v7.4s, v27.4s
sshr v22.4s, v4.4s, #1
shl v4.4s, v4.4s, #31
cmhs v0.4s, v26.4s, v0.4s
bit v24.16b, v7.16b, v3.16b
and v6.16b, v6.16b, v3.16b
sub v29.4s, v29.4s, v22.4s
and v25.16b, v25.16b, v4.16b
and v1.16b, v1.16b, v0.16b
fmov x9, d24
mov x24, v24.d[1]
fmov x10, d6
mov x25, v6.d[1]
ssra v29.4s, v25.4s, #31
eor v29.16b, v29.16b, v28.16b
sub v29.4s, v29.4s, v28.4s
bit v31.16b, v29.16b, v0.16b
stp q31, q1, [x0, #16]
