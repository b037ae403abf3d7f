stp x27, x28, [sp, #80]
add w28, w1, #0xf
adrp x27, .Ltgt
add x27, x27, #0x9e0
asr w28, w28, #4
sub w0, w28, #0x1
stp x19, x20, [sp, #16]
sub w0, w1, w0, lsl #4
stp x21, x22, [sp, #32]
stp x23, x24, [sp, #48]
stp d8, d9, [sp, #96]
str w0, [sp, #128]
adrp x2, .Ltgt
add x1, x4, #0x10
ldr d9, [x4, #56]
add x2, x2, x5, lsl #5
fadd d2, d0, d1
ld1r {v26.2d}, [x4]
ld2r {v16.2d, v17.2d}, [x4]
ldr q4, [x2, #160]
ldr d6, [x2, #176]
trn1 v0.2d, v0.2d, v2.2d
ld2 {v22.2d, v23.2d}, [x1]
fadd d3, d2, d1
mov x7, #0xbfb0000000000000
ld1r {v5.2d}, [x27]
ld1r {v27.2d}, [x4]
fmov v1.2d, #1.000000000000000000e+00
fadd v7.2d, v0.2d, v4.2d
fmla v26.2d, v17.2d, v0.2d
ld2 {v20.2d, v21.2d}, [x1]
fadd d3, d3, d6
fmov d6, x7
fmla v27.2d, v17.2d, v7.2d
ld2 {v29.2d, v30.2d}, [x1]
fmaxnm v26.2d, v26.2d, v5.2d
fmadd d28, d17, d3, d16
fmla v22.2d, v23.2d, v7.d[0]
fmla v20.2d, v21.2d, v0.d[1]
frecpe v2.2d, v26.2d
fmaxnm v27.2d, v27.2d, v5.2d
fmov d18, #5.000000000000000000e-01
fmov x2, d26
fmaxnm d28, d28, d5
mov x3, v26.d[1]
frecps v5.2d, v26.2d, v2.2d
frecpe v21.2d, v27.2d
fmax v4.2d, v26.2d, v27.2d
ld2 {v24.2d, v25.2d}, [x1]
fmul d6, d31, d6
fmov x9, d27
fmul d31, d31, d18
frecpe d23, d28
mov x8, v27.d[1]
fmul v2.2d, v2.2d, v5.2d
ld2 {v18.2d, v19.2d}, [x1]
fmov x1, d28
frecps v16.2d, v27.2d, v21.2d
fmaxp d4, v4.2d
frecps d17, d28, d23
add x2, x2, #0x1
add x1, x1, #0x1
lsl x2, x2, #12
lsl x1, x1, #12
add x8, x8, #0x1
fmul v21.2d, v21.2d, v16.2d
fmul d23, d23, d17
frecps v5.2d, v26.2d, v2.2d
fmax d4, d4, d28
add x9, x9, #0x1
add x3, x3, #0x1
lsl x9, x9, #12
clz x2, x2
lsl x8, x8, #12
frecps v16.2d, v27.2d, v21.2d
frecps d17, d28, d23
clz x9, x9
clz x1, x1
lsl x3, x3, #12
fmul v2.2d, v2.2d, v5.2d
mov v5.16b, v1.16b
fmul v21.2d, v21.2d, v16.2d
fmul d23, d23, d17
mov v16.16b, v1.16b
clz x8, x8
clz x3, x3
orr x9, x9, x8
orr x2, x2, x3
fmov x7, d4
fmls v5.2d, v26.2d, v2.2d
fmsub d17, d28, d23, d1
fmls v16.2d, v27.2d, v21.2d
orr x2, x2, x9
lsr x7, x7, #52
fmla v2.2d, v2.2d, v5.2d
fmadd d23, d23, d17, d23
fmla v21.2d, v21.2d, v16.2d
mov v5.16b, v1.16b
mov v16.16b, v1.16b
orr x2, x2, x1
add x7, x7, #0x19
lsr x7, x7, #5
fmla v18.2d, v19.2d, v0.d[0]
fmls v5.2d, v26.2d, v2.2d
fmls v16.2d, v27.2d, v21.2d
fmsub d17, d28, d23, d1
fmla v29.2d, v30.2d, v3.d[0]
orr x2, x2, x7
fmla v24.2d, v25.2d, v7.d[1]
fmla v21.2d, v21.2d, v16.2d
fmadd d23, d23, d17, d23
fmla v2.2d, v2.2d, v5.2d
dup v9.2d, v9.d[0]
tbz w2, #6, .Ltgt
