ldr x17, [x9], #8
ubfx x3, x17, #16, #8
and x1, x17, #0xff
ubfx x2, x17, #8, #8
ubfx x4, x17, #24, #8
ubfx x6, x17, #40, #8
ldr w3, [x27, x3, lsl #2]
ubfx x7, x17, #48, #8
ubfx x5, x17, #32, #8
lsr x17, x17, #56
ldr w1, [x27, x1, lsl #2]
ldr w2, [x27, x2, lsl #2]
ldr w4, [x27, x4, lsl #2]
ldr w5, [x27, x5, lsl #2]
ldr w17, [x27, x17, lsl #2]
ldr w6, [x27, x6, lsl #2]
orr x10, x3, x4, lsl #32
ldr w7, [x27, x7, lsl #2]
orr x8, x1, x2, lsl #32
orr x1, x1, x1, lsl #32
orr x3, x3, x3, lsl #32
orr x2, x2, x2, lsl #32
orr x11, x5, x6, lsl #32
orr x4, x4, x4, lsl #32
orr x12, x7, x17, lsl #32
orr x5, x5, x5, lsl #32
orr x6, x6, x6, lsl #32
stp x1, x8, [x0, #0]
orr x7, x7, x7, lsl #32
stp x2, x3, [x0, #16]
orr x17, x17, x17, lsl #32
stp x10, x4, [x0, #32]
stp x5, x11, [x0, #48]
stp x6, x7, [x0, #64]
stp x12, x17, [x0, #80]
add x0, x0, #96
stp x1, x8, [x20, #0]
stp x2, x3, [x20, #16]
stp x10, x4, [x20, #32]
stp x5, x11, [x20, #48]
stp x6, x7, [x20, #64]
stp x12, x17, [x20, #80]
stp x1, x8, [x21, #0]
stp x2, x3, [x21, #16]
stp x10, x4, [x21, #32]
stp x5, x11, [x21, #48]
cmp x18, x0
stp x6, x7, [x21, #64]
add x20, x20, #96
stp x12, x17, [x21, #80]
add x21, x21, #96
b.ne 1b
