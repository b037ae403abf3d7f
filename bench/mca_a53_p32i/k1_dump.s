ldr x30, [sp, #168]
ldp x18, x0, [sp, #184]
ext v7.16b, v5.16b, v19.16b, #8 // #0
ext v0.16b, v5.16b, v5.16b, #8 // #1
ldp q6, q17, [x0, #32] // #2
str q5, [x18] // #3
add x28, x0, x28, lsl #7 // #4
sub v7.4s, v7.4s, v5.4s // #5
sub v0.4s, v0.4s, v5.4s // #6
ldp q23, q24, [x28, #128] // #7
ldp q21, q22, [x28, #96] // #8
saddw2 v29.2d, v6.2d, v7.4s // #9
saddw v26.2d, v6.2d, v0.2s // #10
saddw v28.2d, v6.2d, v7.2s // #11
saddw2 v27.2d, v6.2d, v0.4s // #12
fsub v29.2d, v29.2d, v6.2d // #13
fsub v26.2d, v26.2d, v6.2d // #14
fsub v28.2d, v28.2d, v6.2d // #15
ldr q25, [x28, #160] // #16
fmul d31, d31, v1.d[1] // #17
fsub v27.2d, v27.2d, v6.2d // #18
fmul v30.2d, v29.2d, v24.d[0] // #19
ldp q18, q20, [x28, #64] // #20
fmul v26.2d, v26.2d, v3.d[0] // #21
fmov x13, d5 // #22
fmul v28.2d, v28.2d, v3.d[0] // #23
fmul v27.2d, v27.2d, v3.d[1] // #24
fmls v29.2d, v30.2d, v24.d[1] // #25
fcvtzs v26.2d, v26.2d // #26
fcvtzs v27.2d, v27.2d // #27
fcvtzs v28.2d, v28.2d // #28
fmul d31, d31, v25.d[0] // #29
sqxtn v6.2s, v26.2d // #30
fmla v30.2d, v29.2d, v24.d[0] // #31
sqxtn v1.2s, v28.2d // #32
sshr v28.4s, v0.4s, #31 // #33
sqxtn2 v6.4s, v27.2d // #34
sshr v29.4s, v7.4s, #31 // #35
ldp q2, q4, [x0] // #36
fcvtzs v25.2d, v30.2d // #37
fmul v30.2d, v30.2d, v31.d[0] // #38
abs v27.4s, v7.4s // #39
abs v3.4s, v6.4s // #40
ushr v9.4s, v28.4s, #28 // #41
abs v25.2d, v25.2d // #42
fcvtzs v30.2d, v30.2d // #43
ushr v31.4s, v27.4s, #4 // #44
umin v3.4s, v3.4s, v4.4s // #45
mul v7.4s, v6.4s, v2.s[0] // #46
add v9.4s, v0.4s, v9.4s // #47
abs v26.4s, v0.4s // #48
sqxtn2 v1.4s, v30.2d // #49
xtn2 v31.4s, v25.2d // #50
mov v25.16b, v27.16b // #51
abs v0.4s, v1.4s // #52
mul v4.4s, v20.4s, v1.4s // #53
mls v25.4s, v18.4s, v31.4s // #54
sshr v24.4s, v9.4s, #4 // #55
shsub v9.4s, v9.4s, v7.4s // #56
mul v3.4s, v3.4s, v2.4s // #57
cmhi v16.4s, v17.4s, v0.4s // #58
umin v0.4s, v0.4s, v22.4s // #59
cmhi v25.4s, v23.4s, v25.4s // #60
eor v30.16b, v31.16b, v29.16b // #61
sshr v22.4s, v4.4s, #1 // #62
srshr v4.4s, v4.4s, #1 // #63
sshr v9.4s, v9.4s, #3 // #64
mul v0.4s, v0.4s, v21.4s // #65
eor v25.16b, v25.16b, v29.16b // #66
cmhs v3.4s, v26.4s, v3.4s // #67
sub v30.4s, v30.4s, v29.4s // #68
cmhs v0.4s, v27.4s, v0.4s // #69
bit v22.16b, v4.16b, v25.16b // #70
bit v24.16b, v9.16b, v3.16b // #71
and v6.16b, v6.16b, v3.16b // #72
and v0.16b, v0.16b, v16.16b // #73
sub v21.4s, v30.4s, v22.4s // #74
fmov x10, d6 // #75
fmov x9, d24 // #76
and v1.16b, v1.16b, v0.16b // #77
bit v30.16b, v21.16b, v0.16b // #78
and x2, x10, #0xffffffff00000000 // #79
and x1, x9, #0xffffffff00000000 // #80
add x10, x2, w10, sxtw // #81
add x9, x1, w9, sxtw // #82
lsl x20, x10, #2 // #83
lsr x1, x13, #48 // #84
add x17, x10, x9, lsl #1 // #85
stp q30, q1, [x18, #16] // #86
add x14, x13, x9 // #87
add x19, x17, x10, lsl #1 // #88
lsr w9, w13, #16 // #89
add x15, x13, x17 // #90
lsr x2, x14, #48 // #91
lsr x3, x15, #48 // #92
lsr w10, w14, #16 // #93
add x17, x17, x20 // #94
add x13, x15, x17 // #95
madd w1, w1, w30, w9 // #96
add x16, x14, x19 // #97
add x19, x19, x20 // #98
lsr w9, w13, #16 // #99
add x17, x17, x20 // #100
lsr w11, w15, #16 // #101
add x15, x13, x17 // #102
lsr x5, x13, #48 // #103
madd w2, w2, w30, w10 // #104
madd w3, w3, w30, w11 // #105
ldrb w1, [x27, w1, uxtw] // #106
add x14, x16, x19 // #107
add x17, x17, x20 // #108
lsr x6, x14, #48 // #109
lsr x7, x15, #48 // #110
lsr w11, w15, #16 // #111
add x13, x15, x17 // #112
lsr w12, w16, #16 // #113
lsr x4, x16, #48 // #114
add x19, x19, x20 // #115
madd w5, w5, w30, w9 // #116
ldrb w2, [x27, w2, uxtw] // #117
madd w4, w4, w30, w12 // #118
add x16, x14, x19 // #119
ldrb w3, [x27, w3, uxtw] // #120
add x17, x17, x20 // #121
add x19, x19, x20 // #122
lsr x8, x16, #48 // #123
lsr w10, w14, #16 // #124
ldrb w4, [x27, w4, uxtw] // #125
madd w7, w7, w30, w11 // #126
orr x21, x1, x2, lsl #8 // #127
madd w6, w6, w30, w10 // #128
add x15, x13, x17 // #129
add x17, x17, x20 // #130
lsr w11, w15, #16 // #131
add x14, x16, x19 // #132
lsr w9, w13, #16 // #133
lsr x1, x13, #48 // #134
orr x22, x3, x4, lsl #8 // #135
add x13, x15, x17 // #136
lsr w12, w16, #16 // #137
lsr x3, x15, #48 // #138
add x19, x19, x20 // #139
orr x15, x21, x22, lsl #16 // #140
ldrb w6, [x27, w6, uxtw] // #141
madd w8, w8, w30, w12 // #142
ldrb w5, [x27, w5, uxtw] // #143
madd w1, w1, w30, w9 // #144
str w15, [x26] // #145
madd w3, w3, w30, w11 // #146
add x16, x14, x19 // #147
ldrb w7, [x27, w7, uxtw] // #148
add x17, x17, x20 // #149
ldrb w8, [x27, w8, uxtw] // #150
add x15, x13, x17 // #151
add x19, x19, x20 // #152
lsr x2, x14, #48 // #153
lsr w10, w14, #16 // #154
orr x21, x5, x6, lsl #8 // #155
madd w2, w2, w30, w10 // #156
add x14, x16, x19 // #157
orr x22, x7, x8, lsl #8 // #158
lsr x4, x16, #48 // #159
add x19, x19, x20 // #160
lsr w12, w16, #16 // #161
lsr x7, x15, #48 // #162
lsr w10, w14, #16 // #163
lsr x6, x14, #48 // #164
lsr w11, w15, #16 // #165
lsr x5, x13, #48 // #166
orr x15, x21, x22, lsl #16 // #167
lsr w9, w13, #16 // #168
madd w6, w6, w30, w10 // #169
add x16, x14, x19 // #170
ldrb w1, [x27, w1, uxtw] // #171
str w15, [x26, #4] // #172
madd w4, w4, w30, w12 // #173
ldrb w3, [x27, w3, uxtw] // #174
madd w5, w5, w30, w9 // #175
ldrb w2, [x27, w2, uxtw] // #176
madd w7, w7, w30, w11 // #177
lsr w12, w16, #16 // #178
ldrb w4, [x27, w4, uxtw] // #179
ldrb w5, [x27, w5, uxtw] // #180
orr x21, x1, x2, lsl #8 // #181
ldrb w6, [x27, w6, uxtw] // #182
lsr x8, x16, #48 // #183
orr x22, x3, x4, lsl #8 // #184
ldrb w7, [x27, w7, uxtw] // #185
orr x15, x21, x22, lsl #16 // #186
madd w8, w8, w30, w12 // #187
str w15, [x26, #8] // #188
ldrb w8, [x27, w8, uxtw] // #189
orr x21, x5, x6, lsl #8 // #190
ldr x24, [x18, #24] // #191
orr x22, x7, x8, lsl #8 // #192
and x13, x24, #0xffffffff00000000 // #193
orr x15, x21, x22, lsl #16 // #194
add x24, x13, w24, sxtw // #195
str w15, [x26, #12] // #196
ldr x25, [x18, #40] // #197
ldr w1, [x28, #72] // #198
and x13, x25, #0xffffffff00000000 // #199
ldr x23, [x18, #8] // #200
add x25, x13, w25, sxtw // #201
cmp w1, #0xf // #202
mov x5, x23
b.eq .+4
