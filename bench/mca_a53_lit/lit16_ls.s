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
mov v5.s[2], w4
ldp q18, q19, [x12, #32]
ldp q20, q21, [x12, #64]
ldp q22, q23, [x12, #96]
add x13, x11, #64
ldr q4, [x11, #64]
mov v5.s[3], w5
ld4r {v0.8h, v1.8h, v2.8h, v3.8h}, [x13]
ldp w15, w16, [x12, #176]
add w17, w4, w4, lsl #1
add w22, w2, w4, lsl #3
add w27, w5, w5, lsl #1
mov x14, x11
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
uzp2 v16.8h, v28.8h, v29.8h
uzp2 v7.8h, v26.8h, v27.8h
uzp2 v17.8h, v30.8h, v31.8h
dup v18.8h, v6.h[0]
dup v19.8h, v16.h[0]
ldp q30, q31, [x12, #128]
dup v20.8h, v7.h[0]
dup v21.8h, v17.h[0]
eor v18.16b, v18.16b, v6.16b
eor v19.16b, v19.16b, v16.16b
eor v20.16b, v20.16b, v7.16b
eor v21.16b, v21.16b, v17.16b
orr v18.16b, v18.16b, v19.16b
add v19.8h, v7.8h, v0.8h
orr v20.16b, v20.16b, v21.16b
add v21.8h, v17.8h, v1.8h
cmhi v24.8h, v18.8h, v30.8h
add v18.8h, v6.8h, v0.8h
and v23.16b, v19.16b, v2.16b
and v19.16b, v16.16b, v30.16b
cmhi v25.8h, v20.8h, v30.8h
add v20.8h, v16.8h, v1.8h
and v21.16b, v21.16b, v3.16b
and v22.16b, v18.16b, v2.16b
and v18.16b, v6.16b, v30.16b
and v20.16b, v20.16b, v3.16b
mla v23.8h, v21.8h, v4.h[4]
and v21.16b, v17.16b, v30.16b
mul v5.8h, v18.8h, v19.8h
ushl v18.8h, v18.8h, v31.8h
ushl v19.8h, v19.8h, v31.8h
mla v22.8h, v20.8h, v4.h[4]
and v20.16b, v7.16b, v30.16b
add w20, w2, w17
add w24, w22, w17
add w26, w22, w17, lsl #1
sub w23, w22, w4
add w19, w2, w17, lsl #1
add w28, w3, w27, lsl #1
mul v30.8h, v20.8h, v21.8h
ushl v20.8h, v20.8h, v31.8h
ushl v21.8h, v21.8h, v31.8h
ldr q31, [x12, #160]
st1 {v22.8h, v23.8h}, [x14], #32
eor w26, w26, w22
add w13, w3, w27
lsl w21, w20, #3
lsl w25, w24, #3
eor w19, w19, w2
eor w28, w28, w3
sub w21, w21, w20
sub w25, w25, w24
add w20, w3, w5, lsl #3
lsl w12, w13, #3
add w21, w0, w21
add w24, w20, w27
add w22, w20, w27, lsl #1
sub w4, w20, w5
sub w12, w12, w13
lsr w27, w1, w15
orr w13, w19, w28
lsl w17, w24, #3
eor w22, w22, w20
madd x20, x27, x9, x8
sub w17, w17, w24
add w12, w1, w12
lsr w24, w0, w15
orr w5, w26, w22
lsr w0, w21, w15
add w23, w21, w23
add x20, x20, x24, lsl #1
add w4, w12, w4
lsr w1, w12, w15
sub w21, w0, w24
add w25, w23, w25
ldrh w19, [x20]
ldrh w28, [x20, #2]
add x20, x20, x9
sub w12, w1, w27
add w17, w4, w17
ldrh w22, [x20, #2]
ldrh w26, [x20]
madd x20, x1, x9, x8
sub w22, w22, w28
sub w26, w26, w19
sub w28, w28, w19
add x20, x20, x0, lsl #1
lsl w19, w19, w16
sub w22, w22, w26
bfi w28, w26, #16, #16
ldrh w26, [x20]
dup v16.4s, w19
dup v17.4s, w19
bfi x28, x22, #32, #16
ldrh w22, [x20, #2]
add x20, x20, x9
fmov d6, x28
ldrh w19, [x20, #2]
ldrh w28, [x20]
add w20, w21, #1
sub w19, w19, w22
sub w28, w28, w26
sub w22, w22, w26
cmp w20, #2
lsl w26, w26, w16
lsr w20, w25, w15
sub w19, w19, w28
smlal v16.4s, v18.4h, v6.h[0]
dup v26.4s, w26
dup v27.4s, w26
smlal2 v17.4s, v18.8h, v6.h[0]
cset w2, hi
smlal v16.4s, v19.4h, v6.h[1]
smlal2 v17.4s, v19.8h, v6.h[1]
smlal v16.4s, v5.4h, v6.h[2]
smlal2 v17.4s, v5.8h, v6.h[2]
ushl v16.4s, v16.4s, v31.4s
ushl v17.4s, v17.4s, v31.4s
bfi w22, w28, #16, #16
add w28, w12, #1
bfi x22, x19, #32, #16
lsr w19, w23, w15
cmp w28, #2
uzp1 v16.8h, v16.8h, v17.8h
fmov d0, x22
cinc w2, w2, hi
cmp w21, #0
lsr w22, w4, w15
lsr w28, w17, w15
ldp w25, w17, [x14, #-32]
ccmp w12, #0, #4, ne
madd x26, x22, x9, x8
madd x21, x28, x9, x8
smlal v26.4s, v18.4h, v0.h[0]
smlal2 v27.4s, v18.8h, v0.h[0]
cinc w2, w2, ne
add x26, x26, x19, lsl #1
add x21, x21, x20, lsl #1
smlal v26.4s, v19.4h, v0.h[1]
smlal2 v27.4s, v19.8h, v0.h[1]
ldrh w0, [x26]
ldrh w24, [x26, #2]
orr w2, w2, w13, lsr #31
ldrh w12, [x21]
ldrh w13, [x21, #2]
add x26, x26, x9
add x21, x21, x9
smlal v26.4s, v5.4h, v0.h[2]
smlal2 v27.4s, v5.8h, v0.h[2]
ldrh w27, [x26, #2]
ldrh w4, [x21, #2]
ldrh w1, [x26]
ldrh w23, [x21]
sub w26, w20, w19
and w19, w17, #0xffff
ushl v26.4s, v26.4s, v31.4s
ushl v27.4s, v27.4s, v31.4s
ldrb w19, [x6, x19]
sub w27, w27, w24
sub w4, w4, w13
sub w1, w1, w0
sub w23, w23, w12
sub w24, w24, w0
sub w13, w13, w12
lsl w0, w0, w16
lsl w12, w12, w16
sub w27, w27, w1
sub w4, w4, w23
bfi w24, w1, #16, #16
dup v1.4s, w0
dup v3.4s, w0
dup v28.4s, w12
dup v29.4s, w12
uzp1 v26.8h, v26.8h, v27.8h
sub w1, w28, w22
add x0, x11, #32
bfi w13, w23, #16, #16
ldp w16, w23, [x14, #-24]
and w12, w25, #0xffff
bfi x24, x27, #32, #16
add w27, w26, #1
bfi x13, x4, #32, #16
bsl v24.16b, v26.16b, v16.16b
fmov d7, x24
fmov d2, x13
ldrb w12, [x6, x12]
cmp w27, #2
add w24, w1, #1
shl v24.8h, v24.8h, #8
smlal v1.4s, v20.4h, v7.h[0]
smlal2 v3.4s, v20.8h, v7.h[0]
smlal v28.4s, v20.4h, v2.h[0]
smlal2 v29.4s, v20.8h, v2.h[0]
smlal v1.4s, v21.4h, v7.h[1]
smlal2 v3.4s, v21.8h, v7.h[1]
smlal v28.4s, v21.4h, v2.h[1]
smlal2 v29.4s, v21.8h, v2.h[1]
smlal v1.4s, v30.4h, v7.h[2]
smlal2 v3.4s, v30.8h, v7.h[2]
smlal v28.4s, v30.4h, v2.h[2]
smlal2 v29.4s, v30.8h, v2.h[2]
ushl v1.4s, v1.4s, v31.4s
ushl v3.4s, v3.4s, v31.4s
ushl v28.4s, v28.4s, v31.4s
ushl v29.4s, v29.4s, v31.4s
cset w3, hi
cmp w24, #2
uzp1 v1.8h, v1.8h, v3.8h
uzp1 v28.8h, v28.8h, v29.8h
cinc w3, w3, hi
cmp w26, #0
lsr w20, w25, #16
lsr w28, w17, #16
and w22, w16, #0xffff
and w24, w23, #0xffff
bsl v25.16b, v28.16b, v1.16b
ldrb w20, [x6, x20]
ldrb w28, [x6, x28]
ldrb w22, [x6, x22]
ldrb w24, [x6, x24]
shl v25.8h, v25.8h, #8
ccmp w1, #0, #4, ne
lsr w27, w16, #16
lsr w26, w23, #16
ldp w16, w23, [x14, #-8]
st1 {v24.8h, v25.8h}, [x0], #32
ldrb w27, [x6, x27]
ldrb w26, [x6, x26]
cinc w3, w3, ne
ldp w15, w21, [x0, #-32]
ldp w4, w13, [x0, #-24]
orr w3, w3, w5, lsr #31
ldp w1, w5, [x14, #-16]
ldp w25, w17, [x0, #-16]
add w12, w12, w15, uxth
add w20, w20, w15, lsr #16
add w19, w19, w21, uxth
add w28, w28, w21, lsr #16
add w22, w22, w4, uxth
add w27, w27, w4, lsr #16
add w24, w24, w13, uxth
add w26, w26, w13, lsr #16
ldrb w12, [x7, x12]
ldrb w20, [x7, x20]
ldrb w19, [x7, x19]
ldrb w28, [x7, x28]
ldrb w22, [x7, x22]
ldrb w27, [x7, x27]
ldrb w24, [x7, x24]
ldrb w26, [x7, x26]
orr x12, x12, x20, lsl #8
orr x19, x19, x28, lsl #8
orr x22, x22, x27, lsl #8
and w4, w1, #0xffff
and w20, w5, #0xffff
and w27, w16, #0xffff
orr x24, x24, x26, lsl #8
orr x12, x12, x19, lsl #16
and w19, w23, #0xffff
ldp w15, w21, [x0, #-8]
ldrb w4, [x6, x4]
orr x22, x22, x24, lsl #16
ldrb w20, [x6, x20]
ldrb w27, [x6, x27]
ldrb w19, [x6, x19]
add w4, w4, w25, uxth
orr x12, x12, x22, lsl #32
lsr w13, w1, #16
lsr w28, w5, #16
lsr w26, w16, #16
lsr w24, w23, #16
ldrb w13, [x6, x13]
ldrb w28, [x6, x28]
ldrb w26, [x6, x26]
ldrb w24, [x6, x24]
add w13, w13, w25, lsr #16
add w20, w20, w17, uxth
add w28, w28, w17, lsr #16
add w27, w27, w15, uxth
add w26, w26, w15, lsr #16
add w19, w19, w21, uxth
add w24, w24, w21, lsr #16
ldrb w4, [x7, x4]
ldrb w13, [x7, x13]
ldrb w20, [x7, x20]
ldrb w28, [x7, x28]
ldrb w27, [x7, x27]
ldrb w26, [x7, x26]
ldrb w19, [x7, x19]
ldrb w24, [x7, x24]
orr x4, x4, x13, lsl #8
orr x20, x20, x28, lsl #8
orr x27, x27, x26, lsl #8
orr x19, x19, x24, lsl #8
orr x4, x4, x20, lsl #16
orr x27, x27, x19, lsl #16
orr x4, x4, x27, lsl #32
stp x12, x4, [x10]
