add x14, x13, x9
add x17, x10, x9, lsl #1
lsr w9, w13, #16
lsl x20, x10, #2
add x19, x17, x10, lsl #1
add x15, x13, x17
lsr w11, w15, #16
lsr x3, x15, #48
add x16, x14, x19
add x17, x17, x20
lsr x4, x16, #48
lsr w10, w14, #16
lsr w12, w16, #16
lsr x1, x13, #48
lsr x2, x14, #48
add x13, x15, x17
lsr x5, x13, #48
madd w2, w2, w0, w10
add x17, x17, x20
add x19, x19, x20
add x14, x16, x19
madd w4, w4, w0, w12
add x19, x19, x20
madd w3, w3, w0, w11
add x16, x14, x19
madd w1, w1, w0, w9
add x15, x13, x17
add x17, x17, x20
lsr x6, x14, #48
lsr w9, w13, #16
add x19, x19, x20
add x13, x15, x17
lsr w10, w14, #16
lsr w11, w15, #16
lsr w12, w16, #16
lsr x7, x15, #48
madd w7, w7, w0, w11
ldrb w4, [x18, w4, uxtw]
add x14, x16, x19
add x19, x19, x20
lsr x8, x16, #48
add x17, x17, x20
ldrb w1, [x18, w1, uxtw]
madd w8, w8, w0, w12
ldrb w2, [x18, w2, uxtw]
madd w5, w5, w0, w9
ldrb w3, [x18, w3, uxtw]
madd w6, w6, w0, w10
add x15, x13, x17
lsr w10, w14, #16
ldrb w7, [x18, w7, uxtw]
orr x21, x1, x2, lsl #8
add x16, x14, x19
lsr w11, w15, #16
lsr w9, w13, #16
lsr x1, x13, #48
add x19, x19, x20
lsr w12, w16, #16
orr x22, x3, x4, lsl #8
lsr x2, x14, #48
lsr x4, x16, #48
add x14, x16, x19
add x17, x17, x20
lsr x3, x15, #48
add x19, x19, x20
madd w2, w2, w0, w10
ldrb w6, [x18, w6, uxtw]
madd w1, w1, w0, w9
ldrb w5, [x18, w5, uxtw]
add x16, x14, x19
add x13, x15, x17
orr x15, x21, x22, lsl #16
add x17, x17, x20
lsr w9, w13, #16
ldrb w8, [x18, w8, uxtw]
madd w3, w3, w0, w11
ldrb w1, [x18, w1, uxtw]
orr x21, x5, x6, lsl #8
ldrb w2, [x18, w2, uxtw]
str w15, [x26]
madd w4, w4, w0, w12
orr x22, x7, x8, lsl #8
add x15, x13, x17
lsr x8, x16, #48
lsr w11, w15, #16
lsr w12, w16, #16
lsr x5, x13, #48
lsr x6, x14, #48
lsr x7, x15, #48
lsr w10, w14, #16
orr x15, x21, x22, lsl #16
madd w6, w6, w0, w10
ldrb w4, [x18, w4, uxtw]
madd w8, w8, w0, w12
ldrb w3, [x18, w3, uxtw]
add x14, x23, x24
add x17, x25, x24, lsl #1
lsl x20, x25, #2
orr x21, x1, x2, lsl #8
str w15, [x26, #4]
madd w5, w5, w0, w9
orr x22, x3, x4, lsl #8
add x15, x23, x17
lsr w10, w14, #16
add x19, x17, x25, lsl #1
add x17, x17, x20
add x16, x14, x19
lsr w9, w23, #16
lsr x2, x14, #48
lsr x1, x23, #48
ldrb w6, [x18, w6, uxtw]
madd w7, w7, w0, w11
ldrb w8, [x18, w8, uxtw]
add x23, x15, x17
add x19, x19, x20
lsr x3, x15, #48
lsr w11, w15, #16
lsr x4, x16, #48
madd w1, w1, w0, w9
add x14, x16, x19
add x19, x19, x20
lsr w12, w16, #16
orr x15, x21, x22, lsl #16
madd w3, w3, w0, w11
ldrb w7, [x18, w7, uxtw]
madd w4, w4, w0, w12
ldrb w5, [x18, w5, uxtw]
add x17, x17, x20
ldrb w1, [x18, w1, uxtw]
madd w2, w2, w0, w10
str w15, [x26, #8]
add x16, x14, x19
orr x22, x7, x8, lsl #8
add x15, x23, x17
orr x21, x5, x6, lsl #8
lsr x7, x15, #48
lsr w10, w14, #16
lsr x5, x23, #48
lsr w11, w15, #16
lsr w12, w16, #16
lsr x6, x14, #48
lsr w9, w23, #16
add x19, x19, x20
lsr x8, x16, #48
ldrb w4, [x18, w4, uxtw]
add x17, x17, x20
madd w5, w5, w0, w9
ldrb w2, [x18, w2, uxtw]
madd w6, w6, w0, w10
add x14, x16, x19
add x19, x19, x20
add x23, x15, x17
ldrb w3, [x18, w3, uxtw]
orr x15, x21, x22, lsl #16
add x17, x17, x20
lsr w10, w14, #16
madd w8, w8, w0, w12
add x16, x14, x19
orr x21, x1, x2, lsl #8
lsr x2, x14, #48
str w15, [x26, #12]
add x15, x23, x17
orr x22, x3, x4, lsl #8
lsr x1, x23, #48
lsr x3, x15, #48
ldrb w6, [x18, w6, uxtw]
madd w7, w7, w0, w11
add x17, x17, x20
add x19, x19, x20
lsr w9, w23, #16
lsr x4, x16, #48
lsr w12, w16, #16
madd w4, w4, w0, w12
ldrb w8, [x18, w8, uxtw]
madd w1, w1, w0, w9
add x23, x15, x17
ldrb w7, [x18, w7, uxtw]
add x17, x17, x20
ldrb w5, [x18, w5, uxtw]
lsr w11, w15, #16
ldrb w1, [x18, w1, uxtw]
madd w2, w2, w0, w10
add x14, x16, x19
orr x15, x21, x22, lsl #16
lsr w9, w23, #16
lsr w10, w14, #16
orr x21, x5, x6, lsl #8
add x19, x19, x20
madd w3, w3, w0, w11
str w15, [x26, #16]
add x16, x14, x19
orr x22, x7, x8, lsl #8
lsr x5, x23, #48
add x15, x23, x17
lsr x6, x14, #48
lsr x7, x15, #48
lsr x8, x16, #48
lsr w11, w15, #16
madd w5, w5, w0, w9
ldrb w4, [x18, w4, uxtw]
madd w6, w6, w0, w10
ldrb w2, [x18, w2, uxtw]
madd w7, w7, w0, w11
ldrb w3, [x18, w3, uxtw]
lsr w12, w16, #16
ldr x13, [sp, #0]
madd w8, w8, w0, w12
ldr w25, [sp, #12]
orr x15, x21, x22, lsl #16
ldrb w5, [x18, w5, uxtw]
orr x22, x3, x4, lsl #8
ldrb w6, [x18, w6, uxtw]
orr x21, x1, x2, lsl #8
ldrb w7, [x18, w7, uxtw]
str w15, [x26, #20]
ldrb w8, [x18, w8, uxtw]
orr x15, x21, x22, lsl #16
ldrsw x24, [sp, #8]
ldr w17, [sp, #20]
ldrsw x20, [sp, #16]
orr x22, x7, x8, lsl #8
str w15, [x26, #24]
add x19, x24, x25, lsl #32
orr x21, x5, x6, lsl #8
lsr x12, x13, #48
add x16, x26, #32
add x14, x13, x19
add x23, x20, x17, lsl #32
lsr w1, w13, #16
strh w21, [x26, #28]
madd w2, w12, w0, w1
add x9, x23, x19, lsl #1
lsr w4, w14, #16
lsr x3, x14, #48
madd w5, w3, w0, w4
strh w22, [x26, #30]
add x11, x9, x23, lsl #1
lsl x10, x23, #2
tbz w27, #3, .+4
