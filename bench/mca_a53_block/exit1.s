// SB_A53_EXIT1 (asm/neon_block_a53m1.h): SB_A53_EXIT("x30", "4") searched with --mem: 17 -> 14 (A53).
stp d4, d5, [x17]
add x16, x16, #4
stp d6, d7, [x8]
ldp x6, x7, [sp, #32]
ldp x0, x11, [sp]
add x15, x15, x7
ldr x5, [sp, #48]
cmp x15, x6
sub x4, x15, x6
add x11, x11, #4
add x0, x0, #16
ldp x30, x28, [sp, #16]
csel x15, x4, x15, cs
cmp x0, x5
mov x17, x0
stp x0, x11, [sp]
b.ne 5b
