shl v26.8h, v26.8h, #8
shl v27.8h, v27.8h, #8
ldr x28, [x14, #-32]
add x13, x11, #32
ldr x26, [x14, #-24]
ldr x16, [x14, #-16]
ldr x15, [x14, #-8]
st1 {v26.8h, v27.8h}, [x13], #32
and w20, w28, #0xffff
and w5, w26, #0xffff
lsr w25, w28, #16
ubfx x1, x28, #32, #16
lsr x23, x28, #48
lsr w4, w26, #16
ldr x17, [x13, #-32]
ldrb w20, [x6, x20]
ldrb w25, [x6, x25]
ldrb w1, [x6, x1]
ldrb w23, [x6, x23]
ldr x21, [x13, #-24]
ldrb w5, [x6, x5]
ldrb w4, [x6, x4]
add w20, w20, w17, uxth
add w25, w25, w17, lsr #16
ubfx x0, x26, #32, #16
lsr x27, x26, #48
ubfx x24, x17, #32, #16
add x23, x23, x17, lsr #48
ldrb w0, [x6, x0]
ldrb w27, [x6, x27]
add w1, w1, w24
ldrb w20, [x7, x20]
ldrb w25, [x7, x25]
ldrb w23, [x7, x23]
ldrb w1, [x7, x1]
add w5, w5, w21, uxth
add w4, w4, w21, lsr #16
ubfx x22, x21, #32, #16
add x27, x27, x21, lsr #48
orr x20, x20, x25, lsl #8
and w28, w16, #0xffff
add w0, w0, w22
ldrb w5, [x7, x5]
ldrb w4, [x7, x4]
ldrb w27, [x7, x27]
ldrb w0, [x7, x0]
orr x1, x1, x23, lsl #8
and w22, w15, #0xffff
ldr x19, [x13, #-16]
ldr x12, [x13, #-8]
orr x5, x5, x4, lsl #8
orr x0, x0, x27, lsl #8
lsr w26, w16, #16
ubfx x24, x16, #32, #16
lsr x17, x16, #48
lsr w21, w15, #16
ubfx x25, x15, #32, #16
lsr x23, x15, #48
ldrb w28, [x6, x28]
ldrb w26, [x6, x26]
ldrb w24, [x6, x24]
ldrb w17, [x6, x17]
ldrb w22, [x6, x22]
ldrb w21, [x6, x21]
ldrb w25, [x6, x25]
ldrb w23, [x6, x23]
add w28, w28, w19, uxth
add w26, w26, w19, lsr #16
ubfx x4, x19, #32, #16
ubfx x27, x12, #32, #16
add x17, x17, x19, lsr #48
add w22, w22, w12, uxth
add w24, w24, w4
add w21, w21, w12, lsr #16
add w25, w25, w27
add x23, x23, x12, lsr #48
ldrb w28, [x7, x28]
ldrb w26, [x7, x26]
ldrb w24, [x7, x24]
ldrb w17, [x7, x17]
ldrb w22, [x7, x22]
ldrb w21, [x7, x21]
ldrb w25, [x7, x25]
ldrb w23, [x7, x23]
orr x28, x28, x26, lsl #8
orr x24, x24, x17, lsl #8
orr x22, x22, x21, lsl #8
orr x20, x20, x1, lsl #16
orr x5, x5, x0, lsl #16
orr x25, x25, x23, lsl #8
orr x28, x28, x24, lsl #16
orr x20, x20, x5, lsl #32
orr x22, x22, x25, lsl #16
orr x28, x28, x22, lsl #32
stp x20, x28, [x10]
