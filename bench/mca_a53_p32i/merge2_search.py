#!/usr/bin/env python3
# bench/mca_a53_p32i/merge2_search.py: searches merge2.py's zip order (which stream's next line
# goes next) against llvm-mca (Cortex-A53 cycles as a loop, Cortex-A57 to break ties): moves a
# run of one stream's lines a few places; keeps an order when it is no slower and its registers
# fit (merge2.py allocates them on the order).
#   merge2_search.py A.s B.s OUT.s SECONDS [merge2 options]
import random, re, subprocess, sys, time
sys.path.insert(0, __import__("os").path.dirname(__import__("os").path.abspath(__file__)))
import merge2  # noqa: E402


def mca(lines, cpu, it=20):
    r = subprocess.run(["llvm-mca-14", "-mtriple=aarch64", f"-mcpu={cpu}", f"-iterations={it}"],
                       input="\n".join(lines) + "\n", capture_output=True, text=True)
    return int(re.search(r"Total Cycles:\s+(\d+)", r.stdout).group(1)) / it


def build(a, b, seq, opts):
    merge2.SEQ = seq
    try:
        return merge2.main([a, b, "-"] + opts, quiet=True)
    except merge2.Stuck:
        return None


def main():
    a, b, out, secs = sys.argv[1], sys.argv[2], sys.argv[3], float(sys.argv[4])
    opts = sys.argv[5:]
    res, seq = build(a, b, None, opts)
    best = (mca(res, "cortex-a53"), mca(res, "cortex-a57"))
    print("start", best, flush=True)
    end = time.time() + secs
    rnd = random.Random(1)
    while time.time() < end:
        s = list(seq)
        n = len(s)
        i = rnd.randrange(n)
        k = rnd.randint(1, 12)
        run = s[i:i + k]
        del s[i:i + k]
        j = max(0, min(len(s), i + rnd.randint(-24, 24)))
        s[j:j] = run
        s = "".join(s)
        r = build(a, b, s, opts)
        if r is None:
            continue
        sc = (mca(r[0], "cortex-a53"), mca(r[0], "cortex-a57"))
        if sc <= best:
            if sc < best:
                print(f"{sc[0]:.2f} {sc[1]:.2f}", flush=True)
            best, seq = sc, r[1]
            open(out, "w").write("\n".join(r[0]) + "\n")
    print("best", best)


if __name__ == "__main__":
    main()
