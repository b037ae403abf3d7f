#!/usr/bin/env python3
# bench/span_weights.py: the span drawer's estimated cycles a frame per core, from
# bench/span_hist.md (pixels a frame in each class of span, starbow_span_hist) times the cycles a
# pixel of the count row that stands for each class (bench/counts.md, bench/count.sh). Classes
# with no count row are left out and their share of the pixels is printed. A model of a model:
# for ranking where work pays, not a measurement.
#
#   bench/span_weights.py [--res=320x240] [--old=OLD_counts.md]
# --old: "old -> new" per cell; a row OLD lacks counts at the new figure on both sides.
import re, sys, os

ROOT = os.path.dirname(os.path.abspath(__file__))
ROW = {"persp16": "spans of 1-16 px", "persp32": "spans of 17-48 px", "persp64": "spans of 50-64 px, mean 57",
       "persp64lin": "spans of 50-64 px, linear steps", "persp64single": "spans of 50-64 px, one call each",
       "persp72": "spans of 65-80 px", "persp192": "spans of 179-205 px, mean 192",
       "persp192lin": "spans of 179-205 px, linear steps"}
# The variant each target's engine uses for surface_spans_persp, and the cores per target.
CORES = [("x86-64", "sse2", "znver3", 5), ("x86-64", "sse2", "skylake", 6), ("aarch64", "neon", "cortex-a53", 7),
         ("aarch64", "neon", "cortex-a72", 8), ("armhf", "neon", "cortex-a9", 9)]


def counts(path):
    out = {}
    for line in open(path):
        cells = [c.strip() for c in line.split("|")]
        if len(cells) < 10 or not cells[1].startswith("surface_span_persp"):
            continue
        for row, text in ROW.items():
            if text in cells[1]:
                for target, variant, core, col in CORES:
                    if cells[2] == target and cells[3] == variant and cells[col]:
                        out[(row, core)] = float(cells[col].rstrip("†"))
    return out


def hist(path, res):
    maps, cur = {}, None
    for line in open(path):
        m = re.match(r"### (\S+) (\d+x\d+):", line)
        if m:
            cur = m.group(1) if m.group(2) == res else None
            if cur:
                maps[cur] = []
            continue
        cells = [c.strip() for c in line.split("|")]
        if cur and len(cells) == 8 and cells[1] not in ("class", "---"):
            rows = [r.strip() for r in cells[2].split(",") if r.strip()]
            maps[cur].append((cells[1], rows[0] if rows else "", float(cells[4])))
    return maps


def main():
    res, old = "320x240", None
    for a in sys.argv[1:]:
        if a.startswith("--res="):
            res = a[6:]
        elif a.startswith("--old="):
            old = counts(a[6:])
    new = counts(os.path.join(ROOT, "counts.md"))
    maps = hist(os.path.join(ROOT, "span_hist.md"), res)
    if not maps:
        sys.exit(f"span_weights.py: bench/span_hist.md has no section for {res}")
    print(f"Span drawer, estimated kilocycles a frame at {res} (classes with a count row; "
          f"their share of the drawer's pixels in brackets)")
    print("| map | " + " | ".join(c for *_, c, _ in CORES) + " |")
    print("|---" * (len(CORES) + 1) + "|")
    for name, classes in maps.items():
        total = sum(px for *_, px in classes)
        covered = sum(px for _, row, px in classes if row)
        cells = []
        for _, _, core, _ in CORES:
            k = sum(px * new[(row, core)] for _, row, px in classes if row and (row, core) in new) / 1000
            if old:
                ko = sum(px * old.get((row, core), new[(row, core)]) for _, row, px in classes
                         if row and (row, core) in new) / 1000
                cells.append(f"{ko:.0f} → {k:.0f}")
            else:
                cells.append(f"{k:.0f}")
        print(f"| {name} ({100 * covered / total:.0f}%) | " + " | ".join(cells) + " |")
    print()
    # The same sums over the pixels they cover: a frame's mean cycles a pixel, the figure to set
    # beside Quake's 7.5 (a Pentium's inner loop) for the frame as a whole.
    print(f"Mean cycles a pixel over those classes' pixels (Quake's span drawer: 7.5 on a Pentium)")
    print("| map | " + " | ".join(c for *_, c, _ in CORES) + " |")
    print("|---" * (len(CORES) + 1) + "|")
    for name, classes in maps.items():
        cells = []
        for _, _, core, _ in CORES:
            got = [(px, new[(row, core)]) for _, row, px in classes if row and (row, core) in new]
            px_sum = sum(px for px, _ in got)
            mean = sum(px * c for px, c in got) / px_sum if px_sum else 0.0
            if old:
                mo = sum(px * old.get((row, core), new[(row, core)]) for _, row, px in classes
                         if row and (row, core) in new) / px_sum if px_sum else 0.0
                cells.append(f"{mo:.2f} → {mean:.2f}")
            else:
                cells.append(f"{mean:.2f}")
        print(f"| {name} | " + " | ".join(cells) + " |")
    print()
    print("Largest terms (kilocycles a frame, the first map):")
    name, classes = next(iter(maps.items()))
    for _, _, core, _ in CORES:
        terms = sorted(((px * new.get((row, core), 0) / 1000, cls) for cls, row, px in classes if row), reverse=True)
        print(f"  {core}: " + ", ".join(f"{cls} {k:.0f}" for k, cls in terms[:4]))


main()
