adrp x1, .Ltgt
add x1, x1, #0xb10
ldrsw x11, [x9, #32]
and w2, w12, #0x3
add x12, x1, #0x20
sub w14, w14, #0x1
mov w19, #0xd0
mov w1, w30
ldp x20, x21, [x9, #88]
smaddl x12, w2, w19, x12
ldr x8, [x9]
lsr w13, w14, #8
ldr x10, [x9, #24]
and x14, x14, #0xff
add x2, sp, #0x30
lsl x11, x11, #1
stp x20, x21, [sp, #112]
stp x0, x9, [sp, #128]
ldr x9, [x9, #48]
stp w3, w4, [sp, #144]
stp w5, w6, [sp, #152]
stp w7, w30, [sp, #160]
