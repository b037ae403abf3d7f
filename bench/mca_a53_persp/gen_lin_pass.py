#!/usr/bin/env python3
# bench/mca_a53_persp/gen_lin_pass.py: generates persp_fast's aarch64 linear long-span pass
# (asm/span_persp_a64lin_pass.h): one loop iteration = two 16-pixel runs + the stage work
# (steps of runs r + 1, r + 2 by steps16_packed; samples r + 4, r + 5 with their divide), the
# operations of persp_fast's vector loop (asm/span_persp_fast_a64vec.inc, kPre), written with
# value names, registers allocated by a linear scan over the slot order (as gen_long_pass.py,
# the second-order pass, whose drawing pipeline this shares: lin_slot's).
#
#   gen_lin_pass.py body OUT.s          the body in its slot order (for order_search.py)
#   gen_lin_pass.py header IN.s OUT.h [--pad=N]   the header from a (searched) body and
#        lin_long_setup.s; N never-run nops after the loop (default: the present layout's)
# The body's last line is the loop branch; order_search keeps register, flag and store order.
# The present header: gen_lin_pass.py header lin_pass.s ../../asm/span_persp_a64lin_pass.h (from
# this directory). lin_pass.s: the body searched (order_search.py --lcuts=150/151/152: qemu
# cuts it after 151 lines), then lin_pass_subv.py, searched again. lin_long_setup.s: the
# compiler's block of the former head asm and this set-up, searched in its qemu block
# (--head=3 --mem: the compiler's three loads before it pinned), its order carried back by
# line (the binary's text names the stack slots by offset; see LONG.md, wt-lin192).
import re, sys

# Loop-carried values and their registers (the C++ wrapper binds them).
PIN = dict(d="x0", tx="x23", w="x24", c0="x13", c1="x14", c2="x15", c3="x16", e="x17",
           nA="x25", nB="x26", nC="x27",
           kZix="v16", kUVx="v17", k16="v18", k32="v19", kOne="v20", kMin="v21", kMax4="v22", pp="v24")
GPR = ["x%d" % i for i in list(range(1, 18)) + list(range(19, 29)) + [30, 18]]
VEC = ["v%d" % i for i in range(32)]

body = []  # (slot G, text)
PAD = int(next((a.split("=")[1] for a in sys.argv if a.startswith("--pad=")), "612"))


def E(g, *lines):
    for l in lines:
        body.append((g, l))


def group(J, last):
    """Shifts and chain steps of pixel group J (4 pixels): chain i holds pixel 4 g + i."""
    h = ["{X:h%d_%d}" % (J, i) for i in range(4)]
    l = ["{W:l%d_%d}" % (J, i) for i in range(4)]
    c = ["c0", "c1", "c2", "c3"]
    out = []
    for i in range(4):
        out += [f"lsr {h[i]}, {{X:{c[i]}}}, #48", f"lsr {l[i]}, {{W:{c[i]}}}, #16"]
    if not last:  # (groups 3 and 7: lin_start sets the chains after them)
        out += [f"add {{X:{c[i]}}}, {{X:{c[i]}}}, {{X:e}}" for i in range(4)]
    return out


def madd(J):
    return [f"madd {{W:h{J}_{i}}}, {{W:h{J}_{i}}}, {{W:w}}, {{W:l{J}_{i}}}" for i in range(4)]


def loads(J):
    return [f"ldrb {{W:h{J}_{i}}}, [{{X:tx}}, {{W:h{J}_{i}}}, uxtw]" for i in range(4)]


def pairs(J):
    return [f"orr {{X:p{J}_0}}, {{X:h{J}_0}}, {{X:h{J}_1}}, lsl #8", f"orr {{X:p{J}_1}}, {{X:h{J}_2}}, {{X:h{J}_3}}, lsl #8"]


def word(J):
    return [f"orr {{X:q{J}}}, {{X:p{J}_0}}, {{X:p{J}_1}}, lsl #16", f"str {{W:q{J}}}, [{{X:d}}, #{4 * J}]"]


def steps16_packed(a, b, out, t):
    """steps16_packed(a, b) (asm/span_persp_arm.h): (b - a) / 16 truncated for u and v, packed."""
    du, dv, tt, u = (f"{t}du", f"{t}dv", f"{t}t", f"{t}u")
    return [f"sub {{W:{du}}}, {{W:{b}}}, {{W:{a}}}",
            f"lsr {{X:{tt}}}, {{X:{a}}}, #32",
            f"lsr {{X:{dv}}}, {{X:{b}}}, #32",
            f"asr {{W:{u}}}, {{W:{du}}}, #31",
            f"sub {{W:{dv}}}, {{W:{dv}}}, {{W:{tt}}}",
            f"add {{W:{du}}}, {{W:{du}}}, {{W:{u}}}, lsr #28",
            f"asr {{W:{tt}}}, {{W:{dv}}}, #31",
            f"sbfx {{X:{du}}}, {{X:{du}}}, #4, #28",
            f"add {{W:{dv}}}, {{W:{dv}}}, {{W:{tt}}}, lsr #28",
            f"asr {{W:{dv}}}, {{W:{dv}}}, #4",
            f"add {{X:{out}}}, {{X:{du}}}, {{X:{dv}}}, lsl #32"]


def start(uv, duv, t):
    """lin_start: c0 = uv, c1 = uv + duv, c2 = uv + 2 duv, c3 = c1 + 2 duv, e = 4 duv."""
    dd = f"{t}dd"
    return [f"add {{X:{dd}}}, {{X:{duv}}}, {{X:{duv}}}",
            f"mov {{X:c0}}, {{X:{uv}}}",
            f"add {{X:c1}}, {{X:{uv}}}, {{X:{duv}}}",
            f"add {{X:c2}}, {{X:{uv}}}, {{X:{dd}}}",
            f"add {{X:c3}}, {{X:c1}}, {{X:{dd}}}",
            f"add {{X:e}}, {{X:{dd}}}, {{X:{dd}}}"]


def stage(G):
    s = []
    if G == 0:  # the accumulators from the stack slots (kZrow, kUVrow): no vector copies
        s += ["ldr {Q:zi}, [sp]", "ldr {Q:ts4}, [sp, #16]", "ldr {Q:ts5}, [sp, #16]"]
    elif G == 1:  # run r + 1's steps (samples A, B)
        s += steps16_packed("nA", "nB", "bd", "ta")[:6]
    elif G == 2:
        s += ["fadd {V:pos45}.2d, {V:pp}.2d, {V:k32}.2d"]
    elif G == 3:
        s += steps16_packed("nA", "nB", "bd", "ta")[6:]
    elif G == 4:
        s += ["fmla {V:zi}.2d, {V:kZix}.2d, {V:pos45}.2d",
              "fmla {V:ts4}.2d, {V:kUVx}.2d, {V:pos45}.d[0]", "fmla {V:ts5}.2d, {V:kUVx}.2d, {V:pos45}.d[1]"]
    elif G == 5:  # run r + 2's steps (samples B, C)
        s += steps16_packed("nB", "nC", "ad", "tb")[:6]
    elif G == 6:
        s += ["fmaxnm {V:zi}.2d, {V:zi}.2d, {V:kMin}.2d"]
    elif G == 7:  # run r + 1's chains (after group 3)
        s += start("nA", "bd", "sa")
    elif G == 8:
        s += ["fdiv {V:z45}.2d, {V:kOne}.2d, {V:zi}.2d"]
    elif G == 9:
        s += steps16_packed("nB", "nC", "ad", "tb")[6:]
    elif G == 10:
        s += ["fadd {V:pp}.2d, {V:pp}.2d, {V:k16}.2d",
              "fmul {V:ts4}.2d, {V:ts4}.2d, {V:z45}.d[0]", "fmul {V:ts5}.2d, {V:ts5}.2d, {V:z45}.d[1]"]
    elif G == 12:
        s += ["fadd {V:pp}.2d, {V:pp}.2d, {V:k16}.2d",
              "fcvtzu {V:ts4}.2d, {V:ts4}.2d, #16", "fcvtzu {V:ts5}.2d, {V:ts5}.2d, #16"]
    elif G == 14:
        s += ["uqxtn {V:n45}.2s, {V:ts4}.2d", "uqxtn2 {V:n45}.4s, {V:ts5}.2d"]
    elif G == 15:  # the next pass's first run r + 2 (sample B; after group 7)
        s += start("nB", "ad", "sb")
    elif G == 16:
        s += ["umin {V:n45}.4s, {V:n45}.4s, {V:kMax4}.4s"]
    elif G == 18:
        s += ["mov {X:nA}, {X:nC}", "fmov {X:nB}, {D:n45}", "mov {X:nC}, {V:n45}.d[1]"]
    elif G == 19:
        s += ["add {X:d}, {X:d}, #32", "ldr {X:lim}, [sp, #32]", "cmp {X:d}, {X:lim}", "b.lo .Lloop"]
    return s


def build():
    for J in range(10):
        if J >= 3:
            E(2 * J, f"orr {{X:q{J - 3}}}, {{X:p{J - 3}_0}}, {{X:p{J - 3}_1}}, lsl #16")
        if J >= 2:
            E(2 * J, *pairs(J - 2))
        if J < 8:
            E(2 * J, *group(J, J in (3, 7)))
        E(2 * J, *stage(2 * J))
        if J < 8:
            m = madd(J)
            ld = loads(J - 1) if J >= 1 else []
            for i in range(4):
                E(2 * J, m[i])
                if ld:
                    E(2 * J, ld[i])
        elif J == 8:
            E(2 * J, *loads(7))
        if J >= 3:
            E(2 * J, f"str {{W:q{J - 3}}}, [{{X:d}}, #{4 * (J - 3)}]")
        if J == 9:
            E(2 * J, *word(7))
        if J != 9:
            E(2 * J + 1, *stage(2 * J + 1))
    E(19, *stage(19))
    return [t for _, t in body]


TOK = re.compile(r"\{([XWVDQ]):(\w+)\}")


def allocate(lines):
    first, lastuse = {}, {}
    for i, l in enumerate(lines):
        for _, n in TOK.findall(l):
            first.setdefault(n, i)
            lastuse[n] = i
    reg = {}
    for n in first:
        if n in PIN:
            reg[n] = PIN[n]
    pinned = set(PIN.values())
    free_at = {}
    alltok = TOK.findall("".join(lines))
    names = sorted((n for n in first if n not in PIN), key=lambda n: first[n])
    for n in names:
        kind = "v" if any(k in "VDQ" for k, m in alltok if m == n) else "x"
        pool = VEC if kind == "v" else GPR
        for r in pool:
            if r in pinned:
                continue
            if free_at.get(r, -1) < first[n]:
                reg[n] = r
                free_at[r] = lastuse[n]
                break
        else:
            raise SystemExit(f"out of {kind} registers for {n} at line {first[n]}: {lines[first[n]]}")

    def sub(m):
        k, n = m.group(1), m.group(2)
        return {"X": "x", "W": "w", "V": "v", "D": "d", "Q": "q"}[k] + reg[n][1:]
    return [TOK.sub(sub, l) for l in lines], reg


HEADER = """// asm/span_persp_a64lin_pass.h: aarch64 only, persp_fast's linear long spans (n > 64 pixels,
// dzi == 0 or second order off): the head (samples 0 .. 3, run 0's steps) and the passes (two
// 16-pixel runs a pass, while more than 48 pixels are left) as one asm statement with fixed
// registers: the drawing (asm/span_persp_arm.h's lin_slot pipeline, four chains) and the
// stage work of the passes (steps16_packed of runs r + 1, r + 2; samples r + 4, r + 5), each
// operation the scalar code's (the same bits). Generated by bench/mca_a53_persp/gen_lin_pass.py
// from %(src)s (the loop body) and lin_long_setup.s (the set-up), both in orders from
// bench/order_search.py (llvm-mca Cortex-A53, then Cortex-A57): do not edit the asm by hand.
// Internal: included by asm/span_persp_fast.cpp after span_persp_run.h.
//
// Contract (lin_passes(st, p, n)): the span p of n > 64 pixels at st.d; st.tx, st.w the texels
// and their row length (read; unchanged). The set-up loads p's fields and computes, as
// persp_fast's head does lane by lane: positions [P + 16, P] (lane 1 is P + 0.0: only the
// depth reads it, where max(., kMinZi) removes a zero's sign) and + 32, depths 1 / max(zrow +
// zix pos, kMinZi) by two vector divides (fmla, fmaxnm, fdiv), each sample's [u, v] = (urow +
// ux pos, vrow + vx pos) z (fmla by element, fmul by element) converted by fcvtzu #16, uqxtn,
// umin with [umax, vmax] (to_fixed, see persp_fast), packed v 2^32 + u; run 0's steps by
// steps16_packed and its chains by lin_start; pp = [(P + 16) + 16, ((P + 16) + 16) + 16] (the
// walker's sums); lim = d + 32 k with k = (n - 49) / 32 the number of full passes (both
// sample offsets 32; the loop runs while d < lim) and offl = [min(l - 33, 32), l - 49] (l = n
// - 32 k in 49 .. 80) for the one pass after them, in which k32's register holds offl (k = 0:
// that pass alone). A pass draws runs r, r + 1 at d (run r from the chains c0 .. c3, e; run
// r + 1's set after its group 3 by lin_start(nA, steps16_packed(nA, nB))), computes samples
// r + 4, r + 5 at pos45 = pp + 32 (pp + offl) as the set-up does, pp + 16 twice, and sets run
// r + 2's chains (lin_start(nB, steps16_packed(nB, nC))). Outputs (r advanced past the
// passes, 17 .. 48 pixels left): d; c0 = sample r packed, c1 - c0 run r's packed step; nA,
// nB, nC samples r + 1, r + 2, r + 3 (clamped). Four stack slots of the caller's frame as memory operands (s0 kZrow, s16
// kUVrow, s32 lim, s48 offl). The loop starts at a 2 KiB boundary (the set-up branches over
// the padding): no 4 KiB page end falls in it, wherever the code before it ends.
#pragma once
#include "asm/span_persp_run.h"
#if defined(__aarch64__) && defined(__GNUC__)
#include <arm_neon.h>

#include <cstddef>

namespace sb::simd {
namespace {

struct LinPass {
  uint64_t d, tx, w, c0, c1, nA, nB, nC;
};
// The set-up's kMin, loaded inside the asm (adrp / ldr from this symbol, an "S" operand).
alignas(16) constexpr double kLinMin[2] = {kMinZi, kMinZi};
// PerspSpan's fields as the set-up loads them.
static_assert(offsetof(PerspSpan, zi0) == 0);
static_assert(offsetof(PerspSpan, dzi) == 8);
static_assert(offsetof(PerspSpan, uz0) == 16);
static_assert(offsetof(PerspSpan, duz) == 24);
static_assert(offsetof(PerspSpan, vz0) == 32);
static_assert(offsetof(PerspSpan, dvz) == 40);
static_assert(offsetof(PerspSpan, px0) == 48);
static_assert(offsetof(PerspSpan, umax) == 56);
static_assert(offsetof(PerspSpan, vmax) == 60);

// The set-up and the passes of the span p of n > 64 pixels at st.d; st's d (past the
// passes), c0 (sample r packed), c1 (c0 + run r's packed step), nA, nB, nC (samples r + 1 ..
// r + 3) written back.
inline __attribute__((always_inline)) void lin_passes(LinPass& st, const PerspSpan& p, int n) {
  float64x2_t s0, s16, s48;  // the asm's stack slots (kZrow, kUVrow, offl)
  uint64_t s32;  // lim
  register const PerspSpan* r_p __asm__("x4") = &p;
  register int r_n __asm__("x2") = n;
  register uint64_t r_d __asm__("x0") = st.d;
  register uint64_t r_c0 __asm__("x13");
  register uint64_t r_c1 __asm__("x14");
  register uint64_t r_nA __asm__("x25");
  register uint64_t r_nB __asm__("x26");
  register uint64_t r_nC __asm__("x27");
  register uint64_t r_tx __asm__("x23") = st.tx;
  register uint64_t r_w __asm__("x24") = st.w;
  __asm__ volatile(
%(body)s
      : "+r"(r_d), "+r"(r_p), "+r"(r_n), "=r"(r_c0), "=r"(r_c1), "=r"(r_nA), "=r"(r_nB), "=r"(r_nC),
        [s0] "=m"(s0), [s16] "=m"(s16), [s32] "=m"(s32), [s48] "=m"(s48)
      : "r"(r_tx), "r"(r_w), [kmin] "S"(kLinMin)
      : %(clob)s, "cc", "memory");
  st.d = r_d, st.c0 = r_c0, st.c1 = r_c1, st.nA = r_nA, st.nB = r_nB, st.nC = r_nC;
}

}  // namespace
}  // namespace sb::simd
#endif
"""

# The set-up before the loop (once a span): lin_long_setup.s (searched; see there).
SETUP_FILE = "lin_long_setup.s"


def emit_header(ins, outh):
    lines = [l.strip() for l in open(ins) if l.strip() and not l.strip().endswith(":")]
    lines = [l.replace("b.lo .Lloop", "b.lo 1b") for l in lines]
    # PAD never-run nops after the loop's last branch: lin_pairs_a64 (after persp_lin_a64) at
    # the page offset it had before this loop (0x550: its qemu cuts, persp64lin's figures), and
    # tiny_then_batch after it likewise. Follows persp_lin_a64's size (its tail's code).
    pad = [f".rept {PAD}", "nop", ".endr"] if PAD else []
    import os
    su = [l.strip() for l in open(os.path.join(os.path.dirname(os.path.abspath(__file__)), SETUP_FILE))
          if l.strip() and not l.strip().startswith("//")]
    allx = su + ["cbnz w10, 1f", f"ldr q{PIN['k32'][1:]}, [sp, #48]", "b 1f", ".p2align 11", "1:"] + lines + \
        ["b.ne 2f", f"ldr q{PIN['k32'][1:]}, [sp, #48]", "b 1b"] + pad + ["2:"]
    slots = {"[sp]": "%[s0]", "[sp, #16]": "%[s16]", "[sp, #32]": "%[s32]", "[sp, #48]": "%[s48]"}
    for k, v in slots.items():
        allx = [l.replace(k, v) for l in allx]
    allx = [l.replace("kLinMin", "%[kmin]") for l in allx]
    assert not any("sp" in re.sub(r"%\[s\d+\]", "", l) for l in allx)
    used = set()
    for l in allx:
        for m in re.finditer(r"\b([xwvqd])(\d+)\b", l):
            used.add(("v" if m.group(1) in "vqd" else "x") + m.group(2))
    opregs = {PIN[n] for n in ("d", "c0", "c1", "nA", "nB", "nC", "tx", "w")} | {"x4", "x2"}
    clob = [r for r in GPR + VEC if r in used and r not in opregs]
    rows, cur = [], []
    for l in allx:
        cur.append(l)
        if l.endswith(":") or len(cur) == 4:
            rows.append(cur)
            cur = []
    if cur:
        rows.append(cur)
    out = []
    for i, r in enumerate(rows):
        t = " ".join(f'"{l}\\n\\t"' for l in r)
        if i == len(rows) - 1:
            t = t[:-5] + '"'
        out.append("      " + t)
    text = HEADER % dict(src="bench/mca_a53_persp/" + ins.split("/")[-1], body="\n".join(out),
                         clob=", ".join(f'"{c}"' for c in clob))
    open(outh, "w").write(text)


if __name__ == "__main__":
    if sys.argv[1] == "body":
        out, reg = allocate(build())
        sys.stderr.write("registers: " + " ".join(sorted(set(reg.values()))) + f"; {len(out)} lines\n")
        open(sys.argv[2], "w").write(".Lloop:\n" + "\n".join(out) + "\n")
    elif sys.argv[1] == "header":
        emit_header(sys.argv[2], sys.argv[3])
