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
ldr w19, [x12, #180]
mov w21, #1
mov w20, #0x0202
mov x16, x11
mov w15, #514
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
st1 {v22.8h, v23.8h}, [x16], #32
movk w20, #0x0808, lsl #16
lsl w22, w21, w19
mov w21, #256
umaxp v0.16b, v0.16b, v0.16b
orr x20, x20, x22, lsl #32
mov w22, #256
fmov x17, d0
fmov d4, x20
add x20, x11, #32
mvn x23, x17
and w28, w17, #0xff
ubfx w3, w17, #8, #8
ubfx w4, w17, #16, #8
ubfx w5, w17, #24, #8
ubfx x24, x23, #32, #8
ubfx x25, x23, #40, #8
ubfx x26, x23, #48, #8
lsr x27, x23, #56
cmp w24, w13
ldr x23, [x16, #-32]
csel w24, w24, w13, lt
cmp w25, w14
csel w25, w25, w14, lt
cmp w26, w13
sub w28, w28, w24
csel w26, w26, w13, lt
cmp w27, w14
madd x0, x25, x9, x8
add w12, w24, w25, lsl #2
sub w3, w3, w25
csel w27, w27, w14, lt
cmp w28, #2
sub w4, w4, w26
ldr x28, [x16, #-24]
add x0, x0, x24, lsl #1
msub w21, w12, w15, w21
madd x1, x27, x9, x8
add w19, w26, w27, lsl #2
ccmp w3, #2, #2, ls
ldr d0, [x0]
dup v22.8h, w21
msub w22, w19, w15, w22
ldr x15, [x16, #-16]
add x1, x1, x26, lsl #1
add x0, x0, x9
sub w5, w5, w27
ccmp w4, #2, #2, ls
and w4, w23, #0xffff
and w24, w28, #0xffff
ldr d2, [x1]
ld1 {v0.d}[1], [x0]
mla v22.8h, v24.8h, v4.h[0]
dup v23.8h, w22
ldrb w4, [x6, x4]
add x1, x1, x9
add x0, x0, x9
ccmp w5, #2, #2, ls
ldrb w24, [x6, x24]
mla v22.8h, v26.8h, v4.h[1]
mla v23.8h, v25.8h, v4.h[0]
ld1 {v2.d}[1], [x1]
ldr d1, [x0]
add x1, x1, x9
add x0, x0, x9
lsr w5, w23, #16
lsr w25, w28, #16
add v24.8h, v22.8h, v29.8h
mla v23.8h, v27.8h, v4.h[1]
add v26.8h, v22.8h, v7.8h
add v25.8h, v22.8h, v6.8h
ldr d3, [x1]
ld1 {v1.d}[1], [x0]
add x1, x1, x9
ldrb w5, [x6, x5]
add v27.8h, v23.8h, v29.8h
add v17.8h, v23.8h, v7.8h
tbl v24.16b, {v0.16b, v1.16b}, v24.16b
tbl v26.16b, {v0.16b, v1.16b}, v26.16b
add v16.8h, v23.8h, v6.8h
tbl v22.16b, {v0.16b, v1.16b}, v22.16b
tbl v25.16b, {v0.16b, v1.16b}, v25.16b
ld1 {v3.d}[1], [x1]
ldrb w25, [x6, x25]
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
ldr x22, [x16, #-8]
ushl v6.4s, v6.4s, v31.4s
smlal v28.4s, v30.4h, v17.4h
ushl v7.4s, v7.4s, v31.4s
smlal2 v29.4s, v30.8h, v17.8h
cset w2, hi
ushl v28.4s, v28.4s, v31.4s
uzp1 v6.8h, v6.8h, v7.8h
ushl v29.4s, v29.4s, v31.4s
ubfx x0, x23, #32, #16
lsr x1, x23, #48
shl v6.8h, v6.8h, #8
uzp1 v7.8h, v28.8h, v29.8h
ldrb w0, [x6, x0]
ldrb w1, [x6, x1]
ubfx x12, x28, #32, #16
lsr x26, x28, #48
shl v7.8h, v7.8h, #8
ldrb w12, [x6, x12]
ldrb w26, [x6, x26]
and w28, w15, #0xffff
st1 {v6.8h, v7.8h}, [x20], #32
ldrb w28, [x6, x28]
ldr x17, [x20, #-32]
ldr x3, [x20, #-24]
ldr x21, [x20, #-16]
ldr x23, [x20, #-8]
add w4, w4, w17, uxth
add w5, w5, w17, lsr #16
ubfx x27, x17, #32, #16
add x1, x1, x17, lsr #48
add w24, w24, w3, uxth
add w25, w25, w3, lsr #16
add w0, w0, w27
ldrb w4, [x7, x4]
ldrb w5, [x7, x5]
ldrb w1, [x7, x1]
ldrb w0, [x7, x0]
ldrb w24, [x7, x24]
ldrb w25, [x7, x25]
add x26, x26, x3, lsr #48
orr x4, x4, x5, lsl #8
ubfx x19, x3, #32, #16
orr x0, x0, x1, lsl #8
and w3, w22, #0xffff
add w28, w28, w21, uxth
add w12, w12, w19
ldrb w26, [x7, x26]
orr x24, x24, x25, lsl #8
orr x4, x4, x0, lsl #16
lsr w27, w15, #16
ubfx x17, x15, #32, #16
ldrb w12, [x7, x12]
ldrb w27, [x6, x27]
ldrb w17, [x6, x17]
ldrb w3, [x6, x3]
orr x12, x12, x26, lsl #8
ldrb w28, [x7, x28]
add w27, w27, w21, lsr #16
lsr x19, x15, #48
lsr w5, w22, #16
ubfx x1, x22, #32, #16
lsr x25, x22, #48
ldrb w19, [x6, x19]
ldrb w5, [x6, x5]
ldrb w1, [x6, x1]
ldrb w25, [x6, x25]
add x19, x19, x21, lsr #48
add w3, w3, w23, uxth
ubfx x26, x21, #32, #16
ubfx x0, x23, #32, #16
add w5, w5, w23, lsr #16
ldrb w27, [x7, x27]
add w17, w17, w26
add w1, w1, w0
add x25, x25, x23, lsr #48
ldrb w19, [x7, x19]
ldrb w3, [x7, x3]
ldrb w17, [x7, x17]
ldrb w5, [x7, x5]
ldrb w1, [x7, x1]
ldrb w25, [x7, x25]
orr x28, x28, x27, lsl #8
orr x17, x17, x19, lsl #8
orr x3, x3, x5, lsl #8
orr x24, x24, x12, lsl #16
orr x1, x1, x25, lsl #8
orr x28, x28, x17, lsl #16
orr x4, x4, x24, lsl #32
orr x3, x3, x1, lsl #16
orr x28, x28, x3, lsl #32
stp x4, x28, [x10]
