ldp q16, q17, [x12]
ldp q18, q19, [x12, #32]
ldp q20, q21, [x12, #64]
ldp q22, q23, [x12, #96]
fmov s5, w2
mov v5.s[1], w3
mov v5.s[2], w4
mov v5.s[3], w5
dup v24.4s, w0
dup v28.4s, w1
dup v25.4s, w0
dup v29.4s, w1
dup v26.4s, w0
dup v30.4s, w1
dup v27.4s, w0
dup v31.4s, w1
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
mla v26.4s, v22.4s, v5.s[2]
mla v30.4s, v22.4s, v5.s[3]
mla v27.4s, v23.4s, v5.s[2]
mla v31.4s, v23.4s, v5.s[3]
uzp2 v6.8h, v24.8h, v25.8h
uzp2 v7.8h, v26.8h, v27.8h
uzp2 v16.8h, v28.8h, v29.8h
uzp2 v17.8h, v30.8h, v31.8h
ldp q30, q31, [x12, #128]
add x13, x11, #64
ld4r {v0.8h, v1.8h, v2.8h, v3.8h}, [x13]
ldr q4, [x11, #64]
add v18.8h, v6.8h, v0.8h
add v19.8h, v7.8h, v0.8h
add v20.8h, v16.8h, v1.8h
add v21.8h, v17.8h, v1.8h
and v22.16b, v18.16b, v2.16b
and v23.16b, v19.16b, v2.16b
and v20.16b, v20.16b, v3.16b
and v21.16b, v21.16b, v3.16b
mla v22.8h, v20.8h, v4.h[4]
mla v23.8h, v21.8h, v4.h[4]
mov x14, x11
st1 {v22.8h, v23.8h}, [x14], #32
and v18.16b, v6.16b, v30.16b
and v19.16b, v16.16b, v30.16b
and v20.16b, v7.16b, v30.16b
and v21.16b, v17.16b, v30.16b
mul v5.8h, v18.8h, v19.8h
mul v30.8h, v20.8h, v21.8h
ushl v18.8h, v18.8h, v31.8h
ushl v19.8h, v19.8h, v31.8h
ushl v20.8h, v20.8h, v31.8h
ushl v21.8h, v21.8h, v31.8h
ldr q31, [x12, #160]
ldp w15, w16, [x12, #176]
add w17, w4, w4, lsl #1
add w19, w2, w17, lsl #1
eor w19, w19, w2
add w20, w2, w17
lsl w21, w20, #3
sub w21, w21, w20
add w21, w0, w21
add w22, w2, w4, lsl #3
sub w23, w22, w4
add w23, w21, w23
add w24, w22, w17
lsl w25, w24, #3
sub w25, w25, w24
add w25, w23, w25
add w26, w22, w17, lsl #1
eor w26, w26, w22
add w27, w5, w5, lsl #1
add w28, w3, w27, lsl #1
eor w28, w28, w3
add w13, w3, w27
lsl w20, w13, #3
sub w20, w20, w13
add w20, w1, w20
add w4, w3, w5, lsl #3
sub w24, w4, w5
add w24, w20, w24
add w17, w4, w27
lsl w22, w17, #3
sub w22, w22, w17
add w22, w24, w22
add w13, w4, w27, lsl #1
eor w13, w13, w4
orr w2, w19, w28
orr w3, w26, w13
lsr w2, w2, #31
lsr w3, w3, #31
eor w5, w0, w21
eor w17, w1, w20
eor w27, w23, w25
eor w4, w24, w22
orr w5, w5, w17
orr w27, w27, w4
orr w5, w5, w27
lsr w19, w5, w15
lsr w28, w0, w15
lsr w26, w1, w15
lsr w13, w21, w15
lsr w17, w20, w15
lsr w4, w23, w15
lsr w27, w24, w15
lsr w5, w25, w15
lsr w0, w22, w15
madd x1, x26, x9, x8
add x1, x1, x28, lsl #1
ldrh w21, [x1]
ldrh w20, [x1, #2]
add x1, x1, x9
ldrh w23, [x1]
ldrh w24, [x1, #2]
sub w24, w24, w20
sub w20, w20, w21
sub w23, w23, w21
sub w24, w24, w23
lsl w21, w21, w16
bfi w20, w23, #16, #16
bfi x20, x24, #32, #16
fmov d0, x20
dup v26.4s, w21
dup v27.4s, w21
madd x25, x27, x9, x8
add x25, x25, x4, lsl #1
ldrh w22, [x25]
ldrh w15, [x25, #2]
add x25, x25, x9
ldrh w1, [x25]
ldrh w23, [x25, #2]
sub w23, w23, w15
sub w15, w15, w22
sub w1, w1, w22
sub w23, w23, w1
lsl w22, w22, w16
bfi w15, w1, #16, #16
bfi x15, x23, #32, #16
fmov d2, x15
dup v28.4s, w22
dup v29.4s, w22
smlal v26.4s, v18.4h, v0.h[0]
smlal2 v27.4s, v18.8h, v0.h[0]
smlal v26.4s, v19.4h, v0.h[1]
smlal2 v27.4s, v19.8h, v0.h[1]
smlal v26.4s, v5.4h, v0.h[2]
smlal2 v27.4s, v5.8h, v0.h[2]
smlal v28.4s, v20.4h, v2.h[0]
smlal2 v29.4s, v20.8h, v2.h[0]
smlal v28.4s, v21.4h, v2.h[1]
smlal2 v29.4s, v21.8h, v2.h[1]
smlal v28.4s, v30.4h, v2.h[2]
smlal2 v29.4s, v30.8h, v2.h[2]
ushl v26.4s, v26.4s, v31.4s
ushl v27.4s, v27.4s, v31.4s
ushl v28.4s, v28.4s, v31.4s
ushl v29.4s, v29.4s, v31.4s
uzp1 v26.8h, v26.8h, v27.8h
uzp1 v27.8h, v28.8h, v29.8h
cbz w19, 1f
madd x24, x17, x9, x8
add x24, x24, x13, lsl #1
ldrh w20, [x24]
ldrh w21, [x24, #2]
add x24, x24, x9
ldrh w25, [x24]
ldrh w1, [x24, #2]
sub w1, w1, w21
sub w21, w21, w20
sub w25, w25, w20
sub w1, w1, w25
lsl w20, w20, w16
bfi w21, w25, #16, #16
bfi x21, x1, #32, #16
fmov d1, x21
dup v22.4s, w20
dup v23.4s, w20
madd x23, x0, x9, x8
add x23, x23, x5, lsl #1
ldrh w15, [x23]
ldrh w22, [x23, #2]
add x23, x23, x9
ldrh w19, [x23]
ldrh w24, [x23, #2]
sub w24, w24, w22
sub w22, w22, w15
sub w19, w19, w15
sub w24, w24, w19
lsl w15, w15, w16
bfi w22, w19, #16, #16
bfi x22, x24, #32, #16
fmov d3, x22
dup v24.4s, w15
dup v25.4s, w15
sub w25, w13, w28
sub w1, w17, w26
add w21, w25, #1
add w20, w1, #1
cmp w21, #2
cset w23, hi
cmp w20, #2
cinc w23, w23, hi
cmp w25, #0
ccmp w1, #0, #4, ne
cinc w23, w23, ne
orr w2, w2, w23
sub w16, w5, w4
sub w19, w0, w27
add w24, w16, #1
add w22, w19, #1
cmp w24, #2
cset w15, hi
cmp w22, #2
cinc w15, w15, hi
cmp w16, #0
ccmp w19, #0, #4, ne
cinc w15, w15, ne
orr w3, w3, w15
smlal v22.4s, v18.4h, v1.h[0]
smlal2 v23.4s, v18.8h, v1.h[0]
smlal v22.4s, v19.4h, v1.h[1]
smlal2 v23.4s, v19.8h, v1.h[1]
smlal v22.4s, v5.4h, v1.h[2]
smlal2 v23.4s, v5.8h, v1.h[2]
smlal v24.4s, v20.4h, v3.h[0]
smlal2 v25.4s, v20.8h, v3.h[0]
smlal v24.4s, v21.4h, v3.h[1]
smlal2 v25.4s, v21.8h, v3.h[1]
smlal v24.4s, v30.4h, v3.h[2]
smlal2 v25.4s, v30.8h, v3.h[2]
ushl v22.4s, v22.4s, v31.4s
ushl v23.4s, v23.4s, v31.4s
ushl v24.4s, v24.4s, v31.4s
ushl v25.4s, v25.4s, v31.4s
uzp1 v22.8h, v22.8h, v23.8h
uzp1 v24.8h, v24.8h, v25.8h
ldr q29, [x12, #128]
dup v0.8h, v6.h[0]
dup v2.8h, v16.h[0]
eor v0.16b, v0.16b, v6.16b
eor v2.16b, v2.16b, v16.16b
orr v0.16b, v0.16b, v2.16b
cmhi v0.8h, v0.8h, v29.8h
dup v4.8h, v7.h[0]
dup v2.8h, v17.h[0]
eor v4.16b, v4.16b, v7.16b
eor v2.16b, v2.16b, v17.16b
orr v4.16b, v4.16b, v2.16b
cmhi v4.8h, v4.8h, v29.8h
bit v26.16b, v22.16b, v0.16b
bit v27.16b, v24.16b, v4.16b
1:
shl v26.8h, v26.8h, #8
shl v27.8h, v27.8h, #8
add x13, x11, #32
st1 {v26.8h, v27.8h}, [x13], #32
ldr x28, [x14, #-32]
ldr x17, [x13, #-32]
ldr x26, [x14, #-24]
ldr x21, [x13, #-24]
and w20, w28, #0xffff
lsr w25, w28, #16
ubfx x1, x28, #32, #16
lsr x23, x28, #48
and w5, w26, #0xffff
lsr w4, w26, #16
ubfx x0, x26, #32, #16
lsr x27, x26, #48
ldrb w20, [x6, x20]
ldrb w25, [x6, x25]
ldrb w1, [x6, x1]
ldrb w23, [x6, x23]
ldrb w5, [x6, x5]
ldrb w4, [x6, x4]
ldrb w0, [x6, x0]
ldrb w27, [x6, x27]
add w20, w20, w17, uxth
add w25, w25, w17, lsr #16
ubfx x24, x17, #32, #16
add w1, w1, w24
add x23, x23, x17, lsr #48
add w5, w5, w21, uxth
add w4, w4, w21, lsr #16
ubfx x22, x21, #32, #16
add w0, w0, w22
add x27, x27, x21, lsr #48
ldrb w20, [x7, x20]
ldrb w25, [x7, x25]
ldrb w1, [x7, x1]
ldrb w23, [x7, x23]
ldrb w5, [x7, x5]
ldrb w4, [x7, x4]
ldrb w0, [x7, x0]
ldrb w27, [x7, x27]
orr x20, x20, x25, lsl #8
orr x1, x1, x23, lsl #8
orr x5, x5, x4, lsl #8
orr x0, x0, x27, lsl #8
orr x20, x20, x1, lsl #16
orr x5, x5, x0, lsl #16
orr x20, x20, x5, lsl #32
ldr x16, [x14, #-16]
ldr x19, [x13, #-16]
ldr x15, [x14, #-8]
ldr x12, [x13, #-8]
and w28, w16, #0xffff
lsr w26, w16, #16
ubfx x24, x16, #32, #16
lsr x17, x16, #48
and w22, w15, #0xffff
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
add w24, w24, w4
add x17, x17, x19, lsr #48
add w22, w22, w12, uxth
add w21, w21, w12, lsr #16
ubfx x27, x12, #32, #16
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
orr x25, x25, x23, lsl #8
orr x28, x28, x24, lsl #16
orr x22, x22, x25, lsl #16
orr x28, x28, x22, lsl #32
stp x20, x28, [x10]
