add x1, x13, x9
lsl x4, x10, #2
lsr w8, w1, #16
lsr w6, w13, #16
lsr x7, x1, #48
lsr x5, x13, #48
add x2, x10, x9, lsl #1
add x11, x13, x2
add x3, x2, x10, lsl #1
lsr x15, x11, #48
add x1, x1, x3
lsr w19, w1, #16
madd w12, w5, w18, w6
add x3, x3, x4
add x2, x2, x4
lsr w16, w11, #16
lsr x17, x1, #48
add x11, x11, x2
add x1, x1, x3
lsr x6, x11, #48
madd w14, w7, w18, w8
ldrb w20, [x26, w12, uxtw]
madd w22, w15, w18, w16
add x3, x3, x4
madd w5, w17, w18, w19
add x2, x2, x4
lsr w7, w11, #16
lsr x8, x1, #48
lsr w12, w1, #16
ldrb w21, [x26, w14, uxtw]
add x1, x1, x3
ldrb w16, [x26, w22, uxtw]
add x11, x11, x2
ldrb w15, [x26, w5, uxtw]
add x3, x3, x4
madd w19, w6, w18, w7
orr x14, x20, x21, lsl #8
lsr w5, w1, #16
lsr x22, x1, #48
lsr x20, x11, #48
add x1, x1, x3
lsr w21, w11, #16
add x2, x2, x4
add x11, x11, x2
madd w17, w8, w18, w12
add x3, x3, x4
orr x7, x16, x15, lsl #8
ldrb w12, [x26, w19, uxtw]
madd w15, w20, w18, w21
add x2, x2, x4
orr x6, x14, x7, lsl #16
madd w16, w22, w18, w5
ldrb w8, [x26, w17, uxtw]
lsr x14, x11, #48
lsr w7, w11, #16
lsr w17, w1, #16
add x11, x11, x2
lsr x19, x1, #48
orr x20, x12, x8, lsl #8
add x2, x2, x4
ldrb w21, [x26, w15, uxtw]
madd w5, w14, w18, w7
ldrb w22, [x26, w16, uxtw]
add x1, x1, x3
add x3, x3, x4
lsr w15, w11, #16
lsr x8, x11, #48
lsr x16, x1, #48
add x11, x11, x2
lsr w14, w1, #16
orr x7, x21, x22, lsl #8
add x1, x1, x3
madd w12, w19, w18, w17
add x2, x2, x4
orr x19, x20, x7, lsl #16
add x3, x3, x4
orr x17, x6, x19, lsl #32
ldrb w4, [x26, w5, uxtw]
madd w7, w16, w18, w14
ldrb w21, [x26, w12, uxtw]
str x17, [x28, #32]
madd w22, w8, w18, w15
lsr w19, w11, #16
lsr x6, x1, #48
lsr x20, x11, #48
add x11, x11, x2
lsr w17, w1, #16
ldrb w12, [x26, w22, uxtw]
ldrb w8, [x26, w7, uxtw]
madd w16, w6, w18, w17
add x1, x1, x3
madd w15, w20, w18, w19
orr x5, x4, x21, lsl #8
lsr w4, w1, #16
lsr w2, w11, #16
lsr x3, x1, #48
orr x21, x12, x8, lsl #8
lsr x14, x11, #48
madd w17, w3, w18, w4
orr x22, x5, x21, lsl #16
ldrb w19, [x26, w16, uxtw]
ldrb w7, [x26, w15, uxtw]
madd w20, w14, w18, w2
ldrb w1, [x26, w17, uxtw]
orr x6, x7, x19, lsl #8
ldrb w11, [x26, w20, uxtw]
orr x8, x11, x1, lsl #8
orr x12, x6, x8, lsl #16
orr x21, x22, x12, lsl #32
str x21, [x28, #40]
