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
add x15, x11, #64
ldr q4, [x11, #64]
mov v5.s[3], w5
ld4r {v0.8h, v1.8h, v2.8h, v3.8h}, [x15]
mov x16, x11
mov w3, #514
mov w5, #256
mov w1, #256
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
movi v29.16b, #2
mla v23.8h, v21.8h, v4.h[4]
mla v22.8h, v20.8h, v4.h[4]
and v20.16b, v7.16b, v30.16b
mvn v2.16b, v0.16b
mvn v3.16b, v1.16b
umaxp v0.16b, v0.16b, v1.16b
movi v7.16b, #10
and v21.16b, v17.16b, v30.16b
movi v6.16b, #8
and v19.16b, v16.16b, v30.16b
umaxp v2.16b, v2.16b, v3.16b
st1 {v22.8h, v23.8h}, [x16], #32
ldr q4, [x12, #192]
mul v30.8h, v20.8h, v21.8h
ushl v20.8h, v20.8h, v31.8h
ushl v21.8h, v21.8h, v31.8h
mul v5.8h, v18.8h, v19.8h
ushl v18.8h, v18.8h, v31.8h
umaxp v0.16b, v0.16b, v2.16b
ushl v19.8h, v19.8h, v31.8h
ldr q31, [x12, #160]
add x15, x11, #32
ldr x12, [x16, #-32]
umaxp v0.16b, v0.16b, v0.16b
fmov x17, d0
mvn x19, x17
lsr x24, x17, #32
ubfx x20, x19, #32, #8
ubfx x21, x19, #40, #8
ubfx x22, x19, #48, #8
lsr x23, x19, #56
cmp w20, w13
add w25, w17, w24
ldr x17, [x16, #-24]
csel w20, w20, w13, lt
cmp w21, w14
add w25, w25, #1
csel w21, w21, w14, lt
cmp w22, w13
and w26, w25, w25, lsr #1
csel w22, w22, w13, lt
cmp w23, w14
madd x27, x21, x9, x8
add w4, w20, w21, lsl #2
orr w25, w25, w26, lsl #2
csel w23, w23, w14, lt
and w26, w12, #0xffff
lsr w21, w17, #16
add x27, x27, x20, lsl #1
msub w5, w4, w3, w5
madd x28, x23, x9, x8
ldrb w26, [x6, x26]
add w0, w22, w23, lsl #2
tst w25, #0xfcfcfcfc
ldr d0, [x27]
dup v22.8h, w5
msub w1, w0, w3, w1
ldrb w21, [x6, x21]
add x28, x28, x22, lsl #1
add x27, x27, x9
and w20, w17, #0xffff
ldr x3, [x16, #-16]
cset w2, ne
ldr d2, [x28]
ld1 {v0.d}[1], [x27]
mla v22.8h, v24.8h, v4.h[0]
dup v23.8h, w1
ldrb w20, [x6, x20]
add x28, x28, x9
add x27, x27, x9
lsr w25, w12, #16
ubfx x4, x17, #32, #16
mla v22.8h, v26.8h, v4.h[1]
mla v23.8h, v25.8h, v4.h[0]
ld1 {v2.d}[1], [x28]
ldr d1, [x27]
add x28, x28, x9
add x27, x27, x9
ldrb w25, [x6, x25]
add v24.8h, v22.8h, v29.8h
mla v23.8h, v27.8h, v4.h[1]
add v26.8h, v22.8h, v7.8h
add v25.8h, v22.8h, v6.8h
ldr d3, [x28]
ld1 {v1.d}[1], [x27]
add x28, x28, x9
ldrb w4, [x6, x4]
add v27.8h, v23.8h, v29.8h
add v17.8h, v23.8h, v7.8h
tbl v24.16b, {v0.16b, v1.16b}, v24.16b
tbl v26.16b, {v0.16b, v1.16b}, v26.16b
add v16.8h, v23.8h, v6.8h
tbl v22.16b, {v0.16b, v1.16b}, v22.16b
tbl v25.16b, {v0.16b, v1.16b}, v25.16b
ld1 {v3.d}[1], [x28]
ldr x1, [x16, #-8]
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
ushl v6.4s, v6.4s, v31.4s
smlal v28.4s, v30.4h, v17.4h
ushl v7.4s, v7.4s, v31.4s
smlal2 v29.4s, v30.8h, v17.8h
ushl v28.4s, v28.4s, v31.4s
uzp1 v6.8h, v6.8h, v7.8h
ushl v29.4s, v29.4s, v31.4s
ubfx x27, x12, #32, #16
lsr x28, x12, #48
shl v6.8h, v6.8h, #8
uzp1 v7.8h, v28.8h, v29.8h
ldrb w27, [x6, x27]
ldrb w28, [x6, x28]
lsr x22, x17, #48
and w17, w3, #0xffff
shl v7.8h, v7.8h, #8
ldrb w22, [x6, x22]
ldrb w17, [x6, x17]
st1 {v6.8h, v7.8h}, [x15], #32
ldr x19, [x15, #-32]
ldr x24, [x15, #-24]
ldr x5, [x15, #-16]
ldr x12, [x15, #-8]
add w26, w26, w19, uxth
add w25, w25, w19, lsr #16
ubfx x23, x19, #32, #16
add x28, x28, x19, lsr #48
add w20, w20, w24, uxth
add w21, w21, w24, lsr #16
add w27, w27, w23
ldrb w26, [x7, x26]
ldrb w25, [x7, x25]
ldrb w28, [x7, x28]
ldrb w27, [x7, x27]
ldrb w20, [x7, x20]
ldrb w21, [x7, x21]
add x22, x22, x24, lsr #48
orr x26, x26, x25, lsl #8
ubfx x0, x24, #32, #16
orr x27, x27, x28, lsl #8
and w24, w1, #0xffff
add w17, w17, w5, uxth
add w4, w4, w0
ldrb w22, [x7, x22]
orr x20, x20, x21, lsl #8
orr x26, x26, x27, lsl #16
lsr w23, w3, #16
ubfx x19, x3, #32, #16
ldrb w4, [x7, x4]
ldrb w23, [x6, x23]
ldrb w19, [x6, x19]
ldrb w24, [x6, x24]
orr x4, x4, x22, lsl #8
ldrb w17, [x7, x17]
add w23, w23, w5, lsr #16
lsr x0, x3, #48
lsr w25, w1, #16
ubfx x28, x1, #32, #16
lsr x21, x1, #48
ldrb w0, [x6, x0]
ldrb w25, [x6, x25]
ldrb w28, [x6, x28]
ldrb w21, [x6, x21]
add x0, x0, x5, lsr #48
add w24, w24, w12, uxth
ubfx x22, x5, #32, #16
ubfx x27, x12, #32, #16
add w25, w25, w12, lsr #16
ldrb w23, [x7, x23]
add w19, w19, w22
add w28, w28, w27
add x21, x21, x12, lsr #48
ldrb w0, [x7, x0]
ldrb w24, [x7, x24]
ldrb w19, [x7, x19]
ldrb w25, [x7, x25]
ldrb w28, [x7, x28]
ldrb w21, [x7, x21]
orr x17, x17, x23, lsl #8
orr x19, x19, x0, lsl #8
orr x24, x24, x25, lsl #8
orr x20, x20, x4, lsl #16
orr x28, x28, x21, lsl #8
orr x17, x17, x19, lsl #16
orr x26, x26, x20, lsl #32
orr x24, x24, x28, lsl #16
orr x17, x17, x24, lsl #32
stp x26, x17, [x10]
