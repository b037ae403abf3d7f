#!/usr/bin/env python3
"""bench/singlepass_arm.py: single pass (r_singlepass 1) against the surface cache on ARM, as
instruction counts under qemu-user (issue 4: which path wins where).

For each target (aarch64, armhf) x map x resolution x light styles x path, runs the headless
starbow (build/count-<target>/starbow, built as bench/count.sh builds it) under qemu-user with
the `insn` plugin over the flythrough of F1 and of F2 = 2 F1 path frames and differences the two
totals (start-up, map load and the memstats report cancel), as bench/count_report.py does for
whole frames: instructions per path frame and per pixel per frame.

Light styles (cvar r_lightstyles): static = 0 (every style normal), animated = 1 (10 Hz
patterns: styled surfaces rebuild in the cached path when a value steps), dynamic = 2 (every
style value changes every frame: every lit surface in view rebuilds every frame in the cached
path, as starbow_bench --styles=dynamic). Surface cache KiB: the cache region's high-water
mark after the cached path's F2 run (`memstats`); the single pass uses none.

These are instruction counts, not cycles: a load that misses costs more than one that hits,
and the cached path's surface cache costs memory traffic (building and reading the surfaces)
that the count does not see.

  bench/singlepass_arm.py [--targets=aarch64,armhf] [--maps=start,lq_e0m1,lq_e1m1]
                          [--res=320x240,640x480] [--frames=50] [--write]
--write replaces the "## ARM (instruction counts under qemu-user)" section of
bench/results_singlepass.md (appends it when missing); otherwise the section goes to stdout.
Needs what bench/count.sh needs (qemu-user, the cross compilers, build/qemu-plugins/libinsn.so:
run bench/count.sh once to build the plugins). Runs two emulators at a time.
"""
import concurrent.futures
import os
import re
import subprocess
import sys
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
B = os.path.join(ROOT, "build")
PLUG = os.path.join(B, "qemu-plugins", "libinsn.so")
TARGETS = {
    "aarch64": dict(dir="count-aarch64", toolchain="aarch64-linux-gnu.cmake",
                    qemu=["qemu-aarch64", "-L", "/usr/aarch64-linux-gnu", "-cpu", "cortex-a53"]),
    "armhf": dict(dir="count-armhf", toolchain="arm-linux-gnueabihf.cmake",
                  qemu=["qemu-arm", "-L", "/usr/arm-linux-gnueabihf", "-cpu", "cortex-a15"]),
}
STYLES = {"static": 0, "animated": 1, "dynamic": 2}
SECTION = "## ARM (instruction counts under qemu-user)"


def opt(name, default):
    for a in sys.argv[1:]:
        if a.startswith(f"--{name}="):
            return [x for x in a.split("=", 1)[1].split(",") if x]
    return default


def build(t):
    """Configures build/count-<target> as bench/count.sh does (if not yet) and builds starbow."""
    d = os.path.join(B, t["dir"])
    if not os.path.exists(os.path.join(d, "build.ninja")):
        subprocess.run(["cmake", "-S", ROOT, "-B", d, "-G", "Ninja", "-DCMAKE_BUILD_TYPE=RelWithDebInfo",
                        "-DSTARBOW_TESTS=OFF", "-DCMAKE_EXE_LINKER_FLAGS=-no-pie",
                        f"-DCMAKE_TOOLCHAIN_FILE={ROOT}/toolchain/{t['toolchain']}"],
                       check=True, stdout=subprocess.DEVNULL)
    subprocess.run(["cmake", "--build", d, "-j2", "--target", "starbow"], check=True, stdout=subprocess.DEVNULL)
    return os.path.join(d, "starbow")


def run(t, exe, quake_dir, map_name, res, single, style, frames):
    """(instructions of the whole process, surface cache high-water KiB) of one flythrough."""
    log = f"/tmp/sb_spa_{os.getpid()}_{t['dir']}_{map_name}_{res}_{single}_{style}_{frames}.log"
    cmd = t["qemu"] + ["-plugin", PLUG, "-d", "plugin", "-D", log, exe, "-basedir", quake_dir, "-game", "lq1",
                       "-res", res, "+viewmap", map_name, "+r_singlepass", str(single), "+r_lightstyles",
                       str(style), "+flythrough", str(frames), "+memstats", "+quit"]
    r = subprocess.run(cmd, capture_output=True, text=True, cwd="/tmp")
    txt = open(log).read() if os.path.exists(log) else ""
    if os.path.exists(log):
        os.unlink(log)
    m = re.search(r"total insns:\s*(\d+)", txt) or re.search(r"insns:\s*(\d+)", txt)
    c = re.search(r"^cache\s+\d+\s+\d+\s+(\d+)", r.stdout + r.stderr, re.M)
    if r.returncode or not m or "flythrough " + map_name not in r.stdout + r.stderr:
        raise RuntimeError(f"{' '.join(cmd)} failed: {(r.stdout + r.stderr)[-800:]}")
    return int(m.group(1)), int(c.group(1)) if c else None


def main():
    targets = opt("targets", ["aarch64", "armhf"])
    maps = opt("maps", ["start", "lq_e0m1", "lq_e1m1"])
    resolutions = opt("res", ["320x240", "640x480"])
    f1 = int(opt("frames", ["50"])[0])
    f2 = 2 * f1
    quake_dir = os.environ.get("STARBOW_QUAKE_DIR", os.path.join(ROOT, "..", "shared", "quake"))
    if not os.path.isdir(os.path.join(quake_dir, "lq1")):
        quake_dir = "/work/shared/quake"
    exes = {n: build(TARGETS[n]) for n in targets}
    jobs = [(n, m, res, style, single, f)
            for n in targets for m in maps for res in resolutions for style in STYLES
            for single in (0, 1) for f in (f1, f2)]
    t0 = time.time()
    out = {}
    with concurrent.futures.ThreadPoolExecutor(2) as pool:
        futs = {pool.submit(run, TARGETS[j[0]], exes[j[0]], quake_dir, j[1], j[2], j[4], STYLES[j[3]], j[5]): j
                for j in jobs}
        for fu in concurrent.futures.as_completed(futs):
            out[futs[fu]] = fu.result()
            print(f"  {' '.join(map(str, futs[fu]))}: {out[futs[fu]][0]} insns  ({time.time() - t0:.0f} s)",
                  file=sys.stderr)

    md = [SECTION, "",
          f"Generated by `bench/singlepass_arm.py --frames={f1}` (headless starbow, build/count-<target>, "
          "-O2 RelWithDebInfo as bench/count.sh builds it). **Instruction counts, not cycles**: qemu-user's "
          "`insn` plugin counts every instruction the whole process executes; the difference of a "
          f"{f1}- and a {f2}-frame flythrough over the same camera path gives instructions per path frame "
          "(start-up, map load and the report cancel) and, divided by the pixels, per pixel per frame. "
          "A load that misses costs more than one that hits, and the cached path's surface cache costs "
          "memory traffic (building surfaces, reading them back) that an instruction count does not see, "
          "so on a board with a small cache the cached path will do worse than its count suggests. "
          "aarch64 runs as `-cpu cortex-a53`, armhf (Thumb-2 + NEON) as `-cpu cortex-a15`; the kernels "
          "are the tuned NEON ones each build selects.", "",
          "Light styles: *static* = `r_lightstyles 0` (all normal), *animated* = `r_lightstyles 1` (10 Hz "
          "patterns), *dynamic* = `r_lightstyles 2` (every style value changes every frame: every lit "
          "surface in view is rebuilt every frame by the cached path, as `starbow_bench --styles=dynamic`). "
          "*single / cached*: ratio of the instructions per frame; *faster* (by count): single below 0.97, "
          "cached above 1.03, else even. *Surface cache KiB*: the cache region's high-water mark after the "
          f"cached path's {f2}-frame flythrough (`memstats`); the single pass allocates none, so this is the "
          "memory it saves (the permanent 1280 KiB cache slot table is allocated either way).", "",
          "| target | map | resolution | light styles | cached Minstr/frame | cached instr/px | "
          "single Minstr/frame | single instr/px | single / cached | faster | surface cache KiB |",
          "|---|---|---|---|---|---|---|---|---|---|---|"]
    for n in targets:
        for m in maps:
            for res in resolutions:
                w, h = map(int, res.split("x"))
                for style in STYLES:
                    per = []
                    for single in (0, 1):
                        a, b = out[(n, m, res, style, single, f1)][0], out[(n, m, res, style, single, f2)][0]
                        per.append((b - a) / (f2 - f1))
                    r = per[1] / per[0]
                    kib = out[(n, m, res, style, 0, f2)][1]
                    md.append(f"| {n} | {m} | {res} | {style} | {per[0] / 1e6:.2f} | {per[0] / (w * h):.1f} | "
                              f"{per[1] / 1e6:.2f} | {per[1] / (w * h):.1f} | {r:.2f} | "
                              f"{'single' if r < 0.97 else 'cached' if r > 1.03 else 'even'} | "
                              f"{'—' if kib is None else kib} |")
    text = "\n".join(md) + "\n"
    if "--write" in sys.argv:
        path = os.path.join(ROOT, "bench", "results_singlepass.md")
        doc = open(path).read()
        i = doc.find(SECTION)
        if i < 0:
            doc = doc.rstrip("\n") + "\n\n" + text
        else:
            j = doc.find("\n## ", i + len(SECTION))
            doc = doc[:i] + text + (doc[j + 1:] if j >= 0 else "")
            doc = doc.replace(text + "## ", text + "\n## ")
        open(path, "w").write(doc)
        print(f"written: {path}", file=sys.stderr)
    else:
        sys.stdout.write(text)


if __name__ == "__main__":
    main()
