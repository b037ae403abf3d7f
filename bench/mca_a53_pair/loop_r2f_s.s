fmul v18.2d, v18.2d, v30.d[0]
fadd v12.2d, v30.2d, v15.2d
fmul v16.2d, v16.2d, v27.d[0]
fmul v21.2d, v21.2d, v15.d[0]
fmul v22.2d, v22.2d, v29.d[0]
fadd v6.2d, v28.2d, v29.2d
fmul v24.2d, v24.2d, v29.d[1]
fadd v8.2d, v29.2d, v30.2d
fcvtzu v16.2d, v16.2d, #16
fmul v2.2d, v2.2d, v28.d[0]
fcvtzu v18.2d, v18.2d, #16
fadd v0.2d, v27.2d, v28.2d
fcvtzu v22.2d, v22.2d, #16
fcvtzu v21.2d, v21.2d, #16
fmul v26.2d, v26.2d, v27.d[1]
fcvtzu v2.2d, v2.2d, #16
uqxtn v5.2s, v16.2d
fcvtzu v24.2d, v24.2d, #16
uqxtn v19.2s, v22.2d
uqxtn v7.2s, v21.2d
fmul v17.2d, v17.2d, v15.d[1]
trn1 v1.2d, v8.2d, v12.2d
fmul v23.2d, v23.2d, v28.d[1]
uqxtn2 v5.4s, v2.2d
fmul v25.2d, v25.2d, v30.d[1]
fcvtzu v26.2d, v26.2d, #16
trn1 v9.2d, v0.2d, v6.2d
ld1r {v2.2d}, [x8]
uqxtn2 v7.4s, v21.2d
fcvtzu v17.2d, v17.2d, #16
fcvtzu v23.2d, v23.2d, #16
uqxtn v10.2s, v26.2d
uqxtn v11.2s, v24.2d
fcvtzu v25.2d, v25.2d, #16
trn2 v22.2d, v8.2d, v12.2d
uqxtn2 v19.4s, v18.2d
uqxtn v13.2s, v17.2d
uqxtn2 v10.4s, v23.2d
ld1r {v18.2d}, [x13]
fmul v14.2d, v31.2d, v20.2d
uqxtn2 v11.4s, v25.2d
fmov v20.2d, #5.000000000000000000e-01
umin v19.4s, v19.4s, v2.4s
trn2 v4.2d, v0.2d, v6.2d
uqxtn2 v13.4s, v17.2d
fmul v28.2d, v22.2d, v14.d[1]
umin v10.4s, v10.4s, v18.4s
umin v11.4s, v11.4s, v18.4s
fmul v31.2d, v31.2d, v20.2d
fmul v27.2d, v4.2d, v14.d[1]
umin v13.4s, v13.4s, v18.4s
umin v7.4s, v7.4s, v2.4s
fmul v3.2d, v9.2d, v14.d[0]
stp q10, q11, [x24]
tst x20, #0x7fffffffffffffff
and w23, w23, w19
sub w18, w18, #0x11
stp q13, q4, [x24, #32]
sub w17, w17, #0x11
stp q22, q27, [x24, #64]
sub x18, x18, #0x30
sub x17, x17, #0x30
lsl x21, x21, #1
str q28, [x24, #96]
and x17, x17, x18
ccmp x21, #0x0, #0x4, ne
lsr x17, x17, #63
and w23, w23, w16
and w23, w23, w17
add x18, x22, #0xb0
ccmp w23, #0x0, #0x4, ne
umin v5.4s, v5.4s, v2.4s
str q31, [sp, #336]
csel x23, x18, xzr, ne
fmul v16.2d, v1.2d, v14.d[0]
str w27, [sp, #168]
cmp w5, #0x4
str x23, [sp, #200]
sub w9, w27, #0x1
ldr x30, [x22]
b.ne .Ltgt
