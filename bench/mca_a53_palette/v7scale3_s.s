ldr r3, [r9], #4 @m=src
uxtb r4, r3
ubfx r5, r3, #8, #8
ubfx r6, r3, #16, #8
ldr r4, [r8, r4, lsl #2] @m=pal
ldr r5, [r8, r5, lsl #2] @m=pal
ldr r6, [r8, r6, lsl #2] @m=pal
lsrs r3, r3, #24
ldr r3, [r8, r3, lsl #2] @m=pal
vdup.32 d16, r4
vmov d17, r4, r5
vdup.32 d18, r5
vdup.32 d19, r6
vmov d20, r6, r3
vst1.32 {d16-d19}, [r0]! @m=dst
vdup.32 d21, r3
vst1.32 {d20-d21}, [r0], r1 @m=dst
vst1.32 {d16-d19}, [r0]! @m=dst
vst1.32 {d20-d21}, [r0], r1 @m=dst
vst1.32 {d16-d19}, [r0]! @m=dst
vst1.32 {d20-d21}, [r0], r2 @m=dst
cmp r9, r10
bne 1b
