add x20, x2, #88
sub v0.4s, v30.4s, v29.4s
ldr w15, [x1, #8]
cmp x20, x3
ldr w16, [x2, #8]
add x25, x2, #176
ldp q9, q10, [x14, #816]
sub w15, w15, #1
csel x21, x20, x1, ne
sub w16, w16, #1
add x17, x15, x15, lsl #1
ccmp x25, x3, #4, ne
add x19, x16, x16, lsl #1
ldr x26, [x21, #24]
add x17, x14, x17, lsl #4
ldr w22, [x21, #8]
csel x24, x25, x1, ne
saddw2 v18.2d, v9.2d, v0.4s
saddw v17.2d, v9.2d, v0.2s
ldr w23, [x24, #8]
ldp q11, q12, [x17, #48]
add x19, x14, x19, lsl #4
sub w22, w22, #1
ldp q20, q21, [x24, #16]
sub w23, w23, #1
and w27, w23, #15
and w28, w22, #15
ldp q15, q16, [x21, #16]
add x27, x27, x27, lsl #1
fsub v25.2d, v18.2d, v9.2d
ldp q13, q14, [x19, #48]
add x28, x28, x28, lsl #1
fsub v24.2d, v17.2d, v9.2d
zip1 v26.2d, v15.2d, v20.2d
ldp q22, q23, [x21, #48]
add x28, x14, x28, lsl #4
fmul v18.2d, v25.2d, v13.d[1]
fmov v4.2d, #1.0
fmul v17.2d, v24.2d, v11.d[1]
zip2 v27.2d, v15.2d, v20.2d
zip2 v19.2d, v12.2d, v14.2d
ldrb w15, [x21, #80]
zip1 v28.2d, v15.2d, v20.2d
zip2 v20.2d, v16.2d, v21.2d
fmls v25.2d, v18.2d, v14.d[0]
fmls v24.2d, v17.2d, v12.d[0]
zip1 v9.2d, v16.2d, v21.2d
zip1 v15.2d, v16.2d, v21.2d
ldp q14, q16, [x24, #48]
add x27, x14, x27, lsl #4
tst x26, #0x7fffffffffffffff
ldr d21, [x28, #48]
fmla v18.2d, v25.2d, v13.d[1]
fmla v17.2d, v24.2d, v11.d[1]
fneg v12.2d, v27.2d
ldr d24, [x27, #48]
ccmp w15, #0, #4, ne
movi v2.4s, #1
zip2 v25.2d, v23.2d, v16.2d
zip1 v13.2d, v23.2d, v16.2d
zip1 v11.2d, v21.2d, v24.2d
cmlt v6.4s, v0.4s, #0
fmul v24.2d, v17.2d, v31.d[0]
fmov v5.2d, #1.0
fmov v3.2d, #1.0
fmov v1.2d, #1.0
fadd v16.2d, v13.2d, v11.2d
fmla v26.2d, v27.2d, v13.2d
fcvtzs v21.2d, v17.2d
fcvtzs v17.2d, v18.2d
fmla v9.2d, v20.2d, v13.2d
fmla v15.2d, v20.2d, v16.2d
fmla v28.2d, v27.2d, v16.2d
fmaxnm v23.2d, v26.2d, v10.2d
fcvtzs v27.2d, v24.2d
fmul v11.2d, v18.2d, v31.d[1]
zip1 v20.2d, v22.2d, v14.2d
uzp1 v24.4s, v21.4s, v17.4s
abs v7.4s, v0.4s
frecpe v18.2d, v23.2d
fmaxnm v26.2d, v28.2d, v10.2d
fcvtzs v10.2d, v11.2d
sqxtn v28.2s, v27.2d
zip2 v17.2d, v22.2d, v14.2d
zip1 v21.2d, v22.2d, v14.2d
frecps v27.2d, v23.2d, v18.2d
frecpe v11.2d, v26.2d
sqxtn2 v28.4s, v10.2d
eor v10.16b, v24.16b, v6.16b
fmla v20.2d, v17.2d, v13.2d
fmla v21.2d, v17.2d, v16.2d
fmul v22.2d, v18.2d, v27.2d
ccmp w22, #15, #2, ne
sub v27.4s, v10.4s, v6.4s
frecps v14.2d, v26.2d, v11.2d
eor v13.16b, v28.16b, v6.16b
frecps v18.2d, v23.2d, v22.2d
ldrb w16, [x24, #80]
ccmp x20, x3, #4, ls
sub v0.4s, v19.4s, v2.4s
fmul v17.2d, v11.2d, v14.2d
sub v14.4s, v13.4s, v6.4s
fmul v11.2d, v22.2d, v18.2d
mul v18.4s, v19.4s, v27.4s
fmov x7, d29
ldr x26, [x24, #24]
frecps v10.2d, v26.2d, v17.2d
mul v13.4s, v0.4s, v14.4s
abs v16.4s, v28.4s
fmls v1.2d, v23.2d, v11.2d
fmul v22.2d, v17.2d, v10.2d
sub v0.4s, v7.4s, v18.4s
csel x4, x20, x1, ne
tst x26, #0x7fffffffffffffff
movi v8.2d, #0xffffffff00000000
fmax v17.2d, v23.2d, v26.2d
fmls v3.2d, v26.2d, v22.2d
fmla v11.2d, v11.2d, v1.2d
shl v10.4s, v0.4s, #1
ldr q1, [x19, #80]
ccmp w16, #0, #4, ne
ldr q18, [x17, #80]
and v14.16b, v13.16b, v2.16b
cmhi v2.4s, v19.4s, v10.4s
fmls v4.2d, v23.2d, v11.2d
fmla v22.2d, v22.2d, v3.2d
zip2 v3.2d, v18.2d, v1.2d
ccmp w23, #15, #2, ne
and v10.16b, v14.16b, v2.16b
ldr q0, [x14, #880]
ccmp x25, x3, #4, ls
fmls v5.2d, v26.2d, v22.2d
fmla v11.2d, v11.2d, v4.2d
zip1 v19.2d, v18.2d, v1.2d
cmhi v4.4s, v16.4s, v0.4s
ldp q1, q0, [x14, #848]
ccmp x4, x1, #4, ne
umin v2.4s, v16.4s, v3.4s
ssra v10.4s, v13.4s, #1
fmla v22.2d, v22.2d, v5.2d
fmul v14.2d, v9.2d, v11.2d
mul v5.4s, v2.4s, v19.4s
sub v3.4s, v27.4s, v10.4s
orr v13.16b, v23.16b, v1.16b
orr v9.16b, v26.16b, v1.16b
fmul v18.2d, v20.2d, v11.2d
fmul v16.2d, v15.2d, v22.2d
fcvtzu v27.2d, v14.2d, #16
cmhs v2.4s, v7.4s, v5.4s
eor v19.16b, v3.16b, v6.16b
fmul v20.2d, v21.2d, v22.2d
fcvtzu v10.2d, v18.2d, #16
uminp v15.4s, v13.4s, v9.4s
uqxtn v7.2s, v27.2d
bic v1.16b, v2.16b, v4.16b
sub v26.4s, v19.4s, v6.4s
fcvtzu v5.2d, v20.2d, #16
cmhs v23.2d, v17.2d, v0.2d
fcvtzu v21.2d, v16.2d, #16
uqxtn v3.2s, v10.2d
and v14.16b, v28.16b, v1.16b
bit v24.16b, v26.16b, v1.16b
fadd v9.2d, v11.2d, v22.2d
orr v18.16b, v15.16b, v23.16b
uqxtn2 v7.4s, v21.2d
uqxtn2 v3.4s, v5.2d
and v13.16b, v14.16b, v8.16b
and v17.16b, v24.16b, v8.16b
shl v0.2d, v24.2d, #32
shl v2.2d, v14.2d, #32
umaxv s4, v18.4s
fmul v31.2d, v12.2d, v9.2d
zip1 v19.4s, v7.4s, v3.4s
csel x5, x25, x4, ne
ssra v17.2d, v0.2d, #32
zip2 v6.4s, v7.4s, v3.4s
fmov w13, s4
ssra v13.2d, v2.2d, #32
mov x8, v29.d[1]
umin v29.4s, v19.4s, v25.4s
mov x10, v17.d[1]
fmov x9, d17
umin v30.4s, v6.4s, v25.4s
mov x12, v13.d[1]
fmov x11, d13
