// persp_short_inl's full-run and last-run steps for 4 runs (asm/span_persp_a64short.h,
// short_steps_k3): x8 = &kBiasBits, x9 = kShortConsts, x10 = &kRecipSteps[s], x11 = &k1e9;
// in: v5 S01, v19 S23, v7 S44, v3 c01, v16 c23, v1 zs23, v30 double(s), v31 zc / 2;
// out: v0 D01, v7 D23, v3 dlo, v16 ddlo, v1 dhi, v2 ddhi, v4 lin, v6 dd (the last run).
ext v0.16b, v5.16b, v19.16b, #8
ld1r {v6.2d}, [x10]
ext v7.16b, v19.16b, v7.16b, #8
ld1r {v17.2d}, [x8]
sub v0.4s, v0.4s, v5.4s
sub v7.4s, v7.4s, v19.4s
ld1r {v2.2d}, [x11]
ldp q18, q20, [x9]
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
shl v27.2d, v23.2d, #32
bit v28.16b, v16.16b, v29.16b
bit v17.16b, v3.16b, v22.16b
and v16.16b, v21.16b, v26.16b
and v2.16b, v23.16b, v26.16b
shl v25.2d, v28.2d, #32
and v3.16b, v17.16b, v26.16b
ssra v16.2d, v24.2d, #32
shl v24.2d, v17.2d, #32
and v1.16b, v28.16b, v26.16b
ssra v2.2d, v27.2d, #32
ssra v3.2d, v24.2d, #32
ssra v1.2d, v25.2d, #32
