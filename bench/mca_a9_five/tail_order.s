vmul.f64 d14, d14, d10
vmul.f64 d8, d8, d10
vadd.f64 d12, d12, d10
vcvt.u32.f64 d14, d14, #16
vld1.64 {d0, d1, d2, d3}, [r5]!
smulbt r4, r8, r1
uxtah r4, r4, r0, ror #16
add r1, r1, r3
vld1.64 {d16}, [r5]
vcvt.u32.f64 d8, d8, #16
smulbt r5, r8, r1
add r0, r0, r2
vmul.f64 d13, d13, d12
uxtah r5, r5, r0, ror #16
vsli.64 d14, d8, #32
add r3, r3, r7
add r1, r1, r3
ldrb r4, [r9, r4]
add r3, r3, r7
add r2, r2, r6
ldrb r5, [r9, r5]
vmin.u32 d14, d14, d11
add r0, r0, r2
orr r4, r4, r5, lsl #8
smulbt r5, r8, r1
vmul.f64 d13, d13, d3
vsub.i32 d3, d14, d4
uxtah r5, r5, r0, ror #16
ldrb r5, [r9, r5]
add r1, r1, r3
vcvt.f64.s32 d17, s6
add r2, r2, r6
add r0, r0, r2
orr r4, r4, r5, lsl #16
vcvt.f64.s32 d18, s7
smulbt r5, r8, r1
uxtah r5, r5, r0, ror #16
ldrb r5, [r9, r5]
add r3, r3, r7
vdiv.f64 d17, d17, d0
add r2, r2, r6
orr r4, r4, r5, lsl #24
add r0, r0, r2
add r1, r1, r3
add r2, r2, r6
str r4, [r10, #0]
smulbt r4, r8, r1
vabs.s32 d19, d3
add r3, r3, r7
vdiv.f64 d18, d18, d0
uxtah r4, r4, r0, ror #16
add r0, r0, r2
add r1, r1, r3
ldrb r4, [r9, r4]
smulbt r5, r8, r1
add r3, r3, r7
uxtah r5, r5, r0, ror #16
add r1, r1, r3
add r2, r2, r6
ldrb r5, [r9, r5]
add r0, r0, r2
add r3, r3, r7
add r2, r2, r6
orr r4, r4, r5, lsl #8
smulbt r5, r8, r1
uxtah r5, r5, r0, ror #16
ldrb r5, [r9, r5]
add r0, r0, r2
orr r4, r4, r5, lsl #16
add r2, r2, r6
add r1, r1, r3
add r3, r3, r7
smulbt r5, r8, r1
uxtah r5, r5, r0, ror #16
add r0, r0, r2
add r1, r1, r3
add r2, r2, r6
add r3, r3, r7
ldrb r5, [r9, r5]
orr r4, r4, r5, lsl #24
str r4, [r10, #4]
smulbt r4, r8, r1
add r1, r1, r3
uxtah r4, r4, r0, ror #16
add r3, r3, r7
smulbt r5, r8, r1
ldrb r4, [r9, r4]
add r0, r0, r2
vcvt.s32.f64 s0, d17
uxtah r5, r5, r0, ror #16
ldrb r5, [r9, r5]
vmovl.u32 q10, d19
add r2, r2, r6
add r0, r0, r2
add r1, r1, r3
add r2, r2, r6
add r3, r3, r7
vmul.f64 d22, d18, d13
orr r4, r4, r5, lsl #8
smulbt r5, r8, r1
vmul.f64 d19, d17, d13
uxtah r5, r5, r0, ror #16
ldrb r5, [r9, r5]
add r1, r1, r3
vcvt.s32.f64 s6, d19
add r0, r0, r2
add r3, r3, r7
orr r4, r4, r5, lsl #16
add r2, r2, r6
smulbt r5, r8, r1
uxtah r5, r5, r0, ror #16
add r1, r1, r3
ldrb r5, [r9, r5]
orr r4, r4, r5, lsl #24
vcvt.s32.f64 s7, d22
str r4, [r10, #8]
smulbt r4, r8, r1
add r0, r0, r2
add r3, r3, r7
add r1, r1, r3
vcvt.s32.f64 s1, d18
uxtah r4, r4, r0, ror #16
add r3, r3, r7
vabs.s32 d19, d3
vcvt.f64.s32 d22, s6
smulbt r5, r8, r1
add r1, r1, r3
vcvt.f64.s32 d23, s7
add r3, r3, r7
vmull.u32 q12, d19, d2
add r2, r2, r6
ldrb r4, [r9, r4]
add r0, r0, r2
vfms.f64 d18, d23, d1
uxtah r5, r5, r0, ror #16
add r2, r2, r6
vfms.f64 d17, d22, d1
add r0, r0, r2
add r2, r2, r6
vqsub.u64 q12, q12, q10
ldrb r5, [r9, r5]
orr r4, r4, r5, lsl #8
smulbt r5, r8, r1
uxtah r5, r5, r0, ror #16
ldrb r5, [r9, r5]
orr r4, r4, r5, lsl #16
vcgt.u32 d22, d16, d19
add r0, r0, r2
add r1, r1, r3
vqmovn.u64 d16, q12
smulbt r5, r8, r1
vtst.32 d16, d16, d16
uxtah r5, r5, r0, ror #16
ldrb r5, [r9, r5]
orr r4, r4, r5, lsl #24
vmov r0, r1, d4
vcvt.s32.f64 s2, d17
vbic d22, d22, d16
str r4, [r10, #12]
vcvt.s32.f64 s3, d18
vand d3, d3, d22
vbsl d22, d1, d0
vmov r4, r5, d3
vmov r2, r3, d22
