#!/usr/bin/env python3
# bench/gen_v7one.py: generates the ARMv7 set-up asm statements of asm/span_persp_v7one.h (between
# their "Generated" markers): the pair set-up of one-run second-order spans (spans a and b,
# each from its PerspItem to its u0, v0, steps and second-order steps stored to memory) and the
# set-up of one span of 17 .. 48 pixels (span_mid), all in VFP / NEON registers. Each span's
# instruction list (span, span_mid below) is fixed; the lists are scheduled by a list scheduler
# with the Cortex-A9 model's latencies (schedule: in-order issue simulated, two a cycle, one
# FP-pipe op a cycle, the ready op with the longest latency path to the end first; loads no
# earlier than SLACK cycles before their latest start, for register pressure), then registers
# are allocated (linear scan over that order: vld1 lists in consecutive registers, q operands
# in aligned pairs, s-register operands in d0 .. d15).
#
#   python3 bench/gen_v7one.py               rewrites both blocks in asm/span_persp_v7one.h
#   options: --mca F.s / --mca-mid F.s       also write a block as llvm-mca input (no IT)
#            --merge-one                     the one-run pair by the in-order merge of the
#                                            two lists instead (the same 176 A9 cycles on its
#                                            own; in the count persp16 16.97, scheduled 16.12)
#            --slack N                       (default 10; 0 .. 50 measured 158 .. 162 cycles
#                                            for span_mid alone)
# The pair's order is then the one in bench/mca_a9_v7one/pair_order.s (bench/order_search.py's,
# applied when it holds the generated lines; --no-order: without it; see the README there).
# Measured on their own (llvm-mca, cortex-a9): the pair 176 cycles (merged) / 159 (scheduled) /
# 148 (order_search), span_mid 158 / 152 (order_search, mid_order.s) (in program
# order 239; two span_mid lists merged do not fit the 32 d registers; a two-run variant for
# n <= 32, 121 instructions and 142 cycles, moved persp32 only 9.59 -> 9.54: not kept).
import os, re, sys

# Per span, {X} a virtual register (d unless noted), {X.s0}/{X.s1} its singles, {X.q} a q
# register (X, X+1), core operands %[name] (the asm statement's). Each op: text, defs, uses.
# `acc` ops read their destination. Lat: result latency (A9 model), fp: FP-pipe slots.
LAT = {"vadd.f64": 4, "vfma.f64": 9, "vfms.f64": 9, "vmul.f64": 6, "vdiv.f64": 25, "vcmpe.f64": 1, "vmrs": 1,
       "vmovle.f64": 1, "vcvt.u32.f64": 4, "vcvt.f64.s32": 4, "vcvt.s32.f64": 4, "vsli.64": 3, "vmin.u32": 4,
       "vsub.i32": 3, "vabs.s32": 4, "vcgt.u32": 4, "vmull.u32": 7, "vmovl.u32": 4, "vqsub.u64": 4,
       "vqmovn.u64": 4, "vtst.32": 4, "vbic": 3, "vand": 3, "vbsl": 3, "vbit": 3,
       "vshr.s32": 3, "vsra.u32": 3, "vmul.i32": 5, "vcge.u32": 4, "vhsub.s32": 4, "vld1.64": 1, "vst1.32": 1, "ldr": 3, "add": 1,
       "sub": 1}
FP_FREE = ("vld1.64", "vst1.32", "ldr", "add", "sub")


def span(x):
    """The ops of span x ('a' or 'b'): %[ix] its item pointer (then the field pointer), %[rx] its
    row pointer, %[ox] its output pointer; KMIN, ONE, HALF, M2, BIG shared constants."""
    I, R, O = f"%[i{x}]", f"%[r{x}]", f"%[o{x}]"
    ops = [
        # n, the row (kOneRows[n]: n - 1, max(n - 1, 1), (max(n - 1, 1) - 1) / 2, [T, T]), the fields.
        (f"ldr {R}, [{I}, #4]", [R], [I]),
        (f"add {I}, {I}, #8", [I], [I]),
        (f"add {R}, %[kr], {R}, lsl #5", [R], [R, "%[kr]"]),
        (f"vld1.64 {{{{{{Z1}}}}}}, [{I}]", ["Z1"], [I, "M:item"]),  # zi0 (sample 1's accumulator)
        (f"vld1.64 {{{{{{Z0}}, {{ZX}}, {{U0}}, {{UX}}}}}}, [{I}]!", ["Z0", "ZX", "U0", "UX", I], [I, "M:item"]),
        (f"vld1.64 {{{{{{V1}}}}}}, [{I}]", ["V1"], [I, "M:item"]),  # vz0
        (f"vld1.64 {{{{{{V0}}, {{VX}}, {{P}}, {{UV}}}}}}, [{I}]", ["V0", "VX", "P", "UV"], [I, "M:item"]),
        (f"sub {I}, {I}, #16", [I], [I]),
        (f"vld1.64 {{{{{{U1}}}}}}, [{I}]", ["U1"], [I, "M:item"]),  # uz0
        (f"vld1.64 {{{{{{F}}, {{S}}}}}}, [{R}]!", ["F", "S", R], [R, "M:tab"]),
        # Positions P, P + (n - 1); depths max(zrow + zix x, kMinZi) (fused; NaN -> kMinZi), 1 / zi.
        ("vadd.f64 {P1}, {P}, {F}", ["P1"], ["P", "F"]),
        ("vfma.f64 {Z0}, {ZX}, {P}", ["Z0"], ["Z0", "ZX", "P"]),
        ("vfma.f64 {Z1}, {ZX}, {P1}", ["Z1"], ["Z1", "ZX", "P1"]),
        ("vcmpe.f64 {Z0}, {KMIN}", ["FLAGS"], ["Z0", "KMIN"]),
        ("vmrs APSR_nzcv, fpscr", ["APSR"], ["FLAGS"]),
        ("vmovle.f64 {Z0}, {KMIN}", ["Z0"], ["Z0", "KMIN", "APSR"]),
        ("vcmpe.f64 {Z1}, {KMIN}", ["FLAGS"], ["Z1", "KMIN"]),
        ("vmrs APSR_nzcv, fpscr", ["APSR"], ["FLAGS"]),
        ("vmovle.f64 {Z1}, {KMIN}", ["Z1"], ["Z1", "KMIN", "APSR"]),
        ("vdiv.f64 {Z0}, {ONE}, {Z0}", ["Z0"], ["ONE", "Z0"]),
        ("vdiv.f64 {Z1}, {ONE}, {Z1}", ["Z1"], ["ONE", "Z1"]),
        # (urow + ux x), (vrow + vx x) (fused), zix / 2.
        ("vfma.f64 {U0}, {UX}, {P}", ["U0"], ["U0", "UX", "P"]),
        ("vfma.f64 {V0}, {VX}, {P}", ["V0"], ["V0", "VX", "P"]),
        ("vfma.f64 {U1}, {UX}, {P1}", ["U1"], ["U1", "UX", "P1"]),
        ("vfma.f64 {V1}, {VX}, {P1}", ["V1"], ["V1", "VX", "P1"]),
        ("vmul.f64 {ZX}, {ZX}, {HALF}", ["ZX"], ["ZX", "HALF"]),
        # Samples: times z, to 16.16 (usat32(trunc)), [u, v] paired, min [umax, vmax].
        ("vmul.f64 {U0}, {U0}, {Z0}", ["U0"], ["U0", "Z0"]),
        ("vmul.f64 {V0}, {V0}, {Z0}", ["V0"], ["V0", "Z0"]),
        ("vmul.f64 {U1}, {U1}, {Z1}", ["U1"], ["U1", "Z1"]),
        ("vmul.f64 {V1}, {V1}, {Z1}", ["V1"], ["V1", "Z1"]),
        ("vadd.f64 {Z0}, {Z0}, {Z1}", ["Z0"], ["Z0", "Z1"]),
        ("vmul.f64 {ZX}, {ZX}, {Z0}", ["ZX"], ["ZX", "Z0"]),  # curve = (zix * 0.5) (z0 + z1)
        ("vmul.f64 {ZX}, {ZX}, {M2}", ["ZX"], ["ZX", "M2"]),  # c2 = -2 curve (exact)
        ("vcvt.u32.f64 {U0}, {U0}, #16", ["U0"], ["U0"]),
        ("vcvt.u32.f64 {V0}, {V0}, #16", ["V0"], ["V0"]),
        ("vcvt.u32.f64 {U1}, {U1}, #16", ["U1"], ["U1"]),
        ("vcvt.u32.f64 {V1}, {V1}, #16", ["V1"], ["V1"]),
        ("vsli.64 {U0}, {V0}, #32", ["U0"], ["U0", "V0"]),
        ("vsli.64 {U1}, {V1}, #32", ["U1"], ["U1", "V1"]),
        ("vmin.u32 {U0}, {U0}, {UV}", ["U0"], ["U0", "UV"]),
        ("vmin.u32 {U1}, {U1}, {UV}", ["U1"], ["U1", "UV"]),
        ("vsub.i32 {D}, {U1}, {U0}", ["D"], ["U1", "U0"]),  # [du, dv] (exact: both in [0, 2^31))
        (f"vst1.32 {{{{{{U0}}}}}}, [{O}]!", ["M:out" + x, O], ["U0", O, "M:out" + x]),  # u0, v0
        # Quotients double(delta) / max(n - 1, 1); ddf = -2 (q curve), to int32 (trunc, saturating).
        ("vcvt.f64.s32 {FU}, {D.s0}", ["FU"], ["D"]),
        ("vcvt.f64.s32 {FV}, {D.s1}", ["FV"], ["D"]),
        ("vdiv.f64 {FU}, {FU}, {S}", ["FU"], ["FU", "S"]),
        ("vdiv.f64 {FV}, {FV}, {S}", ["FV"], ["FV", "S"]),
        (f"vld1.64 {{{{{{KK}}, {{TT}}}}}}, [{R}]", ["KK", "TT"], [R, "M:tab"]),
        ("vabs.s32 {PD}, {D}", ["PD"], ["D"]),
        ("vmovl.u32 {QPD.q}, {PD}", ["QPD"], ["PD"]),
        # ddf = q c2 (-2 (q curve): the same int32 after vcvt, see the header), dd = its trunc
        # (saturating); lin = trunc(q).
        ("vmul.f64 {TU}, {FU}, {ZX}", ["TU"], ["FU", "ZX"]),
        ("vmul.f64 {TV}, {FV}, {ZX}", ["TV"], ["FV", "ZX"]),
        ("vcvt.s32.f64 {L.s0}, {FU}", ["L"], ["FU"]),
        ("vcvt.s32.f64 {L.s1}, {FV}", ["L"], ["FV", "L"]),
        ("vcvt.s32.f64 {DD.s0}, {TU}", ["DD"], ["TU"]),
        ("vcvt.s32.f64 {DD.s1}, {TV}", ["DD"], ["TV", "DD"]),
        # d = trunc(q - dd k) (k = (s - 1) / 2; dd k exact), used where dd is accepted; beside
        # it the test: |dd| < 1e9 and T |dd| <= |delta| (64-bit), the walker's range and
        # acceptance (last_ddi, last_dd); then dd' = accepted ? dd : 0, d = accepted ? d : lin.
        ("vcvt.f64.s32 {GU}, {DD.s0}", ["GU"], ["DD"]),
        ("vcvt.f64.s32 {GV}, {DD.s1}", ["GV"], ["DD"]),
        ("vabs.s32 {A}, {DD}", ["A"], ["DD"]),
        ("vfms.f64 {FU}, {GU}, {KK}", ["FU"], ["FU", "GU", "KK"]),
        ("vfms.f64 {FV}, {GV}, {KK}", ["FV"], ["FV", "GV", "KK"]),
        ("vmull.u32 {QP.q}, {A}, {TT}", ["QP"], ["A", "TT"]),
        ("vcgt.u32 {M}, {BIG}, {A}", ["M"], ["BIG", "A"]),
        ("vqsub.u64 {QP.q}, {QP.q}, {QPD.q}", ["QP"], ["QP", "QPD"]),
        ("vcvt.s32.f64 {R.s0}, {FU}", ["R"], ["FU"]),
        ("vcvt.s32.f64 {R.s1}, {FV}", ["R"], ["FV", "R"]),
        ("vqmovn.u64 {X}, {QP.q}", ["X"], ["QP"]),
        ("vtst.32 {X}, {X}, {X}", ["X"], ["X"]),
        ("vbic {M}, {M}, {X}", ["M"], ["M", "X"]),
        ("vand {DD}, {DD}, {M}", ["DD"], ["DD", "M"]),
        ("vbsl {M}, {R}, {L}", ["M"], ["M", "R", "L"]),
        (f"vst1.32 {{{{{{DD}}}}}}, [{O}]!", ["M:out" + x, O], ["DD", O, "M:out" + x]),  # ddu, ddv
        (f"vst1.32 {{{{{{M}}}}}}, [{O}]", ["M:out" + x], ["M", O, "M:out" + x]),  # du, dv
    ]
    return ops



def span_mid(x):
    """Spans of 17 .. 48 pixels (two or three runs): samples 0 .. 3 at P, P + 16, P + A2,
    (P + 16) + A3 (the walker's positions; for n <= 32 sample 3 is not used), the full runs'
    steps (0 -> 1, 1 -> 2) as persp_fast's (ddf = double(delta) (zck (z_a + z_b)), steps16_dd
    in NEON lanes as asm/span_persp_v7pass.h's), the last run's as the one-run path's, from
    samples 2 -> 3 (n > 32) or 1 -> 2 (n <= 32: the row's mask picks them)."""
    I, R, O = f"%[i{x}]", f"%[r{x}]", f"%[o{x}]"
    ld = lambda regs, ptr, wb=False: (f"vld1.64 {{{{{', '.join('{' + r + '}' for r in regs)}}}}}, [{ptr}]" + ("!" if wb else ""),
                                      regs + ([ptr] if wb else []), [ptr, "M:item" if ptr == I else "M:tab"])
    st = lambda r: (f"vst1.32 {{{{{{{r}}}}}}}, [{O}]!", ["M:out" + x, O], [r, O, "M:out" + x])
    K = "%[kc]"
    ops = [
        # the constants (V7ShortConsts' order), loaded as late as the scheduler may
        (f"vld1.64 {{{{{{KMIN}}, {{ONE}}, {{C16}}}}}}, [{K}]!", ["KMIN", "ONE", "C16", K], [K, "M:tab"]),
        (f"vld1.64 {{{{{{HALF}}, {{MQ}}, {{M2}}}}}}, [{K}]!", ["HALF", "MQ", "M2", K], [K, "M:tab"]),
        (f"vld1.64 {{{{{{BIG}}, {{K120}}, {{K25}}}}}}, [{K}]", ["BIG", "K120", "K25"], [K, "M:tab"]),
        (f"ldr {R}, [{I}, #4]", [R], [I]),
        (f"add {I}, {I}, #8", [I], [I]),
        (f"add {R}, %[kr], {R}, lsl #6", [R], [R, "%[kr]"]),
        ld(["A2", "A3"], R, True),
        ld(["Z1"], I), ld(["Z2"], I), ld(["Z3"], I),
        ld(["Z0", "ZX", "U0", "UX"], I, True),
        ld(["V0", "VX", "P", "UV"], I),
        ("vadd.f64 {P1}, {P}, {C16}", ["P1"], ["P", "C16"]),
        ("vadd.f64 {P2}, {P}, {A2}", ["P2"], ["P", "A2"]),
        ("vfma.f64 {Z0}, {ZX}, {P}", ["Z0"], ["Z0", "ZX", "P"]),
        ("vadd.f64 {P3}, {P1}, {A3}", ["P3"], ["P1", "A3"]),
        ("vfma.f64 {Z1}, {ZX}, {P1}", ["Z1"], ["Z1", "ZX", "P1"]),
        ("vfma.f64 {Z2}, {ZX}, {P2}", ["Z2"], ["Z2", "ZX", "P2"]),
        ("vfma.f64 {Z3}, {ZX}, {P3}", ["Z3"], ["Z3", "ZX", "P3"]),
    ]
    for z in ("Z0", "Z1", "Z2", "Z3"):
        ops += [(f"vcmpe.f64 {{{z}}}, {{KMIN}}", ["FLAGS"], [z, "KMIN"]),
                ("vmrs APSR_nzcv, fpscr", ["APSR"], ["FLAGS"]),
                (f"vmovle.f64 {{{z}}}, {{KMIN}}", [z], [z, "KMIN", "APSR"])]
    for z in ("Z0", "Z1", "Z2", "Z3"):
        ops.append((f"vdiv.f64 {{{z}}}, {{ONE}}, {{{z}}}", [z], ["ONE", z]))
    ops += [ld(["V1"], I), ld(["V2"], I), ld(["V3"], I),
            (f"sub {I}, {I}, #16", [I], [I]),
            ld(["U1"], I), ld(["U2"], I), ld(["U3"], I)]
    for j, p in enumerate(("P", "P1", "P2", "P3")):
        ops += [(f"vfma.f64 {{U{j}}}, {{UX}}, {{{p}}}", [f"U{j}"], [f"U{j}", "UX", p]),
                (f"vfma.f64 {{V{j}}}, {{VX}}, {{{p}}}", [f"V{j}"], [f"V{j}", "VX", p])]
    ops += [("vmul.f64 {ZH}, {ZX}, {HALF}", ["ZH"], ["ZX", "HALF"]),
            ("vmul.f64 {ZX}, {ZX}, {MQ}", ["ZX"], ["ZX", "MQ"]),  # zck = zix * -1/16
            ld(["SL", "KL"], R, True), ld(["TT", "MK"], R)]
    for j in range(4):
        ops += [(f"vmul.f64 {{U{j}}}, {{U{j}}}, {{Z{j}}}", [f"U{j}"], [f"U{j}", f"Z{j}"]),
                (f"vmul.f64 {{V{j}}}, {{V{j}}}, {{Z{j}}}", [f"V{j}"], [f"V{j}", f"Z{j}"])]
    ops += [("vadd.f64 {Z0}, {Z0}, {Z1}", ["Z0"], ["Z0", "Z1"]),  # z0 + z1
            ("vadd.f64 {Z1}, {Z1}, {Z2}", ["Z1"], ["Z1", "Z2"]),  # z1 + z2
            ("vadd.f64 {Z2}, {Z2}, {Z3}", ["Z2"], ["Z2", "Z3"]),  # z2 + z3
            ("vmul.f64 {Z0}, {ZX}, {Z0}", ["Z0"], ["ZX", "Z0"]),  # c0 = zck (z0 + z1)
            ("vmul.f64 {Z3}, {ZX}, {Z1}", ["Z3"], ["ZX", "Z1"]),  # c1 = zck (z1 + z2)
            ("vbit {Z1}, {Z2}, {MK}", ["Z1"], ["Z1", "Z2", "MK"]),  # the last run's z_a + z_b
            ("vmul.f64 {ZH}, {ZH}, {Z1}", ["ZH"], ["ZH", "Z1"]),  # curve = (zix / 2) (z_a + z_b)
            ("vmul.f64 {ZH}, {ZH}, {M2}", ["ZH"], ["ZH", "M2"])]  # c2 = -2 curve
    for j in range(4):
        ops += [(f"vcvt.u32.f64 {{U{j}}}, {{U{j}}}, #16", [f"U{j}"], [f"U{j}"]),
                (f"vcvt.u32.f64 {{V{j}}}, {{V{j}}}, #16", [f"V{j}"], [f"V{j}"])]
    for j in range(4):
        ops += [(f"vsli.64 {{U{j}}}, {{V{j}}}, #32", [f"U{j}"], [f"U{j}", f"V{j}"]),
                (f"vmin.u32 {{U{j}}}, {{U{j}}}, {{UV}}", [f"U{j}"], [f"U{j}", "UV"])]
    ops += [("vsub.i32 {D0}, {U1}, {U0}", ["D0"], ["U1", "U0"]),
            st("U0"),
            ("vsub.i32 {D1}, {U2}, {U1}", ["D1"], ["U2", "U1"]),
            st("U1"),
            ("vsub.i32 {DL}, {U2}, {U1}", ["DL"], ["U2", "U1"]),
            ("vsub.i32 {D3}, {U3}, {U2}", ["D3"], ["U3", "U2"]),
            st("U2"),
            ("vbit {DL}, {D3}, {MK}", ["DL"], ["DL", "D3", "MK"]),  # the last run's delta
            ("vcvt.f64.s32 {FU}, {DL.s0}", ["FU"], ["DL"]),
            ("vcvt.f64.s32 {FV}, {DL.s1}", ["FV"], ["DL"]),
            ("vdiv.f64 {FU}, {FU}, {SL}", ["FU"], ["FU", "SL"]),
            ("vdiv.f64 {FV}, {FV}, {SL}", ["FV"], ["FV", "SL"])]
    # The full runs' steps: ddf = double(delta) c, dd = trunc (saturating), then steps16_dd.
    for j, (Dn, c) in enumerate((("D0", "Z0"), ("D1", "Z3"))):
        E, H, DD, PD, T, A, X = (f"{n}{j}" for n in ("E", "H", "EE", "PD", "SG", "AA", "XX"))
        ops += [(f"vcvt.f64.s32 {{{E}}}, {{{Dn}.s0}}", [E], [Dn]),
                (f"vcvt.f64.s32 {{{H}}}, {{{Dn}.s1}}", [H], [Dn]),
                (f"vmul.f64 {{{E}}}, {{{E}}}, {{{c}}}", [E], [E, c]),
                (f"vmul.f64 {{{H}}}, {{{H}}}, {{{c}}}", [H], [H, c]),
                (f"vcvt.s32.f64 {{{DD}.s0}}, {{{E}}}", [DD], [E]),
                (f"vcvt.s32.f64 {{{DD}.s1}}, {{{H}}}", [DD], [H, DD]),
                (f"vabs.s32 {{{PD}}}, {{{Dn}}}", [PD], [Dn]),
                (f"vshr.s32 {{{T}}}, {{{Dn}}}, #31", [T], [Dn]),
                (f"vsra.u32 {{{Dn}}}, {{{T}}}, #28", [Dn], [Dn, T]),  # delta + (delta < 0 ? 15 : 0)
                (f"vabs.s32 {{{A}}}, {{{DD}}}", [A], [DD]),
                (f"vmul.i32 {{{X}}}, {{{DD}}}, {{K120}}", [X], [DD, "K120"]),
                (f"vmin.u32 {{{A}}}, {{{A}}}, {{K25}}", [A], [A, "K25"]),
                (f"vmul.i32 {{{A}}}, {{{A}}}, {{K120}}", [A], [A, "K120"]),
                (f"vcge.u32 {{{A}}}, {{{PD}}}, {{{A}}}", [A], [PD, A]),  # accepted: 120 min(|dd|, 2^25) <= pd
                (f"vand {{{DD}}}, {{{DD}}}, {{{A}}}", [DD], [DD, A]),
                (f"vand {{{X}}}, {{{X}}}, {{{A}}}", [X], [X, A]),
                (f"vhsub.s32 {{{Dn}}}, {{{Dn}}}, {{{X}}}", [Dn], [Dn, X]),
                (f"vshr.s32 {{{Dn}}}, {{{Dn}}}, #3", [Dn], [Dn]),
                st(Dn), st(DD)]
    # The last run: as span() (the one-run path) from its quotients.
    ops += [
        ("vmul.f64 {TU}, {FU}, {ZH}", ["TU"], ["FU", "ZH"]),
        ("vmul.f64 {TV}, {FV}, {ZH}", ["TV"], ["FV", "ZH"]),
        ("vcvt.s32.f64 {L.s0}, {FU}", ["L"], ["FU"]),
        ("vcvt.s32.f64 {L.s1}, {FV}", ["L"], ["FV", "L"]),
        ("vcvt.s32.f64 {DD.s0}, {TU}", ["DD"], ["TU"]),
        ("vcvt.s32.f64 {DD.s1}, {TV}", ["DD"], ["TV", "DD"]),
        ("vcvt.f64.s32 {GU}, {DD.s0}", ["GU"], ["DD"]),
        ("vcvt.f64.s32 {GV}, {DD.s1}", ["GV"], ["DD"]),
        ("vabs.s32 {A}, {DD}", ["A"], ["DD"]),
        ("vfms.f64 {FU}, {GU}, {KL}", ["FU"], ["FU", "GU", "KL"]),
        ("vfms.f64 {FV}, {GV}, {KL}", ["FV"], ["FV", "GV", "KL"]),
        ("vmull.u32 {QP.q}, {A}, {TT}", ["QP"], ["A", "TT"]),
        ("vcgt.u32 {M}, {BIG}, {A}", ["M"], ["BIG", "A"]),
        ("vabs.s32 {PD}, {DL}", ["PD"], ["DL"]),
        ("vmovl.u32 {QPD.q}, {PD}", ["QPD"], ["PD"]),
        ("vqsub.u64 {QP.q}, {QP.q}, {QPD.q}", ["QP"], ["QP", "QPD"]),
        ("vcvt.s32.f64 {R.s0}, {FU}", ["R"], ["FU"]),
        ("vcvt.s32.f64 {R.s1}, {FV}", ["R"], ["FV", "R"]),
        ("vqmovn.u64 {X}, {QP.q}", ["X"], ["QP"]),
        ("vtst.32 {X}, {X}, {X}", ["X"], ["X"]),
        ("vbic {M}, {M}, {X}", ["M"], ["M", "X"]),
        ("vand {DD}, {DD}, {M}", ["DD"], ["DD", "M"]),
        ("vbsl {M}, {R}, {L}", ["M"], ["M", "R", "L"]),
        st("DD"), st("M"),
    ]
    return ops


SHARED = ["KMIN", "ONE", "HALF", "M2", "C16", "MQ", "BIG", "K120", "K25", "FLAGS", "APSR", "%[kr]", "M:tab"]
LOW = {"D", "DD", "R", "L", "DL", "D0", "D1", "EE0", "EE1"}  # s-register operands: d0 .. d15
QREG = {"QP", "QPD"}


def tag(ops, x, shared=None):
    """Virtual register names made per span (X -> X_a), core and memory names kept."""
    shared = SHARED if shared is None else shared
    out = []
    for text, defs, uses in ops:
        f = lambda r: r if (r in shared or r.startswith("%") or r.startswith("M:")) else f"{r}_{x}"
        t = re.sub(r"\{([A-Z0-9]+)((?:\.s0|\.s1|\.q)?)\}", lambda m: "{" + f(m.group(1)) + m.group(2) + "}", text)
        out.append((t, [f(r) for r in defs], [f(r) for r in uses], x))
    return out


def opname(text):
    return text.split()[0]


SLACK = 10  # --slack: see schedule
SCHED = False  # schedule (True) or the in-order merge (main sets it per block)
LAG = 0  # span b's first op waits until span a has issued LAG ops (register pressure)


def merge(a, b):
    """Greedy in-order merge: each span's ops in order; at each step the op (of the two heads)
    whose operands are ready first issues (FP-pipe ops one a cycle); ties: the span behind."""
    ready = {}  # register -> cycle its value is ready
    fp_free = 0
    out, ia, ib = [], 0, 0
    cyc = 0
    flags_owner = None
    while ia < len(a) or ib < len(b):
        cands = []
        for which, lst, i in (("a", a, ia), ("b", b, ib)):
            if i >= len(lst):
                continue
            text, defs, uses, x = lst[i]
            # the flags are shared: a span's vcmpe .. vmovle group may not interleave with the other's
            if ("FLAGS" in defs or "APSR" in defs or "APSR" in uses) and flags_owner not in (None, x):
                continue
            if which == "b" and ia < min(LAG, len(a)):
                continue
            t = max([ready.get(u, 0) for u in uses] + [cyc])
            if opname(text) not in FP_FREE:
                t = max(t, fp_free)
            cands.append((t, i, which))
        t, i, which = min(cands)
        lst = a if which == "a" else b
        text, defs, uses, x = lst[i]
        if opname(text) == "vcmpe.f64":
            flags_owner = x
        if opname(text) == "vmovle.f64":
            flags_owner = None
        lat = LAT.get(opname(text), 4)
        for d in defs:
            ready[d] = t + lat
        if opname(text) not in FP_FREE:
            fp_free = t + (2 if opname(text) == "vmull.u32" else 1)
        cyc = t
        out.append(lst[i])
        if which == "a":
            ia += 1
        else:
            ib += 1
    return out


def schedule(ops):
    """List scheduling of a program (one span's or two spans' ops, in any valid order): the
    dependences on names (read after write with the producer's latency; write after read and
    write after write kept in order; memory and flags as names), then a cycle-by-cycle
    simulation of in-order issue (two a cycle, one FP-pipe op a cycle) that starts, among the
    ready ops, the one with the longest latency path to the end. Returns the ops in start order."""
    n = len(ops)
    preds = [[] for _ in range(n)]
    last_def, readers = {}, {}
    for i, (text, defs, uses, x) in enumerate(ops):
        for u in uses:
            if u in last_def:
                j = last_def[u]
                preds[i].append((j, LAT.get(opname(ops[j][0]), 4)))
        for d in defs:
            if d in last_def:
                preds[i].append((last_def[d], 1))
            for j in readers.get(d, []):
                if j != i:
                    preds[i].append((j, 0))
        for u in uses:
            readers.setdefault(u, []).append(i)
        for d in defs:
            last_def[d] = i
            readers[d] = []
    succs = [[] for _ in range(n)]
    for i in range(n):
        for j, l in preds[i]:
            succs[j].append((i, l))
    prio = [0] * n
    for i in reversed(range(n)):
        own = LAT.get(opname(ops[i][0]), 4)
        prio[i] = max([own] + [l + prio[k] for k, l in succs[i]])
    start = [None] * n
    crit = max(prio)
    order, cyc, fp_free, done = [], 0, 0, 0
    while done < n:
        issued = 0
        while issued < 2:
            best = None
            for i in range(n):
                if start[i] is not None:
                    continue
                if any(start[j] is None or start[j] + l > cyc for j, l in preds[i]):
                    continue
                fp = opname(ops[i][0]) not in FP_FREE
                if fp and fp_free > cyc:
                    continue
                # loads as late as possible (less register pressure): not before their
                # latest start less SLACK cycles
                if opname(ops[i][0]) == "vld1.64" and cyc < crit - prio[i] - SLACK:
                    continue
                if best is None or prio[i] > prio[best]:
                    best = i
            if best is None:
                break
            start[best] = cyc
            if opname(ops[best][0]) not in FP_FREE:
                fp_free = cyc + (2 if opname(ops[best][0]) == "vmull.u32" else 1)
            order.append(ops[best])
            issued += 1
            done += 1
        cyc += 1
    return order


def allocate(ops, fixed):
    """Physical d registers for the virtual ones (fixed: the shared constants' registers)."""
    last_use = {}
    for k, (text, defs, uses, x) in enumerate(ops):
        for u in uses:
            last_use[u] = k
    # a value defined and never read (none here) is freed at once
    phys = dict(fixed)
    busy = {p: "const" for p in fixed.values()}
    for p in list(fixed.values()):
        pass

    def vregs_of(text):
        return re.findall(r"\{([A-Za-z0-9_]+)((?:\.s0|\.s1|\.q)?)\}", text)

    for k, (text, defs, uses, x) in enumerate(ops):
        # free the registers whose values were last read before this op
        here = [r for r, _ in vregs_of(text)]
        for p, v in list(busy.items()):
            if v == "const" or v in here:
                continue
            if last_use.get(v, -1) < k:
                del busy[p]
        names = [r for r, _ in vregs_of(text)]
        new = [v for v in names if v not in phys and v in defs]
        if not new:
            continue
        base = lambda v: v.rsplit("_", 1)[0]
        if len(new) > 1:  # a vld1 list: consecutive registers, in order
            n = len(new)
            for s in range(0, 33 - n):
                if all(s + j not in busy for j in range(n)):
                    break
            else:
                raise SystemExit(f"no {n} consecutive registers at op {k}: {text}")
            for j, v in enumerate(new):
                phys[v] = s + j
                busy[s + j] = v
            continue
        v = new[0]
        if base(v) in QREG:
            for s in range(16, 31, 2):
                if s not in busy and s + 1 not in busy:
                    break
            else:
                for s in range(0, 15, 2):
                    if s not in busy and s + 1 not in busy:
                        break
                else:
                    raise SystemExit(f"no q register at op {k}: {text}")
            phys[v] = s
            busy[s] = v
            busy[s + 1] = v
            continue
        rng = list(range(0, 16)) if base(v) in LOW else list(range(16, 32)) + list(range(0, 16))
        free = [r for r in rng if r not in busy]
        if not free:
            raise SystemExit(f"no register for {v} at op {k}: {text}")
        # prefer a register whose pair partner is busy (keeps whole q registers free)
        hi = [r for r in free if r >= 16] if base(v) not in LOW else []
        pool = hi or free
        half = [r for r in pool if (r ^ 1) in busy]
        s = (half or pool)[0]
        phys[v] = s
        busy[s] = v
    # release of q registers: busy entries for the pair's second half were keyed by v too
    return phys


def render(ops, phys):
    lines = []
    for text, defs, uses, x in ops:
        def sub(m):
            v, suf = m.group(1), m.group(2)
            p = phys[v]
            if suf == ".s0":
                return f"s{2 * p}"
            if suf == ".s1":
                return f"s{2 * p + 1}"
            if suf == ".q":
                assert p % 2 == 0
                return f"q{p // 2}"
            return f"d{p}"
        t = re.sub(r"\{([A-Za-z0-9_]+)((?:\.s0|\.s1|\.q)?)\}", sub, text)
        t = t.replace("{{", "{").replace("}}", "}")
        lines.append(t)
    return lines


def reorder(lines, path):
    """The block's lines in the order of `path` (an llvm-mca-form file, as --mca writes it,
    reordered by bench/order_search.py --arch=armv7), which must hold the same lines."""
    core = {f"r{i}": n for i, n in enumerate(("%[ia]", "%[ib]", "%[ra]", "%[rb]", "%[oa]", "%[ob]", "%[kc]", "%[kr]"))}
    out = []
    for l in open(path):
        flags = "@flags" in l
        l = l.split("@")[0].strip()
        if not l or l.startswith("."):
            continue
        l = re.sub(r"\br([0-7])\b", lambda m: core[m.group(0)], l)
        if flags:
            l = l.replace("vmov.f64", "vmovle.f64", 1)
        out.append(l)
    if sorted(out) != sorted(lines):
        raise SystemExit(f"{path}: not the generated block's lines (regenerate it: see bench/mca_a9_v7one)")
    return out


def gen(progs, head, fixed, marker, macro, mca, order=None):
    """One asm statement: the programs merged, registers allocated; written into
    asm/span_persp_v7one.h between `marker` and its clobbers line, the clobbers as `macro`."""
    if SCHED:
        ops = head + schedule([o for p in progs for o in p])
    else:
        ops = head + (merge(*progs) if len(progs) == 2 else progs[0])
    phys = allocate(ops, fixed)
    lines = render(ops, phys)
    if order and os.path.exists(order):
        lines = reorder(lines, order)
    used = sorted(set(int(m) for l in lines for m in re.findall(r"\bd(\d+)\b", l)) |
                  set(int(m) // 2 for l in lines for m in re.findall(r"\bs(\d+)\b", l)) |
                  set(2 * int(m) + j for l in lines for m in re.findall(r"\bq(\d+)\b", l) for j in (0, 1)))
    if mca:
        core = {"%[ia]": "r0", "%[ib]": "r1", "%[ra]": "r2", "%[rb]": "r3", "%[oa]": "r4", "%[ob]": "r5",
                "%[kc]": "r6", "%[kr]": "r7"}
        with open(mca, "w") as fh:
            for l in lines:
                for k, v in core.items():
                    l = l.replace(k, v)
                if l.startswith("vmovle"):
                    l = l.replace("vmovle", "vmov") + " @flags"
                fh.write(l + "\n")
    body = []
    for l in lines:
        if l.startswith("vmovle"):
            body.append('"it le\\n\\t"')
        body.append(f'"{l}\\n\\t"')
    body[-1] = body[-1].replace("\\n\\t", "")
    clob = ", ".join(f'"d{r}"' for r in used)
    text = (f"    {marker} (do not edit by hand).\n"
            + "".join(f"    {l}\n" for l in body)
            + f"    // clobbers: {clob}\n")
    path = "asm/span_persp_v7one.h"
    src = open(path).read()
    s0 = src.index(f"    {marker}")
    s1 = src.index("    // clobbers:", s0)
    s1 = src.index("\n", s1) + 1
    src = src[:s0] + text + src[s1:]
    src = re.sub(rf"#define {macro} .*", f"#define {macro} {clob}", src)
    open(path, "w").write(src)
    print(f"{marker}: {len(lines)} instructions, d registers used: {used}", file=sys.stderr)


def main():
    global SCHED, SLACK
    arg = lambda k: sys.argv[sys.argv.index(k) + 1] if k in sys.argv else None
    SLACK = int(arg("--slack") or 10)
    # The one-run pair: list-scheduled too (176 A9 cycles on its own as the in-order merge of
    # the two lists, --merge-one, but in the count A9 persp16 16.97 -> 16.12: where qemu cuts
    # the statement's blocks moved).
    SCHED = "--merge-one" not in sys.argv
    head = [("vld1.64 {{{KMIN}, {ONE}, {HALF}, {M2}}}, [%[kc]]!", [], ["%[kc]"], "-"),
            ("vld1.64 {{{BIG}}}, [%[kc]]", [], ["%[kc]"], "-")]
    gen([tag(span("a"), "a"), tag(span("b"), "b")], head, {"KMIN": 0, "ONE": 1, "HALF": 2, "M2": 3, "BIG": 4},
        "// Generated by bench/gen_v7one.py", "SB_V7_ONE_CLOBBERS", arg("--mca"),
        None if "--no-order" in sys.argv else os.path.join(os.path.dirname(__file__), "mca_a9_v7one", "pair_order.s"))
    # 17 .. 48 pixels: one span, list-scheduled (in program order 239 cycles, scheduled 158).
    SCHED = True
    mid = [tag(span_mid("a"), "a", ["FLAGS", "APSR", "%[kr]", "M:tab"])]
    gen(mid, [], {}, "// Generated (mid) by bench/gen_v7one.py", "SB_V7_MID2_CLOBBERS", arg("--mca-mid"),
        None if "--no-order" in sys.argv else os.path.join(os.path.dirname(__file__), "mca_a9_v7one", "mid_order.s"))


if __name__ == "__main__":
    main()
