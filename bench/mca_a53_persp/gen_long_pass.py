#!/usr/bin/env python3
# bench/mca_a53_persp/gen_long_pass.py: generates persp_fast's aarch64 second-order long-span
# pass (asm/span_persp_a64long.h): one loop iteration = two 16-pixel runs + the stage work
# (steps of runs r + 1, r + 2; samples r + 4, r + 5 with their divide), written with value
# names, registers allocated by a linear scan over the chosen order.
#
#   gen_long_pass.py body OUT.s          the body in its slot order (for order_search.py)
#   gen_long_pass.py header IN.s OUT.h   the header from a (searched) body (--setup: the
#        present form, with long_setup.s and the folded last pass: the header is made by
#        gen_long_pass.py header long_pass_ru.s ../../asm/span_persp_a64long.h --setup; long_pass_ru.s
#        is the searched REUSE_V body with the u deltas kept too, see REUSE_U)
# The body's last line is the loop branch; order_search keeps register, flag and store order.
import os, re, sys

# Loop-carried values and their registers (the C++ wrapper binds them).
PIN = dict(d="x0", tx="x23", w="x24", c0="x13", c1="x14", e0="x17", e1="x19", dd4="x20",
           nA="x25", nB="x26", nC="x27",
           kZix="v16", kUVx="v17", k16="v18", k32="v19", kOne="v20", kMin="v21", kMax4="v22",
           kZck="v23", pp="v24", z23="v26", cc="v27", pos45="v28", zsn="v29")
GPR = ["x%d" % i for i in list(range(0, 18)) + list(range(19, 29)) + [30, 18]]
VEC = ["v%d" % i for i in range(32)]

body = []   # (slot G, text)
REUSE_V = False  # the v deltas computed once (G1, 64-bit) for the conversions and the steps
REUSE_U = False  # the u deltas likewise (G1, 32-bit; sign-extended for the steps)
# (REUSE_U does not fit the registers in slot order. long_pass_ru.s has it applied by hand to
# long_pass_rv.s's searched body: each run's G1 delta written to x30 / x18, free over that
# order from G1 to the steps' sxtw, the second sub gone; then searched again, see README.md.)
FOLD_LAST = "--fold-last" in sys.argv  # header: the last pass by the loop body, not a copy


def E(g, *lines):
    for l in lines:
        body.append((g, l))


def group(J, ca, cb, ea, eb, ddv, last):
    """Shifts and chain steps of pixel group J (4 pixels) from chains ca (pixel k), cb (k + 1)."""
    h = ["{X:h%d_%d}" % (J, i) for i in range(4)]
    l = ["{W:l%d_%d}" % (J, i) for i in range(4)]
    out = [f"lsr {h[0]}, {{X:{ca}}}, #48", f"lsr {l[0]}, {{W:{ca}}}, #16",
           f"lsr {h[1]}, {{X:{cb}}}, #48", f"lsr {l[1]}, {{W:{cb}}}, #16",
           f"add {{X:{ca}}}, {{X:{ca}}}, {{X:{ea}}}", f"add {{X:{cb}}}, {{X:{cb}}}, {{X:{eb}}}",
           f"add {{X:{ea}}}, {{X:{ea}}}, {{X:{ddv}}}", f"add {{X:{eb}}}, {{X:{eb}}}, {{X:{ddv}}}",
           f"lsr {h[2]}, {{X:{ca}}}, #48", f"lsr {l[2]}, {{W:{ca}}}, #16",
           f"lsr {h[3]}, {{X:{cb}}}, #48", f"lsr {l[3]}, {{W:{cb}}}, #16"]
    if not last:
        out += [f"add {{X:{ca}}}, {{X:{ca}}}, {{X:{ea}}}", f"add {{X:{cb}}}, {{X:{cb}}}, {{X:{eb}}}",
                f"add {{X:{ea}}}, {{X:{ea}}}, {{X:{ddv}}}", f"add {{X:{eb}}}, {{X:{eb}}}, {{X:{ddv}}}"]
    return out


def madd(J):
    return [f"madd {{W:h{J}_{i}}}, {{W:h{J}_{i}}}, {{W:w}}, {{W:l{J}_{i}}}" for i in range(4)]


def loads(J):
    return [f"ldrb {{W:h{J}_{i}}}, [{{X:tx}}, {{W:h{J}_{i}}}, uxtw]" for i in range(4)]


def pairs(J):
    return [f"orr {{X:p{J}_0}}, {{X:h{J}_0}}, {{X:h{J}_1}}, lsl #8", f"orr {{X:p{J}_1}}, {{X:h{J}_2}}, {{X:h{J}_3}}, lsl #8"]


def word(J):
    return [f"orr {{X:q{J}}}, {{X:p{J}_0}}, {{X:p{J}_1}}, lsl #16", f"str {{W:q{J}}}, [{{X:d}}, #{4 * J}]"]


def steps(delta, dd, dout, ddout, t):
    """steps16_dd(delta, dd): delta sign-extended in an x register (|delta| < 2^31), dd an
    int32 in a w register. Accept iff 120 |dd| <= |delta| (steps16_dd's test, the form proved
    in asm/span_persp_run.h); d = trunc((delta - 120 dd') / 16), dd' = dd accepted, else 0
    (|delta - 120 dd'| <= 2 |delta|: 64-bit). dout: d, 64-bit; ddout: dd' in a w register."""
    y, pd, s, x, u = (f"{t}y", f"{t}pd", f"{t}s", f"{t}x", f"{t}u")
    return [f"sbfiz {{X:{y}}}, {{X:{dd}}}, #7, #32",
            f"sub {{X:{y}}}, {{X:{y}}}, {{W:{dd}}}, sxtw #3",          # 120 dd, 64-bit
            f"cmp {{X:{delta}}}, #0",
            f"cneg {{X:{pd}}}, {{X:{delta}}}, lt",                      # |delta|
            f"add {{X:{s}}}, {{X:{y}}}, {{X:{pd}}}",                    # 120 dd + |delta|
            f"cmp {{X:{s}}}, {{X:{pd}}}, lsl #1",                       # <= 2 |delta| unsigned
            f"csel {{W:{ddout}}}, {{W:{dd}}}, wzr, ls",
            f"csel {{X:{y}}}, {{X:{y}}}, xzr, ls",
            f"sub {{X:{x}}}, {{X:{delta}}}, {{X:{y}}}",
            f"asr {{X:{u}}}, {{X:{x}}}, #63",
            f"add {{X:{x}}}, {{X:{x}}}, {{X:{u}}}, lsr #60",
            f"asr {{X:{dout}}}, {{X:{x}}}, #4"]


def start(uv, dpk, ddpk, c1, e0, e1, dd4):
    """lin_start2 from packed d, dd (c0 = uv itself)."""
    return [f"add {{X:{c1}}}, {{X:{uv}}}, {{X:{dpk}}}",
            f"add {{X:{e0}}}, {{X:{ddpk}}}, {{X:{dpk}}}, lsl #1",
            f"add {{X:{e1}}}, {{X:{e0}}}, {{X:{ddpk}}}, lsl #1",
            f"lsl {{X:{dd4}}}, {{X:{ddpk}}}, #2"]


def pack(du, dv, ddu, ddv, dpk, ddpk):
    return [f"add {{X:{dpk}}}, {{X:{du}}}, {{X:{dv}}}, lsl #32",
            f"lsl {{X:{ddpk}}}, {{X:{ddv}}}, #32",
            f"add {{X:{ddpk}}}, {{X:{ddpk}}}, {{W:{ddu}}}, sxtw"]


def stage(G):
    s = []
    if G == 0:
        s += ["ldr {Q:zi}, [sp]", "ldr {Q:ts4}, [sp, #16]", "ldr {Q:ts5}, [sp, #16]"]
    elif G == 1:  # the deltas of runs r + 1 (samples A, B) and r + 2 (B, C)
        if REUSE_V:  # the v deltas 64-bit (exact), kept for the steps (G7, G11)
            s += ["sub {W:fdu1}, {W:nB}, {W:nA}", "sub {W:fdu2}, {W:nC}, {W:nB}",
                  "lsr {X:ftvB}, {X:nB}, #32", "lsr {X:ftvC}, {X:nC}, #32",
                  "sub {X:fdv1}, {X:ftvB}, {X:nA}, lsr #32", "sub {X:fdv2}, {X:ftvC}, {X:nB}, lsr #32"]
        else:
            s += ["sub {W:fdu1}, {W:nB}, {W:nA}", "sub {W:fdu2}, {W:nC}, {W:nB}",
                  "lsr {X:ftvA}, {X:nA}, #32", "lsr {X:ftvB}, {X:nB}, #32", "lsr {X:ftvC}, {X:nC}, #32",
                  "sub {W:fdv1}, {W:ftvB}, {W:ftvA}", "sub {W:fdv2}, {W:ftvC}, {W:ftvB}"]
    elif G == 2:
        s += ["fadd {V:pos45}.2d, {V:pp}.2d, {V:k32}.2d",
              "scvtf {D:fu1}, {W:fdu1}", "scvtf {D:fv1}, {W:fdv1}", "scvtf {D:fu2}, {W:fdu2}", "scvtf {D:fv2}, {W:fdv2}"]
    elif G == 4:
        s += ["fmul {D:fu1}, {D:fu1}, {V:cc}.d[0]", "fmul {D:fv1}, {D:fv1}, {V:cc}.d[0]",
              "fmul {D:fu2}, {D:fu2}, {V:cc}.d[1]", "fmul {D:fv2}, {D:fv2}, {V:cc}.d[1]",
              "fmla {V:zi}.2d, {V:kZix}.2d, {V:pos45}.2d",
              "fmla {V:ts4}.2d, {V:kUVx}.2d, {V:pos45}.d[0]", "fmla {V:ts5}.2d, {V:kUVx}.2d, {V:pos45}.d[1]"]
    elif G == 6:
        s += ["fcvtzs {W:iu1}, {D:fu1}", "fcvtzs {W:iv1}, {D:fv1}", "fmaxnm {V:zi}.2d, {V:zi}.2d, {V:kMin}.2d"]
    elif G == 7:  # run r + 1's steps, its chains (run b: c0 = nA itself)
        s += ["sxtw {X:du1}, {W:fdu1}"] if REUSE_U else ["sub {W:du1}, {W:nB}, {W:nA}", "sxtw {X:du1}, {W:du1}"]
        if not REUSE_V:
            s += ["lsr {X:tvB}, {X:nB}, #32", "sub {X:dv1}, {X:tvB}, {X:nA}, lsr #32"]
        s += steps("du1", "iu1", "su1", "sdu1", "ta") + steps("fdv1" if REUSE_V else "dv1", "iv1", "sv1", "sdv1", "tb")
        s += pack("su1", "sv1", "sdu1", "sdv1", "bd", "bdd")
        s += start("nA", "bd", "bdd", "c1", "e0", "e1", "dd4")
    elif G == 8:
        s += ["fcvtzs {W:iu2}, {D:fu2}", "fcvtzs {W:iv2}, {D:fv2}", "fdiv {V:z45}.2d, {V:kOne}.2d, {V:zi}.2d"]
    elif G == 9:
        s += ["sxtw {X:du2}, {W:fdu2}"] if REUSE_U else ["sub {W:du2}, {W:nC}, {W:nB}", "sxtw {X:du2}, {W:du2}"]
        s += steps("du2", "iu2", "su2", "sdu2", "tc")
    elif G == 10:
        s += ["fadd {V:pp}.2d, {V:pp}.2d, {V:k16}.2d",
              "fmul {V:ts4}.2d, {V:ts4}.2d, {V:z45}.d[0]", "fmul {V:ts5}.2d, {V:ts5}.2d, {V:z45}.d[1]"]
    elif G == 11:
        if REUSE_V:
            s += steps("fdv2", "iv2", "sv2", "sdv2", "td")
        else:
            s += ["lsr {X:tvC}, {X:nC}, #32", "sub {X:dv2}, {X:tvC}, {X:nB}, lsr #32"]
            s += steps("dv2", "iv2", "sv2", "sdv2", "td")
    elif G == 12:
        s += ["fadd {V:pp}.2d, {V:pp}.2d, {V:k16}.2d",
              "fcvtzu {V:ts4}.2d, {V:ts4}.2d, #16", "fcvtzu {V:ts5}.2d, {V:ts5}.2d, #16",
              "ext {V:zsn}.16b, {V:z23}.16b, {V:z45}.16b, #8"]
    elif G == 13:
        s += pack("su2", "sv2", "sdu2", "sdv2", "ad", "add")
    elif G == 14:
        s += ["uqxtn {V:n45}.2s, {V:ts4}.2d", "fadd {V:zsn2}.2d, {V:zsn}.2d, {V:z45}.2d", "uqxtn2 {V:n45}.4s, {V:ts5}.2d"]
    elif G == 15:  # the next pass's first run r + 2 (sample B)
        s += ["mov {X:c0}, {X:nB}"] + start("nB", "ad", "add", "c1", "e0", "e1", "dd4")
    elif G == 16:
        s += ["umin {V:n45}.4s, {V:n45}.4s, {V:kMax4}.4s", "fmul {V:cc}.2d, {V:zsn2}.2d, {V:kZck}.d[0]",
              "mov {V:z23}.16b, {V:z45}.16b"]
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
        if J < 4:
            E(2 * J, *group(J, "c0", "c1", "e0", "e1", "dd4", J == 3))
        elif J < 8:
            E(2 * J, *group(J, "nA", "c1", "e0", "e1", "dd4", J == 7))
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
    free_at = {}  # register -> index after which it is free
    names = sorted((n for n in first if n not in PIN), key=lambda n: first[n])
    for n in names:
        kind = "v" if any(k in "VDQ" for k, m in TOK.findall("".join(lines)) if m == n) else "x"
        pool = VEC if kind == "v" else GPR
        for r in pool:
            if r in pinned:
                continue
            if free_at.get(r, -1) < first[n]:
                reg[n] = r
                free_at[r] = lastuse[n]
                break
        else:
            live = [m for m in reg if m not in PIN and first[m] <= first[n] <= lastuse[m]]
            raise SystemExit(f"out of {kind} registers for {n} at line {first[n]}: {lines[first[n]]}; live {live}")
    def sub(m):
        k, n = m.group(1), m.group(2)
        num = reg[n][1:]
        return {"X": "x", "W": "w", "V": "v", "D": "d", "Q": "q"}[k] + num
    return [TOK.sub(sub, l) for l in lines], reg


if __name__ == "__main__":
    if sys.argv[1] == "body":
        out, reg = allocate(build())
        used = sorted(set(reg.values()))
        sys.stderr.write("registers: " + " ".join(used) + "\n")
        open(sys.argv[2], "w").write(".Lloop:\n" + "\n".join(out) + "\n")


# The state block the asm loads on entry and stores back on exit (fewer than 30 asm operands):
# 64-bit fields first, then 16-byte ones; the header static_asserts every offset.
X_FIELDS = ["d", "tx", "w", "lim", "c0", "c1", "e0", "e1", "dd4", "nA", "nB", "nC"]
V_FIELDS = ["kZrow", "kUVrow", "kZix", "kUVx", "k16", "k32", "kOne", "kMin", "kZck", "kMax4",
            "offl", "pp", "z23", "cc", "pos45", "zsn"]
OUT_X = ["d", "c0", "c1", "e0", "e1", "dd4", "nA", "nB", "nC"]
OUT_V = ["pp", "z23", "cc", "pos45", "zsn"]
OFF = {n: 8 * i for i, n in enumerate(X_FIELDS)}
OFF.update({n: 8 * len(X_FIELDS) + 16 * i for i, n in enumerate(V_FIELDS)})

HEADER = """// asm/span_persp_a64long.h: aarch64 only, persp_fast's second-order long-span passes (two
// 16-pixel runs a pass, while more than 48 pixels are left) as one asm loop with fixed
// registers: the drawing (asm/span_persp_arm.h's lin_slot pipeline) and the stage work of
// persp_fast's vector loop (steps of runs r + 1, r + 2; samples r + 4, r + 5), each operation
// that loop's (the same bits). Generated by bench/mca_a53_persp/gen_long_pass.py (order from
// bench/order_search.py, scored by llvm-mca Cortex-A53 then Cortex-A57): do not
// edit the asm by hand. Internal: included by asm/span_persp_fast.cpp after span_persp_run.h.
//
// Contract (long_passes2, state in LongPass, read on entry and written back on exit): pass k
// = 0 draws runs r, r + 1 at d, 32 pixels a pass:
//   c0, c1, e0, e1, dd4   run r's chains (lin_start2 of its packed start, step and second step);
//   nA, nB, nC            samples r + 1, r + 2, r + 3 packed (v 2^32 + u, clamped to [0, max]);
//   pp = [P_{r+2}, P_{r+2} + 16] (doubles); z23 = [z_{r+2}, z_{r+3}];
//   cc = zck (z_{r+1} + z_{r+2}, z_{r+2} + z_{r+3}) with zck = zc * -1/16 (steps16_sel's ddf =
//        delta cc, see persp_fast); lim = d + 32 k with k >= 1 the number of full passes (left
//        >= 81: both sample offsets 32; the loop runs while d < lim), offl = [min(left' - 33,
//        32), min(left' - 49, 32)] for the one pass after them (left' = left - 32 k in 49 .. 80);
//        tx, w the texels and their row length; constants kZrow =
//        [zrow, zrow], kZix, kUVrow = [urow, vrow], kUVx = [ux, vx], k16, k32, kOne, kMin =
//        [kMinZi, kMinZi], kMax4 = [umax, vmax, umax, vmax] (uint32), kZck = [zck, zck].
// A pass: samples r + 4, r + 5 at pos45 = pp + 32 (the last pass: pp + offl), zi = max(zrow + zix pos, kMinZi)
// (fmla, fmaxnm), z = 1 / zi (fdiv), [u, v] = (uvrow + uvx pos) z converted by fcvtzu #16,
// uqxtn, umin (to_fixed, see persp_fast); the steps of runs r + 1, r + 2 from the packed
// samples: dd = fcvtzs(double(delta) c) and steps16_dd's test as 120 |dd| <= |delta| (the
// equivalent form proved in asm/span_persp_run.h), d = trunc((delta - 120 dd') / 16) with dd'
// = dd accepted, else 0 (the same d: delta - 120 dd' has delta's sign or is 0). On exit the
// state names the next pass's (r advanced by 2): c0 = sample r packed, c1 - c0 its run's
// packed step, dd4 4 times its packed second step, nA sample r + 1, zsn[0] = z_{r+1}, z23 =
// [z_{r+2}, z_{r+3}], pos45 = [pos_{r+2}, pos_{r+3}]. Uses 64 bytes below sp.
#pragma once
#include "asm/span_persp_run.h"
#if defined(__aarch64__) && defined(__GNUC__)
#include <arm_neon.h>

#include <cstddef>

namespace sb::simd {
namespace {

struct alignas(16) LongPass {
  uint64_t %(xfields)s;
  float64x2_t %(vfields)s;
  uint32x4_t kMax4;
  float64x2_t %(sfields)s;
};
%(asserts)s

inline __attribute__((always_inline)) void long_passes2(LongPass& st) {
  register LongPass* r_st __asm__("x0") = &st;
  __asm__ volatile(
%(body)s
      : "+r"(r_st)
      :
      : %(clob)s, "cc", "memory");
}

}  // namespace
}  // namespace sb::simd
#endif
"""


def emit_header(ins, outh):
    lines = [l.strip() for l in open(ins) if l.strip() and not l.strip().endswith(":")]
    lines = [l.replace("b.lo .Lloop", "b.lo 1b") for l in lines]
    pro = ["sub sp, sp, #64", "str x0, [sp, #40]",
           f"ldr q0, [x0, #{OFF['kZrow']}]", f"ldr q1, [x0, #{OFF['kUVrow']}]", f"ldr x1, [x0, #{OFF['lim']}]",
           f"ldr q2, [x0, #{OFF['offl']}]",
           "str q0, [sp]", "str q1, [sp, #16]", "str x1, [sp, #32]", "str q2, [sp, #48]"]
    for n in X_FIELDS:
        if n in PIN and n != "d":
            pro.append(f"ldr {PIN[n]}, [x0, #{OFF[n]}]")
    for n in V_FIELDS:
        if n in PIN:
            pro.append(f"ldr q{PIN[n][1:]}, [x0, #{OFF[n]}]")
    pro.append(f"ldr x0, [x0, #{OFF['d']}]")
    epi = ["ldr x1, [sp, #40]"]
    for n in OUT_X:
        epi.append(f"str {PIN[n]}, [x1, #{OFF[n]}]")
    for n in OUT_V:
        epi.append(f"str q{PIN[n][1:]}, [x1, #{OFF[n]}]")
    epi += ["mov x0, x1", "add sp, sp, #64"]
    # the last pass: the full one with pos45 = pp + offl, no loop branch
    last = []
    for l in lines[:-1]:
        m = re.fullmatch(r"fadd (v\d+)\.2d, (v\d+)\.2d, v%s\.2d" % PIN["k32"][1:], l)
        if m and m.group(1) == PIN["pos45"]:
            last += ["ldr q30, [sp, #48]", f"fadd {m.group(1)}.2d, {m.group(2)}.2d, v30.2d"]
        else:
            last.append(l)
    assert len(last) == len(lines)
    if FOLD_LAST:
        # the last pass is the loop body once more with k32's register reloaded with offl:
        # leaving the loop with d == lim (full passes done) branches back; d > lim: done
        allx = pro + ["1:"] + lines + ["b.ne 2f", f"ldr q{PIN['k32'][1:]}, [sp, #48]", "b 1b", "2:"] + epi
    else:
        allx = pro + ["1:"] + lines + last + epi
    used = set()
    for l in allx:
        for m in re.finditer(r"\b([xwvqd])(\d+)\b", l):
            used.add(("v" if m.group(1) in "vqd" else "x") + m.group(2))
    clob = [r for r in GPR + VEC if r in used and r != "x0"]
    # four instructions a source line (every file stays under 1000 lines)
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
    body = "\n".join(out)
    asserts = "\n".join(f"static_assert(offsetof(LongPass, {n}) == {OFF[n]});" for n in X_FIELDS + V_FIELDS)
    vf = V_FIELDS[:V_FIELDS.index("kMax4")]
    sf = V_FIELDS[V_FIELDS.index("kMax4") + 1:]
    text = HEADER % dict(xfields=", ".join(X_FIELDS), vfields=", ".join(vf), sfields=", ".join(sf), asserts=asserts,
                         body=body, clob=", ".join(f'"{c}"' for c in clob))
    open(outh, "w").write(text)


# REGIO (--regio): the state the C++ code reads back after the loop and the read-only
# constants passed in the loop's registers (asm operands bound to them; GCC allows 30
# operands, an in-out one counts twice), the rest in a small block (LongIn) at x1 that the
# prologue loads: e0, e1, pp, cc, pos45, k32 into their registers, kZrow, kUVrow, lim, offl
# to the 64 bytes below sp the loop reads. Nothing is stored back.
REGIO = "--regio" in sys.argv
IO_X = ["d", "c0", "c1", "dd4", "nA", "nB", "nC"]
IO_V = ["z23", "zsn"]
IN_X = ["tx", "w"]
IN_V = ["kZix", "kUVx", "k16", "kOne", "kMin", "kMax4", "kZck"]
BLK_X = ["e0", "e1", "lim", "pad"]
BLK_V = ["pp", "cc", "pos45", "k32", "kZrow", "kUVrow", "offl"]
BOFF = {n: 8 * i for i, n in enumerate(BLK_X)}
BOFF.update({n: 8 * len(BLK_X) + 16 * i for i, n in enumerate(BLK_V)})

HEADER2 = """// asm/span_persp_a64long.h: aarch64 only, persp_fast's second-order long-span passes (two
// 16-pixel runs a pass, while more than 48 pixels are left) as one asm loop with fixed
// registers: the drawing (asm/span_persp_arm.h's lin_slot pipeline) and the stage work of
// persp_fast's vector loop (steps of runs r + 1, r + 2; samples r + 4, r + 5), each operation
// that loop's (the same bits). Generated by bench/mca_a53_persp/gen_long_pass.py (order from
// bench/order_search.py, scored by llvm-mca Cortex-A53 then Cortex-A57): do not
// edit the asm by hand. Internal: included by asm/span_persp_fast.cpp after span_persp_run.h.
//
// Contract (long_passes2, state in LongPass: read on entry; d, c0, c1, dd4, nA, nB, nC, z23,
// zsn written back on exit, the other fields' exit values are not): pass k
// = 0 draws runs r, r + 1 at d, 32 pixels a pass:
//   c0, c1, e0, e1, dd4   run r's chains (lin_start2 of its packed start, step and second step);
//   nA, nB, nC            samples r + 1, r + 2, r + 3 packed (v 2^32 + u, clamped to [0, max]);
//   pp = [P_{r+2}, P_{r+2} + 16] (doubles); z23 = [z_{r+2}, z_{r+3}];
//   cc = zck (z_{r+1} + z_{r+2}, z_{r+2} + z_{r+3}) with zck = zc * -1/16 (steps16_sel's ddf =
//        delta cc, see persp_fast); lim = d + 32 k with k >= 1 the number of full passes (left
//        >= 81: both sample offsets 32; the loop runs while d < lim), offl = [min(left' - 33,
//        32), min(left' - 49, 32)] for the one pass after them (left' = left - 32 k in 49 .. 80);
//        tx, w the texels and their row length; constants kZrow =
//        [zrow, zrow], kZix, kUVrow = [urow, vrow], kUVx = [ux, vx], k16, k32, kOne, kMin =
//        [kMinZi, kMinZi], kMax4 = [umax, vmax, umax, vmax] (uint32), kZck = [zck, zck].
// A pass: samples r + 4, r + 5 at pos45 = pp + 32 (the last pass: pp + offl), zi = max(zrow + zix pos, kMinZi)
// (fmla, fmaxnm), z = 1 / zi (fdiv), [u, v] = (uvrow + uvx pos) z converted by fcvtzu #16,
// uqxtn, umin (to_fixed, see persp_fast); the steps of runs r + 1, r + 2 from the packed
// samples: dd = fcvtzs(double(delta) c) and steps16_dd's test as 120 |dd| <= |delta| (the
// equivalent form proved in asm/span_persp_run.h), d = trunc((delta - 120 dd') / 16) with dd'
// = dd accepted, else 0 (the same d: delta - 120 dd' has delta's sign or is 0). The last pass
// is the loop body once more, k32's register then holding offl. On exit the
// state names the next pass's (r advanced by 2): c0 = sample r packed, c1 - c0 its run's
// packed step, dd4 4 times its packed second step, nA sample r + 1, zsn[0] = z_{r+1}, z23 =
// [z_{r+2}, z_{r+3}]. The state reaches the asm in the loop's registers (operands) but for
// LongIn's fields, which its prologue loads. Uses 64 bytes below sp.
#pragma once
#include "asm/span_persp_run.h"
#if defined(__aarch64__) && defined(__GNUC__)
#include <arm_neon.h>

#include <cstddef>

namespace sb::simd {
namespace {

struct LongPass {
  uint64_t %(xfields)s;
  float64x2_t %(vfields)s;
  uint32x4_t kMax4;
  float64x2_t %(sfields)s;
};
// The fields the asm's prologue loads (offsets below are the asm's).
struct alignas(16) LongIn {
  uint64_t %(bx)s;
  float64x2_t %(bv)s;
};
%(asserts)s

inline __attribute__((always_inline)) void long_passes2(LongPass& st) {
  LongIn in;
%(fill)s
%(decls)s
  __asm__ volatile(
%(body)s
      : %(outs)s
      : %(ins)s
      : %(clob)s, "cc", "memory");
%(back)s
}

}  // namespace
}  // namespace sb::simd
#endif
"""


def emit_header2(ins, outh):
    lines = [l.strip() for l in open(ins) if l.strip() and not l.strip().endswith(":")]
    lines = [l.replace("b.lo .Lloop", "b.lo 1b") for l in lines]
    pro = ["sub sp, sp, #64",
           f"ldr q0, [x1, #{BOFF['kZrow']}]", f"ldr q1, [x1, #{BOFF['kUVrow']}]", f"ldr q2, [x1, #{BOFF['offl']}]"]
    pro += [f"ldp {PIN['e0']}, {PIN['e1']}, [x1, #{BOFF['e0']}]"]
    for n in ("pp", "cc", "pos45", "k32"):
        pro.append(f"ldr q{PIN[n][1:]}, [x1, #{BOFF[n]}]")
    pro += [f"ldr x1, [x1, #{BOFF['lim']}]", "str q0, [sp]", "str q1, [sp, #16]", "str x1, [sp, #32]", "str q2, [sp, #48]"]
    allx = pro + ["1:"] + lines + ["b.ne 2f", f"ldr q{PIN['k32'][1:]}, [sp, #48]", "b 1b", "2:", "add sp, sp, #64"]
    used = set()
    for l in allx:
        for m in re.finditer(r"\b([xwvqd])(\d+)\b", l):
            used.add(("v" if m.group(1) in "vqd" else "x") + m.group(2))
    opregs = {PIN[n] for n in IO_X + IO_V + IN_X + IN_V} | {"x1"}
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
    vty = lambda n: "uint32x4_t" if n == "kMax4" else "float64x2_t"
    fill = "\n".join(f"  in.{n} = st.{n};" for n in BLK_X + BLK_V if n != "pad") + "\n  in.pad = 0;"
    decls = ['  register LongIn* r_in __asm__("x1") = &in;']
    for n in IO_X + IN_X:
        decls.append(f'  register uint64_t r_{n} __asm__("{PIN[n]}") = st.{n};')
    for n in IO_V + IN_V:
        decls.append(f'  register {vty(n)} r_{n} __asm__("{PIN[n]}") = st.{n};')
    outs = [f'"+r"(r_{n})' for n in IO_X] + [f'"+w"(r_{n})' for n in IO_V] + ['"+r"(r_in)']
    insl = [f'"r"(r_{n})' for n in IN_X] + [f'"w"(r_{n})' for n in IN_V]
    back = "\n".join(f"  st.{n} = r_{n};" for n in IO_X + IO_V)
    vf = V_FIELDS[:V_FIELDS.index("kMax4")]
    sf = V_FIELDS[V_FIELDS.index("kMax4") + 1:]
    asserts = "\n".join(f"static_assert(offsetof(LongIn, {n}) == {BOFF[n]});" for n in BLK_X + BLK_V)
    text = HEADER2 % dict(xfields=", ".join(X_FIELDS), vfields=", ".join(vf), sfields=", ".join(sf),
                          bx=", ".join(BLK_X), bv=", ".join(BLK_V), asserts=asserts, fill=fill,
                          decls="\n".join(decls), body="\n".join(out), outs=", ".join(outs), ins=", ".join(insl),
                          back=back, clob=", ".join(f'"{c}"' for c in clob))
    open(outh, "w").write(text)


# SETUP (--setup): the set-up of the first samples and run 0's steps in the asm too
# (long_setup.s, before the loop), from the LongIn block at x1 and the constants' registers;
# outputs the state the C++ code reads after the loop. Implies the folded last pass.
SETUP = "--setup" in sys.argv
S_OUT_X = ["c0", "c1", "dd4", "nA", "nB", "nC"]
S_OUT_V = ["z23", "zsn", "cc"]  # cc: run r + 1's ddf factor for the tail (cc[0])
S_IN_X = ["tx", "w"]
S_IN_V = []  # kMin: the set-up loads it (kLongMin, an "S" operand: no load in the head)
# PerspSpan's fields the set-up loads (offsets as long_setup.s takes them)
S_P = [("zi0", 0), ("dzi", 8), ("uz0", 16), ("duz", 24), ("vz0", 32), ("dvz", 40), ("px0", 48), ("umax", 56), ("vmax", 60)]

HEADER3 = """// asm/span_persp_a64long.h: aarch64 only, persp_fast's second-order long-span passes (two
// 16-pixel runs a pass, while more than 48 pixels are left) as one asm loop with fixed
// registers: the drawing (asm/span_persp_arm.h's lin_slot pipeline) and the stage work of
// persp_fast's vector loop (steps of runs r + 1, r + 2; samples r + 4, r + 5), each operation
// that loop's (the same bits), after a set-up block (the first four samples, run 0's steps).
// Generated by bench/mca_a53_persp/gen_long_pass.py (order from bench/order_search.py, scored
// by llvm-mca Cortex-A53 then Cortex-A57; the loop body from long_pass_ru.s, the set-up from
// long_setup.s there): do not edit the asm by hand. Internal: included by
// asm/span_persp_fast.cpp after span_persp_run.h.
//
// Contract (long_passes2(st, p, n); LongPass's inputs read on entry, its outputs written on
// exit): the span p of n > 64 pixels, inputs d (dest), tx, w (the texels and their row length);
// kMin = [kMinZi, kMinZi] (kLongMin); with zrow = p.zi0, zix = p.dzi (= zc), [urow, vrow], [ux, vx] (p's
// uz0, vz0, duz, dvz), P = p.px0, lim = d + 32 k with k = (n - 49) / 32 the number of full
// passes (left >= 81: both sample offsets 32; the loop runs while d < lim; k = 0 for n = 65 ..
// 80: the set-up's branch enters the loop at the last pass), offl = [min(left' - 33, 32),
// min(left' - 49, 32)] for the one pass after them (left' = n - 32 k in 49 .. 80), [umax,
// vmax] p's clamps, zck = zc * -1/16 (as the set-up computes them).
// The set-up: positions P_0 = P, P_1 = P + 16, P_j + 32
// for samples 2, 3, depths 1 / max(zrow + zix pos, kMinZi) (fmla, fmaxnm, fdiv), each sample's
// [u, v] = (uvrow + uvx pos) z converted by fcvtzu #16, uqxtn, umin (to_fixed, see
// persp_fast), packed v 2^32 + u; run 0's steps as the loop takes a run's (below), with cc =
// zck (z_0 + z_1); its chains by lin_start2. Pass k = 0 then draws runs r, r + 1 at d, 32
// pixels a pass, with the state
//   c0, c1, e0, e1, dd4   run r's chains (lin_start2 of its packed start, step and second step);
//   nA, nB, nC            samples r + 1, r + 2, r + 3 packed (v 2^32 + u, clamped to [0, max]);
//   pp = [P_{r+2}, P_{r+2} + 16] (doubles); z23 = [z_{r+2}, z_{r+3}];
//   cc = zck (z_{r+1} + z_{r+2}, z_{r+2} + z_{r+3}) (steps16_sel's ddf = delta cc, see
//        persp_fast).
// A pass: samples r + 4, r + 5 at pos45 = pp + 32 (the last pass: pp + offl), zi = max(zrow + zix pos, kMinZi)
// (fmla, fmaxnm), z = 1 / zi (fdiv), [u, v] = (uvrow + uvx pos) z converted by fcvtzu #16,
// uqxtn, umin (to_fixed, see persp_fast); the steps of runs r + 1, r + 2 from the packed
// samples: dd = fcvtzs(double(delta) c) and steps16_dd's test as 120 |dd| <= |delta| (the
// equivalent form proved in asm/span_persp_run.h), d = trunc((delta - 120 dd') / 16) with dd'
// = dd accepted, else 0 (the same d: delta - 120 dd' has delta's sign or is 0). The last pass
// is the loop body once more, k32's register then holding offl. Outputs (the next pass's
// state, r advanced by 2): d, c0 = sample r packed, c1 - c0 its run's packed step, dd4 4
// times its packed second step, nA, nB, nC samples r + 1 .. r + 3, zsn[0] = z_{r+1}, z23 =
// [z_{r+2}, z_{r+3}], cc as above (cc[0]: run r + 1's factor), tx and w as they came in.
// Operands in the loop's registers; four stack slots of the caller's frame as memory
// operands (s0 kZrow, s16 kUVrow, s32 lim, s48 offl).
// The loop starts at a 2 KiB boundary (the set-up branches over the padding).
#pragma once
#include "asm/span_persp_run.h"
#if defined(__aarch64__) && defined(__GNUC__)
#include <arm_neon.h>

#include <cstddef>

namespace sb::simd {
namespace {

struct LongPass {
  uint64_t d, tx, w, c0, c1, dd4, nA, nB, nC;
  float64x2_t z23, zsn, cc;
};
// The set-up's kMin, loaded inside the asm (adrp / ldr from this symbol, an "S" operand): the
// compiler's head before the asm no longer loads it (its adrp -> ldr delayed the set-up's loads).
alignas(16) constexpr double kLongMin[2] = {kMinZi, kMinZi};
// PerspSpan's fields as the set-up loads them.
%(asserts)s

inline __attribute__((always_inline)) void long_passes2(LongPass& st, const PerspSpan& p, int n) {
%(decls)s
  __asm__ volatile(
%(body)s
      : %(outs)s
      : %(ins)s
      : %(clob)s, "cc", "memory");
%(back)s
}

}  // namespace
}  // namespace sb::simd
#endif
"""


def emit_header3(ins, outh, setup):
    lines = [l.strip() for l in open(ins) if l.strip() and not l.strip().endswith(":")]
    lines = [l.replace("b.lo .Lloop", "b.lo 1b") for l in lines]
    su = [l.strip() for l in open(setup) if l.strip() and not l.strip().startswith("//")]
    # The loop at a 2 KiB boundary (its 1320 bytes then never cross a 4 KiB page, where qemu
    # would cut its blocks for bench/count.sh wherever the code before it ends), entered by a
    # branch over the padding (never run). A span of one pass only (full = 0 in x21, n = 65 ..
    # 80) falls through that branch (a cbnz, as the b it replaced one instruction for the
    # others) to k32 = offl, the last pass's, and enters the loop from there.
    # PAD never-run nops after the loop's last branch: the code after the loop (the tail, and
    # persp_lin_a64 and lin_pairs_a64 after persp_long_a64) at the addresses it had with the
    # 330-instruction body (REUSE_U took 2 out; persp192lin's A72 4.859 -> 4.879 by its qemu cuts).
    pad = ["nop"] * max(0, 330 - len(lines))
    allx = su + ["cbnz w21, 1f", f"ldr q{PIN['k32'][1:]}, [sp, #48]", "b 1f", ".p2align 11", "1:"] + lines + ["b.ne 2f", f"ldr q{PIN['k32'][1:]}, [sp, #48]", "b 1b"] + pad + ["2:"]
    # The four stack slots (the searched code's [sp], [sp, #16], [sp, #32], [sp, #48]) as memory
    # operands in the caller's frame: no sp adjustment (the first load after the asm used to
    # wait for its add sp).
    slots = {"[sp]": "%[s0]", "[sp, #16]": "%[s16]", "[sp, #32]": "%[s32]", "[sp, #48]": "%[s48]"}
    for k, v in slots.items():
        allx = [l.replace(k, v) for l in allx]
    allx = [l.replace("kLongMin", "%[kmin]") for l in allx]  # the set-up's kMin load (an "S" operand)
    assert not any("sp" in re.sub(r"%\[s\d+\]", "", l) for l in allx)
    used = set()
    for l in allx:
        for m in re.finditer(r"\b([xwvqd])(\d+)\b", l):
            used.add(("v" if m.group(1) in "vqd" else "x") + m.group(2))
    opregs = {PIN[n] for n in ["d"] + S_OUT_X + S_OUT_V + S_IN_X + S_IN_V} | {"x1", "x2"}
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
    vty = lambda n: "uint32x4_t" if n == "kMax4" else "float64x2_t"
    asserts = "\n".join(f"static_assert(offsetof(PerspSpan, {n}) == {o});" for n, o in S_P)
    blk = fill = ""
    decls = ["  float64x2_t s0, s16, s48;  // the asm's stack slots (kZrow, kUVrow, offl)", "  uint64_t s32;  // lim",
             '  register const PerspSpan* r_p __asm__("x1") = &p;', '  register int r_n __asm__("x2") = n;',
             f'  register uint64_t r_d __asm__("{PIN["d"]}") = st.d;']
    for n in S_OUT_X:
        decls.append(f'  register uint64_t r_{n} __asm__("{PIN[n]}");')
    for n in S_OUT_V:
        decls.append(f'  register float64x2_t r_{n} __asm__("{PIN[n]}");')
    for n in S_IN_X:
        decls.append(f'  register uint64_t r_{n} __asm__("{PIN[n]}") = st.{n};')
    for n in S_IN_V:
        decls.append(f'  register {vty(n)} r_{n} __asm__("{PIN[n]}") = st.{n};')
    # tx, w in-out (unchanged by the asm): the tail takes them from the asm's registers, not
    # from the compiler's stack copies (persp192 A53 9.06 -> 9.02).
    outs = (['"+r"(r_d)', '"+r"(r_p)', '"+r"(r_n)'] + [f'"=r"(r_{n})' for n in S_OUT_X] +
            [f'"=w"(r_{n})' for n in S_OUT_V] + [f'"+r"(r_{n})' for n in S_IN_X] +
            ['[s0] "=m"(s0)', '[s16] "=m"(s16)', '[s32] "=m"(s32)', '[s48] "=m"(s48)'])
    insl = [f'"w"(r_{n})' for n in S_IN_V] + ['[kmin] "S"(kLongMin)']
    back = "\n".join(f"  st.{n} = r_{n};" for n in ["d"] + S_OUT_X + S_OUT_V + S_IN_X)
    text = HEADER3 % dict(blk=blk, asserts=asserts, fill=fill, decls="\n".join(decls), body="\n".join(out),
                          outs=", ".join(outs), ins=", ".join(insl), back=back,
                          clob=", ".join(f'"{c}"' for c in clob))
    open(outh, "w").write(text)


if __name__ == "__main__" and sys.argv[1] == "header":
    if SETUP:
        emit_header3(sys.argv[2], sys.argv[3], os.path.join(os.path.dirname(os.path.abspath(__file__)), "long_setup.s"))
    else:
        (emit_header2 if REGIO else emit_header)(sys.argv[2], sys.argv[3])
