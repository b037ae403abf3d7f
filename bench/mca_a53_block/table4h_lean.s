// m2l_cols2<true>'s 4-row step (asm/neon_block_mip2l.h SB_M2L_STEP4_H; registers as GCC gave them:
// s0 x21, s1 x7, s2 x27, g1..g4 x30 x19 x1 x18, o0 x22, o1 x5, o2 x4, e1..e4 x15 x3 x6 x20) as
// searched by bench/order_search.py --kick=2: Cortex-A53 model 43 -> 38 cycles.
ldr q2, [x21, x19]
ldr q4, [x21, x18]
ldr q3, [x21, x1]
ldr q1, [x21, x30]
ldr q19, [x7, x1]
add x21, x21, x18
ldrh w12, [x27, x1]
subs x0, x0, #0x1
ldrh w13, [x27, x18]
ldr q17, [x7, x30]
ldrh w11, [x27, x19]
ldr q20, [x7, x18]
ldrh w10, [x27, x30]
sub v25.8h, v4.8h, v3.8h
ldr q18, [x7, x19]
sub w14, w13, w12
sub w12, w12, w11
sub w11, w11, w10
sub v5.8h, v1.8h, v0.8h
sub v6.8h, v2.8h, v1.8h
sub v21.8h, v17.8h, v16.8h
sub v22.8h, v18.8h, v17.8h
sub v24.8h, v20.8h, v19.8h
sub v7.8h, v3.8h, v2.8h
str q5, [x22, x15]
str q21, [x5, x15]
sub v23.8h, v19.8h, v18.8h
mov v0.16b, v4.16b
mov v16.16b, v20.16b
str q6, [x22, x3]
str q22, [x5, x3]
str q7, [x22, x6]
sub w10, w10, w9
str q23, [x5, x6]
str q25, [x22, x20]
str q24, [x5, x20]
mov w9, w13
strh w10, [x4, x15]
add x22, x22, x20
strh w11, [x4, x3]
add x7, x7, x18
strh w12, [x4, x6]
add x27, x27, x18
strh w14, [x4, x20]
add x5, x5, x20
add x4, x4, x20
b.ne .+4
