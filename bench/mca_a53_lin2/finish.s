ldr x12, [x0]
ldr x14, [x18]
ldp x19, x3, [x26, #32]
add x7, x29, x27, lsl #5
ldp x4, x6, [x26, #64]
sub w22, w27, #1
sub x14, x14, x12
and w28, w22, #15
cmp x14, #352
lsr w22, w22, #4
sub x14, x12, #176
ldp x23, x2, [x26, #16]
csel x12, x12, x14, ge
cset w14, lt
ldp x25, x5, [x26, #48]
ldrb w17, [x12, #256]
ldrb w21, [x12, #344]
ldr x8, [x12, #200]
sub w24, w19, w23
ldr w11, [x12, #184]
neg x17, x17
ldr w16, [x12, #272]
sub w6, w6, w5
ldr x15, [x12, #288]
and x17, x17, x8, lsl #1
sub w12, w3, w2
neg x21, x21
sub w11, w11, #17
cmp w11, #47
orr x17, x17, x14
ldp x13, x14, [x26]
sub w16, w16, #17
mov w8, #47
ccmp w16, w8, #2, ls
and x21, x21, x15, lsl #1
orr x17, x17, x21
ldr x7, [x7]
sub w10, w2, w14
sub w9, w23, w13
ccmp x17, #0, #0, ls
sub w4, w4, w25
asr w16, w12, #31
sub w20, w25, w19
asr w11, w10, #31
orr x23, x23, x2, lsl #32
cset w1, eq
cmp w28, #0
asr w8, w9, #31
orr x13, x13, x14, lsl #32
sub w15, w5, w3
orr x25, x25, x5, lsl #32
csinc w28, w28, wzr, ne
cmp w22, #2
asr w21, w15, #31
add w10, w10, w11, lsr #28
asr w14, w24, #31
add w9, w9, w8, lsr #28
csel w6, w15, w6, eq
add w15, w15, w21, lsr #28
asr w15, w15, #4
csel w6, w12, w6, lt
sbfiz x21, x6, #29, #32
csel w4, w20, w4, eq
csel w4, w24, w4, lt
orr x19, x19, x3, lsl #32
asr w17, w20, #31
sbfiz x8, x4, #29, #32
add w24, w24, w14, lsr #28
smulh x8, x8, x7
add w20, w20, w17, lsr #28
add w12, w12, w16, lsr #28
asr w12, w12, #4
add w4, w8, w4, lsr #31
sbfx x20, x20, #4, #28
sbfx x9, x9, #4, #28
sbfx x24, x24, #4, #28
smulh x21, x21, x7
add x20, x20, x15, lsl #32
add x24, x24, x12, lsl #32
asr w10, w10, #4
add w6, w21, w6, lsr #31
lsl x6, x6, #32
add x9, x9, x10, lsl #32
add x28, x6, w4, sxtw
