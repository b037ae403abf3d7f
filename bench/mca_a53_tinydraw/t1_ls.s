lsr x11, x0, #48
lsr w10, w0, #16
madd w10, w11, w4, w10
ldrb w10, [x3, w10, uxtw]
strb w10, [x5]
