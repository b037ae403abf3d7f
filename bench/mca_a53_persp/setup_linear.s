// persp_short_inl's linear sample block (asm/span_persp_a64short.h), operands as compiled: x4 = p,
// w7 = n, x2 = &kMinZi, x8 t0, x3 t5, x5 t6, x6 t7; the order from order_search.py (A53 172 -> 160
// cycles as a loop: independent work placed where it completes after a divide).
fmov d1, #16.0
ldr d0, [x4, #48]
sub w3, w7, #1
sub w5, w7, #17
cmp w3, #32
ld2r {v16.2d, v17.2d}, [x4]
mov w6, #32
csel w3, w3, w6, lt
cmp w5, #32
fadd d2, d0, d1
ld1r {v26.2d}, [x4]
add x8, x4, #16
csel w5, w5, w6, lt
ld1r {v27.2d}, [x4]
sub w6, w7, #33
scvtf d4, w3
scvtf d5, w5
fadd d3, d2, d1
trn1 v0.2d, v0.2d, v2.2d
scvtf d6, w6
ld2 {v20.2d, v21.2d}, [x8]
trn1 v4.2d, v4.2d, v5.2d
ld2 {v18.2d, v19.2d}, [x8]
fadd d3, d3, d6
ld1r {v31.2d}, [x2]
fadd v7.2d, v0.2d, v4.2d
fmla v26.2d, v17.2d, v0.2d
ld2 {v22.2d, v23.2d}, [x8]
fmov v1.2d, #1.0
fmadd d28, d17, d3, d16
fmla v27.2d, v17.2d, v7.2d
ld2 {v29.2d, v30.2d}, [x8]
fmaxnm v26.2d, v26.2d, v31.2d
fmla v20.2d, v21.2d, v0.d[1]
fmla v22.2d, v23.2d, v7.d[0]
fmla v18.2d, v19.2d, v0.d[0]
ld2 {v24.2d, v25.2d}, [x8]
fmaxnm v27.2d, v27.2d, v31.2d
fdiv v26.2d, v1.2d, v26.2d
fmaxnm d28, d28, d31
fmla v29.2d, v30.2d, v3.d[0]
fdiv v27.2d, v1.2d, v27.2d
fmul v18.2d, v18.2d, v26.d[0]
fmla v24.2d, v25.2d, v7.d[1]
fdiv d28, d1, d28
fmul v24.2d, v24.2d, v27.d[1]
fmul v22.2d, v22.2d, v27.d[0]
fmul v20.2d, v20.2d, v26.d[1]
add x8, x4, #56
fmul v29.2d, v29.2d, v28.d[0]
fcvtzu v18.2d, v18.2d, #16
fcvtzu v22.2d, v22.2d, #16
fcvtzu v29.2d, v29.2d, #16
uqxtn v5.2s, v18.2d
uqxtn v6.2s, v22.2d
fcvtzu v24.2d, v24.2d, #16
fcvtzu v20.2d, v20.2d, #16
uqxtn v7.2s, v29.2d
ld1r {v31.2d}, [x8]
uqxtn2 v5.4s, v20.2d
uqxtn2 v6.4s, v24.2d
uqxtn2 v7.4s, v29.2d
umin v5.4s, v5.4s, v31.4s
umin v6.4s, v6.4s, v31.4s
umin v7.4s, v7.4s, v31.4s
