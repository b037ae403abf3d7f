add x2, x10, x9, lsl #1
add x1, x13, x9
lsr w8, w1, #16
add x3, x2, x10, lsl #1
lsr w6, w13, #16
lsr x5, x13, #48
lsr x7, x1, #48
madd w12, w5, w18, w6
add x1, x1, x3
add x11, x13, x2
lsr x17, x1, #48
lsr w19, w1, #16
lsr w16, w11, #16
lsl x4, x10, #2
add x2, x2, x4
add x3, x3, x4
lsr x15, x11, #48
add x11, x11, x2
lsr x5, x11, #48
madd w14, w7, w18, w8
add x1, x1, x3
add x3, x3, x4
lsr w8, w11, #16
madd w22, w15, w18, w16
ldrb w20, [x26, w12, uxtw]
madd w6, w17, w18, w19
add x2, x2, x4
lsr x7, x1, #48
lsr w12, w1, #16
add x1, x1, x3
ldrb w21, [x26, w14, uxtw]
madd w17, w7, w18, w12
ldrb w16, [x26, w22, uxtw]
add x11, x11, x2
madd w19, w5, w18, w8
add x3, x3, x4
ldrb w15, [x26, w6, uxtw]
orr x14, x20, x21, lsl #8
add x2, x2, x4
lsr x22, x1, #48
lsr w21, w11, #16
lsr w6, w1, #16
lsr x20, x11, #48
add x1, x1, x3
add x3, x3, x4
add x11, x11, x2
orr x5, x16, x15, lsl #8
madd w16, w20, w18, w21
ldrb w12, [x26, w19, uxtw]
ldrb w7, [x26, w17, uxtw]
madd w15, w22, w18, w6
orr x8, x14, x5, lsl #16
add x22, x23, x24
lsr x19, x1, #48
lsr w17, w1, #16
lsr x14, x11, #48
lsr w5, w11, #16
orr x21, x12, x7, lsl #8
ldrb w6, [x26, w15, uxtw]
add x2, x2, x4
ldrb w20, [x26, w16, uxtw]
add x7, x25, x24, lsl #1
add x11, x11, x2
lsl x16, x25, #2
madd w24, w14, w18, w5
add x12, x7, x25, lsl #1
madd w25, w19, w18, w17
add x1, x1, x3
add x3, x3, x4
lsr x19, x1, #48
lsr w17, w1, #16
lsr w14, w11, #16
lsr x5, x11, #48
add x2, x2, x4
add x1, x1, x3
add x11, x11, x2
add x3, x3, x4
add x2, x2, x4
orr x4, x20, x6, lsl #8
orr x6, x21, x4, lsl #16
ldrb w21, [x26, w25, uxtw]
ldrb w4, [x26, w24, uxtw]
orr x20, x8, x6, lsl #32
madd w8, w5, w18, w14
lsr w24, w11, #16
lsr x25, x1, #48
madd w6, w19, w18, w17
str x20, [x28, #32]
orr x14, x4, x21, lsl #8
lsr w5, w1, #16
lsr x20, x11, #48
add x11, x11, x2
add x1, x1, x3
ldrb w17, [x26, w6, uxtw]
madd w2, w20, w18, w24
ldrb w19, [x26, w8, uxtw]
madd w3, w25, w18, w5
lsr x8, x1, #48
lsr x21, x11, #48
lsr w6, w1, #16
lsr w4, w11, #16
madd w11, w21, w18, w4
ldrb w25, [x26, w3, uxtw]
madd w1, w8, w18, w6
ldrb w5, [x26, w2, uxtw]
orr x24, x19, x17, lsl #8
orr x20, x14, x24, lsl #16
ldrb w17, [x26, w11, uxtw]
add x15, x28, #48
ldrb w14, [x26, w1, uxtw]
orr x24, x17, x14, lsl #8
orr x19, x5, x25, lsl #8
orr x2, x19, x24, lsl #16
orr x3, x20, x2, lsl #32
str x3, [x28, #40]
tbz w0, #3, 1f
lsr x6, x22, #48
lsr w4, w23, #16
lsr w8, w22, #16
lsr x21, x23, #48
add x22, x22, x12
madd w25, w21, w18, w4
add x12, x12, x16
madd w5, w6, w18, w8
add x23, x23, x7
add x7, x7, x16
lsr x14, x22, #48
lsr w1, w23, #16
lsr x11, x23, #48
lsr w17, w22, #16
add x22, x22, x12
add x23, x23, x7
ldrb w24, [x26, w5, uxtw]
madd w2, w11, w18, w1
ldrb w19, [x26, w25, uxtw]
madd w20, w14, w18, w17
add x12, x12, x16
add x7, x7, x16
lsr w21, w23, #16
lsr x3, x23, #48
lsr w8, w22, #16
add x23, x23, x7
lsr x4, x22, #48
orr x6, x19, x24, lsl #8
madd w1, w3, w18, w21
ldrb w25, [x26, w2, uxtw]
madd w11, w4, w18, w8
ldrb w5, [x26, w20, uxtw]
add x22, x22, x12
lsr w17, w23, #16
lsr x14, x23, #48
lsr x19, x22, #48
lsr w24, w22, #16
orr x2, x25, x5, lsl #8
madd w8, w14, w18, w17
add x12, x12, x16
madd w4, w19, w18, w24
orr x20, x6, x2, lsl #16
ldrb w3, [x26, w1, uxtw]
add x22, x22, x12
ldrb w21, [x26, w11, uxtw]
add x7, x7, x16
ldrb w25, [x26, w8, uxtw]
ldrb w2, [x26, w4, uxtw]
orr x5, x3, x21, lsl #8
add x23, x23, x7
add x12, x12, x16
orr x6, x25, x2, lsl #8
orr x1, x5, x6, lsl #16
orr x11, x20, x1, lsl #32
add x7, x7, x16
str x11, [x15], #8
1:
tbz w0, #2, 2f
lsr x17, x23, #48
lsr w24, w22, #16
lsr x19, x22, #48
lsr w14, w23, #16
add x23, x23, x7
lsr w4, w23, #16
madd w21, w19, w18, w24
add x22, x22, x12
lsr x2, x22, #48
lsr x8, x23, #48
lsr w25, w22, #16
madd w3, w17, w18, w14
madd w20, w2, w18, w25
add x12, x12, x16
madd w1, w8, w18, w4
add x22, x22, x12
ldrb w5, [x26, w21, uxtw]
add x7, x7, x16
ldrb w6, [x26, w3, uxtw]
add x23, x23, x7
ldrb w17, [x26, w20, uxtw]
ldrb w14, [x26, w1, uxtw]
orr x11, x6, x5, lsl #8
orr x19, x14, x17, lsl #8
orr x24, x11, x19, lsl #16
add x7, x7, x16
str w24, [x15], #4
add x12, x12, x16
2:
tbz w0, #1, 3f
lsr x12, x23, #48
lsr w16, w23, #16
lsr w21, w22, #16
lsr x3, x22, #48
madd w4, w12, w18, w16
add x23, x23, x7
madd w8, w3, w18, w21
ldrb w25, [x26, w4, uxtw]
ldrb w2, [x26, w8, uxtw]
orr x6, x25, x2, lsl #8
strh w6, [x15], #2
3:
tbz w0, #0, 4f
lsr x5, x23, #48
lsr w1, w23, #16
madd w20, w5, w18, w1
ldrb w14, [x26, w20, uxtw]
strb w14, [x15]
4:
