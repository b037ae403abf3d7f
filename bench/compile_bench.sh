#!/usr/bin/env bash
# bench/compile_bench.sh: the map compiler (sbbsp -> sbvis -> sblight) on the maps that
# ../shared/quake/REFERENCE.md measures ericw-tools on, with LibreQuake's per-map flags,
# 2 threads per stage; writes bench/compile.md: seconds per stage and the BSP's counts
# (bench/bsp_stats.py), each beside the REFERENCE.md figure and as a ratio. Never pass/fail.
#
#   bench/compile_bench.sh [-n N] [-b BUILD_DIR] [-o OUT.md] [map ...]
#     -n N        runs per map; each figure is the median of N (default 1: full vis is slow)
#     -b DIR      build tree holding tools/sbbsp, tools/sbvis, tools/sblight (default build/qa;
#                 the binaries are built there with -j2 if missing, never rebuilt otherwise)
#     -o FILE     the report (default bench/compile.md)
#     -R          report only: rewrite the report from the last run's BUILD_DIR/compile_bench/results.tsv
#     map ...     a subset, by the names in the table (start lq_e0m1 ... e1m1)
#   Environment: STARBOW_QUAKE_DIR (default ../shared/quake beside the project root),
#                THREADS (default 2), STAGE_TIMEOUT seconds per stage (default 3600).
#
# Flags: each map's -buildconfigs-/<folder>/<map>.conf gives ericw-tools' LQ_BSP_FLAGS,
# LQ_VIS_FLAGS and LQ_LIG_FLAGS. An ericw flag is passed on when the Starbow stage lists an
# option of the same name in its usage text (so options the stages gain later are picked
# up); every other flag is ignored and named in the report. LQ_SKIP as vis flags: no vis.
# The id map e1m1 (idmaps/, no textures here) is compiled with default flags, as in the
# reference. Work files go to BUILD_DIR/compile_bench/.
set -euo pipefail
cd "$(dirname "$0")/.."
ROOT=$PWD
RUNS=1
BUILD=$ROOT/build/qa
OUT=$ROOT/bench/compile.md
REPORT_ONLY=0
while getopts "n:b:o:R" opt; do
  case $opt in
    R) REPORT_ONLY=1 ;;
    n) RUNS=$OPTARG ;;
    b) BUILD=$(cd "$OPTARG" && pwd) ;;
    o) OUT=$OPTARG ;;
    *) sed -n '2,20p' "$0"; exit 2 ;;
  esac
done
shift $((OPTIND - 1))
QUAKE=${STARBOW_QUAKE_DIR:-$ROOT/../shared/quake}
QUAKE=$(cd "$QUAKE" && pwd)
THREADS=${THREADS:-2}
STAGE_TIMEOUT=${STAGE_TIMEOUT:-3600}
SRC=$QUAKE/lq1/maps/src
CONF=$SRC/-buildconfigs-

# name | source (relative to the Quake folder) | config (relative to -buildconfigs-, "-": defaults)
MAPS=(
  "start|lq1/maps/src/misc/start.map|misc/start.conf"
  "lq_e0m1|lq1/maps/src/e0/lq_e0m1.map|e0/lq_e0m1.conf"
  "lq_e0m3|lq1/maps/src/e0/lq_e0m3.map|e0/lq_e0m3.conf"
  "lqdm1|lq1/maps/src/dm/lqdm1.map|dm/lqdm1.conf"
  "lqdm2|lq1/maps/src/dm/lqdm2.map|dm/lqdm2.conf"
  "lqdm3|lq1/maps/src/dm/lqdm3.map|dm/lqdm3.conf"
  "lq_e1m2|lq1/maps/src/e1/lq_e1m2.map|e1/lq_e1m2.conf"
  "lq_e1m1|lq1/maps/src/e1/lq_e1m1.map|e1/lq_e1m1.conf"
  "e1m1|idmaps/e1m1.map|-"
)
if (($#)); then
  keep=()
  for want in "$@"; do
    found=0
    for m in "${MAPS[@]}"; do [ "${m%%|*}" = "$want" ] && keep+=("$m") && found=1; done
    ((found)) || { echo "compile_bench: unknown map '$want'" >&2; exit 2; }
  done
  MAPS=("${keep[@]}")
fi

TOOLS=$BUILD/tools
if [ ! -x "$TOOLS/sbbsp" ] || [ ! -x "$TOOLS/sbvis" ] || [ ! -x "$TOOLS/sblight" ]; then
  [ -f "$BUILD/build.ninja" ] || cmake -S "$ROOT" -B "$BUILD" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo
  cmake --build "$BUILD" -j2 --target sbbsp sbvis sblight
fi
WORK=$BUILD/compile_bench
mkdir -p "$WORK"
RAW=$WORK/results.tsv
if ((REPORT_ONLY)); then
  MAPS=()
  started=$(sed -n 1p "$WORK/when" 2>/dev/null || echo "?")
  finished=$(sed -n 2p "$WORK/when" 2>/dev/null || echo "?")
  load_start=$(sed -n 3p "$WORK/when" 2>/dev/null || echo "?")
  RUNS=$(cut -f2 "$RAW" | sort -n | tail -1)
else
  : >"$RAW"
fi

# usage text of each stage, for the flag mapping
usage_bsp=$("$TOOLS/sbbsp" -h 2>&1 || true)
usage_vis=$("$TOOLS/sbvis" -h 2>&1 || true)
usage_light=$("$TOOLS/sblight" -h 2>&1 || true)

conf_value() {  # conf_value FILE KEY: the quoted value of KEY="..." (several may share a line)
  grep -o "$2=\"[^\"]*\"" "$1" 2>/dev/null | head -1 | sed "s/^$2=\"//; s/\"\$//" || true
}

# map_flags USAGE FLAGS...: prints "passed|ignored"; a number after a flag goes with it.
map_flags() {
  local usage=$1; shift
  local passed="" ignored="" prev_ok=-1
  for f in "$@"; do
    if [[ $f =~ ^-?[0-9.]+$ ]] && ((prev_ok >= 0)); then
      if ((prev_ok)); then passed+=" $f"; else ignored+=" $f"; fi
      continue
    fi
    if grep -qE -- "(^|[[ ])$f([] ]|\$)" <<<"$usage"; then passed+=" $f"; prev_ok=1
    else ignored+=" $f"; prev_ok=0; fi
  done
  printf '%s|%s\n' "${passed# }" "${ignored# }"
}

now() { date +%s.%N; }

# run_stage LOG CMD...: runs with the stage timeout; prints "seconds status" (status: ok,
# exit N, signal NAME, timeout).
run_stage() {
  local log=$1; shift
  local t0 t1 rc
  t0=$(now)
  set +e
  timeout "$STAGE_TIMEOUT" "$@" >"$log" 2>&1
  rc=$?
  set -e
  t1=$(now)
  local st=ok
  if ((rc == 124)); then st=timeout
  elif ((rc > 128)); then st="signal $(kill -l $((rc - 128)) 2>/dev/null || echo $((rc - 128)))"
  elif ((rc != 0)); then st="exit $rc"; fi
  printf '%s %s\n' "$(awk -v a="$t0" -v b="$t1" 'BEGIN{printf "%.2f", b-a}')" "$st"
}

if ((!REPORT_ONLY)); then
  started=$(date -u '+%Y-%m-%d %H:%M UTC')
  load_start=$(cut -d' ' -f1-3 /proc/loadavg 2>/dev/null || echo "?")
fi
for m in "${MAPS[@]}"; do
  IFS='|' read -r name src conf <<<"$m"
  bspf="" visf="" ligf=""
  if [ "$conf" != "-" ]; then
    bspf=$(conf_value "$CONF/$conf" LQ_BSP_FLAGS)
    visf=$(conf_value "$CONF/$conf" LQ_VIS_FLAGS)
    ligf=$(conf_value "$CONF/$conf" LQ_LIG_FLAGS)
  fi
  skipvis=0
  [ "$visf" = "LQ_SKIP" ] && skipvis=1 && visf=""
  # shellcheck disable=SC2086
  IFS='|' read -r bsp_pass bsp_ign < <(map_flags "$usage_bsp" $bspf)
  # shellcheck disable=SC2086
  IFS='|' read -r vis_pass vis_ign < <(map_flags "$usage_vis" $visf)
  # shellcheck disable=SC2086
  IFS='|' read -r lig_pass lig_ign < <(map_flags "$usage_light" $ligf)
  for ((run = 1; run <= RUNS; run++)); do
    out=$WORK/$name.bsp
    rm -f "$out" "$WORK/$name.prt" "$WORK/$name.pts"
    echo "== $name run $run/$RUNS: sbbsp $bsp_pass | sbvis $vis_pass | sblight $lig_pass" >&2
    # shellcheck disable=SC2086
    read -r t_bsp s_bsp < <(run_stage "$WORK/$name.bsp.log" "$TOOLS/sbbsp" -threads "$THREADS" $bsp_pass \
                                       "$QUAKE/$src" "$out")
    t_vis=- s_vis=skipped t_lig=- s_lig=skipped
    if [ "$s_bsp" = ok ] && [ -f "$WORK/$name.pts" ]; then s_bsp=leak; fi
    if [ "$s_bsp" = ok ] && ((!skipvis)); then
      # shellcheck disable=SC2086
      read -r t_vis s_vis < <(run_stage "$WORK/$name.vis.log" "$TOOLS/sbvis" -threads "$THREADS" $vis_pass "$out")
    fi
    if [ "$s_bsp" = ok ] || [ "$s_bsp" = leak ]; then
      # shellcheck disable=SC2086
      read -r t_lig s_lig < <(run_stage "$WORK/$name.light.log" "$TOOLS/sblight" -threads "$THREADS" $lig_pass "$out")
    fi
    counts=$(python3 "$ROOT/bench/bsp_stats.py" "$out" 2>/dev/null || echo '{}')
    printf '%s\t%s\t%s %s\t%s %s\t%s %s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\n' "$name" "$run" "$t_bsp" "$s_bsp" \
      "$t_vis" "$s_vis" "$t_lig" "$s_lig" "$counts" "$bsp_pass" "$bsp_ign" "$vis_pass" "$vis_ign" \
      "$lig_pass" "$lig_ign" >>"$RAW"
    echo "   sbbsp $t_bsp s ($s_bsp), sbvis $t_vis s ($s_vis), sblight $t_lig s ($s_lig)" >&2
  done
done
if ((!REPORT_ONLY)); then
  finished=$(date -u '+%Y-%m-%d %H:%M UTC')
  printf '%s\n%s\n%s\n' "$started" "$finished" "$load_start" >"$WORK/when"
fi

python3 - "$RAW" "$OUT" "$started" "$finished" "$RUNS" "$THREADS" "$(uname -srm)" "$(nproc)" "$load_start" "$WORK" <<'EOF'
import json, os, re, statistics, sys
raw, out, started, finished, runs, threads, uname, ncpu, load, work = sys.argv[1:]
# ericw-tools figures from ../shared/quake/REFERENCE.md (June 2025 build, 2 threads):
# qbsp s, vis s, light s, faces, leafs, nodes, clipnodes, vis_leaves, vis_faces
REF = {
    "start":   (0.3, 0.0, 5.5, 1105, 524, 622, 1264, 65.1, 423.2),
    "lq_e0m1": (2.3, 0.4, 55.4, 3865, 1094, 1979, 5123, 99.3, 517.2),
    "lq_e0m3": (5.2, 13.2, 13.0, 4566, 1431, 2620, 7060, 125.6, 603.2),
    "lqdm1":   (4.2, 0.3, 53.4, 4292, 1123, 2130, 3359, 698.1, 3954.7),
    "lqdm2":   (2.4, 0.1, 4.2, 3644, 863, 1516, 2306, 480.8, 2683.1),
    "lqdm3":   (20.3, 13.0, 67.8, 12139, 3244, 5921, 9563, 1644.7, 8145.3),
    "lq_e1m2": (8.4, 1.0, 23.8, 11671, 3654, 5778, 17178, 564.9, 3128.3),
    "lq_e1m1": (16.4, 16.3, 329.5, 17373, 4730, 8017, 19776, 581.8, 3396.7),
    "e1m1":    (4.5, 6.6, 0.4, 6911, 1846, 3426, 7442, 164.8, 1046.7),
}
rows = {}
order = []
for line in open(raw):
    f = line.rstrip("\n").split("\t")
    name = f[0]
    if name not in rows:
        rows[name] = []
        order.append(name)
    rows[name].append(f)

def stage(cell):
    t, st = cell.split(" ", 1)
    return (None if t == "-" else float(t)), st

def med(xs):
    xs = [x for x in xs if x is not None]
    return statistics.median(xs) if xs else None

def fmt(x, digits=1):
    if x is None:
        return "—"
    if isinstance(x, int) or (isinstance(x, float) and x.is_integer() and digits == 0):
        return str(int(x))
    return ("%%.%df" % digits) % x

def ratio(a, b):
    if a is None or b is None or b == 0:
        return "—"
    return "%.2f" % (a / b)

lines = []
lines.append("# Map compiler benchmark: sbbsp, sbvis, sblight beside ericw-tools")
lines.append("")
lines.append("Written by bench/compile_bench.sh (counts: bench/bsp_stats.py). Never pass/fail.")
lines.append("Numbers taken %s to %s on %s, %s CPUs (load average at the start: %s, other work"
             % (started, finished, uname, ncpu, load))
lines.append("running); %s thread(s) per stage; median of %s run(s)." % (threads, runs))
lines.append("Tools built from commit %s. Times are" % __import__("subprocess").run(["git", "describe", "--always", "--dirty"], capture_output=True, text=True).stdout.strip())
lines.append("wall-clock seconds of each program (process start to exit, file I/O included) on a shared,")
lines.append("noisy machine: treat them as ±30%, as REFERENCE.md does. ericw figures: ../shared/quake/REFERENCE.md.")
lines.append("")
lines.append("Each cell is `ours (ericw) ratio`; ratio = ours / ericw (for times and counts lower is")
lines.append("better; for vis_leaves and vis_faces lower means a tighter PVS).")
lines.append("")
cols = ["sbbsp s", "sbvis s (full)", "sblight s", "faces", "leafs", "nodes", "clipnodes", "vis_leaves", "vis_faces"]
lines.append("| map | " + " | ".join(cols) + " |")
lines.append("|---|" + "---|" * len(cols))
notes = []
flag_rows = []
for name in order:
    rs = rows[name]
    tb = [stage(r[2]) for r in rs]
    tv = [stage(r[3]) for r in rs]
    tl = [stage(r[4]) for r in rs]
    counts = [json.loads(r[5]) if r[5] else {} for r in rs]
    ref = REF.get(name)
    cells = []
    for i, series in enumerate((tb, tv, tl)):
        v = med([t for t, st in series if st in ("ok", "leak")])
        bad = sorted({st for t, st in series if st not in ("ok",)})
        c = "%s (%s) %s" % (fmt(v, 2), fmt(ref[i], 1) if ref else "—", ratio(v, ref[i] if ref else None))
        if bad:
            c += " **" + ", ".join(bad) + "**"
        cells.append(c)
    for j, key in enumerate(("faces", "leafs", "nodes", "clipnodes", "vis_leaves", "vis_faces")):
        d = 1 if key.startswith("vis_") else 0
        r = ref[3 + j] if ref else None
        if d and not any(c.get("visdata_bytes") for c in counts):
            cells.append("no visdata (%s)" % fmt(r, d))
            continue
        v = med([c.get(key) for c in counts])
        cells.append("%s (%s) %s" % (fmt(v, d), fmt(r, d), ratio(v, r)))
    lines.append("| %s | %s |" % (name, " | ".join(cells)))
    r0 = rs[0]
    flag_rows.append("| %s | %s | %s | %s | %s | %s | %s |" % (
        name, r0[6] or "—", r0[7] or "—", r0[8] or "—", r0[9] or "—", r0[10] or "—", r0[11] or "—"))
    for c in counts:
        if "error" in c:
            notes.append("- %s: counts unreadable: %s" % (name, c["error"]))
    try:
        log = open(os.path.join(work, name + ".bsp.log")).read()
    except OSError:
        log = ""
    mm = re.search(r"\((\d+) missing\)", log)
    if mm and mm.group(1) != "0":
        notes.append("- %s: %s textures missing (sbbsp found no WAD holding them; drawn as the placeholder)"
                     % (name, mm.group(1)))
    lk = re.search(r"^leak: .*$", log, re.M)
    if lk:
        notes.append("- %s: sbbsp reports `%s`; ericw-tools compiles it sealed (its BSP in lq1/maps has"
                     " visdata), so this is an sbbsp finding; vis not run, vis counts absent" % (name, lk.group(0)))
lines.append("")
lines.append("vis_leaves: mean number of leaves in a leaf's PVS; vis_faces: mean of the marksurfaces of")
lines.append("the leaves in a leaf's PVS (both over leaves 1..visleafs of model 0; REFERENCE.md's")
lines.append("definitions; bsp_stats.py reproduces REFERENCE.md's figures exactly from the ericw-built")
lines.append("BSPs in lq1/maps/). leafs counts every leaf in the lump (leaf 0 included), like the header.")
lines.append("A stage marked **exit N / signal / timeout / leak** did not finish cleanly; — means not run")
lines.append("(LibreQuake's config skips vis, or an earlier stage failed).")
lines.append("")
lines.append("## Flags")
lines.append("")
lines.append("From lq1/maps/src/-buildconfigs-/ (ericw-tools flags). A flag is passed when the Starbow")
lines.append("stage's usage text lists an option of that name; the rest have no equivalent yet and are")
lines.append("ignored. All stages also get `-threads %s`. e1m1: ericw defaults, so none." % threads)
lines.append("")
lines.append("| map | sbbsp passed | sbbsp ignored | sbvis passed | sbvis ignored | sblight passed | sblight ignored |")
lines.append("|---|---|---|---|---|---|---|")
lines += flag_rows
notes.append("- lq_e0m3: its build config asks light for `-extra4 -bounce -dirt`; REFERENCE.md lists"
             " ericw's time as `(-bounce -dirt)`. The config's flags were used here.")
notes.append("- ericw flags with no Starbow option: qbsp -transwater and -splitturb (sbbsp has no switch"
             " for how liquids are portalled or subdivided), vis -noambient* (tools/vis computes no ambient"
             " sound levels), light -soft. They stay listed as ignored above until a stage's usage lists them.")
lines.append("")
lines.append("## Notes")
lines.append("")
lines += notes
open(out, "w").write("\n".join(lines) + "\n")
print("\n".join(lines))
EOF
