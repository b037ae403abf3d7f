// All-scalar mip-0 row (16 texels): two lights a register (lanes at bits 0 and 40), lsr + bfxil
// for each index, ldrb, orr; packing of the second half left out (a lower bound on its cost).
ldp x0, x1, [x15], #16
lsr x9, x2, #8
lsr x10, x2, #48
add x2, x2, x3
bfxil x9, x0, #0, #8
bfxil x10, x0, #8, #8
lsr x11, x2, #8
lsr x12, x2, #48
ldrb w9, [x28, w9, uxtw]
add x2, x2, x3
bfxil x11, x0, #16, #8
ldrb w10, [x28, x10]
bfxil x12, x0, #24, #8
lsr x18, x2, #8
lsr x19, x2, #48
ldrb w11, [x28, w11, uxtw]
add x2, x2, x3
bfxil x18, x0, #32, #8
ldrb w12, [x28, x12]
bfxil x19, x0, #40, #8
orr x9, x9, x10, lsl #8
lsr x20, x2, #8
lsr x21, x2, #48
ldrb w18, [x28, w18, uxtw]
add x2, x2, x3
bfxil x20, x0, #48, #8
ldrb w19, [x28, x19]
bfxil x21, x0, #56, #8
orr x11, x11, x12, lsl #8
lsr x9, x2, #8
lsr x10, x2, #48
ldrb w20, [x28, w20, uxtw]
add x2, x2, x3
bfxil x9, x1, #0, #8
ldrb w21, [x28, x21]
bfxil x10, x1, #8, #8
orr x18, x18, x19, lsl #8
lsr x11, x2, #8
lsr x12, x2, #48
ldrb w9, [x28, w9, uxtw]
add x2, x2, x3
bfxil x11, x1, #16, #8
ldrb w10, [x28, x10]
bfxil x12, x1, #24, #8
orr x20, x20, x21, lsl #8
lsr x18, x2, #8
lsr x19, x2, #48
ldrb w11, [x28, w11, uxtw]
add x2, x2, x3
bfxil x18, x1, #32, #8
ldrb w12, [x28, x12]
bfxil x19, x1, #40, #8
orr x9, x9, x10, lsl #8
lsr x20, x2, #8
lsr x21, x2, #48
ldrb w18, [x28, w18, uxtw]
add x2, x2, x3
bfxil x20, x1, #48, #8
ldrb w19, [x28, x19]
bfxil x21, x1, #56, #8
orr x11, x11, x12, lsl #8
ldrb w20, [x28, w20, uxtw]
ldrb w21, [x28, x21]
orr x18, x18, x19, lsl #8
orr x20, x20, x21, lsl #8
orr x9, x9, x11, lsl #16
orr x18, x18, x20, lsl #16
orr x9, x9, x18, lsl #32
str x9, [x13]
add x2, x2, x4
add x3, x3, x5
add x13, x13, x14
subs x17, x17, #1
