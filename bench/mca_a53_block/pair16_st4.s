st4 {v0.s, v1.s, v2.s, v3.s}[0], [x17]
add v27.4s, v22.4s, v16.4s
add v28.4s, v23.4s, v17.4s
tbl v0.16b, {v21.16b, v22.16b, v23.16b}, v30.16b
add v25.4s, v20.4s, v29.4s
add v24.4s, v19.4s, v18.4s
tbl v1.16b, {v19.16b, v20.16b, v21.16b}, v31.16b
add v22.4s, v27.4s, v16.4s
st4 {v4.s, v5.s, v6.s, v7.s}[0], [x8]
tbl v2.16b, {v26.16b, v27.16b, v28.16b}, v30.16b
fmov x1, v0.d[1]
add v23.4s, v28.4s, v17.4s
tbl v3.16b, {v24.16b, v25.16b, v26.16b}, v31.16b
fmov x0, d0
fmov x3, v1.d[1]
add v19.4s, v24.4s, v18.4s
add v20.4s, v25.4s, v29.4s
fmov x4, d2
fmov x6, d3
fmov x2, d1
fmov x5, v2.d[1]
fmov x7, v3.d[1]
ldr q8, [x27, x13]
add x9, x16, w0, uxth
ror x10, x0, #32
add x12, x16, w2, uxth
ror x21, x4, #32
ror x18, x2, #32
add x0, x16, x0, lsr #48
add x11, x16, w10, uxth
add x23, x16, w6, uxth
add x20, x16, w4, uxth
ldr b5, [x12]
ror x24, x6, #32
ldr b4, [x9]
add x22, x16, w21, uxth
ldr b7, [x23]
add x21, x16, x21, lsr #48
add x19, x16, w18, uxth
add x18, x16, x18, lsr #48
add x25, x16, w24, uxth
add x12, x16, w3, uxth
add x10, x16, x10, lsr #48
add x24, x16, x24, lsr #48
ldr b6, [x20]
add x2, x16, x2, lsr #48
ld1 {v5.b}[1], [x18]
add x6, x16, x6, lsr #48
ld1 {v4.b}[1], [x10]
ror x10, x1, #32
ld1 {v7.b}[1], [x24]
add x4, x16, x4, lsr #48
ld1 {v6.b}[1], [x21]
ror x18, x3, #32
ldr q21, [x14]
add x9, x16, w1, uxth
ld1 {v4.b}[2], [x11]
ror x21, x5, #32
ld1 {v5.b}[2], [x19]
add x20, x16, w5, uxth
ld1 {v6.b}[2], [x22]
ror x24, x7, #32
ld1 {v7.b}[2], [x25]
add x19, x16, w18, uxth
ldr q26, [x14, #16]
add x23, x16, w7, uxth
ld1 {v4.b}[3], [x0]
add x11, x16, w10, uxth
ld1 {v5.b}[3], [x2]
add x10, x16, x10, lsr #48
ld1 {v6.b}[3], [x4]
add x25, x16, w24, uxth
ld1 {v7.b}[3], [x6]
add x22, x16, w21, uxth
ld1 {v4.b}[4], [x9]
add x21, x16, x21, lsr #48
ld1 {v5.b}[4], [x12]
add x18, x16, x18, lsr #48
ld1 {v6.b}[4], [x20]
add x5, x16, x5, lsr #48
ld1 {v7.b}[4], [x23]
add x24, x16, x24, lsr #48
ld1 {v4.b}[5], [x10]
add x17, x17, x15, lsl #1
ld1 {v5.b}[5], [x18]
ld1 {v6.b}[5], [x21]
add x14, x14, #32
ld1 {v7.b}[5], [x24]
add x3, x16, x3, lsr #48
ld1 {v4.b}[6], [x11]
add x1, x16, x1, lsr #48
ld1 {v5.b}[6], [x19]
ld1 {v6.b}[6], [x22]
add x7, x16, x7, lsr #48
ld1 {v7.b}[6], [x25]
add x8, x17, x15
ld1 {v4.b}[7], [x1]
ld1 {v5.b}[7], [x3]
ld1 {v6.b}[7], [x5]
ld1 {v7.b}[7], [x7]
3:
tbl v1.16b, {v19.16b, v20.16b, v21.16b}, v31.16b
add v27.4s, v22.4s, v16.4s
add v28.4s, v23.4s, v17.4s
tbl v0.16b, {v21.16b, v22.16b, v23.16b}, v30.16b
add v24.4s, v19.4s, v18.4s
add v25.4s, v20.4s, v29.4s
stp d4, d5, [x17]
add v22.4s, v27.4s, v16.4s
tbl v2.16b, {v26.16b, v27.16b, v28.16b}, v30.16b
add v23.4s, v28.4s, v17.4s
fmov x0, d0
tbl v3.16b, {v24.16b, v25.16b, v26.16b}, v31.16b
add v19.4s, v24.4s, v18.4s
smull v16.4s, v9.4h, v8.h[0]
add v20.4s, v25.4s, v29.4s
fmov x1, v0.d[1]
fmov x2, d1
smull v17.4s, v9.4h, v8.h[1]
fmov x6, d3
fmov x3, v1.d[1]
fmov x4, d2
smull v29.4s, v9.4h, v8.h[3]
smull v18.4s, v9.4h, v8.h[2]
fmov x5, v2.d[1]
fmov x7, v3.d[1]
smlal2 v17.4s, v9.8h, v8.h[2]
stp d6, d7, [x8]
adds x13, x13, x15
ror x24, x6, #32
add x20, x16, w4, uxth
add x9, x16, w0, uxth
ror x10, x0, #32
ror x21, x4, #32
add x12, x16, w2, uxth
add x23, x16, w6, uxth
ldr q26, [x14, #16]
add x11, x16, w10, uxth
ror x18, x2, #32
add x10, x16, x10, lsr #48
ldr b0, [x9]
add x22, x16, w21, uxth
ldr b6, [x23]
add x25, x16, w24, uxth
ldr b2, [x12]
add x21, x16, x21, lsr #48
add x19, x16, w18, uxth
add x18, x16, x18, lsr #48
ldr b4, [x20]
add x24, x16, x24, lsr #48
ld1 {v0.b}[1], [x10]
ror x10, x1, #32
add x23, x16, w7, uxth
add x12, x16, w3, uxth
ld1 {v2.b}[1], [x18]
add x0, x16, x0, lsr #48
ld1 {v4.b}[1], [x21]
add x2, x16, x2, lsr #48
ld1 {v6.b}[1], [x24]
add x4, x16, x4, lsr #48
ld1 {v0.b}[2], [x11]
ror x21, x5, #32
ld1 {v2.b}[2], [x19]
add x20, x16, w5, uxth
ld1 {v4.b}[2], [x22]
add x9, x16, w1, uxth
add x6, x16, x6, lsr #48
ror x24, x7, #32
ld1 {v6.b}[2], [x25]
add x22, x16, w21, uxth
ld1 {v2.b}[3], [x2]
add x11, x16, w10, uxth
ld1 {v0.b}[3], [x0]
ror x18, x3, #32
ld1 {v4.b}[3], [x4]
add x25, x16, w24, uxth
ld1 {v6.b}[3], [x6]
add x10, x16, x10, lsr #48
ldr q21, [x14]
add x19, x16, w18, uxth
ldr b1, [x9]
add x21, x16, x21, lsr #48
ldr b5, [x20]
add x18, x16, x18, lsr #48
ldr b3, [x12]
add x24, x16, x24, lsr #48
ldr b7, [x23]
add x5, x16, x5, lsr #48
ld1 {v1.b}[1], [x10]
add x3, x16, x3, lsr #48
ld1 {v5.b}[1], [x21]
ld1 {v3.b}[1], [x18]
smlal2 v16.4s, v9.8h, v8.h[1]
ld1 {v7.b}[1], [x24]
ld1 {v5.b}[2], [x22]
add x1, x16, x1, lsr #48
ld1 {v3.b}[2], [x19]
add x7, x16, x7, lsr #48
ld1 {v1.b}[2], [x11]
ld1 {v7.b}[2], [x25]
smlal2 v18.4s, v9.8h, v8.h[3]
smlal2 v29.4s, v9.8h, v8.h[4]
ld1 {v5.b}[3], [x5]
ld1 {v1.b}[3], [x1]
ld1 {v7.b}[3], [x7]
add x17, x17, x15, lsl #1
ld1 {v3.b}[3], [x3]
add x14, x14, #32
add x8, x17, x15
b.ne 1b
