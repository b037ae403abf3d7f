// SB_M2L_B (asm/neon_block_mip2l.h: SB_PAIR16_B with the texel rows read at x14 and x14 + 16,
// x14 += 32) as searched by bench/order_search.py --kick=3 (operands as pair16a_lean.s, wt v9):
// Cortex-A53 model 74 cycles (75 in SB_PAIR16_B's order).
add v27.4s, v22.4s, v16.4s
tbl v0.16b, {v21.16b, v22.16b, v23.16b}, v30.16b
add v25.4s, v20.4s, v29.4s
add v24.4s, v19.4s, v18.4s
add v28.4s, v23.4s, v17.4s
tbl v1.16b, {v19.16b, v20.16b, v21.16b}, v31.16b
add v22.4s, v27.4s, v16.4s
smull v16.4s, v9.4h, v8.h[0]
add v20.4s, v25.4s, v29.4s
tbl v3.16b, {v24.16b, v25.16b, v26.16b}, v31.16b
add v19.4s, v24.4s, v18.4s
tbl v2.16b, {v26.16b, v27.16b, v28.16b}, v30.16b
smull v29.4s, v9.4h, v8.h[3]
add v23.4s, v28.4s, v17.4s
smlal2 v16.4s, v9.8h, v8.h[1]
fmov x6, d3
fmov x3, v1.d[1]
fmov x7, v3.d[1]
fmov x5, v2.d[1]
fmov x4, d2
fmov x0, d0
fmov x1, v0.d[1]
fmov x2, d1
smull v17.4s, v9.4h, v8.h[1]
smull v18.4s, v9.4h, v8.h[2]
stp d4, d5, [x13]
adds x15, x15, x17
stp d6, d7, [x8]
ror x24, x6, #32
add x9, x16, w0, uxth
add x23, x16, w6, uxth
ror x21, x4, #32
ror x10, x0, #32
ldr q26, [x14, #16]
ror x18, x2, #32
ld1 {v4.b}[0], [x9]
add x20, x16, w4, uxth
ld1 {v7.b}[0], [x23]
add x25, x16, w24, uxth
add x12, x16, w2, uxth
add x11, x16, w10, uxth
add x19, x16, w18, uxth
add x10, x16, x10, lsr #48
add x22, x16, w21, uxth
add x18, x16, x18, lsr #48
ld1 {v5.b}[0], [x12]
add x21, x16, x21, lsr #48
ld1 {v6.b}[0], [x20]
add x24, x16, x24, lsr #48
ld1 {v4.b}[1], [x10]
add x23, x16, w7, uxth
add x12, x16, w3, uxth
ror x10, x1, #32
ld1 {v5.b}[1], [x18]
add x0, x16, x0, lsr #48
ld1 {v6.b}[1], [x21]
add x2, x16, x2, lsr #48
ld1 {v7.b}[1], [x24]
add x4, x16, x4, lsr #48
ld1 {v4.b}[2], [x11]
ror x21, x5, #32
ld1 {v5.b}[2], [x19]
add x20, x16, w5, uxth
ld1 {v6.b}[2], [x22]
add x6, x16, x6, lsr #48
ld1 {v7.b}[2], [x25]
add x22, x16, w21, uxth
add x9, x16, w1, uxth
ror x24, x7, #32
ld1 {v5.b}[3], [x2]
add x11, x16, w10, uxth
ld1 {v4.b}[3], [x0]
ror x18, x3, #32
ld1 {v6.b}[3], [x4]
add x25, x16, w24, uxth
ld1 {v7.b}[3], [x6]
add x10, x16, x10, lsr #48
ldr q21, [x14]
add x19, x16, w18, uxth
ld1 {v4.b}[4], [x9]
add x21, x16, x21, lsr #48
ld1 {v6.b}[4], [x20]
add x18, x16, x18, lsr #48
ld1 {v5.b}[4], [x12]
add x24, x16, x24, lsr #48
ld1 {v7.b}[4], [x23]
add x3, x16, x3, lsr #48
ld1 {v4.b}[5], [x10]
ld1 {v6.b}[5], [x21]
add x5, x16, x5, lsr #48
ld1 {v5.b}[5], [x18]
ld1 {v7.b}[5], [x24]
smlal2 v17.4s, v9.8h, v8.h[2]
smlal2 v18.4s, v9.8h, v8.h[3]
ld1 {v6.b}[6], [x22]
add x1, x16, x1, lsr #48
ld1 {v5.b}[6], [x19]
add x13, x13, x17, lsl #1
ld1 {v7.b}[6], [x25]
add x7, x16, x7, lsr #48
ld1 {v4.b}[6], [x11]
ld1 {v6.b}[7], [x5]
smlal2 v29.4s, v9.8h, v8.h[4]
ld1 {v7.b}[7], [x7]
ld1 {v4.b}[7], [x1]
ld1 {v5.b}[7], [x3]
add x8, x13, x17
add x14, x14, #32
b.ne 1b
