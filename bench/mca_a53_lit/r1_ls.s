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
