fmul v18.2d, v18.2d, v2.d[0]
ext v1.16b, v21.16b, v23.16b, #8
fmul v22.2d, v22.2d, v21.d[0]
fmul v29.2d, v29.2d, v23.d[0]
fmul v20.2d, v20.2d, v2.d[1]
fmul v24.2d, v24.2d, v21.d[1]
fcvtzu v18.2d, v18.2d, #16
ext v0.16b, v2.16b, v21.16b, #8
fcvtzu v22.2d, v22.2d, #16
fcvtzu v29.2d, v29.2d, #16
fcvtzu v20.2d, v20.2d, #16
fcvtzu v24.2d, v24.2d, #16
uqxtn v5.2s, v18.2d
uqxtn v19.2s, v22.2d
uqxtn v7.2s, v29.2d
fadd v0.2d, v2.2d, v0.2d
uqxtn2 v5.4s, v20.2d
fadd v1.2d, v21.2d, v1.2d
uqxtn2 v19.4s, v24.2d
fmul v3.2d, v0.2d, v6.d[0]
umin v5.4s, v5.4s, v9.4s
fmul v16.2d, v1.2d, v6.d[0]
umin v19.4s, v19.4s, v9.4s
umin v7.2s, v7.2s, v9.2s
cmp w28, #0x4
sub w1, w0, #0x1
b.ne .Ltgt
