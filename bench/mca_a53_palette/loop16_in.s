ldp x4, x14, [x9], #16
and x6, x4, #0xff
ubfx x5, x4, #8, #8
ubfx x11, x4, #16, #8
ubfx x8, x4, #24, #8
ubfx x7, x4, #32, #8
ubfx x12, x4, #40, #8
ubfx x13, x4, #48, #8
lsr x4, x4, #56
and x16, x14, #0xff
ubfx x15, x14, #8, #8
ubfx x17, x14, #16, #8
ubfx x1, x14, #24, #8
ubfx x2, x14, #32, #8
ubfx x3, x14, #40, #8
ubfx x10, x14, #48, #8
lsr x14, x14, #56
ldr w6, [x27, x6, lsl #2]
ldr w5, [x27, x5, lsl #2]
ldr w11, [x27, x11, lsl #2]
ldr w8, [x27, x8, lsl #2]
ldr w7, [x27, x7, lsl #2]
ldr w12, [x27, x12, lsl #2]
ldr w13, [x27, x13, lsl #2]
ldr w4, [x27, x4, lsl #2]
ldr w16, [x27, x16, lsl #2]
ldr w15, [x27, x15, lsl #2]
ldr w17, [x27, x17, lsl #2]
ldr w1, [x27, x1, lsl #2]
ldr w2, [x27, x2, lsl #2]
ldr w3, [x27, x3, lsl #2]
ldr w10, [x27, x10, lsl #2]
ldr w14, [x27, x14, lsl #2]
add x0, x0, #0x40
stp w6, w5, [x0, #-64]
stp w11, w8, [x0, #-56]
stp w7, w12, [x0, #-48]
stp w13, w4, [x0, #-40]
stp w16, w15, [x0, #-32]
stp w17, w1, [x0, #-24]
stp w2, w3, [x0, #-16]
stp w10, w14, [x0, #-8]
cmp x18, x0
b.ne .+4
