fmul v18.2d, v18.2d, v30.d[0] // #0
fmul v16.2d, v16.2d, v27.d[0] // #1
fmul v22.2d, v22.2d, v29.d[0] // #2
fadd v6.2d, v28.2d, v29.2d // #3
fmul v24.2d, v24.2d, v29.d[1] // #4
fadd v8.2d, v29.2d, v30.2d // #5
fcvtzu v16.2d, v16.2d, #16 // #6
fmul v2.2d, v2.2d, v28.d[0] // #7
fcvtzu v18.2d, v18.2d, #16 // #8
fadd v0.2d, v27.2d, v28.2d // #9
fcvtzu v22.2d, v22.2d, #16 // #10
fmul v26.2d, v26.2d, v27.d[1] // #11
fcvtzu v2.2d, v2.2d, #16 // #12
uqxtn v5.2s, v16.2d // #13
fcvtzu v24.2d, v24.2d, #16 // #14
uqxtn v19.2s, v22.2d // #15
mov v1.16b, v8.16b // #16
fmul v23.2d, v23.2d, v28.d[1] // #17
uqxtn2 v5.4s, v2.2d // #18
fmul v25.2d, v25.2d, v30.d[1] // #19
fcvtzu v26.2d, v26.2d, #16 // #20
trn1 v9.2d, v0.2d, v6.2d // #21
ld1r {v2.2d}, [x8] // #22
fcvtzu v23.2d, v23.2d, #16 // #23
uqxtn v10.2s, v26.2d // #24
uqxtn v11.2s, v24.2d // #25
fcvtzu v25.2d, v25.2d, #16 // #26
dup v22.2d, v8.d[1] // #27
uqxtn2 v19.4s, v18.2d // #28
uqxtn2 v10.4s, v23.2d // #29
ld1r {v18.2d}, [x13] // #30
fmul v14.2d, v31.2d, v20.2d // #31
uqxtn2 v11.4s, v25.2d // #32
fmov v20.2d, #5.000000000000000000e-01 // #33
umin v19.4s, v19.4s, v2.4s // #34
trn2 v4.2d, v0.2d, v6.2d // #35
umin v10.4s, v10.4s, v18.4s // #36
umin v11.4s, v11.4s, v18.4s // #37
fmul v31.2d, v31.2d, v20.2d // #38
fmul v27.2d, v4.2d, v14.d[1] // #39
fmul v3.2d, v9.2d, v14.d[0] // #40
stp q10, q11, [x25] // #41
tst x22, #0x7fffffffffffffff // #42
and w24, w24, w21 // #43
sub w20, w20, #0x11 // #44
str q4, [x25, #48] // #45
sub w19, w19, #0x11 // #46
stp q22, q27, [x25, #64] // #47
sub x20, x20, #0x20 // #48
sub x19, x19, #0x20 // #49
lsl x23, x23, #1 // #50
and x19, x19, x20 // #51
ccmp x23, #0x0, #0x4, ne // #52
lsr x19, x19, #63 // #53
and w24, w24, w17 // #54
and w24, w24, w19 // #55
add x20, x0, #0xb0 // #56
ccmp w24, #0x0, #0x4, ne // #57
umin v5.4s, v5.4s, v2.4s // #58
str q31, [sp, #256] // #59
csel x24, x20, xzr, ne // #60
str x24, [sp, #176]
cmp w16, #0x3
str x24, [sp, #208]
sub w28, w18, #0x1
str w18, [sp, #248]
ldr x26, [x0]
b.ne .+4
