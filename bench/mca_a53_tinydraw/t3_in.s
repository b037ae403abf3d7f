add x6, x0, x1
add x8, x2, x1, lsl #1
lsr x13, x0, #48
lsr w10, w0, #16
madd w10, w13, w4, w10
ldrb w10, [x3, w10, uxtw]
lsr x14, x6, #48
lsr w11, w6, #16
madd w11, w14, w4, w11
ldrb w11, [x3, w11, uxtw]
orr w10, w10, w11, lsl #8
strh w10, [x5]
add x7, x0, x8
lsr x15, x7, #48
lsr w12, w7, #16
madd w12, w15, w4, w12
ldrb w12, [x3, w12, uxtw]
strb w12, [x5, #2]
