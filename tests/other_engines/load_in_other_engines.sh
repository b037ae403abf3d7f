#!/usr/bin/env bash
# tests/other_engines/load_in_other_engines.sh: do other Quake engines load what Starbow's
# compiler writes? Each BSP is put in a scratch game folder (LibreQuake's lq1 as the base
# game, for progs.dat) and started as a map by the dedicated servers of QuakeSpasm and
# DarkPlaces (Debian packages quakespasm, darkplaces-server): the server must reach
# "status" with the map running and exit normally. A truncated copy of the first BSP is the
# negative control: both engines must fail to run it, or the check proves nothing.
#
# usage: load_in_other_engines.sh <quake_dir> <scratch_dir> <file.bsp | file.map>...
# A .map is compiled first with $SBBSP, $SBVIS and $SBLIGHT (paths to Starbow's tools).
# Exit 77 (ctest SKIP_RETURN_CODE) when the engines or LibreQuake's data are absent.
set -u
quake_dir=$1; scratch=$2; shift 2
qs=/usr/games/quakespasm
dp=/usr/games/darkplaces-server
if [ ! -x "$qs" ] || [ ! -x "$dp" ]; then
  echo "SKIP: $qs or $dp missing (apt-get install quakespasm darkplaces-server)"; exit 77
fi
if [ ! -f "$quake_dir/lq1/progs.dat" ] && [ ! -f "$quake_dir/lq1/pak0.pak" ]; then
  echo "SKIP: no LibreQuake game data in $quake_dir/lq1"; exit 77
fi
rm -rf "$scratch"; mkdir -p "$scratch/base/sbtest/maps"
ln -s "$(cd "$quake_dir/lq1" && pwd)" "$scratch/base/id1"

# run_engine <label> <map>: prints the log; 0 when the map ran and the server quit cleanly.
run_engine() {
  local label=$1 map=$2 log="$scratch/$1-$2.log" rc
  case $label in
    quakespasm) timeout 60 "$qs" -dedicated 1 -basedir "$scratch/base" -game sbtest +map "$map" +status +quit >"$log" 2>&1 ;;
    darkplaces) timeout 60 "$dp" -basedir "$scratch/base" -game sbtest +map "$map" +status +quit >"$log" 2>&1 ;;
  esac
  rc=$?
  if [ $rc -ne 0 ]; then echo "  $label $map: exit code $rc"; tail -3 "$log" | sed 's/^/    /'; return 1; fi
  if grep -qiE "Host_Error|Couldn't spawn|SYS_Error|Mod_.*(bad|invalid|wrong)" "$log"; then
    echo "  $label $map: error in log:"; grep -iE "Host_Error|Couldn't spawn|SYS_Error|Mod_" "$log" | head -3 | sed 's/^/    /'
    return 1
  fi
  if ! grep -qE "^map: +$map\$" "$log"; then echo "  $label $map: no 'map: $map' status line"; tail -3 "$log" | sed 's/^/    /'; return 1; fi
  echo "  $label $map: loaded and ran"
  return 0
}

fail=0
first=""
mkdir -p "$scratch/compiled"
for arg in "$@"; do
  bsp=$arg
  if [ "${arg%.map}" != "$arg" ]; then
    bsp="$scratch/compiled/$(basename "$arg" .map).bsp"
    if ! "$SBBSP" -q "$arg" "$bsp" || ! "$SBVIS" -q "$bsp" || ! "$SBLIGHT" -q "$bsp"; then
      echo "$arg: Starbow's tools failed"; fail=1; continue
    fi
  fi
  name=$(basename "$bsp" .bsp)
  cp "$bsp" "$scratch/base/sbtest/maps/$name.bsp"
  [ -f "${bsp%.bsp}.lit" ] && cp "${bsp%.bsp}.lit" "$scratch/base/sbtest/maps/$name.lit"
  [ -z "$first" ] && first=$name
  echo "$name ($(head -c 4 "$bsp" | od -An -tu4 | tr -d ' ' | sed 's/^29$/BSP29/'), $(stat -c %s "$bsp") bytes):"
  run_engine quakespasm "$name" || fail=1
  run_engine darkplaces "$name" || fail=1
done

# Negative control: the same file cut short must not "load".
head -c 4096 "$scratch/base/sbtest/maps/$first.bsp" > "$scratch/base/sbtest/maps/truncated.bsp"
echo "negative control (first BSP truncated to 4096 bytes):"
for label in quakespasm darkplaces; do
  if run_engine $label truncated >/dev/null; then echo "  $label accepted a truncated BSP: the check cannot fail"; fail=1
  else echo "  $label rejected it (as it must)"; fi
done
exit $fail
