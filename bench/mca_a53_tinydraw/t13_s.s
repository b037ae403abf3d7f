add x8, x2, x1, lsl #1
add x6, x0, x1
lsr w10, w0, #16
add x9, x8, x2, lsl #1
lsr w11, w6, #16
lsr x20, x6, #48
add x6, x6, x9
add x7, x0, x8
lsr x19, x0, #48
add x8, x8, x2, lsl #2
lsr w13, w6, #16
lsr x21, x7, #48
lsr w12, w7, #16
lsr x22, x6, #48
add x9, x9, x2, lsl #2
madd w11, w20, w4, w11
add x6, x6, x9
madd w10, w19, w4, w10
add x9, x9, x2, lsl #2
add x7, x7, x8
lsr x20, x6, #48
add x8, x8, x2, lsl #2
lsr w15, w6, #16
lsr x19, x7, #48
lsr w14, w7, #16
ldrb w10, [x3, w10, uxtw]
add x6, x6, x9
madd w13, w22, w4, w13
add x7, x7, x8
madd w12, w21, w4, w12
ldrb w11, [x3, w11, uxtw]
madd w14, w19, w4, w14
lsr w17, w6, #16
lsr w16, w7, #16
lsr x22, x6, #48
lsr x21, x7, #48
ldrb w14, [x3, w14, uxtw]
madd w15, w20, w4, w15
ldrb w12, [x3, w12, uxtw]
madd w16, w21, w4, w16
ldrb w13, [x3, w13, uxtw]
madd w17, w22, w4, w17
orr w10, w10, w11, lsl #8
add x9, x9, x2, lsl #2
add x8, x8, x2, lsl #2
ldrb w15, [x3, w15, uxtw]
ldrb w16, [x3, w16, uxtw]
orr w12, w12, w13, lsl #8
ldrb w17, [x3, w17, uxtw]
add x6, x6, x9
lsr w11, w6, #16
orr w14, w14, w15, lsl #8
lsr x20, x6, #48
add x9, x9, x2, lsl #2
orr w16, w16, w17, lsl #8
add x6, x6, x9
add x7, x7, x8
madd w11, w20, w4, w11
add x8, x8, x2, lsl #2
orr w14, w14, w16, lsl #16
lsr x19, x7, #48
orr w10, w10, w12, lsl #16
lsr w13, w6, #16
orr x10, x10, x14, lsl #32
lsr x22, x6, #48
madd w13, w22, w4, w13
ldrb w11, [x3, w11, uxtw]
str x10, [x5]
lsr w10, w7, #16
add x7, x7, x8
lsr x21, x7, #48
lsr w12, w7, #16
add x8, x8, x2, lsl #2
madd w12, w21, w4, w12
ldrb w13, [x3, w13, uxtw]
madd w10, w19, w4, w10
add x7, x7, x8
lsr x19, x7, #48
lsr w14, w7, #16
ldrb w12, [x3, w12, uxtw]
madd w14, w19, w4, w14
ldrb w10, [x3, w10, uxtw]
orr w12, w12, w13, lsl #8
orr w10, w10, w11, lsl #8
orr w10, w10, w12, lsl #16
ldrb w14, [x3, w14, uxtw]
str w10, [x5, #8]
strb w14, [x5, #12]
