fmul v1.2d, v1.2d, v27.d[0]
fmul v22.2d, v22.2d, v29.d[0]
fmul v21.2d, v21.2d, v31.d[0]
fmul v2.2d, v2.2d, v28.d[0]
fmul v18.2d, v18.2d, v30.d[0]
fmul v26.2d, v26.2d, v27.d[1]
fcvtzu v1.2d, v1.2d, #16
fcvtzu v22.2d, v22.2d, #16
fcvtzu v21.2d, v21.2d, #16
fcvtzu v2.2d, v2.2d, #16
fcvtzu v18.2d, v18.2d, #16
fmul v24.2d, v24.2d, v29.d[1]
uqxtn v3.2s, v1.2d
uqxtn v19.2s, v22.2d
uqxtn v4.2s, v21.2d
fmul v7.2d, v7.2d, v31.d[1]
fadd v0.2d, v27.2d, v28.2d
fadd v6.2d, v28.2d, v29.2d
uqxtn2 v3.4s, v2.2d
uqxtn2 v19.4s, v18.2d
fmul v23.2d, v23.2d, v28.d[1]
fmul v25.2d, v25.2d, v30.d[1]
fcvtzu v26.2d, v26.2d, #16
fcvtzu v24.2d, v24.2d, #16
uqxtn2 v4.4s, v21.2d
fadd v8.2d, v29.2d, v30.2d
fadd v9.2d, v30.2d, v31.2d
fmul v14.2d, v15.2d, v16.2d
fcvtzu v7.2d, v7.2d, #16
trn1 v17.2d, v0.2d, v6.2d
fcvtzu v23.2d, v23.2d, #16
fcvtzu v25.2d, v25.2d, #16
uqxtn v10.2s, v26.2d
uqxtn v11.2s, v24.2d
trn1 v12.2d, v8.2d, v9.2d
uqxtn v13.2s, v7.2d
fmul v20.2d, v17.2d, v14.d[0]
trn2 v5.2d, v0.2d, v6.2d
uqxtn2 v10.4s, v23.2d
uqxtn2 v11.4s, v25.2d
fmul v1.2d, v12.2d, v14.d[0]
uqxtn2 v13.4s, v7.2d
trn2 v22.2d, v8.2d, v9.2d
fmul v27.2d, v5.2d, v14.d[1]
ld1r {v2.2d}, [x8]
ld1r {v18.2d}, [x13]
fmul v28.2d, v22.2d, v14.d[1]
umin v3.4s, v3.4s, v2.4s
umin v19.4s, v19.4s, v2.4s
umin v4.4s, v4.4s, v2.4s
umin v10.4s, v10.4s, v18.4s
umin v11.4s, v11.4s, v18.4s
umin v13.4s, v13.4s, v18.4s
stp q3, q19, [x2, #0]
stp q4, q17, [x2, #32]
stp q12, q20, [x2, #64]
str q1, [x2, #96]
stp q10, q11, [x2, #112]
stp q13, q5, [x2, #144]
stp q22, q27, [x2, #176]
str q28, [x2, #208]
