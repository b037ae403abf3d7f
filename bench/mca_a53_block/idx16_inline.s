// 16-bit indices as idx16_bound.s, NEON run first and the packing drained inside the iteration.
add v27.4s, v22.4s, v16.4s
add v28.4s, v23.4s, v17.4s
add v24.4s, v19.4s, v18.4s
add v25.4s, v20.4s, v29.4s
tbl v0.16b, {v21.16b, v22.16b, v23.16b}, v30.16b
tbl v1.16b, {v19.16b, v20.16b, v21.16b}, v31.16b
tbl v2.16b, {v26.16b, v27.16b, v28.16b}, v30.16b
tbl v3.16b, {v24.16b, v25.16b, v26.16b}, v31.16b
fmov x0, d0
fmov x1, v0.d[1]
fmov x2, d1
fmov x3, v1.d[1]
fmov x4, d2
fmov x5, v2.d[1]
fmov x6, d3
fmov x7, v3.d[1]
add v22.4s, v27.4s, v16.4s
add v23.4s, v28.4s, v17.4s
add v19.4s, v24.4s, v18.4s
add v20.4s, v25.4s, v29.4s
and x9, x30, x0
and x10, x30, x0, lsr #16
and x11, x30, x0, lsr #32
add x0, x28, x0, lsr #48
and x12, x30, x1
and x18, x30, x1, lsr #16
and x19, x30, x1, lsr #32
add x1, x28, x1, lsr #48
and x20, x30, x2
ldrb w9, [x28, x9]
and x21, x30, x2, lsr #16
ldrb w10, [x28, x10]
and x22, x30, x2, lsr #32
ldrb w11, [x28, x11]
add x2, x28, x2, lsr #48
ldrb w0, [x0]
and x23, x30, x3
ldrb w12, [x28, x12]
and x24, x30, x3, lsr #16
ldrb w18, [x28, x18]
and x25, x30, x3, lsr #32
ldrb w19, [x28, x19]
add x3, x28, x3, lsr #48
ldrb w1, [x1]
and x9, x30, x4
ldrb w20, [x28, x20]
and x10, x30, x4, lsr #16
ldrb w21, [x28, x21]
and x11, x30, x4, lsr #32
ldrb w22, [x28, x22]
add x4, x28, x4, lsr #48
ldrb w2, [x2]
orr x9, x9, x10, lsl #8
orr x11, x11, x0, lsl #8
and x12, x30, x5
ldrb w23, [x28, x23]
and x18, x30, x5, lsr #16
ldrb w24, [x28, x24]
and x19, x30, x5, lsr #32
ldrb w25, [x28, x25]
add x5, x28, x5, lsr #48
ldrb w3, [x3]
orr x12, x12, x18, lsl #8
orr x19, x19, x1, lsl #8
orr x0, x9, x11, lsl #16
and x20, x30, x6
ldrb w9, [x28, x9]
and x21, x30, x6, lsr #16
ldrb w10, [x28, x10]
and x22, x30, x6, lsr #32
ldrb w11, [x28, x11]
add x6, x28, x6, lsr #48
ldrb w4, [x4]
orr x20, x20, x21, lsl #8
orr x22, x22, x2, lsl #8
orr x1, x12, x19, lsl #16
orr x0, x0, x1, lsl #32
add x15, x15, #16
and x23, x30, x7
ldrb w12, [x28, x12]
and x24, x30, x7, lsr #16
ldrb w18, [x28, x18]
and x25, x30, x7, lsr #32
ldrb w19, [x28, x19]
add x7, x28, x7, lsr #48
ldrb w5, [x5]
orr x23, x23, x24, lsl #8
orr x25, x25, x3, lsl #8
orr x2, x20, x22, lsl #16
orr x9, x9, x10, lsl #8
ldrb w20, [x28, x20]
orr x11, x11, x4, lsl #8
ldrb w21, [x28, x21]
orr x3, x23, x25, lsl #16
ldrb w22, [x28, x22]
orr x2, x2, x3, lsl #32
ldrb w6, [x6]
add x13, x13, x14
stp x0, x2, [x13]
subs x17, x17, #1
orr x12, x12, x18, lsl #8
ldrb w23, [x28, x23]
orr x19, x19, x5, lsl #8
ldrb w24, [x28, x24]
orr x4, x9, x11, lsl #16
ldrb w25, [x28, x25]
ldrb w7, [x7]
orr x20, x20, x21, lsl #8
ldr x8, [x15]
orr x22, x22, x6, lsl #8
orr x5, x12, x19, lsl #16
orr x4, x4, x5, lsl #32
orr x23, x23, x24, lsl #8
ldr q21, [x8, x16]
orr x25, x25, x7, lsl #8
ldr x8, [x15, #8]
orr x6, x20, x22, lsl #16
orr x7, x23, x25, lsl #16
ldr q26, [x8, x16]
orr x6, x6, x7, lsl #32
stp x4, x6, [x13]
add x13, x13, x14
