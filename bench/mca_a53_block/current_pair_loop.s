// The hot mips 0-1 pair loop of surface_block neon (aarch64) as built at 6da5ed0 (block 403600
// of build/count-aarch64): two rows of 16 texels an iteration.
stp x19, x23, [x14]
add x14, x14, x17
add v28.4s, v23.4s, v18.4s
ushr v2.4s, v23.4s, #8
add v26.4s, v21.4s, v16.4s
add v27.4s, v22.4s, v17.4s
add v24.4s, v19.4s, v29.4s
tbl v0.16b, {v20.16b, v21.16b}, v14.16b
ushr v6.4s, v28.4s, #8
tbl v1.16b, {v20.16b-v22.16b}, v31.16b
tbx v2.16b, {v20.16b}, v11.16b
tbl v3.16b, {v19.16b, v20.16b}, v12.16b
tbl v4.16b, {v25.16b, v26.16b}, v14.16b
tbl v5.16b, {v25.16b-v27.16b}, v31.16b
tbx v6.16b, {v25.16b}, v11.16b
tbl v7.16b, {v24.16b, v25.16b}, v12.16b
fmov x0, d0
fmov x1, v0.d[1]
fmov x2, d1
fmov x3, v1.d[1]
fmov x4, d2
fmov x5, v2.d[1]
fmov x6, d3
fmov x7, v3.d[1]
add v21.4s, v26.4s, v16.4s
add v22.4s, v27.4s, v17.4s
add v23.4s, v28.4s, v18.4s
add v19.4s, v24.4s, v29.4s
fmov x19, d4
fmov x20, v4.d[1]
fmov x21, d5
fmov x22, v5.d[1]
fmov x23, d6
fmov x24, v6.d[1]
fmov x25, d7
fmov x26, v7.d[1]
add x11, x28, x2, lsr #32
ldrb w2, [x28, w2, uxtw]
add x9, x28, x0, lsr #32
ldrb w0, [x28, w0, uxtw]
add x10, x28, x1, lsr #32
ldrb w1, [x28, w1, uxtw]
add x12, x28, x3, lsr #32
ldrb w11, [x11]
add x18, x28, x4, lsr #32
ldrb w9, [x9]
subs x13, x13, #0x1
ldrb w10, [x10]
ldrb w4, [x28, w4, uxtw]
orr x2, x2, x11, lsl #8
ldrb w12, [x12]
add x11, x28, x7, lsr #32
ldrb w7, [x28, w7, uxtw]
orr x1, x1, x10, lsl #8
ldrb w3, [x28, w3, uxtw]
orr x0, x0, x9, lsl #8
ldrb w18, [x18]
add x10, x28, x6, lsr #32
ldrb w11, [x11]
add x9, x28, x5, lsr #32
ldrb w6, [x28, w6, uxtw]
orr x3, x3, x12, lsl #8
ldrb w5, [x28, w5, uxtw]
add x12, x28, x22, lsr #32
ldrb w10, [x10]
orr x4, x4, x18, lsl #8
ldrb w9, [x9]
orr x7, x7, x11, lsl #8
ldr x8, [x15]
add x11, x28, x21, lsr #32
ldrb w21, [x28, w21, uxtw]
orr x6, x6, x10, lsl #8
ldrb w12, [x12]
add x10, x28, x20, lsr #32
ldrb w20, [x28, w20, uxtw]
orr x5, x5, x9, lsl #8
ldrb w11, [x11]
add x9, x28, x19, lsr #32
ldrb w19, [x28, w19, uxtw]
add x18, x28, x23, lsr #32
ldrb w10, [x10]
orr x0, x0, x1, lsl #16
ldrb w22, [x28, w22, uxtw]
orr x21, x21, x11, lsl #8
ldrb w9, [x9]
add x11, x28, x26, lsr #32
ldrb w18, [x18]
orr x20, x20, x10, lsl #8
ldrb w26, [x28, w26, uxtw]
add x10, x28, x25, lsr #32
ldrb w25, [x28, w25, uxtw]
orr x19, x19, x9, lsl #8
ldr q20, [x8, x16]
add x9, x28, x24, lsr #32
ldrb w23, [x28, w23, uxtw]
orr x2, x2, x3, lsl #16
ldrb w24, [x28, w24, uxtw]
orr x4, x4, x5, lsl #16
ldrb w10, [x10]
orr x6, x6, x7, lsl #16
ldrb w9, [x9]
orr x0, x0, x2, lsl #32
ldrb w11, [x11]
orr x19, x19, x20, lsl #16
ldr x8, [x15, #8]
orr x25, x25, x10, lsl #8
orr x23, x23, x18, lsl #8
orr x24, x24, x9, lsl #8
orr x22, x22, x12, lsl #8
orr x4, x4, x6, lsl #32
orr x26, x26, x11, lsl #8
add x15, x15, #0x10
ldr q25, [x8, x16]
orr x21, x21, x22, lsl #16
orr x23, x23, x24, lsl #16
orr x25, x25, x26, lsl #16
stp x0, x4, [x14]
add x14, x14, x17
orr x19, x19, x21, lsl #32
orr x23, x23, x25, lsl #32
b.ne .Ltgt
