// The aarch64 linear long head (persp_fast_inl<false>, kPre: asm/span_persp_fast.cpp) as
// searched by bench/order_search.py; registers: v0 P, v1 zrow, v2 zix, v3 urow, v4 vrow, v5 ux,
// v6 vx, v7 kMin, v8 k16, v9 k32, v10 kOne, v11 kZrow, v12 kZix, v13 kUVrow, v14 kUVx, v15
// pos01 then pp, v16 P + 16, v17 pos23, v18 z01, v19 z23, v20 .. v23 ts0 .. ts3 then samples
// 0 .. 3, v24 kMaxU.
fmov v8.2d, #16.0
dup v19.2d, v1.d[0]
dup v18.2d, v1.d[0]
fmov v10.2d, #1.0
fadd d16, d0, d8
fadd v9.2d, v8.2d, v8.2d
dup v12.2d, v2.d[0]
zip1 v20.2d, v3.2d, v4.2d
zip1 v15.2d, v0.2d, v16.2d
zip1 v14.2d, v5.2d, v6.2d
zip1 v23.2d, v3.2d, v4.2d
dup v11.2d, v1.d[0]
zip1 v21.2d, v3.2d, v4.2d
fadd v17.2d, v15.2d, v9.2d
fmla v18.2d, v15.2d, v2.d[0]
zip1 v22.2d, v3.2d, v4.2d
fmla v21.2d, v14.2d, v16.d[0]
fmla v20.2d, v14.2d, v0.d[0]
fmla v19.2d, v17.2d, v2.d[0]
fmaxnm v18.2d, v18.2d, v7.2d
zip1 v13.2d, v3.2d, v4.2d
fmla v23.2d, v14.2d, v17.d[1]
fmla v22.2d, v14.2d, v17.d[0]
fmaxnm v19.2d, v19.2d, v7.2d
fdiv v18.2d, v10.2d, v18.2d
fdiv v19.2d, v10.2d, v19.2d
fmul v20.2d, v20.2d, v18.d[0]
fmul v21.2d, v21.2d, v18.d[1]
fcvtzu v20.2d, v20.2d, #16
fmul v22.2d, v22.2d, v19.d[0]
fcvtzu v21.2d, v21.2d, #16
fmul v23.2d, v23.2d, v19.d[1]
uqxtn v20.2s, v20.2d
fadd d15, d16, d8
uqxtn v21.2s, v21.2d
fcvtzu v22.2d, v22.2d, #16
fcvtzu v23.2d, v23.2d, #16
umin v20.2s, v20.2s, v24.2s
fadd d16, d15, d8
umin v21.2s, v21.2s, v24.2s
uqxtn v22.2s, v22.2d
uqxtn v23.2s, v23.2d
zip1 v15.2d, v15.2d, v16.2d
