fmov s5, w2
dup v24.4s, w0
dup v25.4s, w0
dup v26.4s, w0
dup v28.4s, w1
dup v29.4s, w1
mov v5.s[1], w3
ldp q16, q17, [x12]
add w13, w5, w5, lsl #1
add x14, x11, #64
add w15, w4, w4, lsl #1
dup v31.4s, w1
dup v27.4s, w0
mov v5.s[2], w4
ld4r {v0.8h, v1.8h, v2.8h, v3.8h}, [x14]
dup v30.4s, w1
ldp q18, q19, [x12, #32]
add w14, w2, w15
add w16, w2, w4, lsl #3
add w17, w3, w13
add w19, w2, w15, lsl #1
mov v5.s[3], w5
ldp q20, q21, [x12, #64]
add w20, w16, w15
sub w4, w16, w4
lsl w21, w14, #3
add w15, w16, w15, lsl #1
add w22, w3, w5, lsl #3
sub w14, w21, w14
add w21, w3, w13, lsl #1
mla v24.4s, v16.4s, v5.s[0]
mla v28.4s, v16.4s, v5.s[1]
mla v25.4s, v17.4s, v5.s[0]
mla v29.4s, v17.4s, v5.s[1]
mla v30.4s, v18.4s, v5.s[1]
mla v27.4s, v19.4s, v5.s[0]
mla v31.4s, v19.4s, v5.s[1]
mla v24.4s, v20.4s, v5.s[2]
mla v28.4s, v20.4s, v5.s[3]
mla v25.4s, v21.4s, v5.s[2]
mla v26.4s, v18.4s, v5.s[0]
ldp q22, q23, [x12, #96]
eor w15, w15, w16
add w16, w22, w13
lsl w23, w16, #3
lsl w24, w17, #3
add w14, w0, w14
lsl w25, w20, #3
sub w17, w24, w17
sub w20, w25, w20
add w13, w22, w13, lsl #1
eor w3, w21, w3
sub w5, w22, w5
add w4, w14, w4
add w17, w1, w17
add w20, w4, w20
sub w16, w23, w16
eor w13, w13, w22
eor w2, w19, w2
add w5, w17, w5
orr w13, w15, w13
ldp w15, w19, [x12, #176]
eor w21, w1, w17
mla v29.4s, v21.4s, v5.s[3]
mla v26.4s, v22.4s, v5.s[2]
uzp2 v6.8h, v24.8h, v25.8h
mla v27.4s, v23.4s, v5.s[2]
mla v30.4s, v22.4s, v5.s[3]
mla v31.4s, v23.4s, v5.s[3]
uzp2 v16.8h, v28.8h, v29.8h
ldr q4, [x11, #64]
orr w2, w2, w3
add w3, w5, w16
lsr w1, w1, w15
eor w16, w4, w20
eor w22, w0, w14
uzp2 v7.8h, v26.8h, v27.8h
uzp2 v17.8h, v30.8h, v31.8h
add v18.8h, v6.8h, v0.8h
add v20.8h, v16.8h, v1.8h
madd x23, x1, x9, x8
ldp q30, q31, [x12, #128]
eor w24, w5, w3
orr w21, w22, w21
lsr w17, w17, w15
lsr w14, w14, w15
lsr w0, w0, w15
add v19.8h, v7.8h, v0.8h
add v21.8h, v17.8h, v1.8h
and v22.16b, v18.16b, v2.16b
and v20.16b, v20.16b, v3.16b
and v18.16b, v6.16b, v30.16b
and v23.16b, v19.16b, v2.16b
and v21.16b, v21.16b, v3.16b
and v19.16b, v16.16b, v30.16b
mla v22.8h, v20.8h, v4.h[4]
and v20.16b, v7.16b, v30.16b
orr w16, w16, w24
add x22, x23, x0, lsl #1
lsr w23, w3, w15
mla v23.8h, v21.8h, v4.h[4]
mul v5.8h, v18.8h, v19.8h
and v21.16b, v17.16b, v30.16b
ldrh w3, [x22, #2]
ushl v19.8h, v19.8h, v31.8h
ldrh w24, [x22]
orr w16, w21, w16
add x21, x22, x9
lsr w5, w5, w15
mul v30.8h, v20.8h, v21.8h
ushl v21.8h, v21.8h, v31.8h
ushl v20.8h, v20.8h, v31.8h
ushl v18.8h, v18.8h, v31.8h
ldrh w22, [x21, #2]
lsr w4, w4, w15
ldrh w21, [x21]
mov x25, x11
lsr w16, w16, w15
lsr w15, w20, w15
ldr q31, [x12, #160]
madd x20, x5, x9, x8
sub w21, w21, w24
sub w22, w22, w3
add x20, x20, x4, lsl #1
sub w26, w3, w24
lsl w24, w24, w19
bfi w26, w21, #16, #16
lsr w2, w2, #31
lsr w3, w13, #31
ldrh w13, [x20]
sub w21, w22, w21
ldrh w22, [x20, #2]
add x20, x20, x9
dup v27.4s, w24
dup v26.4s, w24
ldrh w24, [x20, #2]
ldrh w20, [x20]
bfi x26, x21, #32, #16
sub w21, w24, w22
sub w20, w20, w13
fmov d0, x26
sub w21, w21, w20
sub w22, w22, w13
lsl w13, w13, w19
bfi w22, w20, #16, #16
bfi x22, x21, #32, #16
dup v28.4s, w13
fmov d2, x22
smlal v26.4s, v18.4h, v0.h[0]
smlal2 v27.4s, v18.8h, v0.h[0]
dup v29.4s, w13
smlal v28.4s, v20.4h, v2.h[0]
smlal v26.4s, v19.4h, v0.h[1]
smlal2 v27.4s, v19.8h, v0.h[1]
smlal2 v29.4s, v20.8h, v2.h[0]
smlal v28.4s, v21.4h, v2.h[1]
smlal v26.4s, v5.4h, v0.h[2]
smlal2 v27.4s, v5.8h, v0.h[2]
smlal2 v29.4s, v21.8h, v2.h[1]
smlal v28.4s, v30.4h, v2.h[2]
ushl v26.4s, v26.4s, v31.4s
ushl v27.4s, v27.4s, v31.4s
smlal2 v29.4s, v30.8h, v2.h[2]
ushl v28.4s, v28.4s, v31.4s
uzp1 v26.8h, v26.8h, v27.8h
ushl v29.4s, v29.4s, v31.4s
uzp1 v27.8h, v28.8h, v29.8h
st1 {v22.8h, v23.8h}, [x25], #32
cbz w16, 1f
madd x13, x17, x9, x8
dup v0.8h, v6.h[0]
dup v2.8h, v16.h[0]
dup v4.8h, v7.h[0]
madd x8, x23, x9, x8
ldr q29, [x12, #128]
add x12, x13, x14, lsl #1
eor v0.16b, v0.16b, v6.16b
eor v2.16b, v2.16b, v16.16b
eor v4.16b, v4.16b, v7.16b
ldrh w13, [x12]
ldrh w16, [x12, #2]
add x12, x12, x9
add x8, x8, x15, lsl #1
orr v0.16b, v0.16b, v2.16b
dup v2.8h, v17.h[0]
ldrh w20, [x12, #2]
ldrh w12, [x12]
ldrh w21, [x8]
ldrh w22, [x8, #2]
add x8, x8, x9
cmhi v0.8h, v0.8h, v29.8h
eor v2.16b, v2.16b, v17.16b
ldrh w9, [x8, #2]
ldrh w8, [x8]
sub w20, w20, w16
sub w12, w12, w13
sub w16, w16, w13
lsl w13, w13, w19
sub w20, w20, w12
sub w9, w9, w22
bfi w16, w12, #16, #16
sub w0, w14, w0
sub w8, w8, w21
sub w12, w22, w21
bfi x16, x20, #32, #16
dup v22.4s, w13
dup v23.4s, w13
fmov d1, x16
orr v4.16b, v4.16b, v2.16b
add w13, w0, #1
sub w9, w9, w8
bfi w12, w8, #16, #16
sub w1, w17, w1
lsl w8, w21, w19
smlal v22.4s, v18.4h, v1.h[0]
smlal2 v23.4s, v18.8h, v1.h[0]
dup v24.4s, w8
dup v25.4s, w8
cmhi v4.8h, v4.8h, v29.8h
smlal v22.4s, v19.4h, v1.h[1]
smlal2 v23.4s, v19.8h, v1.h[1]
cmp w13, #2
add w8, w1, #1
bfi x12, x9, #32, #16
sub w4, w15, w4
sub w5, w23, w5
smlal v22.4s, v5.4h, v1.h[2]
fmov d3, x12
smlal2 v23.4s, v5.8h, v1.h[2]
cset w9, hi
cmp w8, #2
add w8, w4, #1
add w12, w5, #1
smlal v24.4s, v20.4h, v3.h[0]
smlal2 v25.4s, v20.8h, v3.h[0]
ushl v22.4s, v22.4s, v31.4s
ushl v23.4s, v23.4s, v31.4s
cinc w9, w9, hi
cmp w0, #0
smlal v24.4s, v21.4h, v3.h[1]
smlal2 v25.4s, v21.8h, v3.h[1]
uzp1 v22.8h, v22.8h, v23.8h
ccmp w1, #0, #4, ne
smlal v24.4s, v30.4h, v3.h[2]
smlal2 v25.4s, v30.8h, v3.h[2]
bit v26.16b, v22.16b, v0.16b
cinc w0, w9, ne
cmp w8, #2
ushl v24.4s, v24.4s, v31.4s
ushl v25.4s, v25.4s, v31.4s
cset w1, hi
cmp w12, #2
orr w2, w2, w0
cinc w0, w1, hi
cmp w4, #0
uzp1 v24.8h, v24.8h, v25.8h
ccmp w5, #0, #4, ne
cinc w0, w0, ne
bit v27.16b, v24.16b, v4.16b
orr w3, w3, w0
1:
shl v27.8h, v27.8h, #8
shl v26.8h, v26.8h, #8
ldr x0, [x25, #-32]
add x1, x11, #32
ldr x4, [x25, #-24]
ldr x5, [x25, #-16]
ldr x8, [x25, #-8]
st1 {v26.8h, v27.8h}, [x1], #32
and w9, w4, #0xffff
and w11, w0, #0xffff
lsr x12, x4, #48
lsr w13, w0, #16
lsr x14, x0, #48
ubfx x0, x0, #32, #16
lsr w15, w4, #16
ldrb w13, [x6, x13]
ldrb w11, [x6, x11]
ldr x16, [x1, #-32]
ldrb w14, [x6, x14]
ldr x17, [x1, #-24]
ldrb w15, [x6, x15]
ldrb w9, [x6, x9]
add w11, w11, w16, uxth
ldrb w0, [x6, x0]
add x14, x14, x16, lsr #48
add w13, w13, w16, lsr #16
ubfx x4, x4, #32, #16
ubfx x19, x17, #32, #16
ubfx x16, x16, #32, #16
ldrb w12, [x6, x12]
add w0, w0, w16
ldrb w4, [x6, x4]
add w9, w9, w17, uxth
ldrb w13, [x7, x13]
add w15, w15, w17, lsr #16
ldr x16, [x1, #-8]
and w20, w5, #0xffff
ldrb w0, [x7, x0]
ldr x1, [x1, #-16]
add w4, w4, w19
ldrb w11, [x7, x11]
ldrb w14, [x7, x14]
lsr x19, x5, #48
ldrb w9, [x7, x9]
and w21, w8, #0xffff
ldrb w4, [x7, x4]
orr x11, x11, x13, lsl #8
ldrb w13, [x7, x15]
orr x0, x0, x14, lsl #8
ldrb w14, [x6, x20]
add x12, x12, x17, lsr #48
ldrb w15, [x6, x19]
lsr w17, w5, #16
lsr w19, w8, #16
lsr x20, x8, #48
ubfx x8, x8, #32, #16
ubfx x5, x5, #32, #16
ldrb w12, [x7, x12]
orr x9, x9, x13, lsl #8
ldrb w13, [x6, x17]
ubfx x17, x1, #32, #16
ldrb w21, [x6, x21]
orr x4, x4, x12, lsl #8
ldrb w12, [x6, x19]
add w13, w13, w1, lsr #16
ldrb w5, [x6, x5]
add w14, w14, w1, uxth
ldrb w8, [x6, x8]
add x1, x15, x1, lsr #48
add w15, w21, w16, uxth
ubfx x19, x16, #32, #16
ldrb w6, [x6, x20]
add w5, w5, w17
ldrb w13, [x7, x13]
add w12, w12, w16, lsr #16
ldrb w14, [x7, x14]
add w8, w8, w19
ldrb w1, [x7, x1]
ldrb w15, [x7, x15]
add x6, x6, x16, lsr #48
ldrb w5, [x7, x5]
orr x13, x14, x13, lsl #8
ldrb w8, [x7, x8]
ldrb w12, [x7, x12]
orr x0, x11, x0, lsl #16
ldrb w6, [x7, x6]
orr x4, x9, x4, lsl #16
orr x1, x5, x1, lsl #8
orr x5, x8, x6, lsl #8
orr x0, x0, x4, lsl #32
orr x4, x15, x12, lsl #8
orr x1, x13, x1, lsl #16
orr x4, x4, x5, lsl #16
orr x1, x1, x4, lsl #32
stp x0, x1, [x10]
