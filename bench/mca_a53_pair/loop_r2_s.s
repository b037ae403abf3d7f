lsl x19, x19, #1
fmul v21.2d, v21.2d, v31.d[0]
fmul v24.2d, v24.2d, v29.d[1]
fmul v22.2d, v22.2d, v29.d[0]
fmul v16.2d, v16.2d, v27.d[0]
fadd v8.2d, v29.2d, v30.2d
fmul v18.2d, v18.2d, v30.d[0]
fmul v2.2d, v2.2d, v28.d[0]
fmul v26.2d, v26.2d, v27.d[1]
fcvtzu v21.2d, v21.2d, #16
fcvtzu v22.2d, v22.2d, #16
fcvtzu v16.2d, v16.2d, #16
fadd v0.2d, v27.2d, v28.2d
fcvtzu v18.2d, v18.2d, #16
fcvtzu v2.2d, v2.2d, #16
fcvtzu v26.2d, v26.2d, #16
uqxtn v7.2s, v21.2d
uqxtn v5.2s, v16.2d
fadd v12.2d, v30.2d, v31.2d
fadd v6.2d, v28.2d, v29.2d
fmul v23.2d, v23.2d, v28.d[1]
uqxtn v19.2s, v22.2d
fmul v17.2d, v17.2d, v31.d[1]
uqxtn2 v5.4s, v2.2d
trn1 v1.2d, v8.2d, v12.2d
ld1r {v2.2d}, [x8]
fcvtzu v24.2d, v24.2d, #16
fmul v25.2d, v25.2d, v30.d[1]
trn1 v9.2d, v0.2d, v6.2d
fcvtzu v17.2d, v17.2d, #16
uqxtn2 v19.4s, v18.2d
fcvtzu v23.2d, v23.2d, #16
uqxtn v10.2s, v26.2d
uqxtn2 v7.4s, v21.2d
uqxtn v11.2s, v24.2d
fmul v14.2d, v15.2d, v20.2d
uqxtn v13.2s, v17.2d
fcvtzu v25.2d, v25.2d, #16
uqxtn2 v10.4s, v23.2d
trn2 v22.2d, v8.2d, v12.2d
ld1r {v18.2d}, [x13]
trn2 v4.2d, v0.2d, v6.2d
uqxtn2 v13.4s, v17.2d
uqxtn2 v11.4s, v25.2d
umin v5.4s, v5.4s, v2.4s
fmul v3.2d, v9.2d, v14.d[0]
umin v19.4s, v19.4s, v2.4s
fmul v28.2d, v22.2d, v14.d[1]
umin v10.4s, v10.4s, v18.4s
umin v11.4s, v11.4s, v18.4s
umin v13.4s, v13.4s, v18.4s
fmul v27.2d, v4.2d, v14.d[1]
umin v7.4s, v7.4s, v2.4s
fmul v16.2d, v1.2d, v14.d[0]
stp q10, q11, [x21]
sub w16, w16, #0x11
stp q13, q4, [x21, #32]
tst x18, #0x7fffffffffffffff
and w20, w20, w17
sub w5, w5, #0x11
stp q22, q27, [x21, #64]
sub x16, x16, #0x30
str q28, [x21, #96]
sub x5, x5, #0x30
ccmp x19, #0x0, #0x4, ne
and x5, x5, x16
and w20, w20, w3
lsr x5, x5, #63
and w20, w20, w5
csel w20, w20, wzr, ne
