ldp x0, x1, [x22]
ldp x2, x3, [x22, #16]
ldp x4, x5, [x22, #32]
add x17, x20, x19, lsr #1
ldrb w9, [x23, w1, uxtw]
ushr v21.4s, v4.4s, #16
ldrb w10, [x23, w2, uxtw]
ldrb w8, [x23, w0, uxtw]
ldp x6, x7, [x22, #48]
ldrb w12, [x23, w4, uxtw]
add x10, x10, x2, lsr #32
ldrb w11, [x23, w3, uxtw]
subs x25, x25, #1
ldrb w15, [x23, w7, uxtw]
add x8, x8, x0, lsr #32
ldrb w13, [x23, w5, uxtw]
add x12, x12, x4, lsr #32
add x11, x11, x3, lsr #32
ldrb w14, [x23, w6, uxtw]
add x9, x9, x1, lsr #32
ldrb w10, [x24, x10]
add x13, x13, x5, lsr #32
ldrb w12, [x24, x12]
add x15, x15, x7, lsr #32
ldrb w8, [x24, x8]
ldrb w11, [x24, x11]
add x14, x14, x6, lsr #32
ldrb w13, [x24, x13]
ldrb w15, [x24, x15]
shrn v16.4h, v6.4s, #16
ldrb w9, [x24, x9]
orr x12, x12, x13, lsl #8
ldrb w14, [x24, x14]
ldr q17, [x21]
orr x8, x8, x9, lsl #8
orr x10, x10, x11, lsl #8
orr x14, x14, x15, lsl #8
ldr x16, [x17]
orr x8, x8, x10, lsl #16
orr x12, x12, x14, lsl #16
mov x19, x21
orr x8, x8, x12, lsl #32
eor x8, x8, x16
and x8, x8, x26
eor x22, x22, #0x40
eor x8, x8, x16
shrn2 v16.8h, v7.4s, #16
shrn v19.4h, v2.4s, #16
ushr v22.4s, v1.4s, #16
shl v21.4s, v21.4s, #8
add v2.4s, v2.4s, v25.4s
ushr v20.4s, v0.4s, #16
cmhs v18.8h, v16.8h, v17.8h
str x8, [x17]
ushr v23.4s, v5.4s, #16
add v7.4s, v7.4s, v27.4s
add v6.4s, v6.4s, v27.4s
umlal v20.4s, v19.4h, v28.4h
bif v16.16b, v17.16b, v18.16b
shrn v17.4h, v3.4s, #16
add v3.4s, v3.4s, v25.4s
shl v23.4s, v23.4s, #8
add v4.4s, v4.4s, v26.4s
xtn v18.8b, v18.8h
add v1.4s, v1.4s, v24.4s
umlal v22.4s, v17.4h, v28.4h
st2 {v20.4s, v21.4s}, [x27], #32
str q16, [x21], #16
add v0.4s, v0.4s, v24.4s
st2 {v22.4s, v23.4s}, [x27], #32
fmov x26, d18
add v5.4s, v5.4s, v26.4s
and x27, x27, #0xffffffffffffff7f
b.ne .+4
