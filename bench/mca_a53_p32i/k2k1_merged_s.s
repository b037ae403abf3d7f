ext v0.16b, v19.16b, v19.16b, #8
fmov x1, d5
ext v2.16b, v5.16b, v19.16b, #8
ldp q6, q4, [x27, #32]
str q19, [x28]
add x30, x27, x30, lsl #7
sub v0.4s, v19.4s, v0.4s
sub v2.4s, v2.4s, v5.4s
ldp q7, q8, [x30, #128]
ldp q10, q9, [x30, #96]
saddw2 v11.2d, v6.2d, v0.4s
saddw v12.2d, v6.2d, v2.2s
saddw v13.2d, v6.2d, v0.2s
saddw2 v14.2d, v6.2d, v2.4s
fsub v11.2d, v11.2d, v6.2d
fmul d31, d31, v1.d[0]
fsub v12.2d, v12.2d, v6.2d
fsub v14.2d, v14.2d, v6.2d
fsub v13.2d, v13.2d, v6.2d
fmul v15.2d, v11.2d, v8.d[0]
ldr q16, [x30, #160]
fmul v12.2d, v12.2d, v3.d[0]
fmul v14.2d, v14.2d, v3.d[1]
fmul v13.2d, v13.2d, v3.d[0]
fmul d31, d31, v16.d[0]
fmls v11.2d, v15.2d, v8.d[1]
fcvtzs v12.2d, v12.2d
fcvtzs v14.2d, v14.2d
fcvtzs v13.2d, v13.2d
ldp q17, q18, [x30, #64]
sqxtn v20.2s, v12.2d
fmla v15.2d, v11.2d, v8.d[0]
sqxtn v21.2s, v13.2d
ldr q22, [x25]
sshr v23.4s, v2.4s, #31
ldp q25, q24, [x27]
sqxtn2 v20.4s, v14.2d
fcvtzs v26.2d, v15.2d
fmul v15.2d, v15.2d, v31.d[0]
abs v27.4s, v0.4s
sshr v28.4s, v0.4s, #31
ushr v29.4s, v23.4s, #28
abs v26.2d, v26.2d
fcvtzs v15.2d, v15.2d
ushr v19.4s, v27.4s, #4
mov x2, v5.d[1]
add v29.4s, v2.4s, v29.4s
abs v1.4s, v20.4s
abs v6.4s, v2.4s
sqxtn2 v21.4s, v15.2d
xtn2 v19.4s, v26.2d
mov v3.16b, v27.16b
mul v16.4s, v20.4s, v25.s[0]
umin v1.4s, v1.4s, v24.4s
abs v12.4s, v21.4s
mul v11.4s, v18.4s, v21.4s
mls v3.4s, v17.4s, v19.4s
sshr v8.4s, v29.4s, #4
shsub v29.4s, v29.4s, v16.4s
mul v1.4s, v1.4s, v25.4s
cmhi v13.4s, v4.4s, v12.4s
umin v12.4s, v12.4s, v9.4s
cmhi v3.4s, v7.4s, v3.4s
sshr v14.4s, v11.4s, #1
eor v31.16b, v19.16b, v28.16b
srshr v11.4s, v11.4s, #1
cmhs v1.4s, v6.4s, v1.4s
mul v12.4s, v12.4s, v10.4s
eor v3.16b, v3.16b, v28.16b
sshr v29.4s, v29.4s, #3
sub v31.4s, v31.4s, v28.4s
cmhs v12.4s, v27.4s, v12.4s
bit v14.16b, v11.16b, v3.16b
and v20.16b, v20.16b, v1.16b
bit v8.16b, v29.16b, v1.16b
ldr q0, [x25, #16]
and v12.16b, v12.16b, v13.16b
sub v23.4s, v31.4s, v14.4s
fmov x3, d20
mov x4, v8.d[1]
fmov x5, d8
mov x6, v20.d[1]
and v21.16b, v21.16b, v12.16b
bit v31.16b, v23.16b, v12.16b
ldr q5, [x25, #80]
and x7, x5, #0xffffffff00000000
and x8, x3, #0xffffffff00000000
and x9, x6, #0xffffffff00000000
add x3, x8, w3, sxtw
lsl x10, x3, #2
add x5, x7, w5, sxtw
lsr x11, x1, #48
stp q31, q21, [x28, #16]
and x12, x4, #0xffffffff00000000
ldr q2, [x25, #48]
add x13, x3, x5, lsl #1
add x14, x1, x5
add x15, x13, x3, lsl #1
add x16, x1, x13
lsr w17, w1, #16
add x4, x12, w4, sxtw
lsr x19, x14, #48
add x13, x13, x10
lsr w20, w14, #16
add x21, x16, x13
lsr x22, x16, #48
madd w11, w11, w0, w17
add x30, x14, x15
add x15, x15, x10
lsr w8, w16, #16
lsr x7, x21, #48
lsr w25, w21, #16
add x13, x13, x10
add x5, x21, x13
madd w19, w19, w0, w20
madd w22, w22, w0, w8
ldrb w11, [x18, w11, uxtw]
add x13, x13, x10
add x3, x30, x15
lsr x1, x5, #48
add x15, x15, x10
add x12, x5, x13
add x6, x9, w6, sxtw
lsr x17, x30, #48
lsr w14, w30, #16
lsr x16, x3, #48
madd w7, w7, w0, w25
ldrb w19, [x18, w19, uxtw]
madd w17, w17, w0, w14
add x21, x3, x15
ldrb w22, [x18, w22, uxtw]
add x15, x15, x10
add x13, x13, x10
lsr w20, w3, #16
lsr x8, x21, #48
lsr w9, w5, #16
ldrb w17, [x18, w17, uxtw]
add x30, x12, x13
add x13, x13, x10
lsr w25, w12, #16
madd w1, w1, w0, w9
orr x14, x11, x19, lsl #8
madd w16, w16, w0, w20
orr x3, x22, x17, lsl #8
add x5, x21, x15
lsr x9, x12, #48
add x19, x30, x13
lsr x11, x30, #48
add x15, x15, x10
lsr w20, w21, #16
lsr w17, w30, #16
orr x22, x14, x3, lsl #16
madd w8, w8, w0, w20
ext v15.16b, v22.16b, v0.16b, #8
ext v26.16b, v22.16b, v22.16b, #8
ldrb w16, [x18, w16, uxtw]
madd w9, w9, w0, w25
ldrb w7, [x18, w7, uxtw]
madd w11, w11, w0, w17
add x12, x5, x15
str w22, [x26]
add x15, x15, x10
ldrb w1, [x18, w1, uxtw]
add x13, x13, x10
ldrb w8, [x18, w8, uxtw]
add x21, x19, x13
orr x30, x7, x16, lsl #8
lsr x3, x5, #48
lsr w14, w5, #16
add x20, x12, x15
madd w3, w3, w0, w14
add x25, x6, x4, lsl #1
add x15, x15, x10
lsr x17, x12, #48
orr x22, x1, x8, lsl #8
lsr w13, w12, #16
lsr x16, x20, #48
lsr w7, w20, #16
lsr x5, x19, #48
lsr w14, w19, #16
lsr x10, x21, #48
lsr w1, w21, #16
orr x8, x30, x22, lsl #16
add x12, x20, x15
ldrb w9, [x18, w9, uxtw]
add x19, x2, x4
madd w17, w17, w0, w13
madd w5, w5, w0, w14
str w8, [x26, #4]
ldrb w3, [x18, w3, uxtw]
madd w16, w16, w0, w7
ldrb w11, [x18, w11, uxtw]
madd w10, w10, w0, w1
add x21, x25, x6, lsl #1
ldrb w17, [x18, w17, uxtw]
add x22, x2, x25
lsl x30, x6, #2
orr x20, x9, x3, lsl #8
lsr x15, x12, #48
ldrb w5, [x18, w5, uxtw]
orr x4, x11, x17, lsl #8
ldrb w16, [x18, w16, uxtw]
add x25, x25, x30
lsr x13, x19, #48
lsr w14, w12, #16
lsr w8, w22, #16
lsr x7, x22, #48
lsr x1, x2, #48
lsr w6, w2, #16
add x3, x22, x25
add x9, x19, x21
ldp q18, q24, [x27, #32]
orr x17, x20, x4, lsl #16
orr x11, x5, x16, lsl #8
lsr x12, x3, #48
madd w1, w1, w0, w6
ldrb w10, [x18, w10, uxtw]
madd w15, w15, w0, w14
add x25, x25, x30
str w17, [x26, #8]
add x2, x3, x25
add x21, x21, x30
lsr w22, w3, #16
add x25, x25, x30
madd w12, w12, w0, w22
ldr x20, [x28, #24]
madd w7, w7, w0, w8
ldrb w15, [x18, w15, uxtw]
add x4, x2, x25
add x25, x25, x30
lsr w5, w2, #16
lsr w16, w19, #16
ldrb w1, [x18, w1, uxtw]
madd w13, w13, w0, w16
orr x6, x10, x15, lsl #8
add x14, x9, x21
lsr w17, w4, #16
lsr x3, x2, #48
add x21, x21, x30
orr x22, x11, x6, lsl #16
lsr x8, x9, #48
lsr w19, w9, #16
str q22, [x28, #48]
madd w8, w8, w0, w19
ldrb w13, [x18, w13, uxtw]
madd w3, w3, w0, w5
str w22, [x26, #12]
add x16, x14, x21
add x21, x21, x30
ldrb w7, [x18, w7, uxtw]
add x10, x4, x25
ldrb w8, [x18, w8, uxtw]
add x25, x25, x30
orr x15, x1, x13, lsl #8
lsr w2, w14, #16
lsr x11, x16, #48
lsr w6, w10, #16
lsr x9, x14, #48
madd w9, w9, w0, w2
ldrb w12, [x18, w12, uxtw]
add x19, x16, x21
orr x5, x7, x8, lsl #8
lsr w22, w16, #16
lsr x1, x4, #48
lsr x13, x10, #48
lsr x14, x19, #48
add x2, x10, x25
madd w11, w11, w0, w22
ldr x7, [x28, #40]
madd w13, w13, w0, w6
orr x8, x15, x5, lsl #16
ldrb w3, [x18, w3, uxtw]
add x21, x21, x30
ldrb w9, [x18, w9, uxtw]
add x16, x19, x21
ldrb w11, [x18, w11, uxtw]
madd w1, w1, w0, w17
str w8, [x26, #16]
add x25, x25, x30
add x21, x21, x30
lsr w4, w16, #16
orr x10, x12, x9, lsl #8
add x24, x27, x24, lsl #7
lsr w22, w19, #16
add x6, x16, x21
lsr x15, x16, #48
lsr w5, w2, #16
lsr x17, x2, #48
madd w15, w15, w0, w4
sub v15.4s, v15.4s, v22.4s
sub v26.4s, v26.4s, v22.4s
madd w14, w14, w0, w22
ldrb w1, [x18, w1, uxtw]
add x21, x21, x30
ldrb w13, [x18, w13, uxtw]
orr x8, x3, x11, lsl #8
add x9, x2, x25
lsr x12, x9, #48
lsr w19, w9, #16
ldrb w14, [x18, w14, uxtw]
madd w17, w17, w0, w5
ldrb w15, [x18, w15, uxtw]
madd w12, w12, w0, w19
orr x16, x10, x8, lsl #16
add x4, x6, x21
lsr w22, w6, #16
lsr x30, x4, #48
lsr x3, x6, #48
lsr w11, w4, #16
madd w3, w3, w0, w22
ldrb w17, [x18, w17, uxtw]
madd w30, w30, w0, w11
ldrb w12, [x18, w12, uxtw]
orr x2, x1, x14, lsl #8
orr x25, x13, x15, lsl #8
str w16, [x26, #20]
orr x9, x2, x25, lsl #16
ldrb w3, [x18, w3, uxtw]
and x5, x20, #0xffffffff00000000
ldrb w30, [x18, w30, uxtw]
ldp q17, q16, [x24, #128]
add x20, x5, w20, sxtw
and x19, x7, #0xffffffff00000000
add x7, x19, w7, sxtw
str w9, [x26, #24]
orr x10, x12, x30, lsl #8
orr x8, x17, x3, lsl #8
ldp q4, q25, [x24, #96]
saddw2 v9.2d, v18.2d, v15.4s
saddw v7.2d, v18.2d, v26.2s
saddw v19.2d, v18.2d, v15.2s
orr x21, x8, x10, lsl #16
saddw2 v6.2d, v18.2d, v26.4s
fsub v9.2d, v9.2d, v18.2d
fsub v7.2d, v7.2d, v18.2d
fsub v19.2d, v19.2d, v18.2d
ldr q10, [x24, #160]
fmul d30, d30, v2.d[1]
fsub v6.2d, v6.2d, v18.2d
fmul v28.2d, v9.2d, v16.d[0]
ldp q27, q11, [x24, #64]
fmul v7.2d, v7.2d, v5.d[0]
fmov x6, d22
fmul v19.2d, v19.2d, v5.d[0]
fmul v6.2d, v6.2d, v5.d[1]
fmls v9.2d, v28.2d, v16.d[1]
fcvtzs v7.2d, v7.2d
fcvtzs v6.2d, v6.2d
ldr x4, [x28]
fcvtzs v19.2d, v19.2d
fmul d30, d30, v10.d[0]
sqxtn v3.2s, v7.2d
fmla v28.2d, v9.2d, v16.d[0]
sqxtn v29.2s, v19.2d
sshr v1.4s, v26.4s, #31
sqxtn2 v3.4s, v6.2d
sshr v13.4s, v15.4s, #31
ldp q8, q14, [x27]
fcvtzs v20.2d, v28.2d
fmul v28.2d, v28.2d, v30.d[0]
abs v12.4s, v15.4s
abs v23.4s, v3.4s
ushr v21.4s, v1.4s, #28
abs v20.2d, v20.2d
fcvtzs v28.2d, v28.2d
ushr v31.4s, v12.4s, #4
umin v23.4s, v23.4s, v14.4s
mul v0.4s, v3.4s, v8.s[0]
add v21.4s, v26.4s, v21.4s
abs v2.4s, v26.4s
sqxtn2 v29.4s, v28.2d
xtn2 v31.4s, v20.2d
mov v18.16b, v12.16b
abs v22.4s, v29.4s
mul v5.4s, v11.4s, v29.4s
mls v18.4s, v27.4s, v31.4s
sshr v10.4s, v21.4s, #4
shsub v21.4s, v21.4s, v0.4s
mul v23.4s, v23.4s, v8.4s
cmhi v7.4s, v24.4s, v22.4s
umin v22.4s, v22.4s, v25.4s
cmhi v18.4s, v17.4s, v18.4s
eor v16.16b, v31.16b, v13.16b
sshr v9.4s, v5.4s, #1
srshr v5.4s, v5.4s, #1
sshr v21.4s, v21.4s, #3
mul v22.4s, v22.4s, v4.4s
eor v18.16b, v18.16b, v13.16b
cmhs v23.4s, v2.4s, v23.4s
str w21, [x26, #28]
sub v16.4s, v16.4s, v13.4s
cmhs v22.4s, v12.4s, v22.4s
bit v9.16b, v5.16b, v18.16b
bit v10.16b, v21.16b, v23.16b
and v3.16b, v3.16b, v23.16b
and v22.16b, v22.16b, v7.16b
sub v19.4s, v16.4s, v9.4s
fmov x22, d3
fmov x11, d10
and v29.16b, v29.16b, v22.16b
bit v16.16b, v19.16b, v22.16b
and x14, x22, #0xffffffff00000000
and x1, x11, #0xffffffff00000000
add x22, x14, w22, sxtw
add x11, x1, w11, sxtw
lsl x15, x22, #2
lsr x13, x6, #48
add x16, x22, x11, lsl #1
stp q16, q29, [x28, #64]
add x25, x6, x11
add x2, x16, x22, lsl #1
lsr w5, w6, #16
add x19, x6, x16
lsr x9, x25, #48
lsr x30, x19, #48
lsr w12, w25, #16
add x16, x16, x15
add x3, x19, x16
madd w13, w13, w0, w5
add x17, x25, x2
add x2, x2, x15
lsr w10, w3, #16
add x16, x16, x15
lsr w8, w19, #16
add x24, x3, x16
lsr x27, x3, #48
madd w9, w9, w0, w12
madd w30, w30, w0, w8
ldrb w13, [x18, w13, uxtw]
add x21, x17, x2
add x16, x16, x15
lsr x26, x21, #48
lsr x14, x24, #48
lsr w1, w24, #16
add x11, x24, x16
lsr w22, w17, #16
lsr x6, x17, #48
add x2, x2, x15
madd w27, w27, w0, w10
ldrb w9, [x18, w9, uxtw]
madd w6, w6, w0, w22
add x5, x21, x2
ldrb w30, [x18, w30, uxtw]
add x16, x16, x15
add x2, x2, x15
lsr x25, x5, #48
lsr w19, w21, #16
ldrb w6, [x18, w6, uxtw]
madd w14, w14, w0, w1
orr x3, x13, x9, lsl #8
madd w26, w26, w0, w19
add x12, x11, x16
add x16, x16, x15
lsr w8, w12, #16
add x24, x5, x2
lsr w17, w11, #16
lsr x10, x11, #48
orr x22, x30, x6, lsl #8
add x21, x12, x16
lsr w1, w5, #16
lsr x13, x12, #48
add x2, x2, x15
orr x9, x3, x22, lsl #16
ldrb w26, [x18, w26, uxtw]
madd w25, w25, w0, w1
ldrb w27, [x18, w27, uxtw]
madd w10, w10, w0, w17
str w9, [x23]
madd w13, w13, w0, w8
add x19, x24, x2
ldrb w14, [x18, w14, uxtw]
add x16, x16, x15
ldrb w25, [x18, w25, uxtw]
add x11, x21, x16
add x2, x2, x15
lsr x6, x24, #48
lsr w30, w24, #16
orr x5, x27, x26, lsl #8
madd w6, w6, w0, w30
add x12, x19, x2
orr x3, x14, x25, lsl #8
lsr x22, x19, #48
add x2, x2, x15
lsr w1, w19, #16
lsr x17, x11, #48
lsr w9, w12, #16
lsr x8, x12, #48
lsr w16, w11, #16
lsr x24, x21, #48
orr x26, x5, x3, lsl #16
lsr w27, w21, #16
madd w8, w8, w0, w9
add x30, x12, x2
ldrb w10, [x18, w10, uxtw]
str w26, [x23, #4]
madd w22, w22, w0, w1
ldrb w13, [x18, w13, uxtw]
madd w24, w24, w0, w27
ldrb w6, [x18, w6, uxtw]
madd w17, w17, w0, w16
lsr w14, w30, #16
ldrb w22, [x18, w22, uxtw]
ldrb w24, [x18, w24, uxtw]
orr x25, x10, x6, lsl #8
ldrb w8, [x18, w8, uxtw]
lsr x15, x30, #48
orr x19, x13, x22, lsl #8
ldrb w17, [x18, w17, uxtw]
orr x11, x25, x19, lsl #16
madd w15, w15, w0, w14
str w11, [x23, #8]
ldrb w15, [x18, w15, uxtw]
orr x5, x24, x8, lsl #8
ldr x3, [x28, #72]
orr x21, x17, x15, lsl #8
and x9, x3, #0xffffffff00000000
orr x12, x5, x21, lsl #16
add x3, x9, w3, sxtw
str w12, [x23, #12]
ldr x2, [x28, #88]
and x26, x2, #0xffffffff00000000
ldr x1, [x28, #56]
add x2, x26, w2, sxtw
