add x6, x0, x1
lsr x12, x0, #48
lsr w10, w0, #16
lsr x13, x6, #48
lsr w11, w6, #16
madd w10, w12, w4, w10
madd w11, w13, w4, w11
ldrb w10, [x3, w10, uxtw]
ldrb w11, [x3, w11, uxtw]
orr w10, w10, w11, lsl #8
strh w10, [x5]
