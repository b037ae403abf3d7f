.Lloop:
lsr x3, x14, #48
lsr x1, x13, #48
lsr w4, w14, #16
lsr w2, w13, #16
lsr x9, x27, #32
add x14, x14, x19
lsr x7, x14, #48
madd w3, w3, w24, w4
add x19, x19, x20
add x13, x13, x17
lsr x5, x13, #48
lsr w8, w14, #16
lsr w6, w13, #16
madd w5, w5, w24, w6
ldr q0, [sp]
madd w1, w1, w24, w2
add x17, x17, x20
madd w7, w7, w24, w8
add x14, x14, x19
add x13, x13, x17
lsr x8, x26, #32
sub w2, w26, w25
lsr x6, x25, #32
sub w10, w8, w6
add x17, x17, x20
ldr q1, [sp, #16]
add x19, x19, x20
sub w6, w9, w8
lsr x11, x14, #48
lsr w12, w14, #16
lsr x8, x13, #48
add x14, x14, x19
lsr w9, w13, #16
add x19, x19, x20
add x13, x13, x17
add x17, x17, x20
lsr w22, w14, #16
lsr w16, w13, #16
lsr x21, x14, #48
lsr x15, x13, #48
add x14, x14, x19
add x13, x13, x17
add x17, x17, x20
scvtf d6, w6
scvtf d3, w2
madd w8, w8, w24, w9
ldrb w5, [x23, w5, uxtw]
madd w15, w15, w24, w16
ldrb w7, [x23, w7, uxtw]
sub w4, w27, w26
ldrb w3, [x23, w3, uxtw]
add x19, x19, x20
ldrb w1, [x23, w1, uxtw]
madd w21, w21, w24, w22
scvtf d4, w10
fmul d3, d3, v27.d[0]
fadd v28.2d, v24.2d, v19.2d
scvtf d5, w4
fmul d6, d6, v27.d[1]
ldrb w15, [x23, w15, uxtw]
madd w11, w11, w24, w12
orr x2, x1, x3, lsl #8
orr x1, x5, x7, lsl #8
lsr x3, x13, #48
lsr w4, w13, #16
lsr x5, x14, #48
lsr w6, w14, #16
add x13, x13, x17
add x14, x14, x19
add x19, x19, x20
add x17, x17, x20
lsr x7, x13, #48
lsr w9, w13, #16
lsr x10, x14, #48
add x13, x13, x17
lsr w12, w14, #16
fcvtzs w22, d3
fmul d4, d4, v27.d[0]
fmla v0.2d, v16.2d, v28.2d
fmla v1.2d, v17.2d, v28.d[0]
fmul d5, d5, v27.d[1]
madd w3, w3, w24, w4
ldrb w11, [x23, w11, uxtw]
add x17, x17, x20
ldrb w8, [x23, w8, uxtw]
ldrb w21, [x23, w21, uxtw]
madd w5, w5, w24, w6
add x14, x14, x19
madd w10, w10, w24, w12
orr x4, x2, x1, lsl #16
madd w7, w7, w24, w9
add x19, x19, x20
orr x1, x8, x11, lsl #8
lsr w11, w14, #16
lsr w8, w13, #16
lsr x9, x14, #48
lsr x6, x13, #48
add x13, x13, x17
str w4, [x0, #0]
orr x2, x15, x21, lsl #8
add x14, x14, x19
lsr x12, x13, #48
lsr w15, w13, #16
lsr x16, x14, #48
madd w6, w6, w24, w8
madd w12, w12, w24, w15
sub w4, w26, w25
add x19, x19, x20
lsr x8, x26, #32
sxtw x4, w4
lsr w21, w14, #16
madd w9, w9, w24, w11
sub x11, x8, x25, lsr #32
cmp x4, #0
sbfiz x8, x22, #7, #32
mov x13, x26
madd w16, w16, w24, w21
ldrb w5, [x23, w5, uxtw]
sub x8, x8, w22, sxtw #3
cneg x15, x4, lt
add x21, x8, x15
ldr q2, [sp, #16]
cmp x21, x15, lsl #1
fcvtzs w28, d4
fadd v24.2d, v24.2d, v18.2d
csel w15, w22, wzr, ls
csel x8, x8, xzr, ls
sub x21, x4, x8
cmp x11, #0
asr x4, x21, #63
sbfiz x8, x28, #7, #32
add x21, x21, x4, lsr #60
sub x8, x8, w28, sxtw #3
asr x4, x21, #4
cneg x21, x11, lt
add x22, x8, x21
ldrb w10, [x23, w10, uxtw]
cmp x22, x21, lsl #1
fmaxnm v0.2d, v0.2d, v21.2d
csel x8, x8, xzr, ls
add x17, x17, x20
sub x22, x11, x8
asr x8, x22, #63
ldrb w3, [x23, w3, uxtw]
add x22, x22, x8, lsr #60
asr x8, x22, #4
ldrb w7, [x23, w7, uxtw]
csel w21, w28, wzr, ls
add x11, x4, x8, lsl #32
lsl x4, x21, #32
add x4, x4, w15, sxtw
lsl x20, x4, #2
add x17, x4, x11, lsl #1
add x19, x17, x4, lsl #1
orr x4, x1, x2, lsl #16
orr x1, x3, x5, lsl #8
add x14, x25, x11
lsr w5, w25, #16
lsr x3, x25, #48
lsr w8, w14, #16
orr x2, x7, x10, lsl #8
lsr x7, x14, #48
add x25, x25, x17
add x14, x14, x19
add x17, x17, x20
lsr w21, w14, #16
lsr x15, x14, #48
lsr x10, x25, #48
lsr w11, w25, #16
add x19, x19, x20
add x25, x25, x17
add x14, x14, x19
str w4, [x0, #4]
add x17, x17, x20
fcvtzs w28, d6
fcvtzs w22, d5
fmla v2.2d, v17.2d, v28.d[1]
fdiv v3.2d, v20.2d, v0.2d
fadd v24.2d, v24.2d, v18.2d
ldrb w16, [x23, w16, uxtw]
madd w7, w7, w24, w8
madd w3, w3, w24, w5
ldrb w12, [x23, w12, uxtw]
sub w4, w27, w26
sxtw x4, w4
cmp x4, #0
sbfiz x5, x22, #7, #32
madd w10, w10, w24, w11
sub x5, x5, w22, sxtw #3
ldrb w6, [x23, w6, uxtw]
cneg x8, x4, lt
ldrb w9, [x23, w9, uxtw]
add x11, x5, x8
ldrb w7, [x23, w7, uxtw]
cmp x11, x8, lsl #1
fmul v2.2d, v2.2d, v3.d[1]
fmul v1.2d, v1.2d, v3.d[0]
madd w15, w15, w24, w21
ldrb w10, [x23, w10, uxtw]
csel x5, x5, xzr, ls
sub x11, x4, x5
asr x4, x11, #63
ldrb w3, [x23, w3, uxtw]
add x11, x11, x4, lsr #60
add x19, x19, x20
asr x4, x11, #4
orr x5, x1, x2, lsl #16
lsr x11, x14, #48
orr x2, x12, x16, lsl #8
lsr w12, w14, #16
orr x1, x6, x9, lsl #8
lsr x6, x25, #48
lsr w9, w25, #16
add x14, x14, x19
add x25, x25, x17
lsr w30, w14, #16
lsr x16, x25, #48
madd w11, w11, w24, w12
str w5, [x0, #8]
csel w8, w22, wzr, ls
lsr x5, x27, #32
madd w6, w6, w24, w9
add x17, x17, x20
sub x9, x5, x26, lsr #32
lsr w21, w25, #16
sbfiz x5, x28, #7, #32
add x19, x19, x20
cmp x9, #0
sub x5, x5, w28, sxtw #3
add x25, x25, x17
lsr x22, x14, #48
add x14, x14, x19
cneg x12, x9, lt
madd w16, w16, w24, w21
add x17, x17, x20
add x21, x5, x12
cmp x21, x12, lsl #1
ext v29.16b, v26.16b, v3.16b, #8
fcvtzu v1.2d, v1.2d, #16
fcvtzu v2.2d, v2.2d, #16
ldrb w15, [x23, w15, uxtw]
madd w22, w22, w24, w30
csel w12, w28, wzr, ls
csel x5, x5, xzr, ls
add x19, x19, x20
sub x21, x9, x5
asr x5, x21, #63
orr x9, x1, x2, lsl #16
orr x1, x3, x7, lsl #8
orr x2, x10, x15, lsl #8
lsr w7, w25, #16
lsr x10, x14, #48
lsr w15, w14, #16
lsr x3, x25, #48
add x25, x25, x17
add x21, x21, x5, lsr #60
add x14, x14, x19
add x19, x19, x20
lsr w18, w14, #16
lsr x30, x14, #48
asr x5, x21, #4
lsr x21, x25, #48
lsr w28, w25, #16
add x17, x17, x20
ldrb w22, [x23, w22, uxtw]
madd w3, w3, w24, w7
add x14, x14, x19
ldrb w11, [x23, w11, uxtw]
madd w10, w10, w24, w15
ldrb w6, [x23, w6, uxtw]
madd w21, w21, w24, w28
ldrb w16, [x23, w16, uxtw]
add x7, x4, x5, lsl #32
orr x5, x1, x2, lsl #16
lsl x4, x12, #32
add x25, x25, x17
add x17, x17, x20
str w9, [x0, #12]
add x4, x4, w8, sxtw
ldrb w3, [x23, w3, uxtw]
add x19, x19, x20
orr x1, x6, x11, lsl #8
lsr w11, w14, #16
lsr w8, w25, #16
lsr x9, x14, #48
lsr x6, x25, #48
add x14, x14, x19
ldrb w21, [x23, w21, uxtw]
add x25, x25, x17
add x19, x19, x20
lsr w15, w25, #16
lsr x12, x25, #48
madd w9, w9, w24, w11
uqxtn v0.2s, v1.2d
fadd v1.2d, v29.2d, v3.2d
mov v26.16b, v3.16b
ldrb w10, [x23, w10, uxtw]
madd w30, w30, w24, w18
str w5, [x0, #16]
orr x2, x16, x22, lsl #8
add x17, x17, x20
lsr w22, w14, #16
lsr x16, x14, #48
uqxtn2 v0.4s, v2.2d
ldrb w9, [x23, w9, uxtw]
madd w12, w12, w24, w15
add x17, x4, x7, lsl #1
madd w6, w6, w24, w8
madd w16, w16, w24, w22
ldrb w30, [x23, w30, uxtw]
add x14, x26, x7
lsl x20, x4, #2
add x19, x17, x4, lsl #1
orr x4, x1, x2, lsl #16
ldrb w6, [x23, w6, uxtw]
orr x1, x3, x10, lsl #8
orr x2, x21, x30, lsl #8
ldrb w16, [x23, w16, uxtw]
fmul v27.2d, v1.2d, v23.d[0]
umin v0.4s, v0.4s, v22.4s
ldrb w12, [x23, w12, uxtw]
mov x25, x27
orr x3, x1, x2, lsl #16
str w4, [x0, #20]
orr x1, x6, x9, lsl #8
orr x2, x12, x16, lsl #8
mov x27, v0.d[1]
str w3, [x0, #24]
orr x3, x1, x2, lsl #16
ldr x1, [sp, #32]
fmov x26, d0
str w3, [x0, #28]
add x0, x0, #32
cmp x0, x1
b.lo .Lloop
