#!/usr/bin/env bash
# bench/testmaps.sh: every .map under ../shared/quake/testmaps (ericw-tools' compiler test maps,
# many of them edge cases, and the 7dfps map) through sbbsp, then sbvis -fast and sblight;
# writes docs/testmaps.md: per map the result (ok / leak / error + message / crash + signal /
# timeout), faces, seconds per stage. A crash (a stage ended by a signal) is a bug, always.
#
#   bench/testmaps.sh [-b BUILD_DIR] [-o OUT.md] [-t SECONDS] [substring ...]
#     -b DIR      build tree with tools/sbbsp, tools/sbvis, tools/sblight (default build/qa;
#                 built there with -j2 when missing, never rebuilt otherwise)
#     -o FILE     the report (default docs/testmaps.md)
#     -t S        time limit per stage (default 300 s): over it is "timeout"
#     substring   only maps whose path (relative to testmaps/) contains one of these
#   STARBOW_QUAKE_DIR: the Quake folder (default ../shared/quake beside the project root).
#
# Default flags everywhere except vis (-fast); the maps name WADs that are mostly absent
# (free_wad.wad), so most compile with missing textures: that is reported, not an error.
# Quake 2 / Half-Life / Hexen 2 maps are attempted like the rest; what sbbsp says about
# them is the result. Work files: BUILD_DIR/testmaps/ (one folder, rewritten each run).
set -euo pipefail
cd "$(dirname "$0")/.."
ROOT=$PWD
BUILD=$ROOT/build/qa
OUT=$ROOT/docs/testmaps.md
LIMIT=300
while getopts "b:o:t:" opt; do
  case $opt in
    b) BUILD=$(cd "$OPTARG" && pwd) ;;
    o) OUT=$OPTARG ;;
    t) LIMIT=$OPTARG ;;
    *) sed -n '2,20p' "$0"; exit 2 ;;
  esac
done
shift $((OPTIND - 1))
QUAKE=${STARBOW_QUAKE_DIR:-$ROOT/../shared/quake}
QUAKE=$(cd "$QUAKE" && pwd)
TM=$QUAKE/testmaps
TOOLS=$BUILD/tools
if [ ! -x "$TOOLS/sbbsp" ] || [ ! -x "$TOOLS/sbvis" ] || [ ! -x "$TOOLS/sblight" ]; then
  [ -f "$BUILD/build.ninja" ] || cmake -S "$ROOT" -B "$BUILD" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo
  cmake --build "$BUILD" -j2 --target sbbsp sbvis sblight
fi
WORK=$BUILD/testmaps
rm -rf "$WORK"
mkdir -p "$WORK"
RAW=$WORK/results.tsv
: >"$RAW"

mapfile -t MAPS < <(cd "$TM" && find . -name '*.map' -type f | sed 's|^\./||' | LC_ALL=C sort)
if (($#)); then
  keep=()
  for m in "${MAPS[@]}"; do
    for s in "$@"; do [[ $m == *"$s"* ]] && { keep+=("$m"); break; }; done
  done
  MAPS=("${keep[@]}")
fi

now() { date +%s.%N; }
# run_stage LOG CMD...: prints "seconds<TAB>status" (ok, exit N, signal NAME, timeout).
run_stage() {
  local log=$1; shift
  local t0 t1 rc st=ok
  t0=$(now)
  set +e
  timeout -k 10 "$LIMIT" "$@" >"$log" 2>&1
  rc=$?
  set -e
  t1=$(now)
  if ((rc == 124 || rc == 137)) && [ "$(awk -v a="$t0" -v b="$t1" -v l="$LIMIT" 'BEGIN{print (b-a >= l)}')" = 1 ]; then
    st=timeout
  elif ((rc > 128)); then st="signal $(kill -l $((rc - 128)) 2>/dev/null || echo $((rc - 128)))"
  elif ((rc != 0)); then st="exit $rc"; fi
  printf '%s\t%s\n' "$(awk -v a="$t0" -v b="$t1" 'BEGIN{printf "%.2f", b-a}')" "$st"
}
# first_line LOG REGEX: the first matching line (or the last line), tabs and pipes flattened.
first_line() {
  { grep -m1 -E "$2" "$1" || tail -n1 "$1"; } 2>/dev/null | tr '\t|' '  ' | cut -c1-200
}
# last_line LOG: the last line (where the stages print the error that stopped them).
last_line() { tail -n1 "$1" 2>/dev/null | tr '\t|' '  ' | cut -c1-240; }

started=$(date -u '+%Y-%m-%d %H:%M UTC')
i=0
for m in "${MAPS[@]}"; do
  i=$((i + 1))
  id=${m//\//__}
  id=${id%.map}
  bsp=$WORK/$id.bsp
  IFS=$'\t' read -r t_bsp s_bsp < <(run_stage "$WORK/$id.sbbsp.log" "$TOOLS/sbbsp" "$TM/$m" "$bsp")
  t_vis=- s_vis=- t_lig=- s_lig=- msg=""
  leak=0
  [ -f "$WORK/$id.pts" ] && leak=1
  if [ "$s_bsp" = ok ] && ((!leak)) && [ -f "$WORK/$id.prt" ]; then
    IFS=$'\t' read -r t_vis s_vis < <(run_stage "$WORK/$id.sbvis.log" "$TOOLS/sbvis" -fast "$bsp")
  fi
  if [ "$s_bsp" = ok ] && [ -f "$bsp" ]; then
    IFS=$'\t' read -r t_lig s_lig < <(run_stage "$WORK/$id.sblight.log" "$TOOLS/sblight" "$bsp")
  fi
  # result: the worst thing that happened, first stage first
  result=ok
  for pair in "sbbsp:$s_bsp" "sbvis:$s_vis" "sblight:$s_lig"; do
    stage=${pair%%:*} st=${pair#*:}
    case $st in
      ok | -) ;;
      signal*) result="crash"; msg="$stage: $st: $(first_line "$WORK/$id.$stage.log" 'rror|assert|Assert')"; break ;;
      timeout) result="timeout"; msg="$stage: over $LIMIT s"; break ;;
      exit*) result="error"; msg="$stage: $st: $(last_line "$WORK/$id.$stage.log")"; break ;;
    esac
  done
  if [ "$result" = ok ] && ((leak)); then
    result=leak
    msg=$(first_line "$WORK/$id.sbbsp.log" 'leak')
  fi
  if [ "$result" = ok ] && [ "$s_bsp" = ok ] && [ ! -f "$WORK/$id.prt" ] && ((!leak)); then
    msg="no .prt (vis not run)"
  fi
  missing=$(grep -oE '\(([0-9]+) missing\)' "$WORK/$id.sbbsp.log" 2>/dev/null | head -1 | tr -dc '0-9' || true)
  nopoint=$(grep -c 'no point entities' "$WORK/$id.sbbsp.log" 2>/dev/null || true)
  faces=-
  fmt=-
  if [ -f "$bsp" ]; then
    stats=$(python3 "$ROOT/bench/bsp_stats.py" "$bsp" 2>/dev/null || true)
    faces=$(python3 -c 'import json,sys; d=json.loads(sys.argv[1]); print(d.get("faces","-"))' "$stats" 2>/dev/null || echo -)
    fmt=$(python3 -c 'import json,sys; d=json.loads(sys.argv[1]); print(d.get("format","-"))' "$stats" 2>/dev/null || echo -)
  fi
  printf '%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\n' "$m" "$result" "$msg" "$faces" "$fmt" "$t_bsp" "$t_vis" \
    "$t_lig" "${missing:-}" "${nopoint:-0}" >>"$RAW"
  printf '[%d/%d] %-50s %-7s %s\n' "$i" "${#MAPS[@]}" "$m" "$result" "$msg" >&2
done
finished=$(date -u '+%Y-%m-%d %H:%M UTC')

python3 - "$RAW" "$OUT" "$started" "$finished" "$LIMIT" <<'EOF'
import sys
raw, out, started, finished, limit = sys.argv[1:]
rows = [l.rstrip("\n").split("\t") for l in open(raw) if l.strip()]
count = {}
for r in rows:
    count[r[1]] = count.get(r[1], 0) + 1
L = []
L.append("# Compiler test maps through sbbsp, sbvis -fast, sblight")
L.append("")
L.append("Written by bench/testmaps.sh from %s to %s: every .map under ../shared/quake/testmaps/"
         % (started, finished))
L.append("(ericw-tools' compiler test maps, Quake 1 and 2 and a few Half-Life / Hexen 2 ones, and the")
L.append("7dfps map), default flags, sbvis -fast, %s s limit per stage. Most name a WAD that is not" % limit)
L.append("there, so they compile with missing textures; that alone is not a failure.")
L.append("Tools built from commit %s." % __import__("subprocess").run(["git", "describe", "--always", "--dirty"], capture_output=True, text=True).stdout.strip())
L.append("")
L.append("Results: " + ", ".join("%s %d" % (k, count[k]) for k in
                                ("ok", "leak", "error", "crash", "timeout") if k in count) +
         " (of %d maps)." % len(rows))
L.append("")
for kind, title in (("crash", "Crashes (a stage ended by a signal: always a bug)"),
                    ("timeout", "Timeouts"), ("error", "Errors")):
    sel = [r for r in rows if r[1] == kind]
    L.append("## %s: %d" % (title, len(sel)))
    L.append("")
    for r in sel:
        L.append("- `%s`: %s" % (r[0], r[2]))
    if not sel:
        L.append("none")
    L.append("")
L.append("## Every map")
L.append("")
L.append("result: ok (every stage exited 0, no leak), leak (sbbsp wrote a .pts; vis not run, light")
L.append("run), error (a stage exited non-zero: its message), crash, timeout. Seconds are wall-clock")
L.append("per program; — = not run. missing: textures sbbsp could not find.")
L.append("")
L.append("| map | result | faces | format | sbbsp s | sbvis s | sblight s | missing | notes |")
L.append("|---|---|---|---|---|---|---|---|---|")
for r in rows:
    m, result, msg, faces, fmt, tb, tv, tl, missing, nopoint = r
    notes = msg
    if nopoint not in ("", "0"):
        notes = (notes + "; " if notes else "") + "no point entities (no outside fill)"
    res = "**%s**" % result if result in ("crash", "timeout") else result
    dash = lambda x: "—" if x in ("-", "") else x
    L.append("| %s | %s | %s | %s | %s | %s | %s | %s | %s |" % (
        m, res, dash(faces), dash(fmt), dash(tb), dash(tv), dash(tl), dash(missing), notes.replace("|", "/")))
open(out, "w").write("\n".join(L) + "\n")
print("\n".join(L[:40]))
EOF
