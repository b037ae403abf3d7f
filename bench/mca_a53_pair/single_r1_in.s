add w1, w1, #0xf
stp x27, x28, [sp, #96]
adrp x0, .Ltgt
add x0, x0, #0x240
asr w1, w1, #4
sub w27, w1, #0x1
add x3, x0, #0x88
stp x19, x20, [sp, #32]
sub w6, w5, w27, lsl #4
stp x21, x22, [sp, #48]
stp x23, x24, [sp, #64]
stp d8, d9, [sp, #112]
ldr d8, [x4, #8]
str w6, [sp, #152]
sub w9, w5, #0x1
cmp w9, #0x20
mov w11, #0x20
sub w10, w5, #0x11
fmov d1, #1.600000000000000000e+01
fmov d18, #5.000000000000000000e-01
ldr d0, [x4, #48]
csel w9, w9, w11, lt
cmp w10, #0x20
add x6, x4, #0x10
ld2r {v16.2d, v17.2d}, [x4]
ld1r {v26.2d}, [x4]
csel w10, w10, w11, lt
fadd d2, d0, d1
sub w11, w5, #0x21
scvtf d5, w10
scvtf d4, w9
ld1r {v27.2d}, [x4]
trn1 v0.2d, v0.2d, v2.2d
fadd d3, d2, d1
ld2 {v20.2d, v21.2d}, [x6]
fmov v1.2d, #1.000000000000000000e+00
scvtf d6, w11
trn1 v4.2d, v4.2d, v5.2d
ld1r {v31.2d}, [x3]
fmla v26.2d, v17.2d, v0.2d
fadd v7.2d, v0.2d, v4.2d
fadd d3, d3, d6
ld2 {v22.2d, v23.2d}, [x6]
mov x9, #0xbfb0000000000000
ld2 {v29.2d, v30.2d}, [x6]
fmaxnm v26.2d, v26.2d, v31.2d
fmla v27.2d, v17.2d, v7.2d
fmadd d28, d17, d3, d16
fmla v20.2d, v21.2d, v0.d[1]
frecpe v2.2d, v26.2d
mov x8, v26.d[1]
fmov d9, x9
fmul d9, d8, d9
fmul d8, d8, d18
fmov x7, d26
ld2 {v24.2d, v25.2d}, [x6]
fmaxnm v27.2d, v27.2d, v31.2d
fmaxnm d28, d28, d31
fmla v22.2d, v23.2d, v7.d[0]
frecps v5.2d, v26.2d, v2.2d
frecpe v6.2d, v27.2d
frecpe d4, d28
ld2 {v18.2d, v19.2d}, [x6]
fmax v31.2d, v26.2d, v27.2d
fmov x6, d28
fmov x11, d27
fmul v2.2d, v2.2d, v5.2d
frecps v16.2d, v27.2d, v6.2d
frecps d17, d28, d4
mov x10, v27.d[1]
fmaxp d31, v31.2d
add x7, x7, #0x1
add x6, x6, #0x1
lsl x7, x7, #12
lsl x6, x6, #12
add x10, x10, #0x1
frecps v5.2d, v26.2d, v2.2d
fmul d4, d4, d17
fmax d31, d31, d28
fmul v6.2d, v6.2d, v16.2d
add x8, x8, #0x1
add x11, x11, #0x1
lsl x8, x8, #12
lsl x10, x10, #12
lsl x11, x11, #12
frecps d17, d28, d4
frecps v16.2d, v27.2d, v6.2d
clz x7, x7
clz x11, x11
clz x10, x10
fmul v2.2d, v2.2d, v5.2d
mov v5.16b, v1.16b
fmul d4, d4, d17
fmul v6.2d, v6.2d, v16.2d
mov v16.16b, v1.16b
fmov x9, d31
orr x11, x11, x10
clz x8, x8
orr x7, x7, x8
fmsub d17, d28, d4, d1
fmls v5.2d, v26.2d, v2.2d
fmla v29.2d, v30.2d, v3.d[0]
fmls v16.2d, v27.2d, v6.2d
orr x7, x7, x11
clz x6, x6
lsr x9, x9, #52
fmla v2.2d, v2.2d, v5.2d
fmadd d4, d4, d17, d4
fmla v6.2d, v6.2d, v16.2d
mov v5.16b, v1.16b
mov v16.16b, v1.16b
add x9, x9, #0x19
orr x7, x7, x6
lsr x9, x9, #5
fmla v18.2d, v19.2d, v0.d[0]
fmls v5.2d, v26.2d, v2.2d
fmls v16.2d, v27.2d, v6.2d
fmsub d17, d28, d4, d1
fmla v24.2d, v25.2d, v7.d[1]
orr x7, x7, x9
fmla v2.2d, v2.2d, v5.2d
fmla v6.2d, v6.2d, v16.2d
fmadd d4, d4, d17, d4
tbz w7, #6, .Ltgt
