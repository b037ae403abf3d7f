// bench/count_align.cpp: linked right after count_kernels.cpp and before starbow_asm, so the
// kernels' code starts at the same offset into a 4 KiB page whatever the harness's size.
// qemu cuts translation blocks at page boundaries and bench/count.sh times those blocks, so
// without this an edit to the harness alone moved the kernels' cuts and their estimates
// (armhf persp1920lin 4.74 -> 4.92 for a longer count_kernels.cpp).
extern "C" __attribute__((aligned(4096), used, noinline)) void starbow_count_kernels_page() {}
