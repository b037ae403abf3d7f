// tail1_steps.s: the left <= 32 tail's steps block (asm/span_persp_a64longspan.h, tail1_steps),
// order from bench/order_search.py (standalone, A53 98 -> 78 cycles as a loop, A57 30.7; then in its
// qemu block with runs_k3's head pinned, --tail=76: 118.07 -> 114.07, A57 60.67 -> 60.17, wt-l192e).
// Written into the header by tail_inline.py (tail1_steps) here. Registers: operands w0 du, w1 dv, w2 steps,
// d1 y, d2 sf, d3 z1, d4 z2 (lane 0 of the loop's z23 vector: no lane move before the block), d5 zc (inputs; the curve factor c2 = -(zc (z1 + z2)) by one fnmul); w6 lnu, w7 lnv, w8 ddu, w18 ddv (outputs);
// x3 - x5, x9 - x17, x19 and v16 - v23 fixed scratch (clobbers).
cmp w2, #1
scvtf d16, w0
scvtf d17, w1
csetm w10, gt
sub w11, w2, #1
fadd d20, d3, d4
fmul d18, d16, d1
fmul d19, d17, d1
mov w13, #0xc9ff
fnmul d20, d5, d20
fmsub d21, d18, d2, d16
fmsub d22, d19, d2, d17
movk w13, #0x3b9a, lsl #16
fmadd d18, d21, d1, d18
fmadd d19, d22, d1, d19
csinc w9, w2, wzr, gt
fmul d21, d18, d20
fcvtzs w7, d19
fmul d22, d19, d20
mul w11, w11, w2
fcvtzs w6, d18
sub w12, w9, #1
fcvtzs w8, d21
fcvtzs w18, d22
mov w14, #0x93ff
asr w4, w1, #31
lsr w11, w11, #1
movk w14, #0x7735, lsl #16
add w15, w8, w13
add w16, w18, w13
cmp w15, w14
asr w3, w0, #31
eor w13, w0, w3
eor w17, w6, w3
csel w8, w8, wzr, lo
cmp w16, w14
eor w14, w1, w4
and w8, w8, w10
eor w19, w7, w4
asr w5, w8, #31
sub w17, w17, w3
csel w18, w18, wzr, lo
eor w15, w8, w5
sub w15, w15, w5
and w18, w18, w10
asr w10, w18, #31
eor w16, w18, w10
sub w13, w13, w3
sub w16, w16, w10
eor w5, w8, w3
umsubl x15, w15, w11, x13
sub w14, w14, w4
msub w13, w9, w17, w13
sub w19, w19, w4
eor w10, w18, w4
sub w5, w5, w3
umsubl x16, w16, w11, x14
cmp w9, w13, lsl #1
msub w14, w9, w19, w14
mul w5, w12, w5
sub w10, w10, w4
cset w13, hi
cmp w9, w14, lsl #1
sub w17, w17, w5, asr #1
and w13, w13, w5
sub w17, w17, w13
mul w10, w12, w10
cset w14, hi
cmp x15, #0
eor w17, w17, w3
sub w19, w19, w10, asr #1
and w14, w14, w10
csel w8, wzr, w8, lt
sub w17, w17, w3
csel w6, w6, w17, lt
cmp x16, #0
sub w19, w19, w14
eor w19, w19, w4
csel w18, wzr, w18, lt
sub w19, w19, w4
csel w7, w7, w19, lt
