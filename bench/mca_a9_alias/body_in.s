vadd.i32 q0, q8, q12
vadd.i32 q1, q9, q13
vadd.i32 q2, q11, q15
vld1.16 {d10-d11}, [r1] @m=z
vshrn.i32 d8, q11, #16
vshrn.i32 d9, q2, #16
vcge.u16 q6, q4, q5
vbit q5, q4, q6
vst1.16 {d10-d11}, [r1]! @m=z
vmovn.i16 d12, q6
vmov r8, r9, d12
vshrn.i32 d4, q9, #16
vshrn.i32 d5, q1, #16
vshr.u32 q4, q8, #16
vshr.u32 q7, q0, #16
vmlal.u16 q4, d4, d7[0]
vmlal.u16 q7, d5, d7[0]
vadd.i32 q0, q10, q14
vshr.u32 q5, q10, #16
vshr.u32 q1, q0, #16
vshl.i32 q5, q5, #8
vshl.i32 q1, q1, #8
vmov q0, q7
vst2.32 {d8-d11}, [r2:128]! @m=buf
vst2.32 {d0-d3}, [r2:128] @m=buf
vadd.i32 q8, q8, q12
vadd.i32 q9, q9, q13
vadd.i32 q10, q10, q14
vadd.i32 q11, q11, q15
vadd.i32 q8, q8, q12
vadd.i32 q9, q9, q13
vadd.i32 q10, q10, q14
vadd.i32 q11, q11, q15
ldrd r4, r5, [r2, #-32] @m=buf
ldrb r4, [r10, r4]
add r5, r5, r4
ldrb r6, [r11, r5]
ldrd r4, r5, [r2, #-24] @m=buf
ldrb r4, [r10, r4]
add r5, r5, r4
ldrb r5, [r11, r5]
orr r6, r6, r5, lsl #8
ldrd r4, r5, [r2, #-16] @m=buf
ldrb r4, [r10, r4]
add r5, r5, r4
ldrb r5, [r11, r5]
orr r6, r6, r5, lsl #16
ldrd r4, r5, [r2, #-8] @m=buf
ldrb r4, [r10, r4]
add r5, r5, r4
ldrb r5, [r11, r5]
orr r6, r6, r5, lsl #24
ldrd r4, r5, [r2, #0] @m=buf
ldrb r4, [r10, r4]
add r5, r5, r4
ldrb r7, [r11, r5]
ldrd r4, r5, [r2, #8] @m=buf
ldrb r4, [r10, r4]
add r5, r5, r4
ldrb r5, [r11, r5]
orr r7, r7, r5, lsl #8
ldrd r4, r5, [r2, #16] @m=buf
ldrb r4, [r10, r4]
add r5, r5, r4
ldrb r5, [r11, r5]
orr r7, r7, r5, lsl #16
ldrd r4, r5, [r2, #24] @m=buf
ldrb r4, [r10, r4]
add r5, r5, r4
ldrb r5, [r11, r5]
orr r7, r7, r5, lsl #24
ldr r4, [r0] @m=dst
ldr r5, [r0, #4] @m=dst
eor r6, r6, r4
eor r7, r7, r5
and r6, r6, r8
and r7, r7, r9
eor r6, r6, r4
eor r7, r7, r5
str r7, [r0, #4] @m=dst
str r6, [r0], #8 @m=dst
sub r2, r2, #32
subs r3, r3, #1
bne 1b
