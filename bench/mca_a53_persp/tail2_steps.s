// tail2_steps.s: the left > 32 tail's steps block (asm/span_persp_a64longspan.h, tail2_steps),
// order from bench/order_search.py (standalone, A53 64 cycles as a loop, A57 25.5; then in its qemu
// block, GCC's ddi and pass_last's head pinned, --head=2 --tail=91: 129.03 -> 126.03, wt-l192e). Written
// into the header by tail_inline.py (tail2_steps) here. Registers: operands w0 du, w1 dv, w2 d1u, w3 d1v
// (inputs); d0 cc, d1 y, d2 sf, v3 z23 = [z1, z2] (the loop's z23, its lanes added by faddp:
// no lane moves before the block), d5 zc (inputs; the curve factor c2 = -(zc (z1 + z2)) by one fnmul); x4 b_d, x5 b_dd, w6 lnu, w7 lnv,
// w8 ddu, w18 ddv (outputs); x9 - x17 and v16 - v25 fixed scratch (clobbers).
sxtw x11, w2
cmp x11, #0
sxtw x12, w3
scvtf d24, w2
scvtf d16, w0
scvtf d17, w1
cneg x15, x11, lt
cmp x12, #0
scvtf d25, w3
fmul d24, d24, d0
fmul d18, d16, d1
faddp d20, v3.2d
fmul d19, d17, d1
cneg x16, x12, lt
fmul d25, d25, d0
fcvtzs w9, d24
fmsub d21, d18, d2, d16
fmsub d22, d19, d2, d17
fnmul d20, d5, d20
fcvtzs w10, d25
sbfiz x13, x9, #7, #32
sub x13, x13, w9, sxtw #3
add x17, x13, x15
sbfiz x14, x10, #7, #32
sub x14, x14, w10, sxtw #3
cmp x17, x15, lsl #1
fmadd d19, d22, d1, d19
fmadd d18, d21, d1, d18
csel x13, x13, xzr, ls
add x5, x14, x16
csel w9, w9, wzr, ls
cmp x5, x16, lsl #1
sub x11, x11, x13
mov w13, #0xc9ff
asr x17, x11, #63
csel x14, x14, xzr, ls
csel w10, w10, wzr, ls
sub x12, x12, x14
asr x5, x12, #63
fmul d22, d19, d20
fcvtzs w6, d18
fmul d21, d18, d20
fcvtzs w7, d19
add x12, x12, x5, lsr #60
movk w13, #0x3b9a, lsl #16
asr x12, x12, #4
add x11, x11, x17, lsr #60
lsl x14, x10, #32
fcvtzs w8, d21
fcvtzs w18, d22
add x5, x14, w9, sxtw
mov w14, #0x93ff
asr x11, x11, #4
movk w14, #0x7735, lsl #16
add x4, x11, x12, lsl #32
add w11, w8, w13
add w12, w18, w13
cmp w11, w14
csel w8, w8, wzr, lo
cmp w12, w14
csel w18, w18, wzr, lo
