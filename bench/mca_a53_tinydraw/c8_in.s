add x6, x0, x1
add x7, x2, x1, lsl #1
add x8, x7, x2, lsl #1
lsr x17, x0, #48
lsr w9, w0, #16
madd w9, w17, w4, w9
ldrb w9, [x3, w9, uxtw]
add x0, x0, x7
add x7, x7, x2, lsl #2
lsr x19, x6, #48
lsr w10, w6, #16
madd w10, w19, w4, w10
ldrb w10, [x3, w10, uxtw]
add x6, x6, x8
add x8, x8, x2, lsl #2
lsr x20, x0, #48
lsr w11, w0, #16
madd w11, w20, w4, w11
ldrb w11, [x3, w11, uxtw]
add x0, x0, x7
add x7, x7, x2, lsl #2
lsr x21, x6, #48
lsr w12, w6, #16
madd w12, w21, w4, w12
ldrb w12, [x3, w12, uxtw]
add x6, x6, x8
add x8, x8, x2, lsl #2
lsr x17, x0, #48
lsr w13, w0, #16
madd w13, w17, w4, w13
ldrb w13, [x3, w13, uxtw]
add x0, x0, x7
add x7, x7, x2, lsl #2
lsr x19, x6, #48
lsr w14, w6, #16
madd w14, w19, w4, w14
ldrb w14, [x3, w14, uxtw]
add x6, x6, x8
lsr x20, x0, #48
lsr w15, w0, #16
madd w15, w20, w4, w15
ldrb w15, [x3, w15, uxtw]
add x0, x0, x7
lsr x21, x6, #48
lsr w16, w6, #16
madd w16, w21, w4, w16
ldrb w16, [x3, w16, uxtw]
add x1, x1, x2, lsl #3
orr w9, w9, w10, lsl #8
orr w11, w11, w12, lsl #8
orr w13, w13, w14, lsl #8
orr w15, w15, w16, lsl #8
orr w9, w9, w11, lsl #16
orr w13, w13, w15, lsl #16
orr x9, x9, x13, lsl #32
str x9, [x5], #8
