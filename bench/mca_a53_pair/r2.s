2:
ld1r {v0.2d}, [x8]
ld1r {v4.2d}, [x13]
fmul v3.2d, v3.2d, v18.d[0]
fmul v25.2d, v25.2d, v18.d[1]
fmul v27.2d, v27.2d, v19.d[0]
fmul v26.2d, v26.2d, v19.d[1]
fmul v28.2d, v28.2d, v20.d[0]
fmul v29.2d, v29.2d, v20.d[1]
fmul v23.2d, v23.2d, v21.d[0]
fmul v30.2d, v30.2d, v21.d[1]
fmul v15.2d, v15.2d, v22.d[0]
fmul v31.2d, v31.2d, v22.d[1]
fadd v1.2d, v18.2d, v19.2d
fadd v13.2d, v19.2d, v20.2d
fadd v14.2d, v20.2d, v21.2d
fadd v16.2d, v21.2d, v22.2d
fmul v24.2d, v5.2d, v11.2d
fcvtzu v3.2d, v3.2d, #16
fcvtzu v25.2d, v25.2d, #16
fcvtzu v27.2d, v27.2d, #16
fcvtzu v26.2d, v26.2d, #16
fcvtzu v28.2d, v28.2d, #16
fcvtzu v29.2d, v29.2d, #16
fcvtzu v23.2d, v23.2d, #16
fcvtzu v30.2d, v30.2d, #16
fcvtzu v15.2d, v15.2d, #16
fcvtzu v31.2d, v31.2d, #16
trn1 v17.2d, v1.2d, v13.2d
trn2 v12.2d, v1.2d, v13.2d
trn1 v6.2d, v14.2d, v16.2d
trn2 v7.2d, v14.2d, v16.2d
uqxtn v8.2s, v3.2d
uqxtn v9.2s, v28.2d
uqxtn v10.2s, v15.2d
uqxtn v2.2s, v25.2d
uqxtn v18.2s, v29.2d
uqxtn v19.2s, v31.2d
fmul v20.2d, v17.2d, v24.d[0]
fmul v21.2d, v12.2d, v24.d[1]
fmul v22.2d, v6.2d, v24.d[0]
fmul v11.2d, v7.2d, v24.d[1]
uqxtn2 v8.4s, v27.2d
uqxtn2 v9.4s, v23.2d
uqxtn2 v10.4s, v15.2d
uqxtn2 v2.4s, v26.2d
uqxtn2 v18.4s, v30.2d
uqxtn2 v19.4s, v31.2d
umin v8.4s, v8.4s, v0.4s
umin v9.4s, v9.4s, v0.4s
umin v10.4s, v10.4s, v0.4s
umin v2.4s, v2.4s, v4.4s
umin v18.4s, v18.4s, v4.4s
umin v19.4s, v19.4s, v4.4s
stp q8, q9, [x2, #0]
stp q10, q17, [x2, #32]
stp q6, q20, [x2, #64]
str q22, [x2, #96]
stp q2, q18, [x2, #112]
stp q19, q12, [x2, #144]
stp q7, q21, [x2, #176]
str q11, [x2, #208]
