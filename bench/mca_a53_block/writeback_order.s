// llvm-mca Cortex-A53: results write back in program order (a scalar op after a 6-cycle NEON op
// waits for it; an op of latency 2 after a load waits a cycle).
add x1, x1, #1
add v0.4s, v0.4s, v1.4s
add x2, x2, #1
add x3, x3, #1
ldrb w4, [x5]
add x6, x6, #1
add x7, x7, #1
add v2.4s, v2.4s, v1.4s
ldrb w8, [x5]
ldrb w9, [x5]
add x10, x10, #1
