// The neon_a53 mips 0-1 loop (asm/neon_block_a53.h SB_PAIR_LOOP_16, operands as registers, the loop
// branch and labels left out): 16-bit indices, addresses cm + lane, ld1 lane loads into v4-v7.
stp d4, d5, [x13]
tbl v0.16b, {v21.16b, v22.16b, v23.16b}, v30.16b
add v27.4s, v22.4s, v16.4s
add v25.4s, v20.4s, v29.4s
add v28.4s, v23.4s, v17.4s
add v24.4s, v19.4s, v18.4s
tbl v1.16b, {v19.16b, v20.16b, v21.16b}, v31.16b
fmov x1, v0.d[1]
fmov x0, d0
add v20.4s, v25.4s, v29.4s
tbl v2.16b, {v26.16b, v27.16b, v28.16b}, v30.16b
add v19.4s, v24.4s, v18.4s
add v23.4s, v28.4s, v17.4s
tbl v3.16b, {v24.16b, v25.16b, v26.16b}, v31.16b
add v22.4s, v27.4s, v16.4s
fmov x3, v1.d[1]
fmov x4, d2
fmov x2, d1
fmov x5, v2.d[1]
fmov x6, d3
fmov x7, v3.d[1]
stp d6, d7, [x8]
add x19, x28, w2, uxth
add x20, x28, w4, uxth
and x22, x26, x0, lsr #32
and x24, x26, x4, lsr #32
and x9, x26, x0, lsr #16
add x18, x28, w0, uxth
and x23, x26, x2, lsr #32
ldr x8, [x15]
add x21, x28, w6, uxth
and x12, x26, x6, lsr #16
add x9, x28, x9
ld1 {v6.b}[0], [x20]
and x10, x26, x2, lsr #16
ld1 {v5.b}[0], [x19]
add x23, x28, x23
and x25, x26, x6, lsr #32
and x11, x26, x4, lsr #16
ld1 {v4.b}[0], [x18]
add x24, x28, x24
add x4, x28, x4, lsr #48
add x10, x28, x10
ld1 {v7.b}[0], [x21]
add x11, x28, x11
add x12, x28, x12
and x20, x26, x5, lsr #16
ld1 {v4.b}[1], [x9]
add x22, x28, x22
ld1 {v5.b}[1], [x10]
add x6, x28, x6, lsr #48
ld1 {v6.b}[1], [x11]
add x0, x28, x0, lsr #48
ld1 {v7.b}[1], [x12]
add x25, x28, x25
ld1 {v4.b}[2], [x22]
add x11, x28, w5, uxth
ld1 {v5.b}[2], [x23]
add x2, x28, x2, lsr #48
ld1 {v6.b}[2], [x24]
add x20, x28, x20
ld1 {v7.b}[2], [x25]
and x19, x26, x3, lsr #16
ld1 {v4.b}[3], [x0]
add x10, x28, w3, uxth
ld1 {v5.b}[3], [x2]
and x22, x26, x1, lsr #32
ld1 {v6.b}[3], [x4]
add x12, x28, w7, uxth
ldr q21, [x8, x16]
add x9, x28, w1, uxth
ld1 {v7.b}[3], [x6]
and x18, x26, x1, lsr #16
and x24, x26, x5, lsr #32
add x19, x28, x19
ld1 {v5.b}[4], [x10]
and x21, x26, x7, lsr #16
add x18, x28, x18
and x25, x26, x7, lsr #32
ld1 {v4.b}[4], [x9]
add x21, x28, x21
ld1 {v6.b}[4], [x11]
add x1, x28, x1, lsr #48
ldr x8, [x15, #8]
and x23, x26, x3, lsr #32
ld1 {v7.b}[4], [x12]
add x22, x28, x22
ld1 {v4.b}[5], [x18]
add x23, x28, x23
ld1 {v5.b}[5], [x19]
add x24, x28, x24
ld1 {v6.b}[5], [x20]
add x3, x28, x3, lsr #48
ld1 {v7.b}[5], [x21]
add x25, x28, x25
ld1 {v4.b}[6], [x22]
add x5, x28, x5, lsr #48
ld1 {v5.b}[6], [x23]
add x13, x13, x14, lsl #1
ld1 {v6.b}[6], [x24]
add x7, x28, x7, lsr #48
ld1 {v7.b}[6], [x25]
ld1 {v4.b}[7], [x1]
add x15, x15, #16
ldr q26, [x8, x16]
ld1 {v6.b}[7], [x5]
ld1 {v7.b}[7], [x7]
subs x17, x17, #1
ld1 {v5.b}[7], [x3]
add x8, x13, x14
