// SB_PAIR_LOOP_16W1 (mip 1's band-end pair) with the ror #32 lane scheme as searched (operands as in
// pair16_ror.s; ete x28, wa..wd v9-v12): Cortex-A53 model 78 cycles (the previous order 79).
1:
add v28.4s, v23.4s, v17.4s
add v25.4s, v20.4s, v29.4s
add v27.4s, v22.4s, v16.4s
tbl v1.16b, {v19.16b, v20.16b, v21.16b}, v31.16b
add v24.4s, v19.4s, v18.4s
tbl v0.16b, {v21.16b, v22.16b, v23.16b}, v30.16b
add v23.4s, v28.4s, v17.4s
add v20.4s, v25.4s, v29.4s
tbl v2.16b, {v26.16b, v27.16b, v28.16b}, v30.16b
fmov x2, d1
tbl v3.16b, {v24.16b, v25.16b, v26.16b}, v31.16b
smull2 v17.4s, v9.8h, v8.h[0]
add v22.4s, v27.4s, v16.4s
smull2 v29.4s, v10.8h, v8.h[1]
fmov x0, d0
add v19.4s, v24.4s, v18.4s
smull v18.4s, v10.4h, v8.h[1]
fmov x5, v2.d[1]
fmov x4, d2
smlal2 v29.4s, v12.8h, v8.h[2]
fmov x6, d3
smull v16.4s, v9.4h, v8.h[0]
fmov x3, v1.d[1]
stp d4, d5, [x13]
ror x22, x4, #32
ror x20, x2, #32
ror x24, x6, #32
add x9, x16, w0, uxth
ror x18, x0, #32
smlal v18.4s, v12.4h, v8.h[2]
smlal v16.4s, v11.4h, v8.h[1]
smlal2 v17.4s, v11.8h, v8.h[1]
fmov x1, v0.d[1]
stp d6, d7, [x8]
add x10, x16, w2, uxth
ldr x8, [x14]
add x11, x16, w4, uxth
add x19, x16, w18, uxth
add x12, x16, w6, uxth
add x18, x16, x18, lsr #48
add x21, x16, w20, uxth
ld1 {v5.b}[0], [x10]
add x23, x16, w22, uxth
ldr q21, [x8, x27]
add x25, x16, w24, uxth
ld1 {v4.b}[0], [x9]
add x9, x16, w3, uxth
ld1 {v6.b}[0], [x11]
add x22, x16, x22, lsr #48
ldr x8, [x14, #8]
add x20, x16, x20, lsr #48
ld1 {v7.b}[0], [x12]
add x24, x16, x24, lsr #48
ld1 {v4.b}[1], [x18]
add x6, x16, x6, lsr #48
ld1 {v6.b}[1], [x22]
add x4, x16, x4, lsr #48
ld1 {v5.b}[1], [x20]
add x26, x16, w1, uxth
ld1 {v7.b}[1], [x24]
add x14, x14, #16
ld1 {v4.b}[2], [x19]
add x0, x16, x0, lsr #48
fmov x7, v3.d[1]
ld1 {v7.b}[2], [x25]
ror x24, x5, #32
ld1 {v6.b}[2], [x23]
add x10, x16, w5, uxth
ror x12, x1, #32
ld1 {v5.b}[2], [x21]
add x2, x16, x2, lsr #48
ld1 {v7.b}[3], [x6]
ror x20, x3, #32
ld1 {v4.b}[3], [x0]
add x11, x16, w7, uxth
ld1 {v6.b}[3], [x4]
add x19, x16, w24, uxth
ld1 {v5.b}[3], [x2]
ror x21, x7, #32
ldr q26, [x8, x27]
add x18, x16, w12, uxth
add x12, x16, x12, lsr #48
add x22, x16, w20, uxth
ld1 {v7.b}[4], [x11]
add x20, x16, x20, lsr #48
ld1 {v4.b}[4], [x26]
add x24, x16, x24, lsr #48
ld1 {v5.b}[4], [x9]
add x5, x16, x5, lsr #48
ld1 {v6.b}[4], [x10]
add x23, x16, w21, uxth
ldr q8, [x28, x30]
add x21, x16, x21, lsr #48
ld1 {v4.b}[5], [x12]
add x7, x16, x7, lsr #48
ld1 {v5.b}[5], [x20]
add x3, x16, x3, lsr #48
ld1 {v6.b}[5], [x24]
add x1, x16, x1, lsr #48
ld1 {v7.b}[5], [x21]
mov x15, #3
ld1 {v4.b}[6], [x18]
ld1 {v5.b}[6], [x22]
ld1 {v6.b}[6], [x19]
ld1 {v7.b}[6], [x23]
adds x30, x30, x17
ld1 {v4.b}[7], [x1]
ld1 {v5.b}[7], [x3]
add x13, x13, x17, lsl #1
ld1 {v6.b}[7], [x5]
ld1 {v7.b}[7], [x7]
add x8, x13, x17
b.ne .+4
