.Lloop:
lsr x7, x16, #48
lsr x1, x13, #48
lsr x5, x15, #48
lsr w4, w14, #16
lsr x3, x14, #48
add x14, x14, x17
lsr w6, w15, #16
lsr w2, w13, #16
lsr w8, w16, #16
madd w7, w7, w24, w8
add x13, x13, x17
madd w1, w1, w24, w2
madd w3, w3, w24, w4
fadd v3.2d, v24.2d, v19.2d
ldr q1, [sp, #16]
madd w5, w5, w24, w6
sub w2, w26, w25
add x15, x15, x17
lsr x6, x26, #32
sub x6, x6, x25, lsr #32
asr w8, w2, #31
ldrb w3, [x23, w3, uxtw]
add x16, x16, x17
add w2, w2, w8, lsr #28
lsr w21, w16, #16
lsr x12, x15, #48
lsr x10, x14, #48
lsr x8, x13, #48
lsr x20, x16, #48
lsr w11, w14, #16
lsr w9, w13, #16
lsr w19, w15, #16
add x14, x14, x17
madd w8, w8, w24, w9
add x15, x15, x17
ldrb w5, [x23, w5, uxtw]
ldrb w1, [x23, w1, uxtw]
madd w20, w20, w24, w21
madd w10, w10, w24, w11
ldrb w7, [x23, w7, uxtw]
add x16, x16, x17
asr w4, w6, #31
lsr x9, x15, #48
add x13, x13, x17
add w6, w6, w4, lsr #28
sbfx x2, x2, #4, #28
asr w6, w6, #4
ldr q0, [sp]
ldr q2, [sp, #16]
madd w12, w12, w24, w19
add x4, x2, x6, lsl #32
orr x2, x1, x3, lsl #8
lsr x19, x16, #48
lsr x3, x13, #48
lsr w11, w15, #16
orr x1, x5, x7, lsl #8
lsr x6, x14, #48
lsr w5, w13, #16
lsr w21, w16, #16
lsr w7, w14, #16
add x13, x13, x17
add x15, x15, x17
add x16, x16, x17
add x14, x14, x17
lsr w18, w16, #16
fmla v0.2d, v16.2d, v3.2d
fmla v2.2d, v17.2d, v3.d[1]
fmla v1.2d, v17.2d, v3.d[0]
ldrb w12, [x23, w12, uxtw]
madd w19, w19, w24, w21
madd w3, w3, w24, w5
ldrb w20, [x23, w20, uxtw]
madd w6, w6, w24, w7
ldrb w10, [x23, w10, uxtw]
madd w9, w9, w24, w11
ldrb w8, [x23, w8, uxtw]
sub w5, w27, w26
lsr x11, x27, #32
asr w21, w5, #31
add w5, w5, w21, lsr #28
orr x21, x2, x1, lsl #16
orr x1, x8, x10, lsl #8
orr x2, x12, x20, lsl #8
lsr x30, x16, #48
lsr w28, w15, #16
lsr x22, x15, #48
lsr x8, x13, #48
lsr w10, w13, #16
lsr w20, w14, #16
lsr x12, x14, #48
fmaxnm v0.2d, v0.2d, v21.2d
madd w8, w8, w24, w10
ldrb w3, [x23, w3, uxtw]
ldrb w6, [x23, w6, uxtw]
madd w12, w12, w24, w20
add x14, x25, x4
ldrb w19, [x23, w19, uxtw]
madd w30, w30, w24, w18
ldrb w9, [x23, w9, uxtw]
madd w22, w22, w24, w28
str w21, [x0, #0]
mov x13, x25
add x10, x4, x4
add x17, x10, x10
orr x4, x1, x2, lsl #16
orr x1, x3, x6, lsl #8
add x16, x14, x10
sbfx x5, x5, #4, #28
add x15, x25, x10
lsr w20, w15, #16
orr x2, x9, x19, lsl #8
lsr x21, x16, #48
lsr w6, w13, #16
lsr x9, x14, #48
lsr w28, w16, #16
lsr x19, x15, #48
lsr w10, w14, #16
lsr x3, x13, #48
fdiv v3.2d, v20.2d, v0.2d
madd w19, w19, w24, w20
ldrb w8, [x23, w8, uxtw]
madd w21, w21, w24, w28
ldrb w22, [x23, w22, uxtw]
madd w9, w9, w24, w10
str w4, [x0, #4]
ldrb w30, [x23, w30, uxtw]
madd w3, w3, w24, w6
add x15, x15, x17
add x14, x14, x17
add x13, x13, x17
sub x11, x11, x26, lsr #32
lsr w10, w14, #16
asr w7, w11, #31
lsr x6, x13, #48
ldrb w12, [x23, w12, uxtw]
add x16, x16, x17
add w11, w11, w7, lsr #28
asr w11, w11, #4
lsr w7, w13, #16
add x4, x5, x11, lsl #32
orr x5, x1, x2, lsl #16
orr x2, x22, x30, lsl #8
orr x1, x8, x12, lsl #8
lsr x20, x16, #48
lsr x8, x14, #48
lsr x11, x15, #48
lsr w22, w16, #16
lsr w12, w15, #16
add x15, x15, x17
add x14, x14, x17
add x16, x16, x17
ldrb w21, [x23, w21, uxtw]
ldrb w3, [x23, w3, uxtw]
madd w8, w8, w24, w10
ldrb w19, [x23, w19, uxtw]
ldrb w9, [x23, w9, uxtw]
madd w20, w20, w24, w22
madd w6, w6, w24, w7
fmul v2.2d, v2.2d, v3.d[1]
fmul v1.2d, v1.2d, v3.d[0]
str w5, [x0, #8]
madd w11, w11, w24, w12
orr x5, x1, x2, lsl #16
orr x2, x19, x21, lsl #8
orr x1, x3, x9, lsl #8
add x13, x13, x17
lsr x12, x15, #48
lsr x3, x13, #48
lsr x21, x16, #48
lsr w10, w14, #16
lsr w19, w15, #16
lsr w22, w16, #16
lsr x9, x14, #48
add x14, x14, x17
lsr w7, w13, #16
fcvtzu v1.2d, v1.2d, #16
fcvtzu v2.2d, v2.2d, #16
madd w9, w9, w24, w10
ldrb w6, [x23, w6, uxtw]
madd w3, w3, w24, w7
ldrb w8, [x23, w8, uxtw]
add x15, x15, x17
ldrb w20, [x23, w20, uxtw]
ldrb w11, [x23, w11, uxtw]
uqxtn v0.2s, v1.2d
ldrb w9, [x23, w9, uxtw]
madd w21, w21, w24, w22
str w5, [x0, #12]
madd w12, w12, w24, w19
add x16, x16, x17
orr x5, x1, x2, lsl #16
lsr w19, w15, #16
add x13, x13, x17
orr x2, x11, x20, lsl #8
orr x1, x6, x8, lsl #8
lsr x8, x14, #48
lsr w10, w14, #16
lsr x11, x15, #48
lsr x6, x13, #48
lsr w7, w13, #16
lsr x20, x16, #48
lsr w22, w16, #16
madd w11, w11, w24, w19
ldrb w21, [x23, w21, uxtw]
uqxtn2 v0.4s, v2.2d
fadd v24.2d, v24.2d, v18.2d
madd w6, w6, w24, w7
ldrb w12, [x23, w12, uxtw]
ldrb w3, [x23, w3, uxtw]
madd w8, w8, w24, w10
madd w20, w20, w24, w22
str w5, [x0, #16]
add x5, x4, x4
ldrb w11, [x23, w11, uxtw]
add x15, x26, x5
add x14, x26, x4
orr x4, x1, x2, lsl #16
mov x25, x27
orr x2, x12, x21, lsl #8
mov x13, x26
orr x1, x3, x9, lsl #8
ldrb w20, [x23, w20, uxtw]
ldrb w8, [x23, w8, uxtw]
umin v0.4s, v0.4s, v22.4s
ldrb w6, [x23, w6, uxtw]
orr x3, x1, x2, lsl #16
orr x2, x11, x20, lsl #8
str w4, [x0, #20]
orr x1, x6, x8, lsl #8
str w3, [x0, #24]
orr x3, x1, x2, lsl #16
ldr x1, [sp, #32]
fadd v24.2d, v24.2d, v18.2d
fmov x26, d0
mov x27, v0.d[1]
str w3, [x0, #28]
add x0, x0, #32
cmp x0, x1
add x17, x5, x5
add x16, x14, x5
b.lo .Lloop
