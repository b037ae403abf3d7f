add x8, x2, x1, lsl #1
add x6, x0, x1
lsr x14, x0, #48
lsr w10, w0, #16
add x9, x8, x2, lsl #1
lsr x15, x6, #48
lsr w11, w6, #16
add x7, x0, x8
madd w10, w14, w4, w10
add x6, x6, x9
madd w11, w15, w4, w11
lsr x16, x7, #48
lsr w12, w7, #16
lsr x17, x6, #48
lsr w13, w6, #16
madd w12, w16, w4, w12
ldrb w10, [x3, w10, uxtw]
madd w13, w17, w4, w13
ldrb w11, [x3, w11, uxtw]
ldrb w12, [x3, w12, uxtw]
ldrb w13, [x3, w13, uxtw]
orr w10, w10, w11, lsl #8
orr w12, w12, w13, lsl #8
orr w10, w10, w12, lsl #16
str w10, [x5]
