ldp x4, x14, [x9], #16
and x1, x4, #0xff
ubfx x2, x4, #8, #8
ubfx x3, x4, #16, #8
ubfx x5, x4, #24, #8
ubfx x6, x4, #32, #8
ubfx x7, x4, #40, #8
ubfx x8, x4, #48, #8
lsr x4, x4, #56
and x10, x14, #0xff
ubfx x11, x14, #8, #8
ubfx x12, x14, #16, #8
ubfx x13, x14, #24, #8
ubfx x15, x14, #32, #8
ubfx x16, x14, #40, #8
ubfx x17, x14, #48, #8
lsr x14, x14, #56
ldr w1, [x27, x1, lsl #2]
ldr w2, [x27, x2, lsl #2]
ldr w3, [x27, x3, lsl #2]
ldr w5, [x27, x5, lsl #2]
ldr w6, [x27, x6, lsl #2]
ldr w7, [x27, x7, lsl #2]
ldr w8, [x27, x8, lsl #2]
ldr w4, [x27, x4, lsl #2]
ldr w10, [x27, x10, lsl #2]
ldr w11, [x27, x11, lsl #2]
ldr w12, [x27, x12, lsl #2]
ldr w13, [x27, x13, lsl #2]
ldr w15, [x27, x15, lsl #2]
ldr w16, [x27, x16, lsl #2]
ldr w17, [x27, x17, lsl #2]
ldr w14, [x27, x14, lsl #2]
orr x1, x1, x1, lsl #32
orr x2, x2, x2, lsl #32
orr x3, x3, x3, lsl #32
orr x5, x5, x5, lsl #32
orr x6, x6, x6, lsl #32
orr x7, x7, x7, lsl #32
orr x8, x8, x8, lsl #32
orr x4, x4, x4, lsl #32
orr x10, x10, x10, lsl #32
orr x11, x11, x11, lsl #32
orr x12, x12, x12, lsl #32
orr x13, x13, x13, lsl #32
orr x15, x15, x15, lsl #32
orr x16, x16, x16, lsl #32
orr x17, x17, x17, lsl #32
orr x14, x14, x14, lsl #32
stp x1, x2, [x0, #0]
stp x3, x5, [x0, #16]
stp x6, x7, [x0, #32]
stp x8, x4, [x0, #48]
stp x10, x11, [x0, #64]
stp x12, x13, [x0, #80]
stp x15, x16, [x0, #96]
stp x17, x14, [x0, #112]
add x0, x0, #128
stp x1, x2, [x20, #0]
stp x3, x5, [x20, #16]
stp x6, x7, [x20, #32]
stp x8, x4, [x20, #48]
stp x10, x11, [x20, #64]
stp x12, x13, [x20, #80]
stp x15, x16, [x20, #96]
stp x17, x14, [x20, #112]
add x20, x20, #128
cmp x18, x0
b.ne 1b
