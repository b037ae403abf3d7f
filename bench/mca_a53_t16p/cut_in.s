mov x10, x19
mov x11, x21
ldp x3, x6, [sp, #176]
add x20, x11, #0x58
cmp x20, x3
ldr w15, [x10, #8]
ldr w16, [x11, #8]
sub v0.4s, v29.4s, v31.4s
add x25, x11, #0xb0
sub w15, w15, #0x1
csel x21, x20, x10, ne
ccmp x25, x3, #0x4, ne
sub w16, w16, #0x1
add x17, x15, x15, lsl #1
add x17, x6, x17, lsl #4
csel x24, x25, x10, ne
ldr w22, [x21, #8]
add x19, x16, x16, lsl #1
movi v2.4s, #0x1
ldr w23, [x24, #8]
ldp q9, q10, [x6, #816]
sub w22, w22, #0x1
add x19, x6, x19, lsl #4
ldp q15, q16, [x21, #16]
sub w23, w23, #0x1
and w28, w22, #0xf
and w27, w23, #0xf
ldp q11, q12, [x17, #48]
add x27, x27, x27, lsl #1
add x28, x28, x28, lsl #1
ldp q13, q14, [x19, #48]
add x27, x6, x27, lsl #4
saddw2 v18.2d, v9.2d, v0.4s
saddw v17.2d, v9.2d, v0.2s
ldp q20, q21, [x24, #16]
ldrb w15, [x21, #80]
fsub v25.2d, v18.2d, v9.2d
fsub v24.2d, v17.2d, v9.2d
ldr x26, [x21, #24]
zip2 v19.2d, v12.2d, v14.2d
ldp q22, q23, [x21, #48]
add x28, x6, x28, lsl #4
fmul v18.2d, v25.2d, v13.d[1]
fmul v17.2d, v24.2d, v11.d[1]
zip1 v26.2d, v15.2d, v20.2d
zip2 v27.2d, v15.2d, v20.2d
zip1 v28.2d, v15.2d, v20.2d
movi v8.2d, #0xffffffff00000000
zip2 v20.2d, v16.2d, v21.2d
fmls v25.2d, v18.2d, v14.d[0]
fmls v24.2d, v17.2d, v12.d[0]
zip1 v15.2d, v16.2d, v21.2d
zip1 v9.2d, v16.2d, v21.2d
ldr d21, [x28, #48]
ldp q14, q16, [x24, #48]
cmlt v6.4s, v0.4s, #0
fmla v18.2d, v25.2d, v13.d[1]
fmla v17.2d, v24.2d, v11.d[1]
zip1 v13.2d, v23.2d, v16.2d
ldr d24, [x27, #48]
fmov v1.2d, #1.000000000000000000e+00
ldrb w16, [x24, #80]
abs v7.4s, v0.4s
fneg v12.2d, v27.2d
zip1 v11.2d, v21.2d, v24.2d
fmul v24.2d, v17.2d, v30.d[0]
tst x26, #0x7fffffffffffffff
fcvtzs v21.2d, v17.2d
zip2 v25.2d, v23.2d, v16.2d
fadd v16.2d, v13.2d, v11.2d
fmla v26.2d, v27.2d, v13.2d
fmul v11.2d, v18.2d, v30.d[1]
fcvtzs v17.2d, v18.2d
fmla v9.2d, v20.2d, v13.2d
fmla v28.2d, v27.2d, v16.2d
fmla v15.2d, v20.2d, v16.2d
fcvtzs v27.2d, v24.2d
fmaxnm v23.2d, v26.2d, v10.2d
uzp1 v24.4s, v21.4s, v17.4s
zip1 v20.2d, v22.2d, v14.2d
ccmp w15, #0x0, #0x4, ne
fmaxnm v26.2d, v28.2d, v10.2d
sqxtn v28.2s, v27.2d
frecpe v18.2d, v23.2d
ccmp w22, #0xf, #0x2, ne
fcvtzs v10.2d, v11.2d
zip2 v17.2d, v22.2d, v14.2d
zip1 v21.2d, v22.2d, v14.2d
frecps v27.2d, v23.2d, v18.2d
ccmp x20, x3, #0x4, ls
frecpe v11.2d, v26.2d
sqxtn2 v28.4s, v10.2d
eor v10.16b, v24.16b, v6.16b
fmla v21.2d, v17.2d, v16.2d
fmla v20.2d, v17.2d, v13.2d
fmul v22.2d, v18.2d, v27.2d
ldr x26, [x24, #24]
csel x4, x20, x10, ne
frecps v14.2d, v26.2d, v11.2d
eor v13.16b, v28.16b, v6.16b
frecps v18.2d, v23.2d, v22.2d
fmov v3.2d, #1.000000000000000000e+00
sub v27.4s, v10.4s, v6.4s
fmul v17.2d, v11.2d, v14.2d
sub v14.4s, v13.4s, v6.4s
sub v0.4s, v19.4s, v2.4s
fmul v11.2d, v22.2d, v18.2d
mul v18.4s, v19.4s, v27.4s
fmov x12, d31
fmov v4.2d, #1.000000000000000000e+00
frecps v10.2d, v26.2d, v17.2d
mul v13.4s, v0.4s, v14.4s
fmls v1.2d, v23.2d, v11.2d
sub v0.4s, v7.4s, v18.4s
fmul v22.2d, v17.2d, v10.2d
fmax v17.2d, v23.2d, v26.2d
ldr q18, [x17, #80]
tst x26, #0x7fffffffffffffff
shl v10.4s, v0.4s, #1
fmla v11.2d, v11.2d, v1.2d
fmls v3.2d, v26.2d, v22.2d
fmov v5.2d, #1.000000000000000000e+00
ldr q1, [x19, #80]
ccmp w16, #0x0, #0x4, ne
and v14.16b, v13.16b, v2.16b
abs v16.4s, v28.4s
cmhi v2.4s, v19.4s, v10.4s
fmls v4.2d, v23.2d, v11.2d
fmla v22.2d, v22.2d, v3.2d
zip2 v3.2d, v18.2d, v1.2d
ccmp w23, #0xf, #0x2, ne
and v10.16b, v14.16b, v2.16b
ldr q0, [x6, #880]
ccmp x25, x3, #0x4, ls
fmls v5.2d, v26.2d, v22.2d
fmla v11.2d, v11.2d, v4.2d
zip1 v19.2d, v18.2d, v1.2d
ssra v10.4s, v13.4s, #1
ccmp x4, x10, #0x4, ne
umin v2.4s, v16.4s, v3.4s
cmhi v4.4s, v16.4s, v0.4s
fmla v22.2d, v22.2d, v5.2d
fmul v14.2d, v9.2d, v11.2d
ldp q1, q0, [x6, #848]
csel x0, x25, x4, ne
mul v5.4s, v2.4s, v19.4s
sub v3.4s, v27.4s, v10.4s
fmul v18.2d, v20.2d, v11.2d
orr v13.16b, v23.16b, v1.16b
fcvtzu v27.2d, v14.2d, #16
orr v9.16b, v26.16b, v1.16b
cmhs v2.4s, v7.4s, v5.4s
eor v19.16b, v3.16b, v6.16b
fcvtzu v10.2d, v18.2d, #16
fmul v16.2d, v15.2d, v22.2d
fmul v20.2d, v21.2d, v22.2d
uminp v15.4s, v13.4s, v9.4s
bic v1.16b, v2.16b, v4.16b
uqxtn v7.2s, v27.2d
sub v26.4s, v19.4s, v6.4s
cmhs v23.2d, v17.2d, v0.2d
fcvtzu v5.2d, v20.2d, #16
fcvtzu v21.2d, v16.2d, #16
uqxtn v3.2s, v10.2d
and v14.16b, v28.16b, v1.16b
bit v24.16b, v26.16b, v1.16b
orr v18.16b, v15.16b, v23.16b
fadd v9.2d, v11.2d, v22.2d
uqxtn2 v7.4s, v21.2d
uqxtn2 v3.4s, v5.2d
and v13.16b, v14.16b, v8.16b
and v17.16b, v24.16b, v8.16b
shl v0.2d, v24.2d, #32
shl v2.2d, v14.2d, #32
umaxv s4, v18.4s
zip1 v19.4s, v7.4s, v3.4s
fmul v30.2d, v12.2d, v9.2d
zip2 v6.4s, v7.4s, v3.4s
ssra v17.2d, v0.2d, #32
ssra v13.2d, v2.2d, #32
mov x5, v31.d[1]
umin v31.4s, v19.4s, v25.4s
fmov w1, s4
umin v29.4s, v6.4s, v25.4s
fmov x13, d17
mov x2, v17.d[1]
fmov x14, d13
mov x18, v13.d[1]
str x2, [sp, #168]
cmp x10, x4
ldr x15, [x10]
mov x19, x4
ldr w22, [x10, #8]
ccmn w1, #0x1, #0x0, ne
ldr w20, [x11, #8]
mov x21, x0
b.eq .+4
