// Split design, phase A (NEON only): two rows' 16-bit indices stored to a buffer (stp q)
// instead of moved to core registers; see README.
ldr q21, [x8, x12]
ldr q26, [x10, x12]
ldp x8, x10, [x11], #16
stp q0, q1, [x9]
stp q2, q3, [x9, #32]
add x9, x9, #64
subs x13, x13, #1
add v28.4s, v23.4s, v17.4s
add v27.4s, v22.4s, v16.4s
add v25.4s, v20.4s, v29.4s
add v24.4s, v19.4s, v18.4s
tbl v0.16b, {v21.16b, v22.16b, v23.16b}, v30.16b
tbl v1.16b, {v19.16b, v20.16b, v21.16b}, v31.16b
tbl v2.16b, {v26.16b, v27.16b, v28.16b}, v30.16b
tbl v3.16b, {v24.16b, v25.16b, v26.16b}, v31.16b
add v23.4s, v28.4s, v17.4s
add v20.4s, v25.4s, v29.4s
add v19.4s, v24.4s, v18.4s
add v22.4s, v27.4s, v16.4s
b.ne 0
