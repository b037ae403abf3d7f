// Split design, phase B (core only): indices loaded from the buffer (ldr x), cm + lane
// addresses as in inorder_loop.s, lane loads, stores; order from order_search.py (54 cycles).
stp d4, d5, [x13]
stp d6, d7, [x8]
ldr x0, [x9, #0]
ldr x4, [x9, #32]
ldr x6, [x9, #48]
add x13, x13, x14, lsl #1
ldr x5, [x9, #40]
add x10, x28, w0, uxth
ldr x1, [x9, #8]
ldr x2, [x9, #16]
add x12, x28, w4, uxth
add x18, x28, w6, uxth
and x23, x26, x0, lsr #16
ldr x7, [x9, #56]
add x19, x28, w1, uxth
and x16, x26, x6, lsr #16
add x11, x28, w2, uxth
ldr x3, [x9, #24]
add x23, x28, x23
ld1 {v4.b}[0], [x10]
add x22, x28, w7, uxth
ld1 {v7.b}[0], [x18]
ld1 {v5.b}[0], [x11]
add x20, x28, w3, uxth
ld1 {v6.b}[0], [x12]
and x24, x26, x2, lsr #16
add x21, x28, w5, uxth
and x11, x26, x3, lsr #16
add x24, x28, x24
and x25, x26, x4, lsr #16
ld1 {v4.b}[4], [x19]
add x25, x28, x25
ld1 {v5.b}[4], [x20]
add x11, x28, x11
ld1 {v6.b}[4], [x21]
and x10, x26, x1, lsr #16
and x19, x26, x0, lsr #32
and x20, x26, x2, lsr #32
ld1 {v4.b}[1], [x23]
and x12, x26, x5, lsr #16
ld1 {v7.b}[4], [x22]
and x18, x26, x7, lsr #16
add x16, x28, x16
add x10, x28, x10
ld1 {v5.b}[1], [x24]
add x19, x28, x19
add x18, x28, x18
add x12, x28, x12
ld1 {v6.b}[1], [x25]
and x21, x26, x4, lsr #32
ld1 {v7.b}[1], [x16]
add x21, x28, x21
add x20, x28, x20
and x24, x26, x3, lsr #32
ld1 {v4.b}[5], [x10]
and x22, x26, x6, lsr #32
ld1 {v5.b}[5], [x11]
and x23, x26, x1, lsr #32
add x11, x28, x2, lsr #48
add x22, x28, x22
ld1 {v6.b}[5], [x12]
add x24, x28, x24
and x16, x26, x7, lsr #32
and x25, x26, x5, lsr #32
ld1 {v7.b}[5], [x18]
add x25, x28, x25
ld1 {v4.b}[2], [x19]
add x23, x28, x23
ld1 {v5.b}[2], [x20]
add x16, x28, x16
ld1 {v6.b}[2], [x21]
add x10, x28, x0, lsr #48
ld1 {v7.b}[2], [x22]
add x21, x28, x5, lsr #48
ld1 {v4.b}[6], [x23]
add x19, x28, x1, lsr #48
ld1 {v5.b}[6], [x24]
subs x17, x17, #1
ld1 {v6.b}[6], [x25]
add x12, x28, x4, lsr #48
ld1 {v7.b}[6], [x16]
add x18, x28, x6, lsr #48
ld1 {v4.b}[3], [x10]
add x22, x28, x7, lsr #48
ld1 {v5.b}[3], [x11]
add x20, x28, x3, lsr #48
ld1 {v6.b}[3], [x12]
ld1 {v7.b}[3], [x18]
add x9, x9, #64
ld1 {v4.b}[7], [x19]
ld1 {v5.b}[7], [x20]
ld1 {v6.b}[7], [x21]
add x8, x13, x14
ld1 {v7.b}[7], [x22]
b.ne 0
