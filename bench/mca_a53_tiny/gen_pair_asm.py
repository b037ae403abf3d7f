#!/usr/bin/env python3
# bench/mca_a53_tiny/gen_pair_asm.py: the tiny pair loop's block (asm/span_persp_a64tiny.cpp,
# tiny_curve_run_a64) as one asm statement: this pair's steps (tiny_steps), the next pair's
# tests (tiny_curve_a64's, branchless) and its samples (tiny_samples<false>, speculative on
# b + 1, b + 2), in program order.
#
#   gen_pair_asm.py OUT.s          the block in program order, registers allocated least
#                                  recently freed first (v0 .. v28)
#   gen_pair_asm.py --vs OUT.vs    the same with virtual registers (input of ../mca_a53_pair/vsched.py --hard; then
#                                  bench/mca_a53_p64/alloc.py OUT.vs A.s `gen_pair_asm.py --pins` 0,..,28)
#   gen_pair_asm.py --embed IN.s NOTE > asm/span_persp_a64tiny_pair.h
#                                  the (searched) block as the header's asm statement
# How the committed order was made: bench/mca_a53_tiny/README.md (pair_asm_in.s -> pair_asm_s.s).
#
# Placeholders (operands of the asm statement): x1 a, x2 b (this pair's items), x3 end, x14
# &kTiny; out x4 xa, x5 xb (the next pair), x7 .. x12 pos_a, pos_b, d_a, d_b, dd_a, dd_b, w13
# fb (all ones iff the samples need the divide fallback); v29 s0, v30 s1, v31 c2 (this pair's
# in, the next pair's out). Scratch (clobbered): v0 .. v28, x15 .. x17, x19 .. x28.
import re, sys

CONST = {}
CARRY = {"s0": "v29", "s1": "v30", "c2": "v31"}
GPR = {"a": "x1", "b": "x2", "end": "x3", "xa": "x4", "xb": "x5",
       "kc": "x14", "posa": "x7", "posb": "x8", "da": "x9", "db": "x10", "dda": "x11", "ddb": "x12", "fb": "w13"}
ACC = ("fmla", "fmls", "bit", "ssra", "uqxtn2", "sqxtn2", "mls")

# Each line: text with {name} vector values (first one written unless a store; ldp writes two),
# [name] GPRs. N: suffixes are written in the text.
P = []
def I(s):
    P.append(s)

# ---- the rows of this pair (a, b) and the next pair's items (xa, xb) and rows ----
# Core scratch: x15 .. x17, x19 .. x26 (SCRATCH). Rows by n - 1: kc + 48 (n - 1) (fields at +48).
I("ldr w15, [[a], #8]")
I("ldr w16, [[b], #8]")
I("sub w15, w15, #1")
I("sub w16, w16, #1")
I("add x17, x15, x15, lsl #1")
I("add x19, x16, x16, lsl #1")
I("add x17, [kc], x17, lsl #4")   # rca - 48
I("add x19, [kc], x19, lsl #4")   # rcb - 48
# The next pair's samples are computed speculatively on ta = xa0 = b + 1 and tb = xb0 = b + 2
# (a when past end: safe pointers) whatever the tests say, their rows by (n - 1) mod 16 (inside
# kTiny for any n): the sample loads wait for no test. Unused when the tests say otherwise (the
# loop ends, or a lone span: b = a, lane 1 never drawn); a needless divide fallback at worst.
I("add x20, [b], #88")               # xa0
I("add x25, [b], #176")              # xb0
I("cmp x20, [end]")
I("csel x21, x20, [a], ne")          # ta
I("ccmp x25, [end], #4, ne")
I("csel x24, x25, [a], ne")          # tb
I("ldr w22, [x21, #8]")
I("ldr w23, [x24, #8]")
I("sub w22, w22, #1")
I("sub w23, w23, #1")
I("and w28, w22, #15")
I("and w27, w23, #15")
I("add x28, x28, x28, lsl #1")
I("add x27, x27, x27, lsl #1")
I("add x28, [kc], x28, lsl #4")      # ta's row - 48
I("add x27, [kc], x27, lsl #4")      # tb's row - 48
# more = xa0 != end and ta is a tiny item (tiny_curve_a64: n - 1 <= 15, second_order, dzi's
# bits << 1 != 0); xa = more ? xa0 : a. two = more, xb0 != end and tb tiny; xb = two ? xb0 : xa.
I("ldr x26, [x21, #24]")
I("ldrb w15, [x21, #80]")
I("tst x26, #0x7fffffffffffffff")
I("ccmp w15, #0, #4, ne")
I("ccmp w22, #15, #2, ne")
I("ccmp x20, [end], #4, ls")
I("csel [xa], x20, [a], ne")
I("ldr x26, [x24, #24]")
I("ldrb w16, [x24, #80]")
I("tst x26, #0x7fffffffffffffff")
I("ccmp w16, #0, #4, ne")
I("ccmp w23, #15, #2, ne")
I("ccmp x25, [end], #4, ls")
I("ccmp [xa], [a], #4, ne")          # and more (xa != a)
I("csel [xb], x25, [xa], ne")

# ---- this pair's steps (tiny_steps), cur = s0, s1, c2 + rows x17, x19 ----
I("ldp q{YA}, q{SA}, [x17, #48]")          # [off_a, y_a], [s_a, s2_a]
I("ldp q{YB}, q{SB}, [x19, #48]")
I("ldr q{KA}, [x17, #80]")            # [t2_a, k2_a]
I("ldr q{KB}, [x19, #80]")
I("ldp q{BIAS}, q{KMIN}, [[kc], #816]")  # kTiny.c (after its 17 rows)
I("ldp q{MASK}, q{BIG}, [[kc], #848]")
I("ldr q{C999}, [[kc], #880]")
I("movi {HI}.2d, #0xffffffff00000000")
I("movi {ONE4}.4s, #1")
I("sub {D}.4s, {s1}.4s, {s0}.4s")
I("fmov [posa], d{s0}")
I("mov [posb], {s0}.d[1]")
I("saddw {Da}.2d, {BIAS}.2d, {D}.2s")
I("saddw2 {Db}.2d, {BIAS}.2d, {D}.4s")
I("fsub {Da}.2d, {Da}.2d, {BIAS}.2d")
I("fsub {Db}.2d, {Db}.2d, {BIAS}.2d")
I("fmul {qa}.2d, {Da}.2d, {YA}.d[1]")
I("fmul {qb}.2d, {Db}.2d, {YB}.d[1]")
I("fmls {Da}.2d, {qa}.2d, {SA}.d[0]")
I("fmls {Db}.2d, {qb}.2d, {SB}.d[0]")
I("fmla {qa}.2d, {Da}.2d, {YA}.d[1]")
I("fmla {qb}.2d, {Db}.2d, {YB}.d[1]")
I("fmul {fa}.2d, {qa}.2d, {c2}.d[0]")
I("fmul {fb}.2d, {qb}.2d, {c2}.d[1]")
I("fcvtzs {La}.2d, {qa}.2d")
I("fcvtzs {Lb}.2d, {qb}.2d")
I("uzp1 {L}.4s, {La}.4s, {Lb}.4s")
I("fcvtzs {Fa}.2d, {fa}.2d")
I("fcvtzs {Fb}.2d, {fb}.2d")
I("sqxtn {DD}.2s, {Fa}.2d")
I("sqxtn2 {DD}.4s, {Fb}.2d")
I("cmlt {sg}.4s, {D}.4s, #0")
I("abs {pd}.4s, {D}.4s")
I("zip2 {kv}.2d, {KA}.2d, {KB}.2d")
I("zip1 {tv}.2d, {KA}.2d, {KB}.2d")
I("zip2 {sv}.2d, {SA}.2d, {SB}.2d")
I("eor {pdd}.16b, {DD}.16b, {sg}.16b")
I("sub {pdd}.4s, {pdd}.4s, {sg}.4s")
I("abs {add}.4s, {DD}.4s")
I("umin {mk}.4s, {add}.4s, {kv}.4s")
I("mul {mk}.4s, {mk}.4s, {tv}.4s")
I("cmhs {acc}.4s, {pd}.4s, {mk}.4s")
I("cmhi {big}.4s, {add}.4s, {C999}.4s")
I("bic {acc}.16b, {acc}.16b, {big}.16b")
I("eor {Q}.16b, {L}.16b, {sg}.16b")
I("sub {Q}.4s, {Q}.4s, {sg}.4s")
I("mul {sQ}.4s, {sv}.4s, {Q}.4s")
I("sub {rr}.4s, {pd}.4s, {sQ}.4s")
I("sub {sm1}.4s, {sv}.4s, {ONE4}.4s")
I("mul {m}.4s, {sm1}.4s, {pdd}.4s")
I("shl {rr}.4s, {rr}.4s, #1")
I("cmhi {c}.4s, {sv}.4s, {rr}.4s")
I("and {t}.16b, {m}.16b, {ONE4}.16b")
I("and {t}.16b, {t}.16b, {c}.16b")
I("ssra {t}.4s, {m}.4s, #1")
I("sub {d0}.4s, {Q}.4s, {t}.4s")
I("eor {dm}.16b, {d0}.16b, {sg}.16b")
I("sub {dm}.4s, {dm}.4s, {sg}.4s")
I("bit {L}.16b, {dm}.16b, {acc}.16b")
I("and {DD}.16b, {DD}.16b, {acc}.16b")
for v, a, b in (("L", "da", "db"), ("DD", "dda", "ddb")):
    I("and {pk%s}.16b, {%s}.16b, {HI}.16b" % (v, v))
    I("shl {sh%s}.2d, {%s}.2d, #32" % (v, v))
    I("ssra {pk%s}.2d, {sh%s}.2d, #32" % (v, v))
    I("fmov [%s], d{pk%s}" % (a, v))
    I("mov [%s], {pk%s}.d[1]" % (b, v))

# ---- the next pair's samples (tiny_samples<false>): spans pa, pb, rows rna, rnb ----
I("ldp q{A0}, q{A1}, [x21, #16]")
I("ldp q{B0}, q{B1}, [x24, #16]")
I("ldp q{A2}, q{A3}, [x21, #48]")
I("ldp q{B2}, q{B3}, [x24, #48]")
I("ldr d{OA}, [x28, #48]")
I("ldr d{OB}, [x27, #48]")
I("zip1 {z0}.2d, {A0}.2d, {B0}.2d")
I("zip1 {z1}.2d, {A0}.2d, {B0}.2d")
I("zip2 {zx}.2d, {A0}.2d, {B0}.2d")
I("zip1 {P}.2d, {A3}.2d, {B3}.2d")
I("zip1 {off}.2d, {OA}.2d, {OB}.2d")
I("fadd {P1}.2d, {P}.2d, {off}.2d")
I("fmla {z0}.2d, {zx}.2d, {P}.2d")
I("fmla {z1}.2d, {zx}.2d, {P1}.2d")
I("fmaxnm {b0}.2d, {z0}.2d, {KMIN}.2d")
I("fmaxnm {b1}.2d, {z1}.2d, {KMIN}.2d")
I("frecpe {y0}.2d, {b0}.2d")
I("frecpe {y1}.2d, {b1}.2d")
for k in range(2):
    I("frecps {e0}.2d, {b0}.2d, {y0}.2d")
    I("frecps {e1}.2d, {b1}.2d, {y1}.2d")
    I("fmul {y0}.2d, {y0}.2d, {e0}.2d")
    I("fmul {y1}.2d, {y1}.2d, {e1}.2d")
for k in range(2):
    I("fmov {g0}.2d, #1.0")
    I("fmov {g1}.2d, #1.0")
    I("fmls {g0}.2d, {b0}.2d, {y0}.2d")
    I("fmls {g1}.2d, {b1}.2d, {y1}.2d")
    I("fmla {y0}.2d, {y0}.2d, {g0}.2d")
    I("fmla {y1}.2d, {y1}.2d, {g1}.2d")
# the fallback test: some b with an all-ones significand, or b >= 2^1000 (+inf too)
I("orr {o0}.16b, {b0}.16b, {MASK}.16b")
I("orr {o1}.16b, {b1}.16b, {MASK}.16b")
I("uminp {o0}.4s, {o0}.4s, {o1}.4s")
I("fmax {mx}.2d, {b0}.2d, {b1}.2d")
I("cmhs {mx}.2d, {mx}.2d, {BIG}.2d")
I("orr {o0}.16b, {o0}.16b, {mx}.16b")
I("umaxv s{o0}, {o0}.4s")
I("fmov [fb], s{o0}")
# the samples
I("zip1 {u0}.2d, {A1}.2d, {B1}.2d")
I("zip1 {u1}.2d, {A1}.2d, {B1}.2d")
I("zip2 {ux}.2d, {A1}.2d, {B1}.2d")
I("zip1 {w0}.2d, {A2}.2d, {B2}.2d")
I("zip1 {w1}.2d, {A2}.2d, {B2}.2d")
I("zip2 {wx}.2d, {A2}.2d, {B2}.2d")
I("zip2 {M}.2d, {A3}.2d, {B3}.2d")
I("fmla {u0}.2d, {ux}.2d, {P}.2d")
I("fmla {u1}.2d, {ux}.2d, {P1}.2d")
I("fmla {w0}.2d, {wx}.2d, {P}.2d")
I("fmla {w1}.2d, {wx}.2d, {P1}.2d")
I("fmul {u0}.2d, {u0}.2d, {y0}.2d")
I("fmul {u1}.2d, {u1}.2d, {y1}.2d")
I("fmul {w0}.2d, {w0}.2d, {y0}.2d")
I("fmul {w1}.2d, {w1}.2d, {y1}.2d")
I("fneg {nzx}.2d, {zx}.2d")
I("fadd {zs}.2d, {y0}.2d, {y1}.2d")
I("fmul {c2}.2d, {nzx}.2d, {zs}.2d")
I("fcvtzu {u0}.2d, {u0}.2d, #16")
I("fcvtzu {u1}.2d, {u1}.2d, #16")
I("fcvtzu {w0}.2d, {w0}.2d, #16")
I("fcvtzu {w1}.2d, {w1}.2d, #16")
I("uqxtn {U}.2s, {u0}.2d")
I("uqxtn2 {U}.4s, {u1}.2d")
I("uqxtn {V}.2s, {w0}.2d")
I("uqxtn2 {V}.4s, {w1}.2d")
I("zip1 {t0}.4s, {U}.4s, {V}.4s")
I("zip2 {t1}.4s, {U}.4s, {V}.4s")
I("umin {s0}.4s, {t0}.4s, {M}.4s")
I("umin {s1}.4s, {t1}.4s, {M}.4s")


def allocate():
    """Replaces {name} by physical registers: least recently freed first, a value's register
    free after its last read (not reused by the same line)."""
    lines = []
    for s in P:
        names = re.findall(r"\{(\w+)\}", s)
        op = s.split()[0]
        dsts = names[:2] if op == "ldp" else names[:1]
        if s.split()[1].startswith("["):  # a GPR destination (fmov / mov to a core register)
            dsts = []
        srcs = names[len(dsts):] + (dsts if op in ACC else [])
        lines.append((s, dsts, srcs, op in ACC))
    # versions: a write of a name (not accumulating) starts a new value
    cur, defs, uses = {}, {}, {}
    ver = []
    for i, (s, dsts, srcs, acc) in enumerate(lines):
        sv = {n: cur.get(n, (n, -1)) for n in srcs}
        for n in srcs:
            uses.setdefault(sv[n], []).append(i)
        dv = {}
        for n in dsts:
            if acc:
                dv[n] = cur[n]
            else:
                cur[n] = (n, i)
                dv[n] = cur[n]
                defs[cur[n]] = i
        ver.append((sv, dv))
    last = {v: max(u) for v, u in uses.items()}
    free = ["v%d" % r for r in range(29)]
    phys = {}
    for n, r in list(CONST.items()) + list(CARRY.items()):
        phys[(n, -1)] = r
    out = []
    for i, (s, dsts, srcs, acc) in enumerate(lines):
        sv, dv = ver[i]
        for n in dsts:
            v = dv[n]
            if v in phys:
                continue
            if n in CARRY:
                phys[v] = CARRY[n]
                continue
            if v not in last:
                raise SystemExit("value never read: %s at line %d" % (n, i))
            phys[v] = free.pop(0)
        t = s
        for n in set(srcs) | set(dsts):
            v = dv.get(n, sv.get(n))
            t = t.replace("{%s}" % n, phys[v][1:] if False else phys[v])
        t = re.sub(r"\b([qds])v(\d+)", r"\1\2", t)
        t = re.sub(r"\[(\w+)\]", lambda m: GPR[m.group(1)] if m.group(1) in GPR else m.group(0), t)
        t = re.sub(r"\[\[(\w+)\]", lambda m: "[" + GPR[m.group(1)], t)
        out.append(t)
        for n in srcs:
            v = sv[n]
            if last.get(v) == i and phys.get(v, "").startswith("v") and v not in dv.values() \
                    and n not in CONST and n not in CARRY:
                if phys[v] not in free:
                    free.append(phys[v])
    return out


def embed(path, note):
    body = [l.split("//")[0].strip() for l in open(path) if l.strip() and not l.strip().endswith(":")]
    inv = {"x" + v[1:]: k for k, v in GPR.items()}
    vinv = {v: k for k, v in list(CONST.items()) + list(CARRY.items())}
    res, used, gused = [], set(), set()
    for l in body:
        used |= set(int(r) for r in re.findall(r"\b[vqds](\d+)\b", l))
        gused |= set(int(r) for r in re.findall(r"\b[xw](\d+)\b", l) if "x" + r not in inv)
        l = re.sub(r"\b([xw])(\d+)\b", lambda m: ("%%%s[%s]" % (m.group(1), inv["x" + m.group(2)]))
                   if "x" + m.group(2) in inv else m.group(0), l)
        l = re.sub(r"\b([vqds])(\d+)\b", lambda m: ("%%%s[%s]" % ("" if m.group(1) == "v" else m.group(1),
                                                                   vinv["v" + m.group(2)]))
                   if "v" + m.group(2) in vinv else m.group(0), l)
        res.append('      "%s\\n"' % l)
    carry = set(int(v[1:]) for v in CARRY.values())
    clob = ", ".join(['"x%d"' % r for r in sorted(gused)] + ['"v%d"' % r for r in sorted(used - carry)])
    print(HEADER % dict(note=note, body="\n".join(res), clob=clob))


HEADER = """// asm/span_persp_a64tiny_pair.h: generated by bench/mca_a53_tiny/gen_pair_asm.py (do not edit;
// %(note)s). aarch64 only, internal to asm/span_persp_a64tiny.cpp (anonymous
// namespace, after kTiny): tiny_curve_run_a64's loop block as one asm statement,
// this pair's steps (tiny_steps' operations) and the next pair's samples (tiny_samples<false>'s)
// in an order searched against llvm-mca's Cortex-A53 model (bench/order_search.py), registers
// fixed by the generator (v0 .. v28 scratch; s0, s1, c2 in the registers GCC gives them).
#pragma once

// In: s0, s1, c2 (this pair's TinySamples fields), a, b (its items), end (the batch's end).
// Out: xa, xb: the next pair (tiny_curve_run_a64's tests: xa = a when there is none, xb = xa
// for a lone one); s0, s1, c2 of the next pair's samples (when there is one; computed
// speculatively on b + 1, b + 2); this pair's packed positions and steps (o.pos*, o.d*,
// o.dd*); o.fb all ones iff the samples need the divide fallback (then s0, s1, c2 are to be
// replaced by tiny_samples_div's on xa, xb).
SB_INLINE void tiny_pair_block(uint32x4_t& s0, uint32x4_t& s1, float64x2_t& c2, const PerspItem* a, const PerspItem* b,
                               const PerspItem* end, const PerspItem*& xa, const PerspItem*& xb, TinyPairOut& o) {
  __asm__(
%(body)s
      : [s0] "+w"(s0), [s1] "+w"(s1), [c2] "+w"(c2), [xa] "=&r"(xa), [xb] "=&r"(xb), [posa] "=&r"(o.posa),
        [posb] "=&r"(o.posb), [da] "=&r"(o.da), [db] "=&r"(o.db), [dda] "=&r"(o.dda), [ddb] "=&r"(o.ddb),
        [fb] "=&r"(o.fb)
      : [a] "r"(a), [b] "r"(b), [end] "r"(end), [kc] "r"(&kTiny), "m"(kTiny)
      : "cc", "memory", %(clob)s);
}
"""


def vs():
    """The block with virtual registers (bench/mca_a53_p64/alloc.py's v@name; constants in_NAME),
    every value (a non-accumulating write) its own name, so the list schedule is free."""
    out, ver = [], {}
    for s in P:
        names = re.findall(r"\{(\w+)\}", s)
        op = s.split()[0]
        dsts = [] if s.split()[1].startswith("[") else (names[:2] if op == "ldp" else names[:1])
        fresh = [n for n in dsts if op not in ACC and n not in CARRY and n not in CONST]
        def nm(n, write):
            if n in CONST:
                return "in_" + n
            if n in CARRY:  # in_: alloc.py never frees its register (a carry is written before its last read)
                return "in_" + n
            return "%s_%d" % (n, ver.get(n, 0))
        # reads first (old versions), then the writes' new versions
        parts = re.split(r"(\{\w+\})", s)
        k = 0
        res = []
        seen_dst = 0
        for p in parts:
            m = re.fullmatch(r"\{(\w+)\}", p)
            if not m:
                res.append(p)
                continue
            n = m.group(1)
            if seen_dst < len(dsts) and n == dsts[seen_dst] and n in fresh:
                seen_dst += 1
                res.append("{%s_%d}" % (n, ver.get(n, 0) + 1) if n not in CONST and n not in CARRY else nm(n, True))
            else:
                if seen_dst < len(dsts) and n == dsts[seen_dst]:
                    seen_dst += 1
                res.append("{%s}" % nm(n, False))
        for n in fresh:
            ver[n] = ver.get(n, 0) + 1
        s = "".join(res)
        s = re.sub(r"\b([qds])\{(\w+)\}", r"\1@\2", s)
        s = re.sub(r"\{(\w+)\}", r"v@\1", s)
        s = re.sub(r"\[(\w+)\]", lambda m: GPR[m.group(1)] if m.group(1) in GPR else m.group(0), s)
        out.append(s)
    return out


def pins():
    return ",".join(["in_%s=%s" % (k, v) for k, v in CONST.items()] + ["in_%s=%s" % (k, v) for k, v in CARRY.items()])


if __name__ == "__main__":
    if sys.argv[1] == "--vs":
        open(sys.argv[2], "w").write("\n".join(vs()) + "\n")
    elif sys.argv[1] == "--pins":
        print(pins())
    elif sys.argv[1] == "--embed":
        embed(sys.argv[2], sys.argv[3] if len(sys.argv) > 3 else sys.argv[2])
    else:
        open(sys.argv[1], "w").write("\n".join(allocate()) + "\n")
