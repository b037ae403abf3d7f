#!/usr/bin/env python3
# bench/mca_a53_tinydraw/gen_chunk_asm.py: draw_tiny (asm/span_persp_a64tiny.cpp) as asm
# statements, asm/span_persp_a64tinydraw.h: tiny_tail<M>, a span of M = 1 .. 16 pixels in one
# block: tail_load's recurrence (even and odd pixels in two chains: x_{k+2} = x_k + e_k,
# e_{k+2} = e_k + 4 dd, e_0 = 2 d + dd, e_1 = 2 d + 3 dd; the same integers modulo 2^64), each
# texel at (x >> 48) w + (u32(x) >> 16) (32-bit madd, as tail_load), the bytes gathered by a
# tree of orr (little-endian) into draw_last's pieces (8 bytes, twice for 16, then 4, 2, 1 by
# M's bits), one store a piece; pixel k's address and texel in a(k mod 8), its v part in
# h(k mod 4) (16 temporaries at most).
# Usage:
#   gen_chunk_asm.py t15 raw > t15_in.s  the block with concrete registers (program order), for
#                                        lsched.py t15_in.s > t15_ls.s (a list schedule), then
#                                        ../order_search.py t15_ls.s t15_s.s
#   gen_chunk_asm.py t15 embed t15_s.s   a searched order back as the asm statement's lines
#   gen_chunk_asm.py header bench/mca_a53_tinydraw .
#                                        the headers asm/span_persp_a64tinydraw.h (M = 1 .. 11)
#                                        and asm/span_persp_a64tinydraw2.h (12 .. 16) under the
#                                        source root given last, from t1_s.s .. t16_s.s
import os, re, sys

def tail_block(m):
    """A span's m = 1 .. 16 pixels from X, D, DD (inputs only): the even pixels' chain in xe,
    pixel k's address and texel in a(k mod 8), the stores in pieces of 8 (one or two), 4, 2, 1
    bytes, each right after its last texel's load (in program order)."""
    temps = ["xo", "xe", "ee", "eo"] + [f"a{k}" for k in range(min(m, 8))] + [f"h{k}" for k in range(min(m, 4))]
    conc = {n: f"x{i}" for i, n in enumerate(["X", "D", "DD", "T", "W", "P"])}
    free = [f"x{i}" for i in list(range(6, 18)) + [19, 20, 21, 22, 23]]
    for n in temps:
        conc[n] = free.pop(0)
    sizes = ([8] if m >= 8 else []) + ([8] if m == 16 else []) + [c for c in (4, 2, 1) if m & c]
    pieces, off = [], 0
    for c in sizes:
        pieces.append((off, c))
        off += c
    L = []
    if m >= 2:
        L.append("add {xo}, {X}, {D}")
    if m >= 3:
        L.append("add {ee}, {DD}, {D}, lsl #1")
    if m >= 4:
        L.append("add {eo}, {ee}, {DD}, lsl #1")
    st = {8: "str", 4: "str", 2: "strh", 1: "strb"}
    for k in range(m):
        if k >= 2 and k % 2 == 0:
            L.append("add {xe}, " + ("{X}" if k == 2 else "{xe}") + ", {ee}")
            if k + 2 < m:
                L.append("add {ee}, {ee}, {DD}, lsl #2")
        if k >= 3 and k % 2 == 1:
            L.append("add {xo}, {xo}, {eo}")
            if k + 2 < m:
                L.append("add {eo}, {eo}, {DD}, lsl #2")
        p = "X" if k == 0 else ("xe" if k % 2 == 0 else "xo")
        h, a = f"h{k % 4}", f"a{k % 8}"
        L.append(f"lsr {{{h}}}, {{{p}}}, #48")
        L.append(f"lsr {{{a}:w}}, {{{p}:w}}, #16")
        L.append(f"madd {{{a}:w}}, {{{h}:w}}, {{W:w}}, {{{a}:w}}")
        L.append(f"ldrb {{{a}:w}}, [{{T}}, {{{a}:w}}, uxtw]")
        for o, c in pieces:
            if o + c - 1 != k:
                continue
            r = lambda j: f"a{(o + j) % 8}"
            for step in (1, 2, 4):
                if step < c:
                    for j in range(0, c, 2 * step):
                        x = "" if step == 4 else ":w"
                        L.append(f"orr {{{r(j)}{x}}}, {{{r(j)}{x}}}, {{{r(j + step)}{x}}}, lsl #{8 * step}")
            x = "" if c == 8 else ":w"
            L.append(f"{st[c]} {{{r(0)}{x}}}, [{{P}}, #{o}]" if o else f"{st[c]} {{{r(0)}{x}}}, [{{P}}]")
    used = [t for t in temps if any("{" + t + "}" in l or "{" + t + ":w}" in l for l in L)]
    return L, conc, used

def render(line, f):
    return re.sub(r"\{(\w+)(:w)?\}", lambda m: f(m.group(1), bool(m.group(2))), line)


def get(C):
    L, conc, _ = tail_block(int(C[1:]))
    return L, conc


def raw(C):
    L, conc = get(C)
    return [render(l, lambda n, w: ("w" + conc[n][1:]) if w else conc[n]) for l in L]


def embed(C, order_file):
    L, conc = get(C)
    back = {r: l for r, l in zip(raw(C), L)}
    order = [l.strip() for l in open(order_file) if l.strip() and not l.startswith("#")]
    assert sorted(order) == sorted(raw(C)), f"{order_file} is not a reordering of the {C}-pixel block"
    return ['      "' + render(back[l], lambda n, w: f"%{'w' if w else 'x'}[{n}]") + '\\n"' for l in order]


SPLIT = 12  # tiny_tail<1 .. 11> in the first header, 12 .. 16 in the second (each < 1000 lines)


def header(d, part):
    """Header part 1 (asm/span_persp_a64tinydraw.h: M = 1 .. SPLIT - 1, which includes part 2)
    or part 2 (asm/span_persp_a64tinydraw2.h: M = SPLIT .. 16), from the searched orders in
    directory d: t1_s.s .. t16_s.s."""
    name = "asm/span_persp_a64tinydraw.h" if part == 1 else "asm/span_persp_a64tinydraw2.h"
    out = [f"// {name}: generated by bench/mca_a53_tinydraw/gen_chunk_asm.py (do not",
           "// edit; the orders: bench/mca_a53_tinydraw/*_s.s, bench/order_search.py against llvm-mca's",
           "// Cortex-A53 model). aarch64 only, internal to asm/span_persp_a64tiny.cpp (anonymous",
           "// namespace): draw_tiny's spans as asm statements, tiny_tail<M> for a span of M = 1 .. 16",
           "// pixels in one block (tail_load's recurrence: even and odd pixels in two chains, the",
           "// same integers modulo 2^64, so the same bytes; the texels stored as draw_last's chunks",
           "// of 8 (twice for 16), 4, 2, 1 by M's bits; bench/mca_a53_tinydraw/README.md).",
           f"// This part: M = {1 if part == 1 else SPLIT} .. {SPLIT - 1 if part == 1 else 16}"
           + (" (asm/span_persp_a64tinydraw2.h: the others)." if part == 1 else "."),
           "#pragma once", ""]

    def operands(outs, ins):
        text = "      : " + ", ".join(outs) + "\n      : " + ", ".join(ins)
        return text.split("\n")
    if part == 1:
        out += ["// A span's M = 1 .. 16 pixels from p at dest (no outputs).",
                "template <int M>",
                "SB_INLINE void tiny_tail(uint8_t* dest, const uint8_t* texels, uint32_t w, const TailPos& p);"]
    for m in range(1, SPLIT) if part == 1 else range(SPLIT, 17):
        _, _, used = tail_block(m)
        out += ["template <>",
                f"SB_INLINE void tiny_tail<{m}>(uint8_t* dest, const uint8_t* texels, uint32_t w, const TailPos& p) {{",
                "  uint64_t " + ", ".join(used) + ";",
                "  __asm__ volatile("]
        out += embed(f"t{m}", f"{d}/t{m}_s.s")
        ins = ['[X] "r"(p.x)', '[D] "r"(p.d)', '[DD] "r"(p.dd)', '[T] "r"(texels)', '[W] "r"(w)', '[P] "r"(dest)']
        out += operands([f'[{t}] "=&r"({t})' for t in used], ins)
        out += ['      : "memory");', "}"]
    if part == 1:
        out += ["", '#include "asm/span_persp_a64tinydraw2.h"']
    out += [""]
    return out


if __name__ == "__main__":
    if sys.argv[1] == "header":
        for part in (1, 2):
            name = "asm/span_persp_a64tinydraw.h" if part == 1 else "asm/span_persp_a64tinydraw2.h"
            open(os.path.join(sys.argv[3], name), "w").write("\n".join(header(sys.argv[2], part)))
    elif sys.argv[2] == "raw":
        print("\n".join(raw(sys.argv[1])))
    else:
        print("\n".join(embed(sys.argv[1], sys.argv[3])))
