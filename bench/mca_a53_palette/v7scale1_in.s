ldr r4, [r9, #4] @m=src
ldr r3, [r9], #8 @m=src
uxtb r5, r3
ubfx r6, r3, #8, #8
ubfx r1, r3, #16, #8
uxtb r2, r4
ubfx ip, r4, #8, #8
ubfx lr, r4, #16, #8
lsr r3, r3, #24
lsr r4, r4, #24
ldr r5, [r8, r5, lsl #2] @m=pal
ldr r6, [r8, r6, lsl #2] @m=pal
ldr r1, [r8, r1, lsl #2] @m=pal
ldr r3, [r8, r3, lsl #2] @m=pal
ldr r2, [r8, r2, lsl #2] @m=pal
ldr ip, [r8, ip, lsl #2] @m=pal
ldr lr, [r8, lr, lsl #2] @m=pal
ldr r4, [r8, r4, lsl #2] @m=pal
strd r5, r6, [r0, #0] @m=dst
strd r1, r3, [r0, #8] @m=dst
strd r2, ip, [r0, #16] @m=dst
strd lr, r4, [r0, #24] @m=dst
add r0, r0, #32
cmp r9, r10
bne 1b
