// persp_short_inl's four-run steps with the last run's last_dd in core registers
// (asm/span_persp_a64mid.h, short_steps_k3i): x26 = kMidConsts, x27 = &kRecipSteps[s],
// x28 = s (1 .. 15), x0 = the second pass's state st[6];
// in: v5 S01, v19 S23, v7 S44, v3 c01, v16 c23, v1 zs23, v30 double(s), v31 zc / 2;
// out: x13 a_uv, x9 a_d, x10 a_dd, x23 b_uv, x24 b_d, x25 b_dd (the first pass);
// st = {c_uv, luv, c_d, c_dd, ld, ldd} (the second pass).
ext v0.16b, v5.16b, v19.16b, #8
ld1r {v6.2d}, [x27]
ext v7.16b, v19.16b, v7.16b, #8
ldp q17, q2, [x26, #32]
sub v0.4s, v0.4s, v5.4s
sub v7.4s, v7.4s, v19.4s
ldp q18, q20, [x26]
saddw v21.2d, v17.2d, v0.2s
saddw2 v22.2d, v17.2d, v0.4s
saddw2 v4.2d, v17.2d, v7.4s
saddw v23.2d, v17.2d, v7.2s
fsub v21.2d, v21.2d, v17.2d
fsub v22.2d, v22.2d, v17.2d
fsub v4.2d, v4.2d, v17.2d
fmul d31, d31, v1.d[1]
fsub v23.2d, v23.2d, v17.2d
abs v26.4s, v0.4s
fmul v21.2d, v21.2d, v3.d[0]
abs v27.4s, v7.4s
fmul v1.2d, v4.2d, v6.2d
sshr v24.4s, v0.4s, #31
sshr v25.4s, v7.4s, #31
fmul v23.2d, v23.2d, v16.d[0]
fcvtzs v21.2d, v21.2d
fmul v22.2d, v22.2d, v3.d[1]
fmls v4.2d, v1.2d, v30.d[0]
ushr v28.4s, v27.4s, #4
sqxtn v21.2s, v21.2d
fcvtzs v22.2d, v22.2d
ushr v17.4s, v26.4s, #4
fcvtzs v23.2d, v23.2d
fmla v1.2d, v4.2d, v6.2d
sqxtn v23.2s, v23.2d
eor v17.16b, v17.16b, v24.16b
sqxtn2 v21.4s, v22.2d
mov v3.16b, v26.16b
fmov v6.2d, #-2.0
mov v16.16b, v27.16b
abs v29.4s, v23.4s
fcvtzs v4.2d, v1.2d
fmul v1.2d, v1.2d, v31.d[0]
eor v31.16b, v23.16b, v25.16b
eor v30.16b, v21.16b, v24.16b
abs v22.4s, v21.4s
umin v29.4s, v29.4s, v20.4s
fmul v1.2d, v1.2d, v6.2d
sub v31.4s, v31.4s, v25.4s
sub v30.4s, v30.4s, v24.4s
sub v17.4s, v17.4s, v24.4s
mul v29.4s, v29.4s, v18.4s
umin v22.4s, v22.4s, v20.4s
facgt v6.2d, v2.2d, v1.2d
mls v16.4s, v31.4s, v18.s[0]
mls v3.4s, v30.4s, v18.s[0]
fcvtzs v1.2d, v1.2d
cmhs v29.4s, v27.4s, v29.4s
mul v22.4s, v22.4s, v18.4s
ushr v16.4s, v16.4s, #4
ushr v3.4s, v3.4s, #4
and v6.16b, v1.16b, v6.16b
eor v28.16b, v28.16b, v25.16b
cmhs v22.4s, v26.4s, v22.4s
and v23.16b, v23.16b, v29.16b
eor v16.16b, v16.16b, v25.16b
eor v3.16b, v3.16b, v24.16b
movi v26.2d, #0xffffffff00000000
sub v28.4s, v28.4s, v25.4s
and v21.16b, v21.16b, v22.16b
sub v16.4s, v16.4s, v25.4s
sub v3.4s, v3.4s, v24.4s
shl v24.2d, v21.2d, #32
bit v28.16b, v16.16b, v29.16b
bit v17.16b, v3.16b, v22.16b
and v16.16b, v21.16b, v26.16b
shl v3.2d, v17.2d, #32
and v2.16b, v17.16b, v26.16b
ssra v16.2d, v24.2d, #32
ssra v2.2d, v3.2d, #32
zip1 v27.2d, v28.2d, v23.2d
uzp1 v4.4s, v4.4s, v6.4s
shl v25.2d, v27.2d, #32
and v27.16b, v27.16b, v26.16b
ssra v27.2d, v25.2d, #32
str q19, [x0]
str q27, [x0, #16]
fmov x13, d5
mov x23, v5.d[1]
mov x24, v2.d[1]
mov x25, v16.d[1]
mov x1, v7.d[1]
fmov x3, d4
mov x5, v4.d[1]
sub w9, w28, #1
mul w10, w28, w9
cmp w28, #1
csetm w14, hi
lsr w10, w10, #1
lsr x2, x1, #32
lsr x4, x3, #32
lsr x6, x5, #32
and w5, w5, w14
and w6, w6, w14
asr w7, w1, #31
asr w8, w2, #31
asr w11, w5, #31
asr w12, w6, #31
eor w14, w1, w7
eor w15, w2, w8
eor w16, w5, w11
eor w17, w6, w12
eor w19, w3, w7
eor w20, w4, w8
sub w14, w14, w7
sub w15, w15, w8
sub w16, w16, w11
sub w17, w17, w12
eor w11, w5, w7
eor w12, w6, w8
sub w19, w19, w7
sub w20, w20, w8
sub w11, w11, w7
sub w12, w12, w8
umsubl x16, w16, w10, x14
umsubl x17, w17, w10, x15
msub w1, w28, w19, w14
msub w2, w28, w20, w15
mul w11, w9, w11
mul w12, w9, w12
cmp w28, w1, lsl #1
cset w1, hi
cmp w28, w2, lsl #1
cset w2, hi
sub w19, w19, w11, asr #1
sub w20, w20, w12, asr #1
and w1, w1, w11
and w2, w2, w12
sub w19, w19, w1
sub w20, w20, w2
eor w19, w19, w7
eor w20, w20, w8
cmp x16, #0
sub w19, w19, w7
csel w5, wzr, w5, lt
sub w20, w20, w8
csel w3, w3, w19, lt
cmp x17, #0
csel w6, wzr, w6, lt
csel w4, w4, w20, lt
lsl x11, x4, #32
lsl x12, x6, #32
add x11, x11, w3, sxtw
add x12, x12, w5, sxtw
fmov x9, d2
fmov x10, d16
stp x11, x12, [x0, #32]
