fmov s5, w2
dup v31.4s, w1
dup v25.4s, w0
dup v30.4s, w1
dup v29.4s, w1
dup v28.4s, w1
mov v5.s[1], w3
dup v24.4s, w0
dup v26.4s, w0
dup v27.4s, w0
ldp q18, q19, [x12, #32]
add x0, x11, #64
mov v5.s[2], w4
ldp q16, q17, [x12]
ldp q20, q21, [x12, #64]
ld4r {v0.8h, v1.8h, v2.8h, v3.8h}, [x0]
mov v5.s[3], w5
ldr q4, [x11, #64]
mov x0, x11
mov w1, #514
mov w2, #256
ldp q22, q23, [x12, #96]
mla v30.4s, v18.4s, v5.s[1]
mla v31.4s, v19.4s, v5.s[1]
mla v28.4s, v16.4s, v5.s[1]
mla v29.4s, v17.4s, v5.s[1]
mla v25.4s, v17.4s, v5.s[0]
mla v24.4s, v16.4s, v5.s[0]
mla v30.4s, v22.4s, v5.s[3]
mla v31.4s, v23.4s, v5.s[3]
mla v26.4s, v18.4s, v5.s[0]
mla v28.4s, v20.4s, v5.s[3]
mla v27.4s, v19.4s, v5.s[0]
mla v29.4s, v21.4s, v5.s[3]
mla v24.4s, v20.4s, v5.s[2]
mla v25.4s, v21.4s, v5.s[2]
uzp2 v17.8h, v30.8h, v31.8h
mla v26.4s, v22.4s, v5.s[2]
mla v27.4s, v23.4s, v5.s[2]
uzp2 v16.8h, v28.8h, v29.8h
ldp q30, q31, [x12, #128]
mov w3, #256
add v21.8h, v17.8h, v1.8h
uzp2 v6.8h, v24.8h, v25.8h
uzp2 v7.8h, v26.8h, v27.8h
neg v29.8h, v31.8h
add v20.8h, v16.8h, v1.8h
and v21.16b, v21.16b, v3.16b
add v19.8h, v7.8h, v0.8h
add v18.8h, v6.8h, v0.8h
and v20.16b, v20.16b, v3.16b
ushl v24.8h, v6.8h, v29.8h
ushl v26.8h, v16.8h, v29.8h
ushl v25.8h, v7.8h, v29.8h
ushl v27.8h, v17.8h, v29.8h
and v23.16b, v19.16b, v2.16b
and v22.16b, v18.16b, v2.16b
uzp1 v0.16b, v24.16b, v26.16b
and v18.16b, v6.16b, v30.16b
uzp1 v1.16b, v25.16b, v27.16b
mla v23.8h, v21.8h, v4.h[4]
mla v22.8h, v20.8h, v4.h[4]
and v20.16b, v7.16b, v30.16b
mvn v2.16b, v0.16b
mvn v3.16b, v1.16b
and v21.16b, v17.16b, v30.16b
umaxp v0.16b, v0.16b, v1.16b
movi v6.16b, #8
and v19.16b, v16.16b, v30.16b
umaxp v2.16b, v2.16b, v3.16b
st1 {v22.8h, v23.8h}, [x0], #32
ldr q4, [x12, #192]
mul v30.8h, v20.8h, v21.8h
ushl v20.8h, v20.8h, v31.8h
ushl v21.8h, v21.8h, v31.8h
mul v5.8h, v18.8h, v19.8h
ushl v18.8h, v18.8h, v31.8h
umaxp v0.16b, v0.16b, v2.16b
ushl v19.8h, v19.8h, v31.8h
movi v29.16b, #2
add x4, x11, #32
umaxp v0.16b, v0.16b, v0.16b
ldr q31, [x12, #160]
ldr x5, [x0, #-32]
movi v7.16b, #10
fmov x11, d0
mvn x12, x11
lsr x15, x11, #32
ubfx x16, x12, #32, #8
ubfx x17, x12, #40, #8
cmp w16, w13
ubfx x19, x12, #48, #8
add w11, w11, w15
ldr x15, [x0, #-24]
csel w16, w16, w13, lt
cmp w17, w14
lsr x12, x12, #56
add w11, w11, #1
csel w17, w17, w14, lt
cmp w19, w13
and w20, w11, w11, lsr #1
csel w13, w19, w13, lt
cmp w12, w14
madd x19, x17, x9, x8
add w17, w16, w17, lsl #2
orr w11, w11, w20, lsl #2
csel w12, w12, w14, lt
lsr w20, w15, #16
and w14, w5, #0xffff
add x16, x19, x16, lsl #1
msub w2, w17, w1, w2
madd x8, x12, x9, x8
add w12, w13, w12, lsl #2
tst w11, #0xfcfcfcfc
add x8, x8, x13, lsl #1
dup v22.8h, w2
msub w1, w12, w1, w3
ldr d0, [x16]
and w12, w15, #0xffff
add x11, x16, x9
ubfx x16, x15, #32, #16
cset w2, ne
ldr d2, [x8]
ldr x13, [x0, #-16]
mla v22.8h, v24.8h, v4.h[0]
ld1 {v0.d}[1], [x11]
dup v23.8h, w1
ldrb w1, [x6, x12]
add x8, x8, x9
add x11, x11, x9
lsr w12, w5, #16
mla v22.8h, v26.8h, v4.h[1]
ldr d1, [x11]
mla v23.8h, v25.8h, v4.h[0]
ld1 {v2.d}[1], [x8]
add x11, x11, x9
add x8, x8, x9
ldrb w12, [x6, x12]
add v24.8h, v22.8h, v29.8h
add v26.8h, v22.8h, v7.8h
mla v23.8h, v27.8h, v4.h[1]
add v25.8h, v22.8h, v6.8h
ldr d3, [x8]
ld1 {v1.d}[1], [x11]
add x8, x8, x9
add v27.8h, v23.8h, v29.8h
add v17.8h, v23.8h, v7.8h
tbl v24.16b, {v0.16b, v1.16b}, v24.16b
tbl v26.16b, {v0.16b, v1.16b}, v26.16b
tbl v22.16b, {v0.16b, v1.16b}, v22.16b
tbl v25.16b, {v0.16b, v1.16b}, v25.16b
add v16.8h, v23.8h, v6.8h
ld1 {v3.d}[1], [x8]
ldr x0, [x0, #-8]
sub v26.8h, v26.8h, v24.8h
sub v24.8h, v24.8h, v22.8h
umull v6.4s, v22.4h, v4.h[2]
tbl v27.16b, {v2.16b, v3.16b}, v27.16b
tbl v17.16b, {v2.16b, v3.16b}, v17.16b
tbl v23.16b, {v2.16b, v3.16b}, v23.16b
umull2 v7.4s, v22.8h, v4.h[2]
tbl v16.16b, {v2.16b, v3.16b}, v16.16b
sub v25.8h, v25.8h, v22.8h
smlal v6.4s, v18.4h, v24.4h
sub v17.8h, v17.8h, v27.8h
sub v27.8h, v27.8h, v23.8h
umull v28.4s, v23.4h, v4.h[2]
smlal2 v7.4s, v18.8h, v24.8h
umull2 v29.4s, v23.8h, v4.h[2]
sub v16.8h, v16.8h, v23.8h
sub v26.8h, v26.8h, v25.8h
smlal v6.4s, v19.4h, v25.4h
smlal v28.4s, v20.4h, v27.4h
smlal2 v7.4s, v19.8h, v25.8h
smlal2 v29.4s, v20.8h, v27.8h
sub v17.8h, v17.8h, v16.8h
smlal v6.4s, v5.4h, v26.4h
smlal v28.4s, v21.4h, v16.4h
smlal2 v7.4s, v5.8h, v26.8h
smlal2 v29.4s, v21.8h, v16.8h
ushl v6.4s, v6.4s, v31.4s
smlal v28.4s, v30.4h, v17.4h
ushl v7.4s, v7.4s, v31.4s
smlal2 v29.4s, v30.8h, v17.8h
lsr x11, x15, #48
ushl v28.4s, v28.4s, v31.4s
uzp1 v6.8h, v6.8h, v7.8h
ushl v29.4s, v29.4s, v31.4s
ubfx x8, x5, #32, #16
ldrb w11, [x6, x11]
lsr x5, x5, #48
uzp1 v7.8h, v28.8h, v29.8h
shl v6.8h, v6.8h, #8
and w15, w13, #0xffff
ldrb w5, [x6, x5]
ldrb w9, [x6, x16]
shl v7.8h, v7.8h, #8
ldrb w8, [x6, x8]
ldrb w15, [x6, x15]
ldrb w3, [x6, x20]
st1 {v6.8h, v7.8h}, [x4], #32
ldrb w14, [x6, x14]
ldr x16, [x4, #-32]
ldr x19, [x4, #-16]
ldr x17, [x4, #-24]
ldr x4, [x4, #-8]
add w14, w14, w16, uxth
add w12, w12, w16, lsr #16
ubfx x20, x16, #32, #16
add x5, x5, x16, lsr #48
add w1, w1, w17, uxth
add w3, w3, w17, lsr #16
add w8, w8, w20
ldrb w12, [x7, x12]
ldrb w5, [x7, x5]
ldrb w14, [x7, x14]
ldrb w1, [x7, x1]
ldrb w3, [x7, x3]
ldrb w8, [x7, x8]
ubfx x16, x4, #32, #16
add x11, x11, x17, lsr #48
orr x12, x14, x12, lsl #8
ubfx x14, x17, #32, #16
orr x5, x8, x5, lsl #8
and w8, w0, #0xffff
add w9, w9, w14
ldrb w11, [x7, x11]
orr x1, x1, x3, lsl #8
orr x3, x12, x5, lsl #16
ubfx x12, x13, #32, #16
lsr w5, w13, #16
ldrb w9, [x7, x9]
add w15, w15, w19, uxth
ldrb w5, [x6, x5]
ldrb w12, [x6, x12]
ldrb w8, [x6, x8]
orr x9, x9, x11, lsl #8
ldrb w11, [x7, x15]
add w5, w5, w19, lsr #16
lsr w14, w0, #16
lsr x13, x13, #48
ubfx x15, x0, #32, #16
lsr x0, x0, #48
ldrb w13, [x6, x13]
ldrb w0, [x6, x0]
ldrb w14, [x6, x14]
add w8, w8, w4, uxth
ldrb w15, [x6, x15]
add x6, x13, x19, lsr #48
ubfx x13, x19, #32, #16
add w12, w12, w13
add w14, w14, w4, lsr #16
ldrb w5, [x7, x5]
add x0, x0, x4, lsr #48
ldrb w4, [x7, x6]
ldrb w6, [x7, x8]
add w13, w15, w16
ldrb w8, [x7, x12]
orr x1, x1, x9, lsl #16
ldrb w0, [x7, x0]
ldrb w12, [x7, x14]
orr x5, x11, x5, lsl #8
ldrb w13, [x7, x13]
orr x4, x8, x4, lsl #8
orr x6, x6, x12, lsl #8
orr x0, x13, x0, lsl #8
orr x1, x3, x1, lsl #32
orr x4, x5, x4, lsl #16
orr x0, x6, x0, lsl #16
orr x0, x4, x0, lsl #32
stp x1, x0, [x10]
