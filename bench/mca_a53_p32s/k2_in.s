ext v7.16b, v19.16b, v19.16b, #8
fmov x13, d5
ext v0.16b, v5.16b, v19.16b, #8
ldp q6, q17, [x27, #32]
str q19, [x28]
add x30, x27, x30, lsl #7
sub v7.4s, v19.4s, v7.4s
sub v0.4s, v0.4s, v5.4s
ldp q23, q24, [x30, #128]
ldp q21, q22, [x30, #96]
saddw2 v29.2d, v6.2d, v7.4s
saddw v26.2d, v6.2d, v0.2s
saddw v28.2d, v6.2d, v7.2s
saddw2 v27.2d, v6.2d, v0.4s
fsub v29.2d, v29.2d, v6.2d
fmul d31, d31, v1.d[0]
fsub v26.2d, v26.2d, v6.2d
fsub v27.2d, v27.2d, v6.2d
fsub v28.2d, v28.2d, v6.2d
fmul v30.2d, v29.2d, v24.d[0]
ldr q25, [x30, #160]
fmul v26.2d, v26.2d, v3.d[0]
fmul v27.2d, v27.2d, v3.d[1]
fmul v28.2d, v28.2d, v3.d[0]
fmul d31, d31, v25.d[0]
fmls v29.2d, v30.2d, v24.d[1]
fcvtzs v26.2d, v26.2d
fcvtzs v27.2d, v27.2d
fcvtzs v28.2d, v28.2d
ldp q18, q20, [x30, #64]
sqxtn v6.2s, v26.2d
fmla v30.2d, v29.2d, v24.d[0]
sqxtn v1.2s, v28.2d
sshr v28.4s, v0.4s, #31
ldp q2, q4, [x27]
sqxtn2 v6.4s, v27.2d
fcvtzs v25.2d, v30.2d
fmul v30.2d, v30.2d, v31.d[0]
abs v27.4s, v7.4s
sshr v29.4s, v7.4s, #31
ushr v9.4s, v28.4s, #28
abs v25.2d, v25.2d
fcvtzs v30.2d, v30.2d
ushr v31.4s, v27.4s, #4
mov x23, v5.d[1]
add v9.4s, v0.4s, v9.4s
abs v3.4s, v6.4s
abs v26.4s, v0.4s
sqxtn2 v1.4s, v30.2d
xtn2 v31.4s, v25.2d
mov v25.16b, v27.16b
mul v7.4s, v6.4s, v2.s[0]
umin v3.4s, v3.4s, v4.4s
abs v0.4s, v1.4s
mul v4.4s, v20.4s, v1.4s
mls v25.4s, v18.4s, v31.4s
sshr v24.4s, v9.4s, #4
shsub v9.4s, v9.4s, v7.4s
mul v3.4s, v3.4s, v2.4s
cmhi v16.4s, v17.4s, v0.4s
umin v0.4s, v0.4s, v22.4s
cmhi v25.4s, v23.4s, v25.4s
sshr v22.4s, v4.4s, #1
eor v30.16b, v31.16b, v29.16b
srshr v4.4s, v4.4s, #1
cmhs v3.4s, v26.4s, v3.4s
mul v0.4s, v0.4s, v21.4s
eor v25.16b, v25.16b, v29.16b
sshr v9.4s, v9.4s, #3
sub v30.4s, v30.4s, v29.4s
cmhs v0.4s, v27.4s, v0.4s
bit v22.16b, v4.16b, v25.16b
and v6.16b, v6.16b, v3.16b
bit v24.16b, v9.16b, v3.16b
and v0.16b, v0.16b, v16.16b
sub v21.4s, v30.4s, v22.4s
fmov x10, d6
mov x24, v24.d[1]
fmov x9, d24
mov x25, v6.d[1]
and v1.16b, v1.16b, v0.16b
bit v30.16b, v21.16b, v0.16b
and x1, x9, #0xffffffff00000000
and x2, x10, #0xffffffff00000000
and x4, x25, #0xffffffff00000000
add x10, x2, w10, sxtw
lsl x20, x10, #2
add x9, x1, w9, sxtw
lsr x1, x13, #48
stp q30, q1, [x28, #16]
and x3, x24, #0xffffffff00000000
add x17, x10, x9, lsl #1
add x14, x13, x9
add x19, x17, x10, lsl #1
add x15, x13, x17
lsr w9, w13, #16
add x24, x3, w24, sxtw
lsr x2, x14, #48
add x17, x17, x20
lsr w10, w14, #16
add x13, x15, x17
lsr x3, x15, #48
madd w1, w1, w0, w9
add x16, x14, x19
add x19, x19, x20
lsr w11, w15, #16
lsr x5, x13, #48
lsr w9, w13, #16
add x17, x17, x20
add x15, x13, x17
madd w2, w2, w0, w10
madd w3, w3, w0, w11
ldrb w1, [x18, w1, uxtw]
add x17, x17, x20
add x14, x16, x19
lsr x7, x15, #48
add x19, x19, x20
add x13, x15, x17
add x25, x4, w25, sxtw
lsr x4, x16, #48
lsr w12, w16, #16
lsr x6, x14, #48
madd w5, w5, w0, w9
ldrb w2, [x18, w2, uxtw]
madd w4, w4, w0, w12
add x16, x14, x19
ldrb w3, [x18, w3, uxtw]
add x19, x19, x20
add x17, x17, x20
lsr w10, w14, #16
lsr x8, x16, #48
lsr w11, w15, #16
ldrb w4, [x18, w4, uxtw]
add x15, x13, x17
add x17, x17, x20
lsr w9, w13, #16
madd w7, w7, w0, w11
orr x21, x1, x2, lsl #8
madd w6, w6, w0, w10
orr x22, x3, x4, lsl #8
add x14, x16, x19
lsr x1, x13, #48
add x13, x15, x17
lsr x3, x15, #48
add x19, x19, x20
lsr w12, w16, #16
lsr w11, w15, #16
orr x15, x21, x22, lsl #16
madd w8, w8, w0, w12
ldrb w6, [x18, w6, uxtw]
madd w1, w1, w0, w9
ldrb w5, [x18, w5, uxtw]
madd w3, w3, w0, w11
add x16, x14, x19
str w15, [x26]
add x19, x19, x20
ldrb w7, [x18, w7, uxtw]
add x17, x17, x20
ldrb w8, [x18, w8, uxtw]
add x15, x13, x17
orr x21, x5, x6, lsl #8
lsr x2, x14, #48
lsr w10, w14, #16
add x14, x16, x19
madd w2, w2, w0, w10
add x17, x25, x24, lsl #1
add x19, x19, x20
lsr x4, x16, #48
orr x22, x7, x8, lsl #8
lsr w12, w16, #16
lsr x6, x14, #48
lsr w10, w14, #16
lsr x5, x13, #48
lsr w9, w13, #16
lsr x7, x15, #48
lsr w11, w15, #16
orr x15, x21, x22, lsl #16
add x16, x14, x19
ldrb w1, [x18, w1, uxtw]
add x14, x23, x24
madd w4, w4, w0, w12
madd w5, w5, w0, w9
str w15, [x26, #4]
ldrb w2, [x18, w2, uxtw]
madd w6, w6, w0, w10
ldrb w3, [x18, w3, uxtw]
madd w7, w7, w0, w11
add x19, x17, x25, lsl #1
ldrb w4, [x18, w4, uxtw]
add x15, x23, x17
lsl x20, x25, #2
orr x21, x1, x2, lsl #8
lsr x8, x16, #48
ldrb w5, [x18, w5, uxtw]
orr x22, x3, x4, lsl #8
ldrb w6, [x18, w6, uxtw]
add x17, x17, x20
lsr x2, x14, #48
lsr w12, w16, #16
lsr w11, w15, #16
lsr x3, x15, #48
lsr x1, x23, #48
lsr w9, w23, #16
add x23, x15, x17
add x16, x14, x19
orr x15, x21, x22, lsl #16
orr x21, x5, x6, lsl #8
lsr x5, x23, #48
madd w1, w1, w0, w9
ldrb w7, [x18, w7, uxtw]
madd w8, w8, w0, w12
add x17, x17, x20
str w15, [x26, #8]
add x15, x23, x17
add x19, x19, x20
lsr w9, w23, #16
add x17, x17, x20
madd w5, w5, w0, w9
ldr x24, [x28, #24]
madd w3, w3, w0, w11
ldrb w8, [x18, w8, uxtw]
add x23, x15, x17
add x17, x17, x20
lsr w11, w15, #16
lsr w10, w14, #16
ldrb w1, [x18, w1, uxtw]
madd w2, w2, w0, w10
orr x22, x7, x8, lsl #8
add x14, x16, x19
lsr w9, w23, #16
lsr x7, x15, #48
add x19, x19, x20
orr x15, x21, x22, lsl #16
lsr x4, x16, #48
lsr w12, w16, #16
madd w4, w4, w0, w12
ldrb w2, [x18, w2, uxtw]
madd w7, w7, w0, w11
str w15, [x26, #12]
add x16, x14, x19
add x19, x19, x20
ldrb w3, [x18, w3, uxtw]
add x15, x23, x17
ldrb w4, [x18, w4, uxtw]
add x17, x17, x20
orr x21, x1, x2, lsl #8
lsr w10, w14, #16
lsr x8, x16, #48
lsr w11, w15, #16
lsr x6, x14, #48
madd w6, w6, w0, w10
ldrb w5, [x18, w5, uxtw]
add x14, x16, x19
orr x22, x3, x4, lsl #8
lsr w12, w16, #16
lsr x1, x23, #48
lsr x3, x15, #48
lsr x2, x14, #48
add x23, x15, x17
madd w8, w8, w0, w12
ldr x25, [x28, #40]
madd w3, w3, w0, w11
orr x15, x21, x22, lsl #16
ldrb w7, [x18, w7, uxtw]
add x19, x19, x20
ldrb w6, [x18, w6, uxtw]
add x16, x14, x19
ldrb w8, [x18, w8, uxtw]
madd w1, w1, w0, w9
str w15, [x26, #16]
add x17, x17, x20
add x19, x19, x20
lsr w12, w16, #16
orr x21, x5, x6, lsl #8
lsr w10, w14, #16
add x14, x16, x19
lsr x4, x16, #48
lsr w9, w23, #16
lsr x5, x23, #48
madd w4, w4, w0, w12
madd w2, w2, w0, w10
ldrb w1, [x18, w1, uxtw]
add x19, x19, x20
ldrb w3, [x18, w3, uxtw]
orr x22, x7, x8, lsl #8
add x15, x23, x17
lsr x7, x15, #48
lsr w11, w15, #16
ldrb w2, [x18, w2, uxtw]
madd w5, w5, w0, w9
ldrb w4, [x18, w4, uxtw]
madd w7, w7, w0, w11
orr x15, x21, x22, lsl #16
add x16, x14, x19
lsr w10, w14, #16
lsr x8, x16, #48
lsr x6, x14, #48
lsr w12, w16, #16
madd w6, w6, w0, w10
ldrb w5, [x18, w5, uxtw]
madd w8, w8, w0, w12
ldrb w7, [x18, w7, uxtw]
orr x21, x1, x2, lsl #8
orr x22, x3, x4, lsl #8
str w15, [x26, #20]
orr x15, x21, x22, lsl #16
ldrb w6, [x18, w6, uxtw]
and x13, x24, #0xffffffff00000000
ldrb w8, [x18, w8, uxtw]
add x24, x13, w24, sxtw
and x13, x25, #0xffffffff00000000
add x25, x13, w25, sxtw
str w15, [x26, #24]
orr x22, x7, x8, lsl #8
ldr w1, [x30, #72]
orr x21, x5, x6, lsl #8
orr x15, x21, x22, lsl #16
ldr x23, [x28]
cmp w1, #0xf
str w15, [x26, #28]
