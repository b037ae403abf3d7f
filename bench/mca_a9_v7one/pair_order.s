ldr r2, [r0, #4]
ldr r3, [r1, #4]
add r0, r0, #8
add r1, r1, #8
vld1.64 {d18}, [r1]
add r2, r7, r2, lsl #5
vld1.64 {d16}, [r0]
vld1.64 {d19, d20, d21, d22}, [r1]!
vld1.64 {d5, d6, d7, d8}, [r0]!
vld1.64 {d9, d10, d11, d12}, [r0]
vld1.64 {d13, d14}, [r2]!
add r3, r7, r3, lsl #5
vfma.f64 d5, d6, d11
vadd.f64 d17, d11, d13
vld1.64 {d25, d26, d27, d28}, [r1]
vfma.f64 d7, d8, d11
vld1.64 {d23, d24}, [r3]!
vld1.64 {d0, d1, d2, d3}, [r6]!
vadd.f64 d29, d27, d23
vfma.f64 d16, d6, d17
vfma.f64 d19, d20, d27
vld1.64 {d23}, [r0]
vfma.f64 d25, d26, d27
vfma.f64 d21, d22, d27
vfma.f64 d18, d20, d29
vld1.64 {d27}, [r1]
vld1.64 {d4}, [r6]
vcmpe.f64 d5, d0
vmrs APSR_nzcv, fpscr
vmov.f64 d5, d0 @flags
sub r1, r1, #16
vdiv.f64 d5, d1, d5
vcmpe.f64 d16, d0
vmrs APSR_nzcv, fpscr
sub r0, r0, #16
vcmpe.f64 d19, d0
vmov.f64 d16, d0 @flags
vdiv.f64 d16, d1, d16
vmrs APSR_nzcv, fpscr
vmov.f64 d19, d0 @flags
vcmpe.f64 d18, d0
vdiv.f64 d19, d1, d19
vmrs APSR_nzcv, fpscr
vld1.64 {d30}, [r0]
vmov.f64 d18, d0 @flags
vdiv.f64 d18, d1, d18
vfma.f64 d9, d10, d11
vmul.f64 d6, d6, d2
vfma.f64 d27, d26, d29
vld1.64 {d31}, [r1]
vfma.f64 d23, d10, d17
vmul.f64 d20, d20, d2
vfma.f64 d30, d8, d17
vmul.f64 d9, d9, d5
vfma.f64 d31, d22, d29
vmul.f64 d7, d7, d5
vadd.f64 d5, d5, d16
vcvt.u32.f64 d9, d9, #16
vmul.f64 d23, d23, d16
vmul.f64 d30, d30, d16
vmul.f64 d25, d25, d19
vmul.f64 d21, d21, d19
vcvt.u32.f64 d7, d7, #16
vmul.f64 d31, d31, d18
vcvt.u32.f64 d23, d23, #16
vmul.f64 d27, d27, d18
vsli.64 d7, d9, #32
vcvt.u32.f64 d30, d30, #16
vcvt.u32.f64 d21, d21, #16
vcvt.u32.f64 d31, d31, #16
vcvt.u32.f64 d25, d25, #16
vsli.64 d30, d23, #32
vcvt.u32.f64 d27, d27, #16
vmin.u32 d7, d7, d12
vst1.32 {d7}, [r4]!
vmin.u32 d30, d30, d12
vsli.64 d21, d25, #32
vsli.64 d31, d27, #32
vmin.u32 d21, d21, d28
vmin.u32 d31, d31, d28
vsub.i32 d15, d30, d7
vadd.f64 d19, d19, d18
vsub.i32 d7, d31, d21
vcvt.f64.s32 d18, s30
vst1.32 {d21}, [r5]!
vcvt.f64.s32 d21, s31
vcvt.f64.s32 d25, s14
vcvt.f64.s32 d16, s15
vdiv.f64 d18, d18, d14
vdiv.f64 d21, d21, d14
vdiv.f64 d25, d25, d24
vdiv.f64 d16, d16, d24
vmul.f64 d6, d6, d5
vmul.f64 d20, d20, d19
vabs.s32 d17, d15
vabs.s32 d19, d7
vmovl.u32 q11, d17
vmovl.u32 q13, d19
vmul.f64 d6, d6, d3
vmul.f64 d20, d20, d3
vmul.f64 d17, d18, d6
vmul.f64 d19, d21, d6
vld1.64 {d7, d8}, [r2]
vmul.f64 d24, d25, d20
vcvt.s32.f64 s10, d18
vmul.f64 d28, d16, d20
vld1.64 {d9, d10}, [r3]
vcvt.s32.f64 s12, d25
vcvt.s32.f64 s22, d17
vcvt.s32.f64 s23, d19
vcvt.s32.f64 s24, d24
vcvt.s32.f64 s11, d21
vcvt.s32.f64 s25, d28
vabs.s32 d17, d11
vcvt.f64.s32 d19, s22
vabs.s32 d20, d12
vmull.u32 q14, d17, d8
vcvt.f64.s32 d24, s24
vfms.f64 d18, d19, d7
vmull.u32 q15, d20, d10
vcvt.s32.f64 s13, d16
vcvt.f64.s32 d8, s23
vcvt.f64.s32 d19, s25
vqsub.u64 q14, q14, q11
vqsub.u64 q15, q15, q13
vfms.f64 d25, d24, d9
vfms.f64 d16, d19, d9
vcgt.u32 d22, d4, d17
vfms.f64 d21, d8, d7
vqmovn.u64 d24, q15
vcgt.u32 d17, d4, d20
vqmovn.u64 d19, q14
vtst.32 d24, d24, d24
vcvt.s32.f64 s14, d18
vcvt.s32.f64 s20, d25
vtst.32 d19, d19, d19
vcvt.s32.f64 s21, d16
vcvt.s32.f64 s15, d21
vbic d22, d22, d19
vbic d17, d17, d24
vand d11, d11, d22
vst1.32 {d11}, [r4]!
vbsl d22, d7, d5
vand d12, d12, d17
vst1.32 {d22}, [r4]
vbsl d17, d10, d6
vst1.32 {d12}, [r5]!
vst1.32 {d17}, [r5]
