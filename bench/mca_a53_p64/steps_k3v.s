// persp_short_inl's four-run steps, every run in vectors (asm/span_persp_a64mid.h,
// short_steps_k3v): x26 = kMidConsts, x27 = &kMidSteps[s], x0 = st[6];
// in: v5 S01, v19 S23, v7 S44, v3 c01, v16 c23, v1 zs23, v31 zc / 2;
// out: x13 a_uv, x9 a_d, x10 a_dd, x23 b_uv, x24 b_d, x25 b_dd (the first pass);
// st = {c_uv, luv, c_d, ld, c_dd, ldd} (the second pass); the steps unpacked ([du, dv] lanes).
ext v0.16b, v5.16b, v19.16b, #8
ext v7.16b, v19.16b, v7.16b, #8
ldp q2, q4, [x26]
ldp q6, q17, [x26, #32]
ldp q18, q20, [x27]
ldp q21, q22, [x27, #32]
ldp q23, q24, [x27, #64]
ldr q25, [x27, #96]
sub v0.4s, v0.4s, v5.4s
sub v7.4s, v7.4s, v19.4s
saddw v26.2d, v6.2d, v0.2s
saddw2 v27.2d, v6.2d, v0.4s
saddw v28.2d, v6.2d, v7.2s
saddw2 v29.2d, v6.2d, v7.4s
fsub v26.2d, v26.2d, v6.2d
fsub v27.2d, v27.2d, v6.2d
fsub v28.2d, v28.2d, v6.2d
fsub v29.2d, v29.2d, v6.2d
fmul d31, d31, v1.d[1]
fmul d31, d31, v25.d[0]
fmul v26.2d, v26.2d, v3.d[0]
fmul v27.2d, v27.2d, v3.d[1]
fmul v28.2d, v28.2d, v16.d[0]
fmul v30.2d, v29.2d, v24.d[0]
fcvtzs v26.2d, v26.2d
fcvtzs v27.2d, v27.2d
fcvtzs v28.2d, v28.2d
fmls v29.2d, v30.2d, v24.d[1]
sqxtn v6.2s, v26.2d
sqxtn2 v6.4s, v27.2d
sqxtn v1.2s, v28.2d
fmla v30.2d, v29.2d, v24.d[0]
fcvtzs v25.2d, v30.2d
fmul v30.2d, v30.2d, v31.d[0]
facgt v3.2d, v17.2d, v30.2d
fcvtzs v30.2d, v30.2d
and v3.16b, v30.16b, v3.16b
sqxtn2 v1.4s, v3.2d
abs v16.4s, v0.4s
abs v26.4s, v7.4s
sshr v27.4s, v0.4s, #31
sshr v28.4s, v7.4s, #31
ushr v24.4s, v16.4s, #4
ushr v29.4s, v26.4s, #4
eor v24.16b, v24.16b, v27.16b
sub v24.4s, v24.4s, v27.4s
abs v25.2d, v25.2d
xtn2 v29.4s, v25.2d
eor v31.16b, v29.16b, v28.16b
sub v31.4s, v31.4s, v28.4s
eor v17.16b, v6.16b, v27.16b
eor v30.16b, v1.16b, v28.16b
sub v17.4s, v17.4s, v27.4s
sub v30.4s, v30.4s, v28.4s
abs v3.4s, v6.4s
abs v0.4s, v1.4s
umin v3.4s, v3.4s, v4.4s
umin v0.4s, v0.4s, v22.4s
mul v3.4s, v3.4s, v2.4s
mul v0.4s, v0.4s, v21.4s
cmhs v3.4s, v16.4s, v3.4s
cmhs v0.4s, v26.4s, v0.4s
mov v7.16b, v16.16b
mls v7.4s, v17.4s, v2.s[0]
ushr v7.4s, v7.4s, #4
eor v7.16b, v7.16b, v27.16b
sub v7.4s, v7.4s, v27.4s
mov v25.16b, v26.16b
mls v25.4s, v18.4s, v29.4s
mul v4.4s, v20.4s, v30.4s
cmhi v25.4s, v23.4s, v25.4s
sshr v22.4s, v4.4s, #1
shl v4.4s, v4.4s, #31
sub v29.4s, v29.4s, v22.4s
and v25.16b, v25.16b, v4.16b
ssra v29.4s, v25.4s, #31
eor v29.16b, v29.16b, v28.16b
sub v29.4s, v29.4s, v28.4s
bit v24.16b, v7.16b, v3.16b
bit v31.16b, v29.16b, v0.16b
and v6.16b, v6.16b, v3.16b
and v1.16b, v1.16b, v0.16b
str q19, [x0]
stp q31, q1, [x0, #16]
fmov x13, d5
mov x23, v5.d[1]
fmov x9, d24
mov x24, v24.d[1]
fmov x10, d6
mov x25, v6.d[1]
