#!/usr/bin/env bash
# bench/count.sh: instruction counts and estimated cycles for every asm/ kernel x target x
# variant, plus instructions per pixel per frame (x86-64, aarch64, armhf), as one table printed and written
# to bench/counts.md. Deterministic counts, model-estimated cycles; never pass/fail.
#
#   bench/count.sh            everything (about 2 minutes on 2 cores once built)
#   bench/count.sh --quick    kernels only, no whole-frame runs
#   bench/count.sh --only=block_mip,span [--variants=scalar,neon]   the cases whose names
#                             start so (starbow_count_kernels list), those variants; only those
#                             rows of bench/counts.md are replaced (see bench/count_report.py)
#
# Builds (only what it needs, own build dirs, -no-pie so addresses match the binary):
#   build/count          starbow_count_kernels + starbow (x86-64, native)
#   build/count-aarch64  starbow_count_kernels + starbow (toolchain/aarch64-linux-gnu.cmake)
#   build/count-armhf    starbow_count_kernels + starbow (toolchain/arm-linux-gnueabihf.cmake, NEON)
#   build/qemu-plugins   libinsn.so, libhotblocks.so from Debian's qemu source package
#                        (cached: built once; a private apt sources list with deb-src lines)
# Needs (Debian): valgrind qemu-user g++-aarch64-linux-gnu g++-arm-linux-gnueabihf llvm-14
# libglib2.0-dev; installed with apt-get when run as root. The work is in
# bench/count_report.py.
set -euo pipefail
cd "$(dirname "$0")/.."
ROOT=$PWD

need=()
for p in valgrind:valgrind qemu-aarch64:qemu-user aarch64-linux-gnu-g++:g++-aarch64-linux-gnu \
         arm-linux-gnueabihf-g++:g++-arm-linux-gnueabihf llvm-mca-14:llvm-14 pkg-config:pkg-config; do
  command -v "${p%%:*}" >/dev/null || need+=("${p#*:}")
done
pkg-config --exists glib-2.0 2>/dev/null || need+=(libglib2.0-dev)
if ((${#need[@]})); then
  if [ "$(id -u)" = 0 ]; then
    apt-get install -y --no-install-recommends "${need[@]}"
  else
    echo "missing: ${need[*]} (sudo apt-get install ${need[*]})" >&2
    exit 1
  fi
fi

# ---- the qemu TCG plugins (Debian ships qemu-user without them)
PLUG=$ROOT/build/qemu-plugins
if [ ! -f "$PLUG/libinsn.so" ] || [ ! -f "$PLUG/libhotblocks.so" ]; then
  echo "== building qemu plugins from Debian's qemu source package (once)"
  mkdir -p "$PLUG/apt/lists/partial" "$PLUG/apt/cache/archives/partial" "$PLUG/src"
  codename=$(. /etc/os-release && echo "${VERSION_CODENAME:-bookworm}")
  cat >"$PLUG/apt/sources.list" <<EOF
deb-src http://deb.debian.org/debian $codename main
deb-src http://deb.debian.org/debian $codename-updates main
deb-src http://deb.debian.org/debian-security $codename-security main
EOF
  apt_opts=(-o "Dir::Etc::SourceList=$PLUG/apt/sources.list" -o Dir::Etc::SourceParts=/dev/null
            -o "Dir::State::Lists=$PLUG/apt/lists" -o "Dir::Cache=$PLUG/apt/cache")
  [ "$(id -u)" = 0 ] && apt_opts+=(-o APT::Sandbox::User=root)
  apt-get "${apt_opts[@]}" update >/dev/null
  (cd "$PLUG/src" && apt-get "${apt_opts[@]}" source --download-only qemu >/dev/null)
  tarball=$(ls "$PLUG"/src/qemu_*.orig.tar.* | head -1)
  top=$(set +o pipefail; tar -tf "$tarball" | head -1 | cut -d/ -f1)
  tar -xf "$tarball" -C "$PLUG/src" "$top/include/qemu/qemu-plugin.h" "$top/tests/plugin/insn.c" \
      "$top/contrib/plugins/hotblocks.c"
  # hotblocks reports its 20 most executed blocks; 400 covers a kernel's hot code.
  sed -i "s/static guint64 limit = 20;/static guint64 limit = 400;/" "$PLUG/src/$top/contrib/plugins/hotblocks.c"
  for c in tests/plugin/insn.c contrib/plugins/hotblocks.c; do
    n=$(basename "$c" .c)
    # shellcheck disable=SC2046
    gcc -O2 -shared -fPIC -o "$PLUG/lib$n.so" "$PLUG/src/$top/$c" -I"$PLUG/src/$top/include/qemu" \
        $(pkg-config --cflags --libs glib-2.0)
  done
fi
# hotblocks keys its table by pc ^ instruction count, so two blocks can share an entry (one
# block's executions then counted under the other's address and length: seen on armhf, a
# 71-instruction loop merged into a 19-instruction block). Key by pc ^ count << 48 instead
# (unique for user-space addresses). Applied once to a cached plugin build too.
if [ ! -f "$PLUG/hotblocks-key-fixed" ]; then
  hb=$(ls "$PLUG"/src/*/contrib/plugins/hotblocks.c | head -1)
  sed -i "s/uint64_t hash = pc ^ insns;/uint64_t hash = pc ^ ((uint64_t) insns << 48);/" "$hb"
  # shellcheck disable=SC2046
  gcc -O2 -shared -fPIC -o "$PLUG/libhotblocks.so" "$hb" -I"$(dirname "$hb")/../../include/qemu" \
      $(pkg-config --cflags --libs glib-2.0)
  touch "$PLUG/hotblocks-key-fixed"
fi

# ---- builds
echo "== building starbow_count_kernels (x86-64, aarch64, armhf) and starbow"
configure() {  # dir [cmake args...]
  local dir=$1; shift
  [ -f "$ROOT/build/$dir/build.ninja" ] || cmake -S "$ROOT" -B "$ROOT/build/$dir" -G Ninja \
    -DCMAKE_BUILD_TYPE=RelWithDebInfo -DSTARBOW_TESTS=OFF -DCMAKE_EXE_LINKER_FLAGS=-no-pie "$@" >/dev/null
}
tools=OFF
[ -d "${STARBOW_QUAKE_DIR:-$ROOT/../shared/quake}/lq1" ] || tools=ON  # sample map needs content/
configure count -DSTARBOW_BENCH=OFF -DSTARBOW_TOOLS=$tools
configure count-aarch64 -DCMAKE_TOOLCHAIN_FILE="$ROOT/toolchain/aarch64-linux-gnu.cmake"
configure count-armhf -DCMAKE_TOOLCHAIN_FILE="$ROOT/toolchain/arm-linux-gnueabihf.cmake"
build() {  # dir target...: the build's output goes to build/<dir>.log, its end to stderr on failure
  local dir=$1 log="$ROOT/build/$1.log"; shift
  cmake --build "build/$dir" -j2 --target "$@" >"$log" 2>&1 || {
    echo "count.sh: building $* in build/$dir failed; the end of $log:" >&2
    tail -n 40 "$log" >&2
    exit 1
  }
}
build count starbow_count_kernels starbow
if [[ " $* " == *" --quick "* || " $* " == *" --only="* || " $* " == *" --variants="* ]]; then
  build count-aarch64 starbow_count_kernels
  build count-armhf starbow_count_kernels
else  # whole frames on ARM too (the headless starbow under qemu-user)
  build count-aarch64 starbow_count_kernels starbow
  build count-armhf starbow_count_kernels starbow
fi

echo "== counting (progress on stderr)"
python3 bench/count_report.py "$@"
echo "written: bench/counts.md"
