ldp x2, x3, [x22, #16]
ldp x0, x1, [x22]
add x17, x20, x19, lsr #1
ldp x4, x5, [x22, #32]
ldp x6, x7, [x22, #48]
ldrb w11, [x23, w3, uxtw]
ldrb w10, [x23, w2, uxtw]
ldrb w12, [x23, w4, uxtw]
ldrb w13, [x23, w5, uxtw]
ldrb w15, [x23, w7, uxtw]
add x10, x10, x2, lsr #32
ldrb w9, [x23, w1, uxtw]
add x12, x12, x4, lsr #32
add x11, x11, x3, lsr #32
ldrb w14, [x23, w6, uxtw]
ldrb w8, [x23, w0, uxtw]
add x13, x13, x5, lsr #32
ldrb w12, [x24, x12]
add x15, x15, x7, lsr #32
ldrb w10, [x24, x10]
add x14, x14, x6, lsr #32
ldrb w11, [x24, x11]
add x9, x9, x1, lsr #32
ldrb w13, [x24, x13]
add x8, x8, x0, lsr #32
ldrb w15, [x24, x15]
ldrb w14, [x24, x14]
orr x10, x10, x11, lsl #8
ldrb w9, [x24, x9]
orr x12, x12, x13, lsl #8
ldrb w8, [x24, x8]
orr x14, x14, x15, lsl #8
ldr x16, [x17]
orr x8, x8, x9, lsl #8
orr x12, x12, x14, lsl #16
orr x8, x8, x10, lsl #16
orr x8, x8, x12, lsl #32
eor x8, x8, x16
and x8, x8, x26
eor x8, x8, x16
str x8, [x17]
