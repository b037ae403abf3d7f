add x15, x13, x9, lsl #1
add x14, x13, x9
lsr x2, x14, #48
add x16, x14, x9, lsl #1
lsr x4, x16, #48
lsl x17, x9, #2
lsr w11, w15, #16
lsr x1, x13, #48
lsr x3, x15, #48
lsr w12, w16, #16
lsr w10, w14, #16
add x15, x15, x17
lsr w9, w13, #16
madd w1, w1, w0, w9
add x13, x13, x17
madd w3, w3, w0, w11
add x14, x14, x17
lsr x5, x13, #48
lsr w9, w13, #16
lsr w11, w15, #16
madd w2, w2, w0, w10
madd w4, w4, w0, w12
add x16, x16, x17
lsr w10, w14, #16
lsr w12, w16, #16
lsr x8, x16, #48
lsr x6, x14, #48
lsr x7, x15, #48
add x14, x14, x17
ldrb w1, [x18, w1, uxtw]
madd w7, w7, w0, w11
add x13, x13, x17
ldrb w2, [x18, w2, uxtw]
madd w8, w8, w0, w12
ldrb w4, [x18, w4, uxtw]
madd w5, w5, w0, w9
ldrb w3, [x18, w3, uxtw]
add x15, x15, x17
madd w6, w6, w0, w10
add x16, x16, x17
orr x21, x1, x2, lsl #8
lsr w11, w15, #16
lsr w10, w14, #16
lsr x1, x13, #48
orr x22, x3, x4, lsl #8
lsr x4, x16, #48
lsr w12, w16, #16
lsr w9, w13, #16
lsr x2, x14, #48
lsr x3, x15, #48
ldrb w6, [x18, w6, uxtw]
ldrb w5, [x18, w5, uxtw]
madd w1, w1, w0, w9
add x16, x16, x17
madd w4, w4, w0, w12
madd w3, w3, w0, w11
ldrb w8, [x18, w8, uxtw]
orr x9, x21, x22, lsl #16
orr x21, x5, x6, lsl #8
ldrb w7, [x18, w7, uxtw]
ldrb w1, [x18, w1, uxtw]
madd w2, w2, w0, w10
add x15, x15, x17
add x13, x13, x17
lsr x5, x13, #48
str w9, [x26, #0]
orr x22, x7, x8, lsl #8
add x14, x14, x17
lsr w11, w15, #16
lsr w10, w14, #16
lsr x7, x15, #48
lsr x6, x14, #48
lsr w9, w13, #16
lsr x8, x16, #48
lsr w12, w16, #16
ldrb w4, [x18, w4, uxtw]
madd w5, w5, w0, w9
ldrb w2, [x18, w2, uxtw]
add x14, x23, x24
ldrb w3, [x18, w3, uxtw]
add x16, x14, x24, lsl #1
orr x9, x21, x22, lsl #16
lsl x17, x24, #2
madd w7, w7, w0, w11
ldrb w5, [x18, w5, uxtw]
madd w8, w8, w0, w12
orr x22, x3, x4, lsl #8
add x15, x23, x24, lsl #1
lsr w11, w15, #16
lsr x4, x16, #48
str w9, [x26, #4]
madd w6, w6, w0, w10
orr x21, x1, x2, lsl #8
lsr x1, x23, #48
lsr w10, w14, #16
lsr x3, x15, #48
lsr w12, w16, #16
lsr x2, x14, #48
lsr w9, w23, #16
madd w2, w2, w0, w10
ldrb w6, [x18, w6, uxtw]
add x23, x23, x17
madd w4, w4, w0, w12
ldrb w7, [x18, w7, uxtw]
madd w1, w1, w0, w9
ldrb w8, [x18, w8, uxtw]
madd w3, w3, w0, w11
orr x9, x21, x22, lsl #16
add x15, x15, x17
lsr w11, w15, #16
orr x21, x5, x6, lsl #8
lsr x5, x23, #48
ldrb w1, [x18, w1, uxtw]
add x16, x16, x17
str w9, [x26, #8]
add x14, x14, x17
orr x22, x7, x8, lsl #8
lsr w12, w16, #16
lsr x7, x15, #48
lsr w9, w23, #16
lsr x6, x14, #48
lsr x8, x16, #48
lsr w10, w14, #16
add x14, x14, x17
madd w5, w5, w0, w9
orr x9, x21, x22, lsl #16
ldrb w2, [x18, w2, uxtw]
add x16, x16, x17
ldrb w4, [x18, w4, uxtw]
madd w8, w8, w0, w12
ldrb w3, [x18, w3, uxtw]
madd w6, w6, w0, w10
madd w7, w7, w0, w11
ldrb w5, [x18, w5, uxtw]
add x15, x15, x17
str w9, [x26, #12]
add x23, x23, x17
orr x21, x1, x2, lsl #8
lsr x2, x14, #48
lsr w11, w15, #16
lsr w9, w23, #16
lsr x1, x23, #48
lsr w12, w16, #16
orr x22, x3, x4, lsl #8
lsr x3, x15, #48
lsr w10, w14, #16
lsr x4, x16, #48
ldrb w6, [x18, w6, uxtw]
ldrb w8, [x18, w8, uxtw]
madd w3, w3, w0, w11
madd w1, w1, w0, w9
ldrb w7, [x18, w7, uxtw]
orr x9, x21, x22, lsl #16
madd w4, w4, w0, w12
orr x21, x5, x6, lsl #8
add x14, x14, x17
ldrb w3, [x18, w3, uxtw]
madd w2, w2, w0, w10
add x15, x15, x17
str w9, [x26, #16]
orr x22, x7, x8, lsl #8
add x23, x23, x17
lsr x6, x14, #48
add x16, x16, x17
lsr w9, w23, #16
lsr w12, w16, #16
lsr w11, w15, #16
lsr x8, x16, #48
lsr x5, x23, #48
lsr w10, w14, #16
lsr x7, x15, #48
madd w5, w5, w0, w9
madd w6, w6, w0, w10
ldrb w1, [x18, w1, uxtw]
ldrb w4, [x18, w4, uxtw]
madd w7, w7, w0, w11
ldrb w2, [x18, w2, uxtw]
madd w8, w8, w0, w12
orr x9, x21, x22, lsl #16
ldrb w5, [x18, w5, uxtw]
ldrb w6, [x18, w6, uxtw]
orr x22, x3, x4, lsl #8
ldrb w7, [x18, w7, uxtw]
orr x21, x1, x2, lsl #8
str w9, [x26, #20]
orr x9, x21, x22, lsl #16
ldrb w8, [x18, w8, uxtw]
str w9, [x26, #24]
orr x21, x5, x6, lsl #8
orr x22, x7, x8, lsl #8
strh w21, [x26, #28]
strh w22, [x26, #30]
