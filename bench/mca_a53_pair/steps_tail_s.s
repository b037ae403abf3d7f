ldrb w2, [x26, w2, uxtw]
lsr x8, x16, #48
lsr w10, w14, #16
lsr x7, x15, #48
lsr w11, w15, #16
ldrb w4, [x26, w4, uxtw]
madd w7, w7, w28, w11
add x14, x16, x19
add x15, x13, x17
lsr w9, w13, #16
add x17, x17, x20
orr x21, x1, x2, lsl #8
madd w6, w6, w28, w10
add x19, x19, x20
orr x22, x3, x4, lsl #8
lsr x1, x13, #48
lsr x3, x15, #48
lsr w11, w15, #16
lsr w12, w16, #16
add x13, x15, x17
orr x15, x21, x22, lsl #16
madd w8, w8, w28, w12
ldrb w6, [x26, w6, uxtw]
madd w1, w1, w28, w9
ldrb w5, [x26, w5, uxtw]
madd w3, w3, w28, w11
str w15, [x27]
add x16, x14, x19
add x19, x19, x20
ldrb w7, [x26, w7, uxtw]
add x17, x17, x20
ldrb w8, [x26, w8, uxtw]
orr x21, x5, x6, lsl #8
add x15, x13, x17
lsr w10, w14, #16
lsr x2, x14, #48
add x14, x16, x19
madd w2, w2, w28, w10
add x17, x25, x24, lsl #1
add x19, x19, x20
lsr x4, x16, #48
orr x22, x7, x8, lsl #8
lsr x5, x13, #48
lsr x6, x14, #48
lsr w12, w16, #16
lsr w11, w15, #16
lsr w10, w14, #16
lsr w9, w13, #16
lsr x7, x15, #48
orr x15, x21, x22, lsl #16
add x16, x14, x19
ldrb w1, [x26, w1, uxtw]
add x14, x23, x24
madd w4, w4, w28, w12
madd w5, w5, w28, w9
str w15, [x27, #4]
ldrb w2, [x26, w2, uxtw]
madd w6, w6, w28, w10
ldrb w3, [x26, w3, uxtw]
madd w7, w7, w28, w11
ldrb w4, [x26, w4, uxtw]
add x19, x17, x25, lsl #1
lsl x20, x25, #2
orr x21, x1, x2, lsl #8
lsr x8, x16, #48
ldrb w5, [x26, w5, uxtw]
orr x22, x3, x4, lsl #8
ldrb w6, [x26, w6, uxtw]
add x15, x23, x17
add x17, x17, x20
lsr w12, w16, #16
lsr x3, x15, #48
lsr w11, w15, #16
lsr x2, x14, #48
lsr x1, x23, #48
lsr w9, w23, #16
add x23, x15, x17
orr x15, x21, x22, lsl #16
orr x21, x5, x6, lsl #8
add x16, x14, x19
lsr x5, x23, #48
madd w1, w1, w28, w9
ldrb w7, [x26, w7, uxtw]
madd w8, w8, w28, w12
add x17, x17, x20
str w15, [x27, #8]
add x19, x19, x20
add x15, x23, x17
lsr w9, w23, #16
add x17, x17, x20
madd w5, w5, w28, w9
ldr x24, [x30, #24]
madd w3, w3, w28, w11
ldrb w8, [x26, w8, uxtw]
add x23, x15, x17
add x17, x17, x20
lsr w11, w15, #16
lsr w10, w14, #16
ldrb w1, [x26, w1, uxtw]
madd w2, w2, w28, w10
orr x22, x7, x8, lsl #8
add x14, x16, x19
lsr x7, x15, #48
lsr w9, w23, #16
add x19, x19, x20
orr x15, x21, x22, lsl #16
lsr w12, w16, #16
lsr x4, x16, #48
madd w4, w4, w28, w12
ldrb w2, [x26, w2, uxtw]
str w15, [x27, #12]
madd w7, w7, w28, w11
add x16, x14, x19
ldr x25, [x30, #40]
add x19, x19, x20
ldrb w3, [x26, w3, uxtw]
add x15, x23, x17
ldrb w4, [x26, w4, uxtw]
add x17, x17, x20
orr x21, x1, x2, lsl #8
lsr x6, x14, #48
lsr x8, x16, #48
lsr w10, w14, #16
lsr w11, w15, #16
madd w6, w6, w28, w10
ldrb w5, [x26, w5, uxtw]
add x14, x16, x19
orr x22, x3, x4, lsl #8
lsr w12, w16, #16
lsr x2, x14, #48
lsr x1, x23, #48
add x23, x15, x17
lsr x3, x15, #48
madd w8, w8, w28, w12
orr x15, x21, x22, lsl #16
madd w3, w3, w28, w11
ldrb w7, [x26, w7, uxtw]
add x19, x19, x20
ldrb w6, [x26, w6, uxtw]
add x16, x14, x19
ldrb w8, [x26, w8, uxtw]
madd w1, w1, w28, w9
str w15, [x27, #16]
add x19, x19, x20
add x17, x17, x20
lsr w12, w16, #16
orr x21, x5, x6, lsl #8
lsr w10, w14, #16
lsr x4, x16, #48
lsr w9, w23, #16
add x14, x16, x19
lsr x5, x23, #48
madd w4, w4, w28, w12
madd w2, w2, w28, w10
ldrb w1, [x26, w1, uxtw]
add x19, x19, x20
ldrb w3, [x26, w3, uxtw]
orr x22, x7, x8, lsl #8
add x15, x23, x17
lsr w11, w15, #16
lsr x7, x15, #48
ldrb w2, [x26, w2, uxtw]
madd w5, w5, w28, w9
madd w7, w7, w28, w11
ldrb w4, [x26, w4, uxtw]
orr x15, x21, x22, lsl #16
lsr w10, w14, #16
add x16, x14, x19
lsr x6, x14, #48
lsr x8, x16, #48
lsr w12, w16, #16
madd w6, w6, w28, w10
madd w8, w8, w28, w12
str w15, [x27, #20]
orr x22, x3, x4, lsl #8
ldrb w5, [x26, w5, uxtw]
orr x21, x1, x2, lsl #8
ldrb w7, [x26, w7, uxtw]
orr x15, x21, x22, lsl #16
ldrb w6, [x26, w6, uxtw]
and x13, x24, #0xffffffff00000000
ldrb w8, [x26, w8, uxtw]
add x24, x13, w24, sxtw
and x13, x25, #0xffffffff00000000
ldr x9, [x30, #16]
add x25, x13, w25, sxtw
str w15, [x27, #24]
orr x22, x7, x8, lsl #8
ldr w1, [x18, #8]
orr x21, x5, x6, lsl #8
ldr x10, [x30, #32]
orr x15, x21, x22, lsl #16
ldr x13, [x30]
and x11, x9, #0xffffffff00000000
ldr x23, [x30, #8]
add x9, x11, w9, sxtw
cmp w1, #0xf
and x11, x10, #0xffffffff00000000
str w15, [x27, #28]
add x10, x11, w10, sxtw
b.eq .Ltgt
