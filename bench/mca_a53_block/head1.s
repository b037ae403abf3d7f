// SB_A53_HEAD1 (asm/neon_block_a53m1.h), registers as in band16w1.s: searched 59 -> 50 (A53).
ldr q0, [x11]
add x10, x11, x13
ldr x8, [x28]
add x9, x10, x13
ldr x14, [x28, #8]
ldr q8, [x10]
smull2 v23.4s, v31.8h, v0.h[0]
smull v22.4s, v31.4h, v0.h[0]
smull2 v20.4s, v12.8h, v0.h[1]
ldr q21, [x8, x15]
smull v19.4s, v12.4h, v0.h[1]
smull v16.4s, v31.4h, v8.h[0]
smull2 v17.4s, v31.8h, v8.h[0]
smlal v22.4s, v30.4h, v0.h[1]
smlal2 v23.4s, v30.8h, v0.h[1]
smull v18.4s, v12.4h, v8.h[1]
smlal2 v20.4s, v13.8h, v0.h[2]
smlal v19.4s, v13.4h, v0.h[2]
smull2 v29.4s, v12.8h, v8.h[1]
smlal v16.4s, v30.4h, v8.h[1]
shl v23.4s, v23.4s, #3
shl v22.4s, v22.4s, #3
shl v20.4s, v20.4s, #3
smlal2 v17.4s, v30.8h, v8.h[1]
smlal2 v29.4s, v13.8h, v8.h[2]
shl v19.4s, v19.4s, #3
smlal v18.4s, v13.4h, v8.h[2]
add v27.4s, v22.4s, v16.4s
tbl v0.16b, {v21.16b, v22.16b, v23.16b}, v9.16b
ldr q26, [x14, x15]
add v28.4s, v23.4s, v17.4s
add v25.4s, v20.4s, v29.4s
add v24.4s, v19.4s, v18.4s
tbl v1.16b, {v19.16b, v20.16b, v21.16b}, v10.16b
fmov x0, d0
add v22.4s, v27.4s, v16.4s
tbl v2.16b, {v26.16b, v27.16b, v28.16b}, v9.16b
add v20.4s, v25.4s, v29.4s
add v19.4s, v24.4s, v18.4s
tbl v3.16b, {v24.16b, v25.16b, v26.16b}, v10.16b
fmov x2, d1
add v23.4s, v28.4s, v17.4s
fmov x5, v2.d[1]
fmov x3, v1.d[1]
fmov x1, v0.d[1]
fmov x7, v3.d[1]
fmov x6, d3
fmov x4, d2
ldr q8, [x9]
add x28, x28, #16
sub x17, x17, x13, lsl #1
b 2f
