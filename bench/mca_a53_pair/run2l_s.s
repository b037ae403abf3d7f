add x2, x10, x9, lsl #1
add x1, x13, x9
lsl x4, x10, #2
lsr w6, w13, #16
lsr x7, x1, #48
add x3, x2, x10, lsl #1
lsr w8, w1, #16
add x11, x13, x2
lsr x5, x13, #48
madd w14, w7, w18, w8
add x2, x2, x4
madd w12, w5, w18, w6
add x1, x1, x3
add x3, x3, x4
lsr x17, x1, #48
lsr x15, x11, #48
lsr w16, w11, #16
add x11, x11, x2
lsr w19, w1, #16
ldrb w20, [x26, w12, uxtw]
add x2, x2, x4
madd w22, w15, w18, w16
ldrb w21, [x26, w14, uxtw]
madd w5, w17, w18, w19
add x1, x1, x3
add x3, x3, x4
lsr w12, w1, #16
lsr w7, w11, #16
lsr x6, x11, #48
lsr x8, x1, #48
ldrb w16, [x26, w5, uxtw]
madd w19, w8, w18, w12
orr x14, x20, x21, lsl #8
add x11, x11, x2
madd w17, w6, w18, w7
ldrb w15, [x26, w22, uxtw]
add x1, x1, x3
add x3, x3, x4
lsr x20, x11, #48
lsr x22, x1, #48
lsr w5, w1, #16
add x1, x1, x3
add x2, x2, x4
add x3, x3, x4
lsr w21, w11, #16
add x11, x11, x2
add x2, x2, x4
orr x6, x15, x16, lsl #8
ldrb w8, [x26, w17, uxtw]
madd w16, w22, w18, w5
madd w15, w20, w18, w21
ldrb w12, [x26, w19, uxtw]
add x5, x23, x24
orr x7, x14, x6, lsl #16
lsr x14, x11, #48
lsr w6, w11, #16
lsr w19, w1, #16
lsr x17, x1, #48
add x1, x1, x3
ldrb w21, [x26, w15, uxtw]
orr x20, x8, x12, lsl #8
add x8, x25, x24, lsl #1
add x11, x11, x2
add x12, x8, x25, lsl #1
lsl x15, x25, #2
madd w24, w14, w18, w6
ldrb w22, [x26, w16, uxtw]
madd w25, w17, w18, w19
add x3, x3, x4
lsr w19, w1, #16
add x2, x2, x4
lsr x17, x1, #48
lsr w6, w11, #16
lsr x14, x11, #48
add x1, x1, x3
add x11, x11, x2
add x2, x2, x4
add x3, x3, x4
orr x4, x21, x22, lsl #8
orr x21, x20, x4, lsl #16
ldrb w20, [x26, w24, uxtw]
orr x22, x7, x21, lsl #32
madd w21, w17, w18, w19
ldrb w4, [x26, w25, uxtw]
str x22, [x28, #32]
madd w7, w14, w18, w6
lsr x22, x11, #48
lsr x25, x1, #48
lsr w24, w11, #16
lsr w14, w1, #16
add x11, x11, x2
ldrb w17, [x26, w7, uxtw]
ldrb w19, [x26, w21, uxtw]
madd w2, w22, w18, w24
orr x6, x20, x4, lsl #8
add x1, x1, x3
lsr w4, w11, #16
madd w3, w25, w18, w14
lsr x20, x11, #48
lsr w21, w1, #16
lsr x7, x1, #48
madd w11, w20, w18, w4
add x16, x28, #48
madd w1, w7, w18, w21
ldrb w25, [x26, w2, uxtw]
orr x22, x17, x19, lsl #8
ldrb w14, [x26, w3, uxtw]
ldrb w19, [x26, w11, uxtw]
orr x24, x6, x22, lsl #16
ldrb w6, [x26, w1, uxtw]
lsr x21, x5, #48
orr x17, x25, x14, lsl #8
orr x22, x19, x6, lsl #8
lsr x20, x23, #48
lsr w4, w23, #16
orr x2, x17, x22, lsl #16
madd w7, w20, w18, w4
lsr w25, w5, #16
orr x3, x24, x2, lsl #32
madd w14, w21, w18, w25
str x3, [x28, #40]
tbz w0, #3, 1f
add x23, x23, x8
add x8, x8, x15
add x5, x5, x12
lsr w6, w5, #16
lsr w1, w23, #16
lsr x11, x23, #48
add x23, x23, x8
lsr x19, x5, #48
madd w24, w11, w18, w1
add x12, x12, x15
ldrb w22, [x26, w14, uxtw]
madd w2, w19, w18, w6
ldrb w17, [x26, w7, uxtw]
add x8, x8, x15
add x5, x5, x12
lsr x4, x5, #48
lsr x3, x23, #48
add x12, x12, x15
lsr w20, w23, #16
lsr w21, w5, #16
add x23, x23, x8
ldrb w1, [x26, w2, uxtw]
add x5, x5, x12
orr x25, x17, x22, lsl #8
lsr w22, w23, #16
madd w19, w3, w18, w20
madd w6, w4, w18, w21
ldrb w11, [x26, w24, uxtw]
add x12, x12, x15
lsr x17, x23, #48
add x8, x8, x15
lsr w2, w5, #16
lsr x24, x5, #48
orr x3, x11, x1, lsl #8
madd w11, w17, w18, w22
ldrb w4, [x26, w19, uxtw]
madd w1, w24, w18, w2
orr x20, x25, x3, lsl #16
ldrb w21, [x26, w6, uxtw]
add x23, x23, x8
ldrb w3, [x26, w11, uxtw]
add x8, x8, x15
ldrb w19, [x26, w1, uxtw]
add x5, x5, x12
lsr w2, w23, #16
orr x25, x4, x21, lsl #8
lsr x4, x5, #48
lsr x24, x23, #48
orr x6, x3, x19, lsl #8
lsr w21, w5, #16
orr x17, x25, x6, lsl #16
madd w14, w4, w18, w21
madd w7, w24, w18, w2
orr x22, x20, x17, lsl #32
add x12, x12, x15
str x22, [x16], #8
1:
tbz w0, #2, 2f
add x23, x23, x8
lsr x11, x23, #48
ldrb w6, [x26, w14, uxtw]
add x5, x5, x12
add x12, x12, x15
lsr x3, x5, #48
lsr w1, w23, #16
lsr w19, w5, #16
madd w20, w11, w18, w1
add x5, x5, x12
ldrb w25, [x26, w7, uxtw]
add x8, x8, x15
madd w17, w3, w18, w19
add x23, x23, x8
ldrb w24, [x26, w20, uxtw]
lsr w1, w5, #16
ldrb w2, [x26, w17, uxtw]
add x12, x12, x15
add x8, x8, x15
lsr x11, x5, #48
lsr w15, w23, #16
lsr x12, x23, #48
madd w14, w11, w18, w1
orr x4, x24, x2, lsl #8
orr x22, x25, x6, lsl #8
madd w7, w12, w18, w15
orr x21, x22, x4, lsl #16
str w21, [x16], #4
2:
tbz w0, #1, 3f
ldrb w19, [x26, w14, uxtw]
add x23, x23, x8
ldrb w3, [x26, w7, uxtw]
lsr x6, x23, #48
lsr w20, w23, #16
madd w7, w6, w18, w20
orr x25, x3, x19, lsl #8
strh w25, [x16], #2
3:
tbz w0, #0, 4f
ldrb w17, [x26, w7, uxtw]
strb w17, [x16]
4:
