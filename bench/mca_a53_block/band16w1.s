// SB_BAND_16W1 (asm/neon_block_a53m1.h) as concrete registers (d x17, rp x28, q x14, ete x16, goff x15,
// cm x27, w x13, j0 v9, j1 v10, wa v31, wb v12, wc v30, wd v13): mip 1, a band an iteration.
1:
add v25.4s, v20.4s, v29.4s
add v28.4s, v23.4s, v17.4s
tbl v0.16b, {v21.16b, v22.16b, v23.16b}, v9.16b
add v27.4s, v22.4s, v16.4s
add v24.4s, v19.4s, v18.4s
tbl v1.16b, {v19.16b, v20.16b, v21.16b}, v10.16b
stp d4, d5, [x17]
add v20.4s, v25.4s, v29.4s
fmov x0, d0
add v23.4s, v28.4s, v17.4s
tbl v3.16b, {v24.16b, v25.16b, v26.16b}, v10.16b
tbl v2.16b, {v26.16b, v27.16b, v28.16b}, v9.16b
fmov x2, d1
fmov x1, v0.d[1]
add v22.4s, v27.4s, v16.4s
fmov x3, v1.d[1]
fmov x6, d3
fmov x4, d2
add v19.4s, v24.4s, v18.4s
fmov x5, v2.d[1]
fmov x7, v3.d[1]
stp d6, d7, [x8]
2:
ror x9, x0, #32
add x10, x27, w0, uxth
ror x11, x2, #32
add x19, x27, x0, lsr #48
ror x18, x4, #32
add x20, x27, w6, uxth
add x12, x27, w2, uxth
ldr x8, [x28]
add x23, x27, w9, uxth
ror x22, x6, #32
add x21, x27, w4, uxth
ldr b4, [x10]
add x24, x27, w18, uxth
ldr b7, [x20]
add x10, x27, x9, lsr #48
ldr b5, [x12]
add x26, x27, w22, uxth
ldr b6, [x21]
add x21, x27, x18, lsr #48
add x9, x27, x11, lsr #48
add x25, x27, w11, uxth
ld1 {v4.b}[1], [x10]
ror x18, x3, #32
ldr x14, [x28, #8]
add x20, x27, x22, lsr #48
ld1 {v6.b}[1], [x21]
add x17, x17, x13, lsl #1
ld1 {v5.b}[1], [x9]
ror x10, x5, #32
ld1 {v4.b}[2], [x23]
add x9, x27, x6, lsr #48
ldr q26, [x14, x15]
add x11, x27, x2, lsr #48
ld1 {v7.b}[1], [x20]
add x22, x27, w3, uxth
ld1 {v5.b}[2], [x25]
add x25, x27, w18, uxth
ld1 {v4.b}[3], [x19]
add x23, x27, w1, uxth
ld1 {v6.b}[2], [x24]
add x19, x27, w10, uxth
ld1 {v7.b}[2], [x26]
ror x20, x1, #32
add x21, x27, x4, lsr #48
ror x24, x7, #32
ld1 {v4.b}[4], [x23]
add x26, x27, x10, lsr #48
ld1 {v5.b}[3], [x11]
add x12, x27, w5, uxth
ld1 {v7.b}[3], [x9]
add x23, x27, x18, lsr #48
ld1 {v6.b}[3], [x21]
add x11, x27, w24, uxth
ldr q21, [x8, x15]
add x18, x27, w7, uxth
ld1 {v5.b}[4], [x22]
add x8, x17, x13
add x21, x27, x20, lsr #48
ld1 {v6.b}[4], [x12]
add x9, x27, x24, lsr #48
ld1 {v7.b}[4], [x18]
add x10, x27, w20, uxth
ld1 {v4.b}[5], [x21]
add x12, x27, x7, lsr #48
ld1 {v5.b}[5], [x23]
add x24, x27, x5, lsr #48
ld1 {v6.b}[5], [x26]
add x22, x27, x1, lsr #48
ld1 {v7.b}[5], [x9]
ld1 {v4.b}[6], [x10]
add v27.4s, v22.4s, v16.4s
ld1 {v6.b}[6], [x19]
add x20, x27, x3, lsr #48
ld1 {v5.b}[6], [x25]
ld1 {v7.b}[6], [x11]
tbl v0.16b, {v21.16b, v22.16b, v23.16b}, v9.16b
ld1 {v4.b}[7], [x22]
add v25.4s, v20.4s, v29.4s
add v24.4s, v19.4s, v18.4s
add v28.4s, v23.4s, v17.4s
tbl v1.16b, {v19.16b, v20.16b, v21.16b}, v10.16b
fmov x0, d0
fmov x1, v0.d[1]
add v20.4s, v25.4s, v29.4s
ld1 {v5.b}[7], [x20]
tbl v2.16b, {v26.16b, v27.16b, v28.16b}, v9.16b
ld1 {v7.b}[7], [x12]
tbl v3.16b, {v24.16b, v25.16b, v26.16b}, v10.16b
add v22.4s, v27.4s, v16.4s
add v19.4s, v24.4s, v18.4s
add v23.4s, v28.4s, v17.4s
fmov x5, v2.d[1]
fmov x2, d1
fmov x6, d3
fmov x4, d2
fmov x7, v3.d[1]
fmov x3, v1.d[1]
stp d4, d5, [x17]
ror x23, x0, #32
add x26, x27, w0, uxth
add x9, x27, w6, uxth
ld1 {v6.b}[7], [x24]
add x18, x27, w2, uxth
ror x19, x4, #32
add x25, x27, w4, uxth
ror x21, x2, #32
add x10, x27, x0, lsr #48
ldr b4, [x26]
ror x11, x6, #32
stp d6, d7, [x8]
add x24, x27, w23, uxth
ldr x8, [x28, #16]
add x22, x27, w21, uxth
ldr b6, [x25]
add x20, x27, w11, uxth
ldr b7, [x9]
add x9, x27, x21, lsr #48
add x26, x27, x23, lsr #48
add x25, x27, x19, lsr #48
add x12, x27, w19, uxth
ror x21, x5, #32
ldr b5, [x18]
ld1 {v4.b}[1], [x26]
ldr x14, [x28, #24]
add x23, x27, x11, lsr #48
ld1 {v6.b}[1], [x25]
add x26, x27, w3, uxth
ld1 {v5.b}[1], [x9]
add x11, x27, x2, lsr #48
ld1 {v4.b}[2], [x24]
ld1 {v7.b}[1], [x23]
add x25, x27, w5, uxth
ld1 {v6.b}[2], [x12]
ror x18, x3, #32
ld1 {v5.b}[2], [x22]
add x19, x27, w1, uxth
ld1 {v4.b}[3], [x10]
add x24, x27, x4, lsr #48
ldr q21, [x8, x15]
add x9, x27, x6, lsr #48
ld1 {v7.b}[2], [x20]
ror x22, x7, #32
ror x23, x1, #32
add x10, x27, w21, uxth
ld1 {v5.b}[3], [x11]
add x12, x27, x21, lsr #48
ld1 {v6.b}[3], [x24]
add x24, x27, w7, uxth
ld1 {v4.b}[4], [x19]
add x21, x27, x18, lsr #48
ld1 {v7.b}[3], [x9]
add x20, x27, w18, uxth
ld1 {v5.b}[4], [x26]
add x9, x27, x23, lsr #48
ld1 {v6.b}[4], [x25]
add x19, x27, x22, lsr #48
ldr q26, [x14, x15]
add x11, x27, w23, uxth
ld1 {v7.b}[4], [x24]
add x23, x27, x3, lsr #48
ld1 {v4.b}[5], [x9]
add x25, x27, x7, lsr #48
ld1 {v5.b}[5], [x21]
ld1 {v6.b}[5], [x12]
add x18, x27, w22, uxth
ld1 {v7.b}[5], [x19]
add x22, x27, x1, lsr #48
ld1 {v4.b}[6], [x11]
ld1 {v5.b}[6], [x20]
add x17, x17, x13, lsl #1
ld1 {v6.b}[6], [x10]
add x26, x27, x5, lsr #48
ld1 {v7.b}[6], [x18]
add x8, x17, x13
ld1 {v4.b}[7], [x22]
ld1 {v5.b}[7], [x23]
add v27.4s, v22.4s, v16.4s
tbl v0.16b, {v21.16b, v22.16b, v23.16b}, v9.16b
add v25.4s, v20.4s, v29.4s
add v28.4s, v23.4s, v17.4s
add v24.4s, v19.4s, v18.4s
tbl v1.16b, {v19.16b, v20.16b, v21.16b}, v10.16b
ld1 {v7.b}[7], [x25]
stp d4, d5, [x17]
add v20.4s, v25.4s, v29.4s
tbl v2.16b, {v26.16b, v27.16b, v28.16b}, v9.16b
fmov x0, d0
add v23.4s, v28.4s, v17.4s
tbl v3.16b, {v24.16b, v25.16b, v26.16b}, v10.16b
add v19.4s, v24.4s, v18.4s
ld1 {v6.b}[7], [x26]
fmov x5, v2.d[1]
add v22.4s, v27.4s, v16.4s
fmov x2, d1
add v25.4s, v20.4s, v29.4s
fmov x7, v3.d[1]
fmov x4, d2
fmov x1, v0.d[1]
fmov x3, v1.d[1]
fmov x6, d3
stp d6, d7, [x8]
add x9, x27, w0, uxth
add x12, x27, w2, uxth
ror x11, x4, #32
ror x24, x2, #32
add x18, x27, w4, uxth
ldr x8, [x28, #32]
ror x21, x0, #32
ror x19, x6, #32
add x22, x27, w24, uxth
ldr b4, [x9]
add x20, x27, w6, uxth
ldr b6, [x18]
add x10, x27, x0, lsr #48
add x26, x27, w11, uxth
add x25, x27, w19, uxth
add x9, x27, x21, lsr #48
ldr b7, [x20]
add x18, x27, x11, lsr #48
ldr b5, [x12]
add x20, x27, x24, lsr #48
add x23, x27, w21, uxth
add x21, x27, x19, lsr #48
ld1 {v4.b}[1], [x9]
add x11, x27, w1, uxth
ld1 {v6.b}[1], [x18]
ror x9, x5, #32
ldr x14, [x28, #40]
add x19, x27, w3, uxth
ld1 {v7.b}[1], [x21]
ror x21, x1, #32
ld1 {v5.b}[1], [x20]
add x24, x27, x2, lsr #48
ld1 {v4.b}[2], [x23]
ror x12, x3, #32
ldr q26, [x14, x15]
add x18, x27, x6, lsr #48
ld1 {v5.b}[2], [x22]
add x20, x27, w7, uxth
ld1 {v6.b}[2], [x26]
add x17, x17, x13, lsl #1
ld1 {v7.b}[2], [x25]
add x22, x27, x4, lsr #48
ld1 {v4.b}[3], [x10]
ld1 {v5.b}[3], [x24]
add x25, x27, x9, lsr #48
ror x23, x7, #32
add x26, x27, w9, uxth
ld1 {v7.b}[3], [x18]
add x24, x27, w21, uxth
add x9, x27, w5, uxth
add x10, x27, w12, uxth
ld1 {v6.b}[3], [x22]
add x22, x27, w23, uxth
ldr q21, [x8, x15]
add x18, x27, x12, lsr #48
ld1 {v4.b}[4], [x11]
add x12, x27, x21, lsr #48
ld1 {v5.b}[4], [x19]
add x11, x27, x23, lsr #48
ld1 {v6.b}[4], [x9]
add x9, x27, x5, lsr #48
ld1 {v7.b}[4], [x20]
ld1 {v4.b}[5], [x12]
add x8, x17, x13
ld1 {v5.b}[5], [x18]
add x19, x27, x7, lsr #48
ld1 {v6.b}[5], [x25]
add x23, x27, x1, lsr #48
ld1 {v7.b}[5], [x11]
add x21, x27, x3, lsr #48
ld1 {v4.b}[6], [x24]
ld1 {v5.b}[6], [x10]
tbl v1.16b, {v19.16b, v20.16b, v21.16b}, v10.16b
add v28.4s, v23.4s, v17.4s
add v20.4s, v25.4s, v29.4s
add v27.4s, v22.4s, v16.4s
ld1 {v6.b}[6], [x26]
tbl v0.16b, {v21.16b, v22.16b, v23.16b}, v9.16b
smull2 v29.4s, v12.8h, v8.h[1]
add v23.4s, v28.4s, v17.4s
add v24.4s, v19.4s, v18.4s
ld1 {v5.b}[7], [x21]
tbl v2.16b, {v26.16b, v27.16b, v28.16b}, v9.16b
ld1 {v4.b}[7], [x23]
fmov x0, d0
fmov x3, v1.d[1]
smull2 v17.4s, v31.8h, v8.h[0]
tbl v3.16b, {v24.16b, v25.16b, v26.16b}, v10.16b
ld1 {v7.b}[6], [x22]
fmov x4, d2
ld1 {v6.b}[7], [x9]
fmov x2, d1
fmov x5, v2.d[1]
add v19.4s, v24.4s, v18.4s
fmov x6, d3
add v22.4s, v27.4s, v16.4s
smull v16.4s, v31.4h, v8.h[0]
smull v18.4s, v12.4h, v8.h[1]
fmov x1, v0.d[1]
smlal2 v17.4s, v30.8h, v8.h[1]
stp d4, d5, [x17]
add x25, x27, w0, uxth
ror x12, x4, #32
ror x11, x6, #32
ld1 {v7.b}[7], [x19]
ror x18, x2, #32
ror x20, x0, #32
ldr b4, [x25]
smlal v16.4s, v30.4h, v8.h[1]
stp d6, d7, [x8]
add x9, x27, w6, uxth
add x24, x27, w2, uxth
add x22, x27, x20, lsr #48
add x21, x27, w18, uxth
add x10, x27, w4, uxth
ldr x8, [x28, #48]
add x19, x27, w12, uxth
ldr b5, [x24]
add x25, x27, x18, lsr #48
add x24, x27, x12, lsr #48
add x23, x27, w11, uxth
ldr b6, [x10]
add x10, x27, x11, lsr #48
ldr b7, [x9]
add x9, x27, x0, lsr #48
ldr x14, [x28, #56]
ror x11, x5, #32
ld1 {v5.b}[1], [x25]
add x28, x28, #64
ld1 {v4.b}[1], [x22]
add x26, x27, w20, uxth
ld1 {v7.b}[1], [x10]
ld1 {v6.b}[1], [x24]
fmov x7, v3.d[1]
smlal v18.4s, v13.4h, v8.h[2]
smlal2 v29.4s, v13.8h, v8.h[2]
ld1 {v4.b}[2], [x26]
add x12, x27, x6, lsr #48
ld1 {v7.b}[2], [x23]
add x25, x27, x2, lsr #48
ld1 {v5.b}[2], [x21]
ror x22, x1, #32
ld1 {v6.b}[2], [x19]
add x26, x27, w11, uxth
ror x24, x3, #32
add x20, x27, w3, uxth
ld1 {v7.b}[3], [x12]
add x18, x27, x4, lsr #48
ld1 {v5.b}[3], [x25]
add x12, x27, x22, lsr #48
ld1 {v4.b}[3], [x9]
add x23, x27, w7, uxth
ldr q26, [x14, x15]
ror x10, x7, #32
add x21, x27, w22, uxth
add x22, x27, w1, uxth
ldr q8, [x16, x30]
add x19, x27, w5, uxth
ld1 {v6.b}[3], [x18]
add x9, x27, w24, uxth
ld1 {v7.b}[4], [x23]
ld1 {v4.b}[4], [x22]
add x25, x27, x24, lsr #48
ld1 {v5.b}[4], [x20]
add x24, x27, x11, lsr #48
ld1 {v6.b}[4], [x19]
add x11, x27, x10, lsr #48
ldr q21, [x8, x15]
add x22, x27, w10, uxth
ld1 {v4.b}[5], [x12]
add x17, x17, x13, lsl #1
ld1 {v5.b}[5], [x25]
ld1 {v6.b}[5], [x24]
add x20, x27, x7, lsr #48
ld1 {v7.b}[5], [x11]
ld1 {v4.b}[6], [x21]
add x18, x27, x1, lsr #48
ld1 {v5.b}[6], [x9]
add x19, x27, x3, lsr #48
ld1 {v6.b}[6], [x26]
add x23, x27, x5, lsr #48
ld1 {v7.b}[6], [x22]
ld1 {v4.b}[7], [x18]
add x8, x17, x13
ld1 {v5.b}[7], [x19]
adds x30, x30, x13
ld1 {v6.b}[7], [x23]
ld1 {v7.b}[7], [x20]
b.ne 1b
