fmov s5, w2
dup v30.4s, w1
dup v31.4s, w1
dup v28.4s, w1
dup v29.4s, w1
dup v25.4s, w0
mov v5.s[1], w3
dup v24.4s, w0
dup v26.4s, w0
dup v27.4s, w0
ldp q18, q19, [x12, #32]
mov v5.s[2], w4
ldp q16, q17, [x12]
ldp q22, q23, [x12, #96]
ldp q20, q21, [x12, #64]
add x0, x11, #64
ldr q4, [x11, #64]
mov v5.s[3], w5
ld4r {v0.8h, v1.8h, v2.8h, v3.8h}, [x0]
ldr w0, [x12, #180]
mov w1, #1
mov w2, #0x0202
mov x3, x11
mov w4, #514
mla v30.4s, v18.4s, v5.s[1]
mla v31.4s, v19.4s, v5.s[1]
mla v28.4s, v16.4s, v5.s[1]
mla v29.4s, v17.4s, v5.s[1]
mla v25.4s, v17.4s, v5.s[0]
mla v24.4s, v16.4s, v5.s[0]
mla v30.4s, v22.4s, v5.s[3]
mla v31.4s, v23.4s, v5.s[3]
mla v26.4s, v18.4s, v5.s[0]
mla v27.4s, v19.4s, v5.s[0]
mla v28.4s, v20.4s, v5.s[3]
mla v29.4s, v21.4s, v5.s[3]
mla v24.4s, v20.4s, v5.s[2]
uzp2 v17.8h, v30.8h, v31.8h
mla v25.4s, v21.4s, v5.s[2]
mla v26.4s, v22.4s, v5.s[2]
mla v27.4s, v23.4s, v5.s[2]
uzp2 v16.8h, v28.8h, v29.8h
ldp q30, q31, [x12, #128]
add v21.8h, v17.8h, v1.8h
uzp2 v6.8h, v24.8h, v25.8h
uzp2 v7.8h, v26.8h, v27.8h
neg v29.8h, v31.8h
add v20.8h, v16.8h, v1.8h
and v21.16b, v21.16b, v3.16b
add v18.8h, v6.8h, v0.8h
add v19.8h, v7.8h, v0.8h
ushl v24.8h, v6.8h, v29.8h
ushl v25.8h, v7.8h, v29.8h
ushl v26.8h, v16.8h, v29.8h
ushl v27.8h, v17.8h, v29.8h
and v22.16b, v18.16b, v2.16b
and v23.16b, v19.16b, v2.16b
and v20.16b, v20.16b, v3.16b
and v18.16b, v6.16b, v30.16b
uzp1 v0.16b, v24.16b, v26.16b
uzp1 v1.16b, v25.16b, v27.16b
and v19.16b, v16.16b, v30.16b
mla v23.8h, v21.8h, v4.h[4]
mla v22.8h, v20.8h, v4.h[4]
and v20.16b, v7.16b, v30.16b
mvn v2.16b, v0.16b
mvn v3.16b, v1.16b
umaxp v0.16b, v0.16b, v1.16b
mul v5.8h, v18.8h, v19.8h
and v21.16b, v17.16b, v30.16b
ushl v18.8h, v18.8h, v31.8h
ushl v19.8h, v19.8h, v31.8h
movi v29.16b, #2
umaxp v2.16b, v2.16b, v3.16b
movi v7.16b, #10
mul v30.8h, v20.8h, v21.8h
ushl v20.8h, v20.8h, v31.8h
ushl v21.8h, v21.8h, v31.8h
movi v6.16b, #8
umaxp v0.16b, v0.16b, v2.16b
ldr q31, [x12, #160]
st1 {v22.8h, v23.8h}, [x3], #32
movk w2, #0x0808, lsl #16
lsl w0, w1, w0
mov w1, #256
umaxp v0.16b, v0.16b, v0.16b
orr x0, x2, x0, lsl #32
mov w2, #256
fmov x5, d0
fmov d4, x0
add x0, x11, #32
mvn x11, x5
and w12, w5, #0xff
ubfx w15, w5, #8, #8
ubfx w16, w5, #16, #8
ubfx w5, w5, #24, #8
ubfx x17, x11, #32, #8
ubfx x19, x11, #40, #8
ubfx x20, x11, #48, #8
lsr x11, x11, #56
cmp w17, w13
ldr x21, [x3, #-32]
csel w17, w17, w13, lt
cmp w19, w14
csel w19, w19, w14, lt
cmp w20, w13
sub w12, w12, w17
csel w13, w20, w13, lt
cmp w11, w14
madd x20, x19, x9, x8
add w22, w17, w19, lsl #2
sub w15, w15, w19
csel w11, w11, w14, lt
cmp w12, #2
sub w12, w16, w13
ldr x14, [x3, #-24]
add x16, x20, x17, lsl #1
msub w1, w22, w4, w1
madd x8, x11, x9, x8
add w17, w13, w11, lsl #2
ccmp w15, #2, #2, ls
ldr d0, [x16]
dup v22.8h, w1
msub w1, w17, w4, w2
ldr x4, [x3, #-16]
add x2, x8, x13, lsl #1
add x8, x16, x9
sub w5, w5, w11
ccmp w12, #2, #2, ls
and w11, w21, #0xffff
and w12, w14, #0xffff
ldr d2, [x2]
ld1 {v0.d}[1], [x8]
mla v22.8h, v24.8h, v4.h[0]
dup v23.8h, w1
ldrb w1, [x6, x11]
add x2, x2, x9
add x8, x8, x9
ccmp w5, #2, #2, ls
ldrb w5, [x6, x12]
mla v22.8h, v26.8h, v4.h[1]
mla v23.8h, v25.8h, v4.h[0]
ld1 {v2.d}[1], [x2]
ldr d1, [x8]
add x2, x2, x9
add x8, x8, x9
lsr w11, w21, #16
lsr w12, w14, #16
add v24.8h, v22.8h, v29.8h
mla v23.8h, v27.8h, v4.h[1]
add v26.8h, v22.8h, v7.8h
add v25.8h, v22.8h, v6.8h
ldr d3, [x2]
ld1 {v1.d}[1], [x8]
add x2, x2, x9
ldrb w8, [x6, x11]
add v27.8h, v23.8h, v29.8h
add v17.8h, v23.8h, v7.8h
tbl v24.16b, {v0.16b, v1.16b}, v24.16b
tbl v26.16b, {v0.16b, v1.16b}, v26.16b
add v16.8h, v23.8h, v6.8h
tbl v22.16b, {v0.16b, v1.16b}, v22.16b
tbl v25.16b, {v0.16b, v1.16b}, v25.16b
ld1 {v3.d}[1], [x2]
ldrb w9, [x6, x12]
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
sub v26.8h, v26.8h, v25.8h
sub v16.8h, v16.8h, v23.8h
smlal v6.4s, v19.4h, v25.4h
smlal v28.4s, v20.4h, v27.4h
smlal2 v7.4s, v19.8h, v25.8h
smlal2 v29.4s, v20.8h, v27.8h
sub v17.8h, v17.8h, v16.8h
smlal v6.4s, v5.4h, v26.4h
smlal v28.4s, v21.4h, v16.4h
smlal2 v7.4s, v5.8h, v26.8h
smlal2 v29.4s, v21.8h, v16.8h
ldr x3, [x3, #-8]
ushl v6.4s, v6.4s, v31.4s
smlal v28.4s, v30.4h, v17.4h
ushl v7.4s, v7.4s, v31.4s
smlal2 v29.4s, v30.8h, v17.8h
cset w2, hi
ushl v28.4s, v28.4s, v31.4s
uzp1 v6.8h, v6.8h, v7.8h
ushl v29.4s, v29.4s, v31.4s
ubfx x11, x21, #32, #16
lsr x12, x21, #48
shl v6.8h, v6.8h, #8
uzp1 v7.8h, v28.8h, v29.8h
ldrb w11, [x6, x11]
ldrb w12, [x6, x12]
ubfx x13, x14, #32, #16
lsr x14, x14, #48
shl v7.8h, v7.8h, #8
ldrb w13, [x6, x13]
ldrb w14, [x6, x14]
and w15, w4, #0xffff
st1 {v6.8h, v7.8h}, [x0], #32
ldrb w15, [x6, x15]
ldr x16, [x0, #-32]
ldr x17, [x0, #-24]
ldr x19, [x0, #-16]
ldr x0, [x0, #-8]
add w1, w1, w16, uxth
add w8, w8, w16, lsr #16
ubfx x20, x16, #32, #16
add x12, x12, x16, lsr #48
add w5, w5, w17, uxth
add w9, w9, w17, lsr #16
add w11, w11, w20
ldrb w1, [x7, x1]
ldrb w8, [x7, x8]
ldrb w12, [x7, x12]
ldrb w11, [x7, x11]
ldrb w5, [x7, x5]
ldrb w9, [x7, x9]
add x14, x14, x17, lsr #48
orr x1, x1, x8, lsl #8
ubfx x8, x17, #32, #16
orr x11, x11, x12, lsl #8
and w12, w3, #0xffff
add w15, w15, w19, uxth
add w8, w13, w8
ldrb w13, [x7, x14]
orr x5, x5, x9, lsl #8
orr x1, x1, x11, lsl #16
lsr w9, w4, #16
ubfx x11, x4, #32, #16
ldrb w8, [x7, x8]
ldrb w9, [x6, x9]
ldrb w11, [x6, x11]
ldrb w12, [x6, x12]
orr x8, x8, x13, lsl #8
ldrb w13, [x7, x15]
add w9, w9, w19, lsr #16
lsr x4, x4, #48
lsr w14, w3, #16
ubfx x15, x3, #32, #16
lsr x3, x3, #48
ldrb w4, [x6, x4]
ldrb w14, [x6, x14]
ldrb w15, [x6, x15]
ldrb w3, [x6, x3]
add x4, x4, x19, lsr #48
add w6, w12, w0, uxth
ubfx x12, x19, #32, #16
ubfx x16, x0, #32, #16
add w14, w14, w0, lsr #16
ldrb w9, [x7, x9]
add w11, w11, w12
add w12, w15, w16
add x0, x3, x0, lsr #48
ldrb w3, [x7, x4]
ldrb w4, [x7, x6]
ldrb w6, [x7, x11]
ldrb w11, [x7, x14]
ldrb w12, [x7, x12]
ldrb w0, [x7, x0]
orr x7, x13, x9, lsl #8
orr x3, x6, x3, lsl #8
orr x4, x4, x11, lsl #8
orr x5, x5, x8, lsl #16
orr x0, x12, x0, lsl #8
orr x3, x7, x3, lsl #16
orr x1, x1, x5, lsl #32
orr x0, x4, x0, lsl #16
orr x0, x3, x0, lsl #32
stp x1, x0, [x10]
