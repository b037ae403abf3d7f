ldp x4, x6, [x26, #64]
sub w22, w27, #1
ldp x19, x3, [x26, #32]
and w28, w22, #15
ldp x23, x2, [x26, #16]
cmp w28, #0
ldp x13, x1, [x26]
add x7, x29, x27, lsl #5
ldp x25, x5, [x26, #48]
csinc w28, w28, wzr, ne
sub w24, w19, w23
lsr w22, w22, #4
asr w14, w24, #31
sub w10, w2, w1
ldr x7, [x7]
sub w9, w23, w13
orr x13, x13, x1, lsl #32
sub w20, w25, w19
sub w15, w5, w3
cmp w22, #2
sub w12, w3, w2
asr w11, w10, #31
sub w4, w4, w25
asr w8, w9, #31
asr w16, w12, #31
asr w21, w15, #31
csel w4, w20, w4, eq
add w10, w10, w11, lsr #28
sub w6, w6, w5
asr w17, w20, #31
csel w6, w15, w6, eq
csel w4, w24, w4, lt
add w9, w9, w8, lsr #28
csel w6, w12, w6, lt
add w15, w15, w21, lsr #28
asr w15, w15, #4
sbfiz x8, x4, #29, #32
add w24, w24, w14, lsr #28
smulh x8, x8, x7
orr x19, x19, x3, lsl #32
add w20, w20, w17, lsr #28
asr w10, w10, #4
add w12, w12, w16, lsr #28
asr w12, w12, #4
add w4, w8, w4, lsr #31
sbfx x24, x24, #4, #28
sbfx x9, x9, #4, #28
sbfiz x21, x6, #29, #32
sbfx x20, x20, #4, #28
add x24, x24, x12, lsl #32
smulh x21, x21, x7
orr x23, x23, x2, lsl #32
add w6, w21, w6, lsr #31
orr x25, x25, x5, lsl #32
add x20, x20, x15, lsl #32
add x9, x9, x10, lsl #32
lsl x6, x6, #32
add x28, x6, w4, sxtw
