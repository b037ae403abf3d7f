ldr r2, [r0, #4]
add r0, r0, #8
vld1.64 {d17}, [r0]
vld1.64 {d16}, [r0]
vld1.64 {d18}, [r0]
vld1.64 {d0, d1, d2, d3}, [r0]!
add r2, r7, r2, lsl #6
vld1.64 {d7, d8, d9, d10}, [r0]
vfma.f64 d0, d1, d9
vld1.64 {d4, d5, d6}, [r6]!
vadd.f64 d19, d9, d6
vfma.f64 d2, d3, d9
vld1.64 {d11, d12}, [r2]!
vld1.64 {d22}, [r0]
vadd.f64 d20, d9, d11
vfma.f64 d16, d1, d19
vadd.f64 d21, d19, d12
vfma.f64 d17, d1, d20
vcmpe.f64 d0, d4
vld1.64 {d24}, [r0]
vmrs APSR_nzcv, fpscr
vfma.f64 d18, d1, d21
vmov.f64 d0, d4 @flags
vdiv.f64 d0, d5, d0
vld1.64 {d11, d12, d13}, [r6]!
vcmpe.f64 d16, d4
vmrs APSR_nzcv, fpscr
vmov.f64 d16, d4 @flags
vcmpe.f64 d17, d4
vld1.64 {d23}, [r0]
vdiv.f64 d16, d5, d16
vmrs APSR_nzcv, fpscr
vcmpe.f64 d18, d4
vmov.f64 d17, d4 @flags
vmrs APSR_nzcv, fpscr
sub r0, r0, #16
vld1.64 {d27}, [r0]
vmov.f64 d18, d4 @flags
vdiv.f64 d18, d5, d18
vdiv.f64 d17, d5, d17
vfma.f64 d24, d8, d21
vld1.64 {d26}, [r0]
vfma.f64 d7, d8, d9
vld1.64 {d25}, [r0]
vfma.f64 d25, d3, d19
vfma.f64 d22, d8, d19
vmul.f64 d2, d2, d0
vmul.f64 d7, d7, d0
vfma.f64 d23, d8, d20
vfma.f64 d26, d3, d20
vfma.f64 d27, d3, d21
vmul.f64 d22, d22, d16
vmul.f64 d25, d25, d16
vcvt.u32.f64 d7, d7, #16
vld1.64 {d3, d4}, [r2]!
vcvt.u32.f64 d2, d2, #16
vadd.f64 d0, d0, d16
vmul.f64 d19, d1, d11
vmul.f64 d24, d24, d18
vmul.f64 d26, d26, d17
vmul.f64 d23, d23, d17
vsli.64 d2, d7, #32
vmul.f64 d27, d27, d18
vcvt.u32.f64 d22, d22, #16
vcvt.u32.f64 d25, d25, #16
vcvt.u32.f64 d26, d26, #16
vld1.64 {d5, d6}, [r2]
vcvt.u32.f64 d23, d23, #16
vcvt.u32.f64 d24, d24, #16
vcvt.u32.f64 d27, d27, #16
vsli.64 d25, d22, #32
vsli.64 d26, d23, #32
vmin.u32 d25, d25, d10
vsli.64 d27, d24, #32
vmin.u32 d26, d26, d10
vmin.u32 d27, d27, d10
vadd.f64 d16, d16, d17
vmul.f64 d1, d1, d12
vsub.i32 d11, d26, d25
vsub.i32 d24, d27, d26
vadd.f64 d17, d17, d18
vbit d11, d24, d6
vmin.u32 d2, d2, d10
vmul.f64 d18, d1, d16
vcvt.f64.s32 d24, s22
vcvt.f64.s32 d27, s23
vst1.32 {d2}, [r4]!
vst1.32 {d25}, [r4]!
vbit d16, d17, d6
vst1.32 {d26}, [r4]!
vmul.f64 d0, d1, d0
vdiv.f64 d24, d24, d3
vld1.64 {d6, d7, d8}, [r6]
vdiv.f64 d27, d27, d3
vsub.i32 d3, d25, d2
vmul.f64 d19, d19, d16
vsub.i32 d1, d26, d25
vcvt.f64.s32 d25, s6
vcvt.f64.s32 d26, s7
vcvt.f64.s32 d17, s3
vcvt.f64.s32 d16, s2
vmul.f64 d25, d25, d0
vmul.f64 d19, d19, d13
vmul.f64 d26, d26, d0
vmul.f64 d16, d16, d18
vabs.s32 d20, d11
vmul.f64 d17, d17, d18
vcvt.s32.f64 s0, d25
vabs.s32 d18, d3
vmovl.u32 q11, d20
vcvt.s32.f64 s4, d16
vcvt.s32.f64 s1, d26
vcvt.s32.f64 s5, d17
vshr.s32 d25, d3, #31
vmul.i32 d21, d0, d7
vabs.s32 d17, d0
vabs.s32 d16, d1
vmul.f64 d26, d24, d19
vmin.u32 d17, d17, d8
vmul.f64 d20, d27, d19
vabs.s32 d19, d2
vmul.i32 d17, d17, d7
vcvt.s32.f64 s20, d26
vsra.u32 d3, d25, #28
vcvt.s32.f64 s18, d24
vmin.u32 d19, d19, d8
vcvt.s32.f64 s21, d20
vcvt.f64.s32 d28, s20
vmul.i32 d19, d19, d7
vcge.u32 d17, d18, d17
vmul.i32 d26, d2, d7
vabs.s32 d18, d10
vand d21, d21, d17
vfms.f64 d24, d28, d4
vshr.s32 d20, d1, #31
vmull.u32 q15, d18, d5
vcvt.f64.s32 d29, s21
vsra.u32 d1, d20, #28
vhsub.s32 d3, d3, d21
vcge.u32 d19, d16, d19
vqsub.u64 q15, q15, q11
vcvt.s32.f64 s19, d27
vand d26, d26, d19
vfms.f64 d27, d29, d4
vqmovn.u64 d16, q15
vhsub.s32 d1, d1, d26
vcgt.u32 d25, d6, d18
vand d0, d0, d17
vtst.32 d16, d16, d16
vshr.s32 d1, d1, #3
vshr.s32 d3, d3, #3
vst1.32 {d3}, [r4]!
vst1.32 {d0}, [r4]!
vcvt.s32.f64 s16, d24
vbic d25, d25, d16
vcvt.s32.f64 s17, d27
vst1.32 {d1}, [r4]!
vand d2, d2, d19
vst1.32 {d2}, [r4]!
vand d10, d10, d25
vst1.32 {d10}, [r4]!
vbsl d25, d8, d9
vst1.32 {d25}, [r4]!
