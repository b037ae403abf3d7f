uhadd v2.8h, v16.8h, v17.8h
ushr v1.8h, v19.8h, #1
add v3.8h, v19.8h, v20.8h
cmp x30, #4
stp d4, d5, [x1]
add x1, x1, x2
bit v2.16b, v25.16b, v31.16b
trn2 v1.16b, v24.16b, v1.16b
ushr v3.16b, v3.16b, #2
bif v24.16b, v16.16b, v31.16b
stp d6, d7, [x1]
ldr q16, [x3]
fmov x13, v2.d[1]
fmov x10, d1
trn2 v3.16b, v25.16b, v3.16b
fmov x8, d24
fmov x9, v24.d[1]
fmov x12, d2
add v21.8h, v18.8h, v22.8h
fmov x11, v1.d[1]
fmov x15, v3.d[1]
fmov x14, d3
ldr q24, [x5]
add x16, x0, w8, uxth
add x17, x0, w12, uxth
add x20, x0, w10, uxth
add x24, x0, x8, lsr #48
add x19, x0, w13, uxth
add x18, x0, w9, uxth
add x21, x0, w14, uxth
ld1 {v4.b}[0], [x16]
add x25, x0, x12, lsr #48
ld1 {v6.b}[0], [x17]
add x22, x0, w11, uxth
ld1 {v5.b}[0], [x18]
add x23, x0, w15, uxth
ld1 {v7.b}[0], [x19]
add x18, x0, x11, lsr #48
ld1 {v4.b}[1], [x20]
add x17, x0, x10, lsr #48
ld1 {v6.b}[1], [x21]
add x16, x0, x13, lsr #48
ld1 {v5.b}[1], [x22]
add x27, x0, x9, lsr #48
ld1 {v7.b}[1], [x23]
ror x8, x8, #32
add x19, x0, x14, lsr #48
ror x12, x12, #32
ld1 {v4.b}[6], [x24]
ror x9, x9, #32
ld1 {v6.b}[6], [x25]
ror x10, x10, #32
ld1 {v5.b}[6], [x27]
add x20, x0, x15, lsr #48
ldr q25, [x5, #16]
add x21, x0, w8, uxth
ror x15, x15, #32
add x22, x0, w12, uxth
ld1 {v7.b}[6], [x16]
add x5, x5, #32
ld1 {v6.b}[7], [x19]
ror x13, x13, #32
ld1 {v4.b}[7], [x17]
add x19, x0, x12, lsr #48
add x23, x0, w9, uxth
ror x14, x14, #32
ld1 {v7.b}[7], [x20]
add x24, x0, w13, uxth
ror x11, x11, #32
add x20, x0, x9, lsr #48
ld1 {v5.b}[7], [x18]
add x25, x0, w10, uxth
ld1 {v6.b}[4], [x22]
add x16, x0, w11, uxth
ld1 {v4.b}[4], [x21]
add x21, x0, x13, lsr #48
add x27, x0, w14, uxth
add x22, x0, x10, lsr #48
ld1 {v5.b}[4], [x23]
add x18, x0, x8, lsr #48
ld1 {v7.b}[4], [x24]
add x17, x0, w15, uxth
ld1 {v4.b}[5], [x25]
ld1 {v6.b}[5], [x27]
and x5, x5, x28
ld1 {v5.b}[5], [x16]
csel x26, x4, xzr, ge
ld1 {v7.b}[5], [x17]
add x23, x0, x14, lsr #48
ld1 {v4.b}[2], [x18]
ldur q22, [x3, #2]
add x24, x0, x11, lsr #48
ld1 {v6.b}[2], [x19]
ld1 {v5.b}[2], [x20]
ld1 {v7.b}[2], [x21]
add x25, x0, x15, lsr #48
ld1 {v4.b}[3], [x22]
ld1 {v6.b}[3], [x23]
subs x30, x30, #1
ld1 {v5.b}[3], [x24]
add x3, x3, x26
ld1 {v7.b}[3], [x25]
add x1, x1, x2
b.ne .Ltgt
