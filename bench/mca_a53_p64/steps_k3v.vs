// persp_short_inl's four-run steps, every run in vectors (asm/span_persp_a64mid.h,
// short_steps_k3v): x26 = kMidConsts, x27 = &kMidSteps[s], x0 = st[6];
// in: v5 S01, v19 S23, v7 S44, v3 c01, v16 c23, v1 zs23, v31 zc / 2;
// out: x13 a_uv, x9 a_d, x10 a_dd, x23 b_uv, x24 b_d, x25 b_dd (the first pass);
// st = {c_uv, luv, c_d, ld, c_dd, ldd} (the second pass); the steps unpacked ([du, dv] lanes).
ext v@D01.16b, v@in_S01.16b, v@in_S23.16b, #8
ext v@D23.16b, v@in_S23.16b, v@D23.16b, #8
ldp q@k120, q@k25, [x26]
ldp q@bias, q@k1e9, [x26, #32]
ldp q@S, q@SM1, [x27]
ldp q@T, q@C, [x27, #32]
ldp q@H, q@Y, [x27, #64]
ldr q@K, [x27, #96]
sub v@D01.4s, v@D01.4s, v@in_S01.4s
sub v@D23.4s, v@D23.4s, v@in_S23.4s
saddw v@fa.2d, v@bias.2d, v@D01.2s
saddw2 v@fb.2d, v@bias.2d, v@D01.4s
saddw v@fc.2d, v@bias.2d, v@D23.2s
saddw2 v@f3.2d, v@bias.2d, v@D23.4s
fsub v@fa.2d, v@fa.2d, v@bias.2d
fsub v@fb.2d, v@fb.2d, v@bias.2d
fsub v@fc.2d, v@fc.2d, v@bias.2d
fsub v@f3.2d, v@f3.2d, v@bias.2d
fmul d@zch, d@zch, v@zs.d[1]
fmul d@zch, d@zch, v@K.d[0]
fmul v@fa.2d, v@fa.2d, v@c01.d[0]
fmul v@fb.2d, v@fb.2d, v@c01.d[1]
fmul v@fc.2d, v@fc.2d, v@c23.d[0]
fmul v@q.2d, v@f3.2d, v@Y.d[0]
fcvtzs v@fa.2d, v@fa.2d
fcvtzs v@fb.2d, v@fb.2d
fcvtzs v@fc.2d, v@fc.2d
fmls v@f3.2d, v@q.2d, v@Y.d[1]
sqxtn v@dd01.2s, v@fa.2d
sqxtn2 v@dd01.4s, v@fb.2d
sqxtn v@dd23.2s, v@fc.2d
fmla v@q.2d, v@f3.2d, v@Y.d[0]
fcvtzs v@lin3.2d, v@q.2d
fmul v@q.2d, v@q.2d, v@zch.d[0]
facgt v@ok.2d, v@k1e9.2d, v@q.2d
fcvtzs v@q.2d, v@q.2d
sqxtn2 v@dd23.4s, v@q.2d
movi v@okx.2d, #0xffffffffffffffff
xtn2 v@okx.4s, v@ok.2d
abs v@pd01.4s, v@D01.4s
abs v@pd23.4s, v@D23.4s
sshr v@sg01.4s, v@D01.4s, #31
sshr v@sg23.4s, v@D23.4s, #31
ushr v@L01.4s, v@pd01.4s, #4
ushr v@Q.4s, v@pd23.4s, #4
eor v@L01.16b, v@L01.16b, v@sg01.16b
sub v@L01.4s, v@L01.4s, v@sg01.4s
abs v@lin3.2d, v@lin3.2d
xtn2 v@Q.4s, v@lin3.2d
eor v@L23.16b, v@Q.16b, v@sg23.16b
sub v@L23.4s, v@L23.4s, v@sg23.4s
eor v@pdd01.16b, v@dd01.16b, v@sg01.16b
sub v@pdd01.4s, v@pdd01.4s, v@sg01.4s
abs v@a01.4s, v@dd01.4s
abs v@a23.4s, v@dd23.4s
umin v@a01.4s, v@a01.4s, v@k25.4s
umin v@a23.4s, v@a23.4s, v@C.4s
mul v@a01.4s, v@a01.4s, v@k120.4s
mul v@a23.4s, v@a23.4s, v@T.4s
cmhs v@a01.4s, v@pd01.4s, v@a01.4s
cmhs v@a23.4s, v@pd23.4s, v@a23.4s
and v@a23.16b, v@a23.16b, v@okx.16b
mov v@e01.16b, v@pd01.16b
mls v@e01.4s, v@pdd01.4s, v@k120.s[0]
ushr v@e01.4s, v@e01.4s, #4
eor v@e01.16b, v@e01.16b, v@sg01.16b
sub v@e01.4s, v@e01.4s, v@sg01.4s
mov v@r.16b, v@pd23.16b
mls v@r.4s, v@S.4s, v@Q.4s
mul v@m.4s, v@SM1.4s, v@dd23.4s
cmhi v@r.4s, v@H.4s, v@r.4s
sshr v@t.4s, v@m.4s, #1
shl v@m.4s, v@m.4s, #31
eor v@r.16b, v@r.16b, v@sg23.16b
sub v@d23.4s, v@L23.4s, v@t.4s
and v@r.16b, v@r.16b, v@m.16b
ssra v@d23.4s, v@r.4s, #31
bit v@L01.16b, v@e01.16b, v@a01.16b
bit v@L23.16b, v@d23.16b, v@a23.16b
and v@dd01.16b, v@dd01.16b, v@a01.16b
and v@dd23.16b, v@dd23.16b, v@a23.16b
str q@in_S23, [x0]
stp q@L23, q@dd23, [x0, #16]
fmov x13, d@in_S01
mov x23, v@in_S01.d[1]
fmov x9, d@L01
mov x24, v@L01.d[1]
fmov x10, d@dd01
mov x25, v@dd01.d[1]
