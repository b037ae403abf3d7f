ldr x0, [sp, #176]
str x0, [sp, #200]
ldp x6, x25, [sp, #232]
add x4, x0, #0x10
ldr w3, [x0, #8]
add x5, x0, #0x68
ldrsw x2, [x0, #96]
ldp x28, x26, [sp, #216]
sbfiz x1, x3, #5, #32
add x2, x6, x2, lsl #5
add x1, x6, x1
ldr q18, [x26, #16] // #0
add x12, x5, #0x30 // #1
ldr d31, [x4, #8] // #2
add x9, x5, #0x8 // #3
ldr d2, [x1] // #4
add x7, x0, #0x108 // #5
ldr d4, [x4] // #6
add w16, w3, #0xf // #7
cmp x28, x7 // #8
asr w16, w16, #4 // #9
ldr d0, [x4, #48] // #10
add x7, x0, #0xb0 // #11
ldr d21, [x4, #16] // #12
add x6, x4, #0x20 // #13
ldr d7, [x1, #16] // #14
sub w18, w3, w16, lsl #4 // #15
ldr q16, [x26] // #16
csel x7, x7, x0, hi // #17
ld1 {v4.d}[1], [x5] // #18
add x15, x2, #0x10 // #19
ld1 {v0.d}[1], [x12] // #20
add x14, x2, #0x8 // #21
ld1 {v2.d}[1], [x2] // #22
ldr d5, [x1, #8] // #23
ld1 {v7.d}[1], [x15] // #24
ldrb w21, [x7, #168] // #25
fadd v6.2d, v0.2d, v16.2d // #26
mov v1.16b, v4.16b // #27
ldr x22, [x7, #24] // #28
cset w17, hi // #29
ld1 {v5.d}[1], [x14] // #30
ld1 {v31.d}[1], [x9] // #31
ldr x23, [x7, #112] // #32
fadd v17.2d, v6.2d, v16.2d // #33
mov v13.16b, v4.16b // #34
mov v11.16b, v4.16b // #35
fadd v8.2d, v0.2d, v2.2d // #36
mov v10.16b, v4.16b // #37
fadd v12.2d, v6.2d, v5.2d // #38
fadd v14.2d, v17.2d, v7.2d // #39
ldp q20, q9, [x26, #64] // #40
fmla v1.2d, v31.2d, v8.2d // #41
fmla v10.2d, v31.2d, v0.2d // #42
fmla v11.2d, v31.2d, v6.2d // #43
fmla v4.2d, v31.2d, v14.2d // #44
fmla v13.2d, v31.2d, v12.2d // #45
mov v25.16b, v18.16b // #46
ldp q19, q3, [x26, #32] // #47
add x11, x5, #0x28 // #48
fmaxnm v10.2d, v10.2d, v9.2d // #49
fmaxnm v11.2d, v11.2d, v9.2d // #50
fmaxnm v1.2d, v1.2d, v9.2d // #51
fmaxnm v13.2d, v13.2d, v9.2d // #52
mov v23.16b, v18.16b // #53
fmaxnm v4.2d, v4.2d, v9.2d // #54
frecpe v27.2d, v10.2d // #55
frecpe v28.2d, v11.2d // #56
frecpe v29.2d, v1.2d // #57
frecpe v30.2d, v13.2d // #58
mov v24.16b, v18.16b // #59
frecps v2.2d, v10.2d, v27.2d // #60
frecps v5.2d, v11.2d, v28.2d // #61
mov v22.16b, v18.16b // #62
frecps v17.2d, v1.2d, v29.2d // #63
frecps v7.2d, v13.2d, v30.2d // #64
fmul v27.2d, v27.2d, v2.2d // #65
fmul v28.2d, v28.2d, v5.2d // #66
fmul v29.2d, v29.2d, v17.2d // #67
fmul v30.2d, v30.2d, v7.2d // #68
fmax v16.2d, v10.2d, v11.2d // #69
frecps v2.2d, v10.2d, v27.2d // #70
frecps v5.2d, v11.2d, v28.2d // #71
frecps v17.2d, v1.2d, v29.2d // #72
frecps v7.2d, v13.2d, v30.2d // #73
ldr w19, [x7, #8] // #74
fmul v27.2d, v27.2d, v2.2d // #75
fmul v28.2d, v28.2d, v5.2d // #76
fmul v29.2d, v29.2d, v17.2d // #77
fmax v2.2d, v1.2d, v13.2d // #78
fmul v30.2d, v30.2d, v7.2d // #79
orr v5.16b, v10.16b, v19.16b // #80
orr v7.16b, v1.16b, v19.16b // #81
orr v17.16b, v11.16b, v19.16b // #82
fmax v16.2d, v16.2d, v2.2d // #83
fmls v24.2d, v1.2d, v29.2d // #84
fmls v22.2d, v10.2d, v27.2d // #85
fmls v23.2d, v11.2d, v28.2d // #86
fmls v25.2d, v13.2d, v30.2d // #87
orr v9.16b, v13.16b, v19.16b // #88
fmax v16.2d, v16.2d, v4.2d // #89
orr v2.16b, v4.16b, v19.16b // #90
uminp v19.4s, v5.4s, v17.4s // #91
fmla v29.2d, v29.2d, v24.2d // #92
fmla v28.2d, v28.2d, v23.2d // #93
fmla v30.2d, v30.2d, v25.2d // #94
fmla v27.2d, v27.2d, v22.2d // #95
mov v23.16b, v18.16b // #96
cmhs v16.2d, v16.2d, v3.2d // #97
mov v24.16b, v18.16b // #98
uminp v22.4s, v7.4s, v9.4s // #99
mov v25.16b, v18.16b // #100
ldr d9, [x5, #24] // #101
add w18, w18, #0x10 // #102
add x10, x5, #0x20 // #103
ldr d17, [x5, #16] // #104
mov v3.16b, v18.16b // #105
uminp v26.4s, v2.4s, v16.4s // #106
umax v19.4s, v19.4s, v22.4s // #107
fmls v23.2d, v10.2d, v27.2d // #108
fmls v25.2d, v1.2d, v29.2d // #109
fmls v24.2d, v11.2d, v28.2d // #110
fmls v3.2d, v13.2d, v30.2d // #111
umax v19.4s, v19.4s, v26.4s // #112
ld1 {v17.d}[1], [x10] // #113
ldr w20, [x7, #96] // #114
ldrb w24, [x7, #80] // #115
fmla v29.2d, v29.2d, v25.2d // #116
fmla v27.2d, v27.2d, v23.2d // #117
fmla v28.2d, v28.2d, v24.2d // #118
mov v24.16b, v17.16b // #119
ld1 {v21.d}[1], [x6] // #120
add x7, x4, #0x28 // #121
ld1 {v9.d}[1], [x11] // #122
ldr d7, [x4, #24] // #123
umaxv s19, v19.4s // #124
mov v23.16b, v17.16b // #125
mov v2.16b, v21.16b // #126
mov v25.16b, v17.16b // #127
ld1 {v7.d}[1], [x7] // #128
mov v18.16b, v21.16b // #129
mov v16.16b, v21.16b // #130
fmov w6, s19 // #131
mov v22.16b, v21.16b // #132
mov v26.16b, v17.16b // #133
fmla v2.2d, v7.2d, v6.d[0] // #134
fmla v25.2d, v9.2d, v12.d[1] // #135
fmla v16.2d, v7.2d, v0.d[0] // #136
fmla v22.2d, v7.2d, v8.d[0] // #137
fmla v18.2d, v7.2d, v12.d[0] // #138
fmla v23.2d, v9.2d, v6.d[1] // #139
fmla v24.2d, v9.2d, v8.d[1] // #140
fmla v26.2d, v9.2d, v0.d[1] // #141
fmla v30.2d, v30.2d, v3.2d // #142
add x13, x5, #0x38 // #143
cmn w6, #0x1 // #144
add x8, x4, #0x38 // #145
b.ne .+4 // #146
