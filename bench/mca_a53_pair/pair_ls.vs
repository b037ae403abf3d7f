// persp_short_inl's sample block for two spans A, B at once (asm/span_persp_a64pair.h,
// short_samples2): each vector [span A's value, span B's value] of one sample k (0 .. 4).
// x0 = &A (PerspSpan), x1 = &B, x2 = out (two ShortSamples), x3 = kPairConsts,
// x4 = kShortOffsets + 32 nA, x5 = kShortOffsets + 32 nB; x6 .. x15 scratch.
ldr d@P0, [x0, #48]
add x12, x1, #48
ldr q@k16, [x3]
ldr d@O0, [x4]
ldr d@O1, [x4, #8]
ld1 {v@P0.d}[1], [x12]
ldr d@O2, [x4, #16]
ldr d@b4, [x0]
add x14, x5, #8
add x15, x5, #16
fadd v@P1.2d, v@P0.2d, v@k16.2d
ld1 {v@O0.d}[1], [x5]
ld1 {v@O1.d}[1], [x14]
ld1 {v@O2.d}[1], [x15]
ld1 {v@b4.d}[1], [x1]
fadd v@P2.2d, v@P1.2d, v@k16.2d
fadd v@pos2.2d, v@P0.2d, v@O0.2d
fadd v@pos3.2d, v@P1.2d, v@O1.2d
mov v@b0.16b, v@b4.16b
mov v@b1.16b, v@b4.16b
mov v@b2.16b, v@b4.16b
mov v@b3.16b, v@b4.16b
fadd v@pos4.2d, v@P2.2d, v@O2.2d
ldr d@zix, [x0, #8]
add x9, x1, #8
ldp q@kq, q@kmin, [x3, #64]
ldr q@one, [x3, #16]
ldp q@mask, q@big, [x3, #32]
ld1 {v@zix.d}[1], [x9]
ldr d@uvA4, [x0, #16]
mov v@r0.16b, v@one.16b
mov v@r1.16b, v@one.16b
fmla v@b0.2d, v@zix.2d, v@P0.2d
fmla v@b1.2d, v@zix.2d, v@P1.2d
fmla v@b2.2d, v@zix.2d, v@pos2.2d
fmla v@b3.2d, v@zix.2d, v@pos3.2d
fmla v@b4.2d, v@zix.2d, v@pos4.2d
mov v@r2.16b, v@one.16b
mov v@r3.16b, v@one.16b
fmaxnm v@b0.2d, v@b0.2d, v@kmin.2d
fmaxnm v@b1.2d, v@b1.2d, v@kmin.2d
fmaxnm v@b2.2d, v@b2.2d, v@kmin.2d
fmaxnm v@b3.2d, v@b3.2d, v@kmin.2d
fmaxnm v@b4.2d, v@b4.2d, v@kmin.2d
mov v@r4.16b, v@one.16b
frecpe v@y0.2d, v@b0.2d
frecpe v@y1.2d, v@b1.2d
frecpe v@y2.2d, v@b2.2d
frecpe v@y3.2d, v@b3.2d
frecpe v@y4.2d, v@b4.2d
fmax v@m01.2d, v@b0.2d, v@b1.2d
frecps v@t0.2d, v@b0.2d, v@y0.2d
frecps v@t1.2d, v@b1.2d, v@y1.2d
frecps v@t2.2d, v@b2.2d, v@y2.2d
frecps v@t3.2d, v@b3.2d, v@y3.2d
frecps v@t4.2d, v@b4.2d, v@y4.2d
fmul v@y0.2d, v@y0.2d, v@t0.2d
fmul v@y1.2d, v@y1.2d, v@t1.2d
fmul v@y2.2d, v@y2.2d, v@t2.2d
fmul v@y3.2d, v@y3.2d, v@t3.2d
fmul v@y4.2d, v@y4.2d, v@t4.2d
frecps v@t0.2d, v@b0.2d, v@y0.2d
frecps v@t1.2d, v@b1.2d, v@y1.2d
frecps v@t2.2d, v@b2.2d, v@y2.2d
frecps v@t3.2d, v@b3.2d, v@y3.2d
frecps v@t4.2d, v@b4.2d, v@y4.2d
fmul v@y0.2d, v@y0.2d, v@t0.2d
fmax v@m23.2d, v@b2.2d, v@b3.2d
fmul v@y1.2d, v@y1.2d, v@t1.2d
fmul v@y2.2d, v@y2.2d, v@t2.2d
fmul v@y3.2d, v@y3.2d, v@t3.2d
fmul v@y4.2d, v@y4.2d, v@t4.2d
fmls v@r0.2d, v@b0.2d, v@y0.2d
fmls v@r1.2d, v@b1.2d, v@y1.2d
fmls v@r2.2d, v@b2.2d, v@y2.2d
fmls v@r3.2d, v@b3.2d, v@y3.2d
fmls v@r4.2d, v@b4.2d, v@y4.2d
fmax v@m01.2d, v@m01.2d, v@m23.2d
orr v@h0.16b, v@b0.16b, v@mask.16b
orr v@h1.16b, v@b1.16b, v@mask.16b
orr v@h2.16b, v@b2.16b, v@mask.16b
orr v@h3.16b, v@b3.16b, v@mask.16b
orr v@h4.16b, v@b4.16b, v@mask.16b
fmax v@m01.2d, v@m01.2d, v@b4.2d
fmla v@y0.2d, v@y0.2d, v@r0.2d
fmla v@y1.2d, v@y1.2d, v@r1.2d
fmla v@y2.2d, v@y2.2d, v@r2.2d
fmla v@y3.2d, v@y3.2d, v@r3.2d
fmla v@y4.2d, v@y4.2d, v@r4.2d
cmhs v@m01.2d, v@m01.2d, v@big.2d
uminp v@u01.4s, v@h0.4s, v@h1.4s
uminp v@u23.4s, v@h2.4s, v@h3.4s
mov v@s0.16b, v@one.16b
mov v@s1.16b, v@one.16b
mov v@s2.16b, v@one.16b
uminp v@u4.4s, v@h4.4s, v@m01.4s
mov v@s3.16b, v@one.16b
umax v@u01.4s, v@u01.4s, v@u23.4s
mov v@s4.16b, v@one.16b
fmls v@s0.2d, v@b0.2d, v@y0.2d
fmls v@s1.2d, v@b1.2d, v@y1.2d
fmls v@s2.2d, v@b2.2d, v@y2.2d
fmls v@s3.2d, v@b3.2d, v@y3.2d
fmls v@s4.2d, v@b4.2d, v@y4.2d
umax v@u01.4s, v@u01.4s, v@u4.4s
fmla v@y0.2d, v@y0.2d, v@s0.2d
fmla v@y1.2d, v@y1.2d, v@s1.2d
fmla v@y2.2d, v@y2.2d, v@s2.2d
fmla v@y3.2d, v@y3.2d, v@s3.2d
fmla v@y4.2d, v@y4.2d, v@s4.2d
umaxv s@u01, v@u01.4s
ldr d@uvB4, [x1, #16]
add x6, x0, #32
add x10, x1, #32
ldr d@uvxA, [x0, #24]
ldr d@uvxB, [x1, #24]
ld1 {v@uvA4.d}[1], [x6]
fmov w6, s@u01
ld1 {v@uvB4.d}[1], [x10]
add x7, x0, #40
add x11, x1, #40
mov v@uvA0.16b, v@uvA4.16b
mov v@uvA1.16b, v@uvA4.16b
mov v@uvA2.16b, v@uvA4.16b
mov v@uvA3.16b, v@uvA4.16b
mov v@uvB0.16b, v@uvB4.16b
mov v@uvB1.16b, v@uvB4.16b
mov v@uvB2.16b, v@uvB4.16b
mov v@uvB3.16b, v@uvB4.16b
ld1 {v@uvxA.d}[1], [x7]
ld1 {v@uvxB.d}[1], [x11]
add x8, x0, #56
add x13, x1, #56
cmn w6, #1
fmla v@uvA0.2d, v@uvxA.2d, v@P0.d[0]
fmla v@uvA1.2d, v@uvxA.2d, v@P1.d[0]
fmla v@uvA2.2d, v@uvxA.2d, v@pos2.d[0]
fmla v@uvA3.2d, v@uvxA.2d, v@pos3.d[0]
fmla v@uvA4.2d, v@uvxA.2d, v@pos4.d[0]
fmla v@uvB0.2d, v@uvxB.2d, v@P0.d[1]
fmla v@uvB1.2d, v@uvxB.2d, v@P1.d[1]
fmla v@uvB2.2d, v@uvxB.2d, v@pos2.d[1]
fmla v@uvB3.2d, v@uvxB.2d, v@pos3.d[1]
fmla v@uvB4.2d, v@uvxB.2d, v@pos4.d[1]
b.ne 2f
ldr q@onef, [x3, #16]
fdiv v@y0.2d, v@onef.2d, v@b0.2d
fdiv v@y1.2d, v@onef.2d, v@b1.2d
fdiv v@y2.2d, v@onef.2d, v@b2.2d
fdiv v@y3.2d, v@onef.2d, v@b3.2d
fdiv v@y4.2d, v@onef.2d, v@b4.2d
2:
fmul v@uvA0.2d, v@uvA0.2d, v@y0.d[0]
fmul v@uvA2.2d, v@uvA2.2d, v@y2.d[0]
fmul v@uvA4.2d, v@uvA4.2d, v@y4.d[0]
fmul v@uvA1.2d, v@uvA1.2d, v@y1.d[0]
fmul v@uvA3.2d, v@uvA3.2d, v@y3.d[0]
fmul v@uvB0.2d, v@uvB0.2d, v@y0.d[1]
fcvtzu v@uvA0.2d, v@uvA0.2d, #16
fcvtzu v@uvA2.2d, v@uvA2.2d, #16
fcvtzu v@uvA4.2d, v@uvA4.2d, #16
fcvtzu v@uvA1.2d, v@uvA1.2d, #16
fcvtzu v@uvA3.2d, v@uvA3.2d, #16
fmul v@uvB2.2d, v@uvB2.2d, v@y2.d[1]
uqxtn v@S01A.2s, v@uvA0.2d
uqxtn v@S23A.2s, v@uvA2.2d
uqxtn v@S44A.2s, v@uvA4.2d
fmul v@uvB4.2d, v@uvB4.2d, v@y4.d[1]
fadd v@s01.2d, v@y0.2d, v@y1.2d
fadd v@s12.2d, v@y1.2d, v@y2.2d
uqxtn2 v@S01A.4s, v@uvA1.2d
uqxtn2 v@S23A.4s, v@uvA3.2d
fmul v@uvB1.2d, v@uvB1.2d, v@y1.d[1]
fmul v@uvB3.2d, v@uvB3.2d, v@y3.d[1]
fcvtzu v@uvB0.2d, v@uvB0.2d, #16
fcvtzu v@uvB2.2d, v@uvB2.2d, #16
uqxtn2 v@S44A.4s, v@uvA4.2d
fadd v@s23.2d, v@y2.2d, v@y3.2d
fadd v@s34.2d, v@y3.2d, v@y4.2d
fmul v@zck.2d, v@zix.2d, v@kq.2d
fcvtzu v@uvB4.2d, v@uvB4.2d, #16
trn1 v@zs01A.2d, v@s01.2d, v@s12.2d
fcvtzu v@uvB1.2d, v@uvB1.2d, #16
fcvtzu v@uvB3.2d, v@uvB3.2d, #16
uqxtn v@S01B.2s, v@uvB0.2d
uqxtn v@S23B.2s, v@uvB2.2d
trn1 v@zs23A.2d, v@s23.2d, v@s34.2d
uqxtn v@S44B.2s, v@uvB4.2d
fmul v@c01A.2d, v@zs01A.2d, v@zck.d[0]
trn2 v@zs01B.2d, v@s01.2d, v@s12.2d
uqxtn2 v@S01B.4s, v@uvB1.2d
uqxtn2 v@S23B.4s, v@uvB3.2d
fmul v@c23A.2d, v@zs23A.2d, v@zck.d[0]
uqxtn2 v@S44B.4s, v@uvB4.2d
trn2 v@zs23B.2d, v@s23.2d, v@s34.2d
fmul v@c01B.2d, v@zs01B.2d, v@zck.d[1]
ld1r {v@mA.2d}, [x8]
ld1r {v@mB.2d}, [x13]
fmul v@c23B.2d, v@zs23B.2d, v@zck.d[1]
umin v@S01A.4s, v@S01A.4s, v@mA.4s
umin v@S23A.4s, v@S23A.4s, v@mA.4s
umin v@S44A.4s, v@S44A.4s, v@mA.4s
umin v@S01B.4s, v@S01B.4s, v@mB.4s
umin v@S23B.4s, v@S23B.4s, v@mB.4s
umin v@S44B.4s, v@S44B.4s, v@mB.4s
stp q@S01A, q@S23A, [x2, #0]
stp q@S44A, q@zs01A, [x2, #32]
stp q@zs23A, q@c01A, [x2, #64]
str q@c23A, [x2, #96]
stp q@S01B, q@S23B, [x2, #112]
stp q@S44B, q@zs01B, [x2, #144]
stp q@zs23B, q@c01B, [x2, #176]
str q@c23B, [x2, #208]
