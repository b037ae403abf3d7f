add x21, x23, x24
add x22, x25, x24, lsl #1
lsl x8, x25, #2
add x5, x22, x25, lsl #1
lsr w3, w23, #16
lsr w19, w21, #16
add x12, x26, #48
lsr x2, x23, #48
lsr x15, x21, #48
madd w20, w2, w0, w3
madd w17, w15, w0, w19
tbz w29, #3, 1f
add x23, x23, x22
add x22, x22, x8
add x21, x21, x5
lsr w1, w21, #16
lsr w16, w23, #16
lsr x25, x23, #48
add x23, x23, x22
lsr x11, x21, #48
madd w6, w25, w0, w16
add x5, x5, x8
ldrb w14, [x18, w17, uxtw]
madd w4, w11, w0, w1
ldrb w7, [x18, w20, uxtw]
add x22, x22, x8
add x21, x21, x5
lsr x3, x21, #48
lsr x24, x23, #48
add x5, x5, x8
lsr w2, w23, #16
lsr w15, w21, #16
add x23, x23, x22
ldrb w16, [x18, w4, uxtw]
add x21, x21, x5
orr x19, x7, x14, lsl #8
lsr w14, w23, #16
madd w11, w24, w0, w2
madd w1, w3, w0, w15
ldrb w25, [x18, w6, uxtw]
add x5, x5, x8
lsr x7, x23, #48
add x22, x22, x8
lsr w4, w21, #16
lsr x6, x21, #48
orr x24, x25, x16, lsl #8
madd w25, w7, w0, w14
ldrb w3, [x18, w11, uxtw]
madd w16, w6, w0, w4
orr x2, x19, x24, lsl #16
ldrb w15, [x18, w1, uxtw]
add x23, x23, x22
ldrb w24, [x18, w25, uxtw]
add x22, x22, x8
ldrb w11, [x18, w16, uxtw]
add x21, x21, x5
lsr w4, w23, #16
orr x19, x3, x15, lsl #8
lsr x3, x21, #48
lsr x6, x23, #48
orr x1, x24, x11, lsl #8
lsr w15, w21, #16
orr x7, x19, x1, lsl #16
madd w17, w3, w0, w15
madd w20, w6, w0, w4
orr x14, x2, x7, lsl #32
add x5, x5, x8
str x14, [x12], #8
1:
tbz w29, #2, 2f
add x23, x23, x22
lsr w16, w23, #16
lsr x25, x23, #48
add x21, x21, x5
lsr x24, x21, #48
lsr w11, w21, #16
add x5, x5, x8
madd w2, w25, w0, w16
madd w7, w24, w0, w11
ldrb w19, [x18, w20, uxtw]
add x21, x21, x5
lsr w16, w21, #16
ldrb w1, [x18, w17, uxtw]
add x22, x22, x8
ldrb w6, [x18, w2, uxtw]
add x23, x23, x22
ldrb w4, [x18, w7, uxtw]
lsr x25, x21, #48
lsr x5, x23, #48
orr x14, x19, x1, lsl #8
madd w17, w25, w0, w16
add x22, x22, x8
orr x3, x6, x4, lsl #8
lsr w8, w23, #16
madd w20, w5, w0, w8
orr x15, x14, x3, lsl #16
str w15, [x12], #4
2:
tbz w29, #1, 3f
ldrb w11, [x18, w17, uxtw]
add x23, x23, x22
ldrb w24, [x18, w20, uxtw]
lsr x1, x23, #48
lsr w2, w23, #16
madd w20, w1, w0, w2
orr x19, x24, x11, lsl #8
strh w19, [x12], #2
3:
tbz w29, #0, 4f
ldrb w7, [x18, w20, uxtw]
strb w7, [x12]
4:
