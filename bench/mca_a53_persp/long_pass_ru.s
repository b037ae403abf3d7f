.Lloop:
lsr x2, x13, #48
lsr x1, x14, #48
lsr w4, w13, #16
lsr w3, w14, #16
add x14, x14, x19
madd w2, w2, w24, w4
madd w1, w1, w24, w3
ldr q1, [sp, #16]
add x13, x13, x17
add x19, x19, x20
lsr w7, w14, #16
lsr x3, x13, #48
lsr x6, x14, #48
lsr w8, w13, #16
lsr x5, x27, #32
madd w3, w3, w24, w8
add x17, x17, x20
add x14, x14, x19
lsr w9, w14, #16
add x19, x19, x20
lsr x4, x26, #32
madd w6, w6, w24, w7
add x13, x13, x17
ldrb w3, [x23, w3, uxtw]
sub x8, x4, x25, lsr #32
add x17, x17, x20
sub w30, w26, w25
sub x4, x5, x26, lsr #32
lsr w11, w13, #16
lsr x5, x14, #48
lsr x10, x13, #48
ldr q0, [sp]
add x13, x13, x17
add x14, x14, x19
lsr x21, x13, #48
lsr x16, x14, #48
lsr w12, w14, #16
ldrb w6, [x23, w6, uxtw]
sub w18, w27, w26
add x17, x17, x20
lsr w15, w13, #16
add x19, x19, x20
add x14, x14, x19
add x13, x13, x17
add x17, x17, x20
scvtf d3, w30
madd w21, w21, w24, w15
ldrb w1, [x23, w1, uxtw]
add x19, x19, x20
madd w16, w16, w24, w12
ldrb w2, [x23, w2, uxtw]
scvtf d4, w8
madd w10, w10, w24, w11
fmul d3, d3, v27.d[0]
fadd v28.2d, v24.2d, v19.2d
madd w5, w5, w24, w9
ldrb w21, [x23, w21, uxtw]
orr x7, x2, x1, lsl #8
orr x1, x3, x6, lsl #8
lsr x6, x14, #48
lsr w9, w14, #16
lsr w3, w13, #16
lsr x2, x13, #48
add x13, x13, x17
add x14, x14, x19
add x17, x17, x20
add x19, x19, x20
lsr w22, w14, #16
lsr x11, x13, #48
lsr w12, w13, #16
add x13, x13, x17
lsr x15, x14, #48
fmul d4, d4, v27.d[0]
scvtf d5, w18
fcvtzs w28, d3
fmla v0.2d, v16.2d, v28.2d
fmla v1.2d, v17.2d, v28.d[0]
fmul d5, d5, v27.d[1]
madd w6, w6, w24, w9
ldrb w10, [x23, w10, uxtw]
madd w2, w2, w24, w3
ldrb w5, [x23, w5, uxtw]
add x14, x14, x19
orr x3, x7, x1, lsl #16
ldrb w16, [x23, w16, uxtw]
madd w15, w15, w24, w22
add x17, x17, x20
madd w11, w11, w24, w12
add x19, x19, x20
orr x1, x10, x5, lsl #8
lsr x9, x14, #48
lsr w7, w13, #16
lsr x10, x13, #48
lsr w5, w14, #16
add x13, x13, x17
madd w10, w10, w24, w7
str w3, [x0, #0]
madd w9, w9, w24, w5
orr x3, x21, x16, lsl #8
add x14, x14, x19
lsr x21, x14, #48
lsr x12, x13, #48
lsr w16, w13, #16
madd w12, w12, w24, w16
add x19, x19, x20
sxtw x7, w30
cmp x7, #0
lsr w16, w14, #16
sbfiz x5, x28, #7, #32
madd w21, w21, w24, w16
ldrb w6, [x23, w6, uxtw]
sub x5, x5, w28, sxtw #3
cneg x16, x7, lt
add x22, x5, x16
cmp x22, x16, lsl #1
fcvtzs w16, d4
scvtf d2, w4
ldrb w21, [x23, w21, uxtw]
csel w22, w28, wzr, ls
csel x5, x5, xzr, ls
cmp x8, #0
sub x28, x7, x5
sbfiz x7, x16, #7, #32
asr x5, x28, #63
sub x7, x7, w16, sxtw #3
add x28, x28, x5, lsr #60
asr x5, x28, #4
cneg x28, x8, lt
add x30, x7, x28
ldrb w15, [x23, w15, uxtw]
cmp x30, x28, lsl #1
fmaxnm v0.2d, v0.2d, v21.2d
fmul d2, d2, v27.d[1]
fadd v24.2d, v24.2d, v18.2d
ldrb w2, [x23, w2, uxtw]
csel x7, x7, xzr, ls
ldr q3, [sp, #16]
sub x28, x8, x7
csel w8, w16, wzr, ls
asr x7, x28, #63
ldrb w9, [x23, w9, uxtw]
add x28, x28, x7, lsr #60
add x17, x17, x20
asr x7, x28, #4
ldrb w11, [x23, w11, uxtw]
add x16, x5, x7, lsl #32
lsl x5, x8, #32
add x5, x5, w22, sxtw
lsl x20, x5, #2
add x17, x5, x16, lsl #1
add x14, x25, x16
add x19, x17, x5, lsl #1
orr x5, x1, x3, lsl #16
orr x1, x2, x6, lsl #8
lsr x3, x25, #48
orr x7, x11, x15, lsl #8
lsr w6, w14, #16
lsr x8, x14, #48
lsr w2, w25, #16
str w5, [x0, #4]
add x14, x14, x19
add x25, x25, x17
lsr x16, x25, #48
lsr x15, x14, #48
lsr w11, w14, #16
fcvtzs w5, d2
fcvtzs w28, d5
fmla v3.2d, v17.2d, v28.d[1]
fdiv v2.2d, v20.2d, v0.2d
fadd v24.2d, v24.2d, v18.2d
madd w3, w3, w24, w2
ldrb w10, [x23, w10, uxtw]
add x19, x19, x20
madd w8, w8, w24, w6
add x17, x17, x20
add x14, x14, x19
lsr w22, w25, #16
sbfiz x6, x28, #7, #32
sxtw x2, w18
cmp x2, #0
mov x13, x26
fmul v1.2d, v1.2d, v2.d[0]
madd w16, w16, w24, w22
ldrb w8, [x23, w8, uxtw]
sub x6, x6, w28, sxtw #3
cneg x22, x2, lt
add x30, x6, x22
ldrb w12, [x23, w12, uxtw]
cmp x30, x22, lsl #1
fmul v3.2d, v3.2d, v2.d[1]
ldrb w3, [x23, w3, uxtw]
madd w15, w15, w24, w11
csel x6, x6, xzr, ls
add x19, x19, x20
sub x11, x2, x6
add x25, x25, x17
asr x2, x11, #63
orr x6, x1, x7, lsl #16
add x11, x11, x2, lsr #60
add x17, x17, x20
asr x2, x11, #4
orr x7, x12, x21, lsl #8
lsr w11, w14, #16
orr x12, x10, x9, lsl #8
lsr x9, x25, #48
lsr x1, x14, #48
lsr w10, w25, #16
str w6, [x0, #8]
add x25, x25, x17
madd w1, w1, w24, w11
add x14, x14, x19
madd w9, w9, w24, w10
add x17, x17, x20
csel w6, w28, wzr, ls
lsr w21, w14, #16
cmp x4, #0
lsr x22, x25, #48
lsr w10, w25, #16
lsr x28, x14, #48
add x25, x25, x17
sbfiz x11, x5, #7, #32
cneg x30, x4, lt
sub x11, x11, w5, sxtw #3
ldrb w16, [x23, w16, uxtw]
add x19, x19, x20
madd w22, w22, w24, w10
add x14, x14, x19
add x10, x11, x30
cmp x10, x30, lsl #1
ext v29.16b, v26.16b, v2.16b, #8
fcvtzu v3.2d, v3.2d, #16
fcvtzu v1.2d, v1.2d, #16
ldrb w15, [x23, w15, uxtw]
madd w28, w28, w24, w21
csel x11, x11, xzr, ls
ldrb w22, [x23, w22, uxtw]
csel w10, w5, wzr, ls
sub x5, x4, x11
asr x4, x5, #63
orr x11, x12, x7, lsl #16
add x19, x19, x20
add x5, x5, x4, lsr #60
orr x7, x3, x8, lsl #8
orr x3, x16, x15, lsl #8
lsr w15, w14, #16
lsr x16, x25, #48
lsr w8, w25, #16
lsr x12, x14, #48
add x14, x14, x19
add x17, x17, x20
add x25, x25, x17
add x19, x19, x20
lsr x21, x14, #48
lsr w4, w14, #16
asr x30, x5, #4
add x14, x14, x19
lsr w18, w25, #16
lsr x5, x25, #48
madd w16, w16, w24, w8
ldrb w1, [x23, w1, uxtw]
add x17, x17, x20
madd w12, w12, w24, w15
add x8, x2, x30, lsl #32
orr x2, x7, x3, lsl #16
lsl x3, x10, #32
str w11, [x0, #12]
add x25, x25, x17
ldrb w9, [x23, w9, uxtw]
ldrb w12, [x23, w12, uxtw]
madd w5, w5, w24, w18
add x19, x19, x20
uqxtn v0.2s, v1.2d
fadd v1.2d, v29.2d, v2.2d
ldrb w16, [x23, w16, uxtw]
madd w21, w21, w24, w4
add x3, x3, w6, sxtw
orr x6, x9, x1, lsl #8
add x17, x17, x20
lsr w7, w25, #16
lsr x9, x14, #48
lsr w1, w14, #16
lsr x10, x25, #48
add x25, x25, x17
add x14, x14, x19
lsr w11, w25, #16
str w2, [x0, #16]
madd w9, w9, w24, w1
ldrb w5, [x23, w5, uxtw]
add x17, x17, x20
add x17, x3, x8, lsl #1
lsr x15, x25, #48
add x19, x19, x20
lsr w2, w14, #16
ldrb w28, [x23, w28, uxtw]
madd w15, w15, w24, w11
uqxtn2 v0.4s, v3.2d
madd w10, w10, w24, w7
ldrb w9, [x23, w9, uxtw]
mov x25, x27
orr x1, x22, x28, lsl #8
lsr x4, x14, #48
lsl x20, x3, #2
ldrb w21, [x23, w21, uxtw]
madd w4, w4, w24, w2
ldrb w15, [x23, w15, uxtw]
add x19, x17, x3, lsl #1
orr x2, x6, x1, lsl #16
orr x1, x16, x12, lsl #8
ldrb w10, [x23, w10, uxtw]
orr x3, x5, x21, lsl #8
ldrb w4, [x23, w4, uxtw]
umin v0.4s, v0.4s, v22.4s
fmul v27.2d, v1.2d, v23.d[0]
str w2, [x0, #20]
orr x5, x1, x3, lsl #16
orr x2, x15, x4, lsl #8
orr x1, x10, x9, lsl #8
add x14, x26, x8
orr x3, x1, x2, lsl #16
ldr x1, [sp, #32]
str w5, [x0, #24]
mov x27, v0.d[1]
fmov x26, d0
mov v26.16b, v2.16b
str w3, [x0, #28]
add x0, x0, #32
cmp x0, x1
b.lo .Lloop
