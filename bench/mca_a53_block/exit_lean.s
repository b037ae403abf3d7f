// The mip-2 lean path's group exit, tw != 32 (asm/neon_block_mip2l.h; d x17, t0 x28, ete x14,
// q x13, w x15, rp x27) as searched by bench/order_search.py: Cortex-A53 model 13 -> 11 cycles.
ldp x27, x30, [sp]
add x28, x28, #0x8
stp d4, d5, [x17]
add x13, x28, x15, lsl #1
stp d6, d7, [x8]
add x14, x14, #0x8
ldr q8, [x28, x15]
add x26, x26, #0x10
ldr q0, [x28]
sub x13, x13, x14
ldr q21, [x27]
cmp x26, x30
ldr q26, [x27, #16]
add x27, x27, #0x20
b.ne .+4
