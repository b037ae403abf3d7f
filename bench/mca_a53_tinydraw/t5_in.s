add x6, x0, x1
add x8, x2, x1, lsl #1
add x9, x8, x2, lsl #1
lsr x15, x0, #48
lsr w10, w0, #16
madd w10, w15, w4, w10
ldrb w10, [x3, w10, uxtw]
lsr x16, x6, #48
lsr w11, w6, #16
madd w11, w16, w4, w11
ldrb w11, [x3, w11, uxtw]
add x7, x0, x8
add x8, x8, x2, lsl #2
lsr x17, x7, #48
lsr w12, w7, #16
madd w12, w17, w4, w12
ldrb w12, [x3, w12, uxtw]
add x6, x6, x9
lsr x19, x6, #48
lsr w13, w6, #16
madd w13, w19, w4, w13
ldrb w13, [x3, w13, uxtw]
orr w10, w10, w11, lsl #8
orr w12, w12, w13, lsl #8
orr w10, w10, w12, lsl #16
str w10, [x5]
add x7, x7, x8
lsr x15, x7, #48
lsr w14, w7, #16
madd w14, w15, w4, w14
ldrb w14, [x3, w14, uxtw]
strb w14, [x5, #4]
