uhadd v2.8h, v16.8h, v17.8h
ushr v1.8h, v19.8h, #1
add v3.8h, v19.8h, v20.8h
stp d4, d5, [x1]
add x1, x1, x2
ldp x6, x7, [x5], #16
bit v2.16b, v25.16b, v31.16b
ushr v3.16b, v3.16b, #2
trn2 v1.16b, v24.16b, v1.16b
bif v24.16b, v16.16b, v31.16b
stp d6, d7, [x1]
ldr q16, [x3]
add x1, x1, x2
fmov x13, v2.d[1]
trn2 v3.16b, v25.16b, v3.16b
fmov x12, d2
fmov x11, v1.d[1]
fmov x8, d24
fmov x10, d1
add v21.8h, v18.8h, v22.8h
fmov x9, v24.d[1]
fmov x14, d3
fmov x15, v3.d[1]
ldur q22, [x3, #2]
add x20, x0, w10, uxth
add x16, x0, w8, uxth
add x17, x0, w12, uxth
ldr q24, [x6, x28]
add x18, x0, w9, uxth
ldr q25, [x7, x28]
add x19, x0, w13, uxth
ld1 {v4.b}[0], [x16]
add x21, x0, w14, uxth
ld1 {v6.b}[0], [x17]
and x24, x27, x8, lsr #16
ld1 {v5.b}[0], [x18]
and x16, x27, x9, lsr #16
ld1 {v7.b}[0], [x19]
add x22, x0, w11, uxth
and x25, x27, x12, lsr #16
add x23, x0, w15, uxth
ld1 {v4.b}[1], [x20]
add x24, x0, x24
ld1 {v6.b}[1], [x21]
and x17, x27, x13, lsr #16
add x16, x0, x16
and x20, x27, x11, lsr #16
and x21, x27, x15, lsr #16
add x17, x0, x17
and x19, x27, x14, lsr #16
add x25, x0, x25
ld1 {v5.b}[1], [x22]
and x18, x27, x10, lsr #16
ld1 {v7.b}[1], [x23]
add x18, x0, x18
ld1 {v4.b}[2], [x24]
add x19, x0, x19
ld1 {v6.b}[2], [x25]
add x20, x0, x20
ld1 {v5.b}[2], [x16]
add x21, x0, x21
ld1 {v7.b}[2], [x17]
and x22, x27, x8, lsr #32
ld1 {v4.b}[3], [x18]
add x22, x0, x22
and x24, x27, x9, lsr #32
and x23, x27, x12, lsr #32
and x25, x27, x13, lsr #32
add x23, x0, x23
ld1 {v6.b}[3], [x19]
add x25, x0, x25
ld1 {v5.b}[3], [x20]
add x24, x0, x24
and x17, x27, x14, lsr #32
and x16, x27, x10, lsr #32
ld1 {v7.b}[3], [x21]
and x18, x27, x11, lsr #32
ld1 {v4.b}[4], [x22]
and x19, x27, x15, lsr #32
ld1 {v6.b}[4], [x23]
add x16, x0, x16
ld1 {v5.b}[4], [x24]
add x17, x0, x17
ld1 {v7.b}[4], [x25]
add x20, x0, x8, lsr #48
add x18, x0, x18
add x19, x0, x19
ld1 {v4.b}[5], [x16]
add x21, x0, x12, lsr #48
ld1 {v6.b}[5], [x17]
add x22, x0, x9, lsr #48
ld1 {v5.b}[5], [x18]
add x24, x0, x10, lsr #48
ld1 {v7.b}[5], [x19]
add x23, x0, x13, lsr #48
ld1 {v4.b}[6], [x20]
add x16, x0, x11, lsr #48
ld1 {v6.b}[6], [x21]
ld1 {v5.b}[6], [x22]
add x25, x0, x14, lsr #48
cmp x30, #4
ld1 {v7.b}[6], [x23]
add x17, x0, x15, lsr #48
ld1 {v4.b}[7], [x24]
ld1 {v5.b}[7], [x16]
csel x26, x4, xzr, ge
ld1 {v6.b}[7], [x25]
subs x30, x30, #1
ld1 {v7.b}[7], [x17]
add x3, x3, x26
