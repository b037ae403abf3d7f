ldr x17, [x9], #8
ubfx x2, x17, #8, #8
and x1, x17, #0xff
ubfx x6, x17, #40, #8
ubfx x4, x17, #24, #8
ubfx x3, x17, #16, #8
ubfx x7, x17, #48, #8
ubfx x5, x17, #32, #8
ldr w1, [x27, x1, lsl #2]
lsr x17, x17, #56
ldr w2, [x27, x2, lsl #2]
ldr w4, [x27, x4, lsl #2]
ldr w5, [x27, x5, lsl #2]
ldr w17, [x27, x17, lsl #2]
ldr w3, [x27, x3, lsl #2]
dup v0.4s, w1
dup v1.4s, w2
dup v3.4s, w4
ldr w6, [x27, x6, lsl #2]
ldr w7, [x27, x7, lsl #2]
dup v2.4s, w3
dup v7.4s, w17
dup v4.4s, w5
dup v5.4s, w6
dup v6.4s, w7
stp q0, q1, [x0, #0]
stp q2, q3, [x0, #32]
stp q4, q5, [x0, #64]
stp q6, q7, [x0, #96]
stp q0, q1, [x20, #0]
stp q2, q3, [x20, #32]
stp q4, q5, [x20, #64]
add x0, x0, #128
stp q6, q7, [x20, #96]
stp q0, q1, [x21, #0]
cmp x18, x0
stp q2, q3, [x21, #32]
stp q4, q5, [x21, #64]
stp q6, q7, [x21, #96]
add x21, x21, #128
stp q0, q1, [x22, #0]
stp q2, q3, [x22, #32]
add x20, x20, #128
stp q4, q5, [x22, #64]
stp q6, q7, [x22, #96]
add x22, x22, #128
b.ne 1b
