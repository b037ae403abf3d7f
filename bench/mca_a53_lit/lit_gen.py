# bench/mca_a53_lit/lit_gen.py: the parts gen_lit16.py (lit16_block) and gen_win16.py
# (win16_block) share: the 16 positions and texel indices in NEON lanes, the core part that
# draws 8 pixels, and the linear-scan allocation of the core values named %name.
import re


def head(e):
    """Positions u, v of pixels 0..15 as 16-bit lanes (v6, v7 / v16, v17), the mip's B - 1 and
    log B (v30, v31), and the texel indices stored to the frame (%tp = frame + 32 after)."""
    # ---------------------------------------------------------------- NEON: positions
    e("ldp q16, q17, [x%tab]")            # j = 0..7 (u32)
    e("ldp q18, q19, [x%tab, #32]")       # j = 8..15
    e("ldp q20, q21, [x%tab, #64]")       # j (j - 1) / 2
    e("ldp q22, q23, [x%tab, #96]")
    e("fmov s5, w%du")
    e("mov v5.s[1], w%dv")
    e("mov v5.s[2], w%ddu")
    e("mov v5.s[3], w%ddv")
    for i in range(4):
        e(f"dup v{24 + i}.4s, w%u")
        e(f"dup v{28 + i}.4s, w%v")
    for i in range(4):
        e(f"mla v{24 + i}.4s, v{16 + i}.4s, v5.s[0]")
        e(f"mla v{28 + i}.4s, v{16 + i}.4s, v5.s[1]")
    for i in range(4):
        e(f"mla v{24 + i}.4s, v{20 + i}.4s, v5.s[2]")
        e(f"mla v{28 + i}.4s, v{20 + i}.4s, v5.s[3]")
    # U, V of pixels 0..7 (v6, v16) and 8..15 (v7, v17) as 16-bit lanes
    e("uzp2 v6.8h, v24.8h, v25.8h")
    e("uzp2 v7.8h, v26.8h, v27.8h")
    e("uzp2 v16.8h, v28.8h, v29.8h")
    e("uzp2 v17.8h, v30.8h, v31.8h")
    e("ldp q30, q31, [x%tab, #128]")      # B - 1, log B (u16 lanes)
    # ---------------------------------------------------------------- NEON: texel indices
    # ((V + to) & tmask) * tex_width + ((U + so) & smask) in 16 bits (textures of at most 2^16
    # texels only)
    e("add x%p, x%fr, #64")
    e("ld4r {v0.8h, v1.8h, v2.8h, v3.8h}, [x%p]")
    e("ldr q4, [x%fr, #64]")              # h[4] = tex_width
    e("add v18.8h, v6.8h, v0.8h")
    e("add v19.8h, v7.8h, v0.8h")
    e("add v20.8h, v16.8h, v1.8h")
    e("add v21.8h, v17.8h, v1.8h")
    e("and v22.16b, v18.16b, v2.16b")
    e("and v23.16b, v19.16b, v2.16b")
    e("and v20.16b, v20.16b, v3.16b")
    e("and v21.16b, v21.16b, v3.16b")
    e("mla v22.8h, v20.8h, v4.h[4]")
    e("mla v23.8h, v21.8h, v4.h[4]")
    # stored at once; %tp = frame + 32 after it: the indices' loads use it, so no reordering
    # moves them before the store
    e("mov x%tp, x%fr")
    e("st1 {v22.8h, v23.8h}, [x%tp], #32")

# ---------------------------------------------------------------- core: pixels
def pixels(e, g, base):
    """8 pixels: texel, then colormap[(num >> S + 8) << 8 + texel]; one 64-bit word. The
    indices and the light come 4 a load (ldr x: one load-unit cycle, ldp w two)."""
    for i in range(2):
        e(f"ldr x%{g}w{i}, [x%tp, #{base - 32 + 8 * i}]")
        e(f"ldr x%{g}s{i}, [x%lp, #{base - 32 + 8 * i}]")
    for j in range(8):
        w = f"%{g}w{j // 4}"
        e((f"and w%{g}t{j}, w{w}, #0xffff", f"lsr w%{g}t{j}, w{w}, #16", f"ubfx x%{g}t{j}, x{w}, #32, #16",
           f"lsr x%{g}t{j}, x{w}, #48")[j % 4])
    for j in range(8):
        e(f"ldrb w%{g}t{j}, [x6, x%{g}t{j}]")
    for j in range(8):
        s = f"%{g}s{j // 4}"
        if j % 4 == 2:
            e(f"ubfx x%{g}h{j}, x{s}, #32, #16")
        e((f"add w%{g}t{j}, w%{g}t{j}, w{s}, uxth", f"add w%{g}t{j}, w%{g}t{j}, w{s}, lsr #16",
           f"add w%{g}t{j}, w%{g}t{j}, w%{g}h{j}", f"add x%{g}t{j}, x%{g}t{j}, x{s}, lsr #48")[j % 4])
    for j in range(8):
        e(f"ldrb w%{g}t{j}, [x7, x%{g}t{j}]")
    e(f"orr x%{g}t0, x%{g}t0, x%{g}t1, lsl #8")
    e(f"orr x%{g}t2, x%{g}t2, x%{g}t3, lsl #8")
    e(f"orr x%{g}t4, x%{g}t4, x%{g}t5, lsl #8")
    e(f"orr x%{g}t6, x%{g}t6, x%{g}t7, lsl #8")
    e(f"orr x%{g}t0, x%{g}t0, x%{g}t2, lsl #16")
    e(f"orr x%{g}t4, x%{g}t4, x%{g}t6, lsl #16")
    e(f"orr x%{g}t0, x%{g}t0, x%{g}t4, lsl #32")



def allocate(lines, pin, pool, freeable, keep, flags, kept):
    names = [re.findall(r"%(\w+)", l) for l in lines]
    last = {}
    for i, ns in enumerate(names):
        for n in ns:
            last[n] = i
    reg, free, out = {}, list(pool), []
    for i, l in enumerate(lines):
        ns = names[i]
        for n in dict.fromkeys(ns):
            if n not in reg:
                if n in pin:
                    r = pin[n]
                    assert r not in free or n in flags, (n, i)
                    if r in free:
                        free.remove(r)
                    reg[n] = r
                else:
                    assert free, f"out of registers at line {i}: {l}"
                    reg[n] = free.pop(0)
        out.append(re.sub(r"%(\w+)", lambda m: str(reg[m.group(1)]), l))
        for n in dict.fromkeys(ns):
            if last[n] == i and n not in flags:
                r = reg[n]
                if n in pin and n not in freeable:
                    continue
                if r in keep and n in kept:
                    continue
                free.append(r)
    return out

