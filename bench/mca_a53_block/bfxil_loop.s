// inorder_loop.s with a 16 KiB-aligned colormap: lanes 1-2 addressed by one bfxil into a
// register holding cm (instead of and + add); order from order_search.py (stores first).
stp d4, d5, [x13]
stp d6, d7, [x8]
tbl v0.16b, {v21.16b, v22.16b, v23.16b}, v30.16b
add v24.4s, v19.4s, v18.4s
add v25.4s, v20.4s, v29.4s
add v27.4s, v22.4s, v16.4s
add v28.4s, v23.4s, v17.4s
tbl v1.16b, {v19.16b, v20.16b, v21.16b}, v31.16b
fmov x1, v0.d[1]
fmov x0, d0
tbl v3.16b, {v24.16b, v25.16b, v26.16b}, v31.16b
add v20.4s, v25.4s, v29.4s
tbl v2.16b, {v26.16b, v27.16b, v28.16b}, v30.16b
add v22.4s, v27.4s, v16.4s
fmov x3, v1.d[1]
fmov x2, d1
fmov x7, v3.d[1]
fmov x6, d3
fmov x4, d2
add v19.4s, v24.4s, v18.4s
fmov x5, v2.d[1]
ldr x8, [x15]
add x18, x28, w0, uxth
add x19, x28, w2, uxth
bfxil x12, x6, #16, #14
bfxil x11, x4, #16, #14
bfxil x9, x0, #16, #14
add x20, x28, w4, uxth
bfxil x10, x2, #16, #14
ld1 {v4.b}[0], [x18]
ld1 {v5.b}[0], [x19]
add x21, x28, w6, uxth
bfxil x22, x0, #32, #14
bfxil x25, x6, #32, #14
bfxil x23, x2, #32, #14
ld1 {v6.b}[0], [x20]
ld1 {v7.b}[0], [x21]
add x0, x28, x0, lsr #48
add x6, x28, x6, lsr #48
bfxil x24, x4, #32, #14
ld1 {v4.b}[1], [x9]
ld1 {v5.b}[1], [x10]
ld1 {v6.b}[1], [x11]
ld1 {v7.b}[1], [x12]
add x9, x28, w1, uxth
ld1 {v4.b}[2], [x22]
ldr q21, [x8, x16]
ld1 {v6.b}[2], [x24]
ld1 {v5.b}[2], [x23]
add x12, x28, w7, uxth
add x11, x28, w5, uxth
bfxil x22, x1, #32, #14
ld1 {v4.b}[3], [x0]
subs x17, x17, #1
ld1 {v7.b}[2], [x25]
add x2, x28, x2, lsr #48
add x4, x28, x4, lsr #48
bfxil x18, x1, #16, #14
bfxil x21, x7, #16, #14
bfxil x20, x5, #16, #14
bfxil x19, x3, #16, #14
bfxil x25, x7, #32, #14
bfxil x23, x3, #32, #14
bfxil x24, x5, #32, #14
ld1 {v5.b}[3], [x2]
add x1, x28, x1, lsr #48
ld1 {v4.b}[4], [x9]
ld1 {v6.b}[3], [x4]
ld1 {v7.b}[3], [x6]
add x10, x28, w3, uxth
ld1 {v4.b}[5], [x18]
ld1 {v6.b}[4], [x11]
ld1 {v5.b}[4], [x10]
add v23.4s, v28.4s, v17.4s
ldr x8, [x15, #8]
add x3, x28, x3, lsr #48
ld1 {v7.b}[4], [x12]
add x15, x15, #16
ld1 {v5.b}[5], [x19]
ld1 {v6.b}[5], [x20]
add x7, x28, x7, lsr #48
ld1 {v4.b}[6], [x22]
add x13, x13, x14, lsl #1
ld1 {v7.b}[5], [x21]
add x5, x28, x5, lsr #48
ld1 {v5.b}[6], [x23]
ld1 {v6.b}[6], [x24]
ldr q26, [x8, x16]
ld1 {v7.b}[6], [x25]
add x8, x13, x14
ld1 {v5.b}[7], [x3]
ld1 {v4.b}[7], [x1]
ld1 {v6.b}[7], [x5]
ld1 {v7.b}[7], [x7]
b.ne 0
