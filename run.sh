#!/usr/bin/env bash
# run.sh: build Starbow and start it.
#   - installs missing Debian packages when run as root (else prints the apt-get line)
#   - configures and builds with the default preset (build/default)
#   - with a display: the SDL window (WASD + mouse, space/c up/down, shift faster, Esc quits)
#   - without one: headless screenshots (out/*.png) and flythrough figures for the sample maps
# Arguments are passed to the engine, e.g. ./run.sh +viewmap lq_e1m1 -res 1280x720
set -euo pipefail
cd "$(dirname "$0")"
. .ci/deps.sh
starbow_ensure_deps

cmake --preset default >/dev/null
targets=(starbow)
grep -q '^build starbow_sdl:' build/default/build.ninja && targets+=(starbow_sdl)  # SDL2 found
cmake --build --preset default --target "${targets[@]}"

bin=build/default
if [ -n "${DISPLAY:-}${WAYLAND_DISPLAY:-}" ] && [ -x "$bin/starbow_sdl" ]; then
  exec "$bin/starbow_sdl" "$@"
fi
if [ $# -gt 0 ]; then
  exec "$bin/starbow" "$@"
fi
echo "no display: running headless (screenshots in out/, flythrough figures below)"
mkdir -p out
# Starbow's own sample world (content/, compiled by tools/ during the build).
"$bin/starbow" -res 640x480 +viewmap sample +screenshot out/sample.png +flythrough 300 +quit
# LibreQuake's maps too, when the shared content sits beside the source tree.
quake="$(pwd)/../shared/quake"
if [ -d "$quake/lq1/maps" ]; then
  args=()
  for map in start lq_e0m1 lq_e1m1; do
    args+=(+viewmap "$map" +screenshot "out/$map.png" +flythrough 300)
  done
  exec "$bin/starbow" -basedir "$quake" -game lq1 -res 640x480 "${args[@]}" +quit
fi
