ldp w0, w1, [x28]
ldp w4, w5, [x28, #16]
ldp w2, w3, [x28, #8]
ldp w6, w7, [x28, #24]
dup v0.4s, w0
dup v24.4s, w4
dup v2.4s, w1
dup v25.4s, w5
dup v4.4s, w2
dup v26.4s, w6
dup v6.4s, w3
dup v27.4s, w7
mla v0.4s, v24.4s, v29.4s
mla v2.4s, v25.4s, v29.4s
mla v4.4s, v26.4s, v29.4s
mla v6.4s, v27.4s, v29.4s
shl v16.4s, v24.4s, #2
shl v17.4s, v25.4s, #2
shl v18.4s, v26.4s, #2
shl v19.4s, v27.4s, #2
add v1.4s, v0.4s, v16.4s
add v3.4s, v2.4s, v17.4s
add v5.4s, v4.4s, v18.4s
add v7.4s, v6.4s, v19.4s
dup v28.4h, w30
dup v30.4s, w18
ushr v21.4s, v4.4s, #16
shrn v16.4h, v6.4s, #16
ldr q17, [x21]
mov x19, x21
shrn2 v16.8h, v7.4s, #16
shrn v19.4h, v2.4s, #16
ushr v22.4s, v1.4s, #16
shl v21.4s, v21.4s, #8
mla v2.4s, v25.4s, v30.4s
ushr v20.4s, v0.4s, #16
cmhs v18.8h, v16.8h, v17.8h
ushr v23.4s, v5.4s, #16
mla v7.4s, v27.4s, v30.4s
mla v6.4s, v27.4s, v30.4s
umlal v20.4s, v19.4h, v28.4h
bif v16.16b, v17.16b, v18.16b
shrn v17.4h, v3.4s, #16
mla v3.4s, v25.4s, v30.4s
shl v23.4s, v23.4s, #8
mla v4.4s, v26.4s, v30.4s
xtn v18.8b, v18.8h
mla v1.4s, v24.4s, v30.4s
umlal v22.4s, v17.4h, v28.4h
st2 {v20.4s, v21.4s}, [x27], #32
str q16, [x21]
add x21, x21, x18, lsl #1
mla v0.4s, v24.4s, v30.4s
st2 {v22.4s, v23.4s}, [x27], #32
fmov x26, d18
mla v5.4s, v26.4s, v30.4s
and x27, x27, #0xffffffffffffff7f
shl v24.4s, v24.4s, #3
shl v25.4s, v25.4s, #3
shl v26.4s, v26.4s, #3
shl v27.4s, v27.4s, #3
