ldp x1, x30, [sp, #264]
mov w0, #0x70
ldr x28, [sp, #192]
fmov d31, d8
smaddl x9, w9, w0, x1
ldr x0, [sp, #256]
mov x18, x9
ext v7.16b, v19.16b, v7.16b, #8
ext v0.16b, v5.16b, v19.16b, #8
mov x23, v5.d[1]
ldp q6, q17, [x0, #32]
sub v7.4s, v7.4s, v19.4s
sub v0.4s, v0.4s, v5.4s
ldp q23, q24, [x18, #64]
saddw2 v29.2d, v6.2d, v7.4s
saddw v26.2d, v6.2d, v0.2s
saddw v28.2d, v6.2d, v7.2s
ldp q18, q20, [x18]
saddw2 v27.2d, v6.2d, v0.4s
fsub v29.2d, v29.2d, v6.2d
fmul d31, d31, v1.d[1]
fsub v28.2d, v28.2d, v6.2d
ldr q25, [x18, #96]
fsub v26.2d, v26.2d, v6.2d
fsub v27.2d, v27.2d, v6.2d
fmul v30.2d, v29.2d, v24.d[0]
fmul v26.2d, v26.2d, v3.d[0]
fmul v28.2d, v28.2d, v16.d[0]
fmul v27.2d, v27.2d, v3.d[1]
fmls v29.2d, v30.2d, v24.d[1]
fcvtzs v26.2d, v26.2d
fmul d31, d31, v25.d[0]
fcvtzs v28.2d, v28.2d
fcvtzs v27.2d, v27.2d
ldp q2, q4, [x0]
sqxtn v6.2s, v26.2d
fmla v30.2d, v29.2d, v24.d[0]
abs v26.4s, v0.4s
sqxtn v1.2s, v28.2d
sshr v28.4s, v0.4s, #31
sqxtn2 v6.4s, v27.2d
fcvtzs v25.2d, v30.2d
fmul v30.2d, v30.2d, v31.d[0]
abs v27.4s, v7.4s
sshr v29.4s, v7.4s, #31
ushr v9.4s, v28.4s, #28
abs v25.2d, v25.2d
fcvtzs v30.2d, v30.2d
ushr v31.4s, v27.4s, #4
ldp q21, q22, [x18, #32]
abs v3.4s, v6.4s
add v9.4s, v0.4s, v9.4s
sqxtn2 v1.4s, v30.2d
xtn2 v31.4s, v25.2d
mov v25.16b, v27.16b
umin v3.4s, v3.4s, v4.4s
mul v7.4s, v6.4s, v2.s[0]
abs v0.4s, v1.4s
mul v4.4s, v20.4s, v1.4s
mls v25.4s, v18.4s, v31.4s
sshr v24.4s, v9.4s, #4
mul v3.4s, v3.4s, v2.4s
shsub v9.4s, v9.4s, v7.4s
cmhi v16.4s, v17.4s, v0.4s
umin v0.4s, v0.4s, v22.4s
cmhi v25.4s, v23.4s, v25.4s
sshr v22.4s, v4.4s, #1
srshr v4.4s, v4.4s, #1
cmhs v3.4s, v26.4s, v3.4s
eor v30.16b, v31.16b, v29.16b
mul v0.4s, v0.4s, v21.4s
eor v25.16b, v25.16b, v29.16b
sshr v9.4s, v9.4s, #3
sub v30.4s, v30.4s, v29.4s
cmhs v0.4s, v27.4s, v0.4s
bit v22.16b, v4.16b, v25.16b
bit v24.16b, v9.16b, v3.16b
and v6.16b, v6.16b, v3.16b
and v0.16b, v0.16b, v16.16b
sub v21.4s, v30.4s, v22.4s
fmov x13, d5
str q19, [x30]
mov x25, v6.d[1]
fmov x10, d6
and v1.16b, v1.16b, v0.16b
bit v30.16b, v21.16b, v0.16b
fmov x9, d24
mov x24, v24.d[1]
and x2, x10, #0xffffffff00000000
and x4, x25, #0xffffffff00000000
add x10, x2, w10, sxtw
stp q30, q1, [x30, #16]
and x1, x9, #0xffffffff00000000
add x9, x1, w9, sxtw
and x3, x24, #0xffffffff00000000
lsl x20, x10, #2
add x14, x13, x9
add x25, x4, w25, sxtw
add x17, x10, x9, lsl #1
lsr w9, w13, #16
lsr x1, x13, #48
add x24, x3, w24, sxtw
add x19, x17, x10, lsl #1
add x15, x13, x17
add x17, x17, x20
add x13, x15, x17
madd w1, w1, w28, w9
add x16, x14, x19
add x19, x19, x20
lsr x2, x14, #48
add x17, x17, x20
lsr w9, w13, #16
lsr x3, x15, #48
lsr w10, w14, #16
lsr w11, w15, #16
lsr x5, x13, #48
add x15, x13, x17
madd w3, w3, w28, w11
ldrb w1, [x26, w1, uxtw]
add x17, x17, x20
add x14, x16, x19
lsr x7, x15, #48
madd w2, w2, w28, w10
add x19, x19, x20
add x13, x15, x17
lsr x4, x16, #48
lsr x6, x14, #48
lsr w12, w16, #16
madd w4, w4, w28, w12
madd w5, w5, w28, w9
ldrb w2, [x26, w2, uxtw]
add x16, x14, x19
ldrb w3, [x26, w3, uxtw]
add x19, x19, x20
add x17, x17, x20
lsr x8, x16, #48
lsr w10, w14, #16
lsr w11, w15, #16
ldrb w4, [x26, w4, uxtw]
