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
