// SB_PAIR_LOOP_16 with the ror #32 lane scheme as searched (operands: d x13, rp x14, q x15, cm x16,
// w x17, goff x27, j0 v30, j1 v31): Cortex-A53 model 69 cycles (the previous order 70).
tbl v0.16b, {v21.16b, v22.16b, v23.16b}, v30.16b
add v25.4s, v20.4s, v29.4s
add v27.4s, v22.4s, v16.4s
add v28.4s, v23.4s, v17.4s
stp d4, d5, [x13]
add v24.4s, v19.4s, v18.4s
tbl v1.16b, {v19.16b, v20.16b, v21.16b}, v31.16b
fmov x0, d0
add v20.4s, v25.4s, v29.4s
tbl v2.16b, {v26.16b, v27.16b, v28.16b}, v30.16b
fmov x1, v0.d[1]
add v19.4s, v24.4s, v18.4s
tbl v3.16b, {v24.16b, v25.16b, v26.16b}, v31.16b
fmov x2, d1
fmov x3, v1.d[1]
fmov x4, d2
add v22.4s, v27.4s, v16.4s
add v23.4s, v28.4s, v17.4s
fmov x6, d3
fmov x5, v2.d[1]
fmov x7, v3.d[1]
stp d6, d7, [x8]
2:
ror x20, x2, #32
ror x18, x0, #32
add x9, x16, w0, uxth
ldr x8, [x14]
add x10, x16, w2, uxth
ror x22, x4, #32
add x12, x16, w6, uxth
add x0, x16, x0, lsr #48
add x11, x16, w4, uxth
ror x24, x6, #32
add x21, x16, w20, uxth
add x19, x16, w18, uxth
add x23, x16, w22, uxth
ld1 {v4.b}[0], [x9]
add x25, x16, w24, uxth
ld1 {v6.b}[0], [x11]
add x18, x16, x18, lsr #48
ld1 {v7.b}[0], [x12]
add x22, x16, x22, lsr #48
ld1 {v5.b}[0], [x10]
add x24, x16, x24, lsr #48
ldr q21, [x8, x27]
add x20, x16, x20, lsr #48
ld1 {v4.b}[1], [x18]
add x9, x16, w1, uxth
ld1 {v6.b}[1], [x22]
ror x22, x3, #32
ldr x8, [x14, #8]
add x13, x13, x17, lsl #1
ld1 {v5.b}[1], [x20]
ld1 {v4.b}[2], [x19]
add x2, x16, x2, lsr #48
add x10, x16, w3, uxth
add x11, x16, w5, uxth
ld1 {v7.b}[1], [x24]
ror x19, x5, #32
ld1 {v5.b}[2], [x21]
add x6, x16, x6, lsr #48
ld1 {v4.b}[3], [x0]
ld1 {v6.b}[2], [x23]
add x4, x16, x4, lsr #48
ror x18, x1, #32
ror x23, x7, #32
ld1 {v7.b}[2], [x25]
add x21, x16, w19, uxth
add x24, x16, w22, uxth
add x19, x16, x19, lsr #48
ld1 {v5.b}[3], [x2]
add x22, x16, x22, lsr #48
ld1 {v6.b}[3], [x4]
add x20, x16, w18, uxth
ldr q26, [x8, x27]
add x25, x16, w23, uxth
ld1 {v7.b}[3], [x6]
add x12, x16, w7, uxth
ld1 {v4.b}[4], [x9]
add x18, x16, x18, lsr #48
ld1 {v5.b}[4], [x10]
add x23, x16, x23, lsr #48
ld1 {v6.b}[4], [x11]
add x3, x16, x3, lsr #48
ld1 {v7.b}[4], [x12]
ld1 {v4.b}[5], [x18]
add x8, x13, x17
ld1 {v5.b}[5], [x22]
add x5, x16, x5, lsr #48
ld1 {v6.b}[5], [x19]
ld1 {v7.b}[5], [x23]
add x1, x16, x1, lsr #48
ld1 {v4.b}[6], [x20]
ld1 {v5.b}[6], [x24]
add x7, x16, x7, lsr #48
ld1 {v6.b}[6], [x21]
ld1 {v7.b}[6], [x25]
subs x15, x15, #1
ld1 {v4.b}[7], [x1]
ld1 {v5.b}[7], [x3]
ld1 {v6.b}[7], [x5]
add x14, x14, #16
ld1 {v7.b}[7], [x7]
b.ne .+4
