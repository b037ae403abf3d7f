fmov s5, w2
dup v24.4s, w0
dup v28.4s, w1
dup v25.4s, w0
dup v29.4s, w1
dup v26.4s, w0
mov v5.s[1], w3
dup v30.4s, w1
dup v27.4s, w0
dup v31.4s, w1
ldp q16, q17, [x12]
add x13, x11, #64
add w17, w4, w4, lsl #1
add w27, w5, w5, lsl #1
mov v5.s[2], w4
ld4r {v0.8h, v1.8h, v2.8h, v3.8h}, [x13]
ldp q18, q19, [x12, #32]
add w20, w2, w17
add w22, w2, w4, lsl #3
add w13, w3, w27
add w19, w2, w17, lsl #1
mov v5.s[3], w5
ldp q20, q21, [x12, #64]
sub w23, w22, w4
add w24, w22, w17
lsl w21, w20, #3
add w26, w22, w17, lsl #1
add w4, w3, w5, lsl #3
add w28, w3, w27, lsl #1
sub w21, w21, w20
mla v24.4s, v16.4s, v5.s[0]
mla v28.4s, v16.4s, v5.s[1]
mla v25.4s, v17.4s, v5.s[0]
mla v29.4s, v17.4s, v5.s[1]
mla v26.4s, v18.4s, v5.s[0]
mla v30.4s, v18.4s, v5.s[1]
mla v27.4s, v19.4s, v5.s[0]
mla v31.4s, v19.4s, v5.s[1]
mla v24.4s, v20.4s, v5.s[2]
mla v28.4s, v20.4s, v5.s[3]
mla v25.4s, v21.4s, v5.s[2]
mla v29.4s, v21.4s, v5.s[3]
ldp q22, q23, [x12, #96]
eor w26, w26, w22
add w17, w4, w27
lsl w20, w13, #3
lsl w25, w24, #3
add w21, w0, w21
eor w28, w28, w3
sub w20, w20, w13
sub w25, w25, w24
add w13, w4, w27, lsl #1
sub w24, w4, w5
lsl w22, w17, #3
add w23, w21, w23
add w20, w1, w20
ldp w15, w16, [x12, #176]
eor w13, w13, w4
sub w22, w22, w17
eor w19, w19, w2
add w25, w23, w25
add w24, w20, w24
eor w17, w1, w20
orr w3, w26, w13
mla v26.4s, v22.4s, v5.s[2]
mla v30.4s, v22.4s, v5.s[3]
mla v27.4s, v23.4s, v5.s[2]
mla v31.4s, v23.4s, v5.s[3]
uzp2 v6.8h, v24.8h, v25.8h
uzp2 v16.8h, v28.8h, v29.8h
ldr q4, [x11, #64]
add w22, w24, w22
orr w2, w19, w28
lsr w26, w1, w15
eor w5, w0, w21
eor w27, w23, w25
uzp2 v7.8h, v26.8h, v27.8h
uzp2 v17.8h, v30.8h, v31.8h
add v18.8h, v6.8h, v0.8h
add v20.8h, v16.8h, v1.8h
madd x1, x26, x9, x8
ldp q30, q31, [x12, #128]
eor w4, w24, w22
orr w5, w5, w17
lsr w28, w0, w15
lsr w13, w21, w15
lsr w17, w20, w15
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
orr w27, w27, w4
add x1, x1, x28, lsl #1
lsr w4, w23, w15
lsr w0, w22, w15
mla v23.8h, v21.8h, v4.h[4]
mul v5.8h, v18.8h, v19.8h
and v21.16b, v17.16b, v30.16b
ushl v18.8h, v18.8h, v31.8h
ushl v19.8h, v19.8h, v31.8h
ldrh w21, [x1]
ldrh w20, [x1, #2]
orr w5, w5, w27
add x1, x1, x9
lsr w27, w24, w15
mul v30.8h, v20.8h, v21.8h
ushl v20.8h, v20.8h, v31.8h
ushl v21.8h, v21.8h, v31.8h
ldrh w24, [x1, #2]
ldrh w23, [x1]
ldr q31, [x12, #160]
mov x14, x11
lsr w19, w5, w15
lsr w5, w25, w15
madd x25, x27, x9, x8
sub w24, w24, w20
sub w23, w23, w21
sub w20, w20, w21
st1 {v22.8h, v23.8h}, [x14], #32
add x25, x25, x4, lsl #1
sub w24, w24, w23
bfi w20, w23, #16, #16
lsl w21, w21, w16
lsr w2, w2, #31
lsr w3, w3, #31
ldrh w22, [x25]
ldrh w15, [x25, #2]
add x25, x25, x9
dup v26.4s, w21
dup v27.4s, w21
ldrh w23, [x25, #2]
ldrh w1, [x25]
bfi x20, x24, #32, #16
sub w23, w23, w15
sub w1, w1, w22
sub w15, w15, w22
fmov d0, x20
sub w23, w23, w1
bfi w15, w1, #16, #16
lsl w22, w22, w16
bfi x15, x23, #32, #16
dup v28.4s, w22
dup v29.4s, w22
fmov d2, x15
smlal v26.4s, v18.4h, v0.h[0]
smlal2 v27.4s, v18.8h, v0.h[0]
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
cbz w19, 1f
madd x24, x17, x9, x8
dup v0.8h, v6.h[0]
dup v2.8h, v16.h[0]
dup v4.8h, v7.h[0]
madd x23, x0, x9, x8
ldr q29, [x12, #128]
add x24, x24, x13, lsl #1
eor v0.16b, v0.16b, v6.16b
eor v2.16b, v2.16b, v16.16b
eor v4.16b, v4.16b, v7.16b
ldrh w20, [x24]
ldrh w21, [x24, #2]
add x24, x24, x9
add x23, x23, x5, lsl #1
orr v0.16b, v0.16b, v2.16b
dup v2.8h, v17.h[0]
ldrh w1, [x24, #2]
ldrh w25, [x24]
ldrh w15, [x23]
ldrh w22, [x23, #2]
add x23, x23, x9
cmhi v0.8h, v0.8h, v29.8h
eor v2.16b, v2.16b, v17.16b
ldrh w24, [x23, #2]
ldrh w19, [x23]
sub w1, w1, w21
sub w25, w25, w20
sub w21, w21, w20
lsl w20, w20, w16
sub w1, w1, w25
sub w24, w24, w22
bfi w21, w25, #16, #16
sub w25, w13, w28
sub w19, w19, w15
sub w22, w22, w15
bfi x21, x1, #32, #16
dup v22.4s, w20
dup v23.4s, w20
fmov d1, x21
orr v4.16b, v4.16b, v2.16b
add w21, w25, #1
sub w24, w24, w19
bfi w22, w19, #16, #16
sub w1, w17, w26
lsl w15, w15, w16
smlal v22.4s, v18.4h, v1.h[0]
smlal2 v23.4s, v18.8h, v1.h[0]
dup v24.4s, w15
dup v25.4s, w15
cmhi v4.8h, v4.8h, v29.8h
smlal v22.4s, v19.4h, v1.h[1]
smlal2 v23.4s, v19.8h, v1.h[1]
cmp w21, #2
add w20, w1, #1
bfi x22, x24, #32, #16
sub w16, w5, w4
sub w19, w0, w27
smlal v22.4s, v5.4h, v1.h[2]
fmov d3, x22
smlal2 v23.4s, v5.8h, v1.h[2]
cset w23, hi
cmp w20, #2
add w24, w16, #1
add w22, w19, #1
smlal v24.4s, v20.4h, v3.h[0]
smlal2 v25.4s, v20.8h, v3.h[0]
ushl v22.4s, v22.4s, v31.4s
ushl v23.4s, v23.4s, v31.4s
cinc w23, w23, hi
cmp w25, #0
smlal v24.4s, v21.4h, v3.h[1]
smlal2 v25.4s, v21.8h, v3.h[1]
uzp1 v22.8h, v22.8h, v23.8h
ccmp w1, #0, #4, ne
smlal v24.4s, v30.4h, v3.h[2]
smlal2 v25.4s, v30.8h, v3.h[2]
bit v26.16b, v22.16b, v0.16b
cinc w23, w23, ne
cmp w24, #2
ushl v24.4s, v24.4s, v31.4s
ushl v25.4s, v25.4s, v31.4s
cset w15, hi
cmp w22, #2
orr w2, w2, w23
cinc w15, w15, hi
cmp w16, #0
uzp1 v24.8h, v24.8h, v25.8h
ccmp w19, #0, #4, ne
cinc w15, w15, ne
bit v27.16b, v24.16b, v4.16b
orr w3, w3, w15
1:
shl v26.8h, v26.8h, #8
shl v27.8h, v27.8h, #8
ldr x28, [x14, #-32]
add x13, x11, #32
ldr x26, [x14, #-24]
ldr x16, [x14, #-16]
ldr x15, [x14, #-8]
st1 {v26.8h, v27.8h}, [x13], #32
and w20, w28, #0xffff
and w5, w26, #0xffff
lsr w25, w28, #16
ubfx x1, x28, #32, #16
lsr x23, x28, #48
lsr w4, w26, #16
ldr x17, [x13, #-32]
ldrb w20, [x6, x20]
ldrb w25, [x6, x25]
ldrb w1, [x6, x1]
ldrb w23, [x6, x23]
ldr x21, [x13, #-24]
ldrb w5, [x6, x5]
ldrb w4, [x6, x4]
add w20, w20, w17, uxth
add w25, w25, w17, lsr #16
ubfx x0, x26, #32, #16
lsr x27, x26, #48
ubfx x24, x17, #32, #16
add x23, x23, x17, lsr #48
ldrb w0, [x6, x0]
ldrb w27, [x6, x27]
add w1, w1, w24
ldrb w20, [x7, x20]
ldrb w25, [x7, x25]
ldrb w23, [x7, x23]
ldrb w1, [x7, x1]
add w5, w5, w21, uxth
add w4, w4, w21, lsr #16
ubfx x22, x21, #32, #16
add x27, x27, x21, lsr #48
orr x20, x20, x25, lsl #8
and w28, w16, #0xffff
add w0, w0, w22
ldrb w5, [x7, x5]
ldrb w4, [x7, x4]
ldrb w27, [x7, x27]
ldrb w0, [x7, x0]
orr x1, x1, x23, lsl #8
and w22, w15, #0xffff
ldr x19, [x13, #-16]
ldr x12, [x13, #-8]
orr x5, x5, x4, lsl #8
orr x0, x0, x27, lsl #8
lsr w26, w16, #16
ubfx x24, x16, #32, #16
lsr x17, x16, #48
lsr w21, w15, #16
ubfx x25, x15, #32, #16
lsr x23, x15, #48
ldrb w28, [x6, x28]
ldrb w26, [x6, x26]
ldrb w24, [x6, x24]
ldrb w17, [x6, x17]
ldrb w22, [x6, x22]
ldrb w21, [x6, x21]
ldrb w25, [x6, x25]
ldrb w23, [x6, x23]
add w28, w28, w19, uxth
add w26, w26, w19, lsr #16
ubfx x4, x19, #32, #16
ubfx x27, x12, #32, #16
add x17, x17, x19, lsr #48
add w22, w22, w12, uxth
add w24, w24, w4
add w21, w21, w12, lsr #16
add w25, w25, w27
add x23, x23, x12, lsr #48
ldrb w28, [x7, x28]
ldrb w26, [x7, x26]
ldrb w24, [x7, x24]
ldrb w17, [x7, x17]
ldrb w22, [x7, x22]
ldrb w21, [x7, x21]
ldrb w25, [x7, x25]
ldrb w23, [x7, x23]
orr x28, x28, x26, lsl #8
orr x24, x24, x17, lsl #8
orr x22, x22, x21, lsl #8
orr x20, x20, x1, lsl #16
orr x5, x5, x0, lsl #16
orr x25, x25, x23, lsl #8
orr x28, x28, x24, lsl #16
orr x20, x20, x5, lsl #32
orr x22, x22, x25, lsl #16
orr x28, x28, x22, lsl #32
stp x20, x28, [x10]
