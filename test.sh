#!/usr/bin/env bash
# test.sh: build and run every test.
#   1. default preset (RelWithDebInfo): build everything, ctest (all tests)
#   2. sanitize preset (ASan + UBSan, Debug): build, ctest with label 'sanitize'
#   3. cross-aarch64 preset: cross build, ctest under qemu-aarch64 (toolchain/)
#   4. cross-armhf preset: cross build, ctest under qemu-arm (Cortex-A7, NEON)
# Installs missing Debian packages when run as root (else prints the apt-get line).
# Data tests skip visibly when ../shared/quake (LibreQuake) is absent.
set -euo pipefail
cd "$(dirname "$0")"
. .ci/deps.sh
STARBOW_DEBIAN_PACKAGES="$STARBOW_DEBIAN_PACKAGES $STARBOW_TEST_PACKAGES"
starbow_ensure_deps

start=$(date +%s)
stage() { echo; echo "== $* ($(( $(date +%s) - start )) s so far)"; }

stage "configure + build: default preset"
cmake --preset default
cmake --build --preset default
stage "ctest: default preset"
ctest --preset default

stage "configure + build: sanitize preset"
cmake --preset sanitize
cmake --build --preset sanitize
stage "ctest: sanitize preset (label sanitize)"
ctest --preset sanitize

stage "configure + build: cross-aarch64 preset (tests run under qemu-aarch64)"
cmake --preset cross-aarch64
cmake --build --preset cross-aarch64
stage "ctest: cross-aarch64 preset"
ctest --preset cross-aarch64

stage "configure + build: cross-armhf preset (tests run under qemu-arm)"
cmake --preset cross-armhf
cmake --build --preset cross-armhf
stage "ctest: cross-armhf preset"
ctest --preset cross-armhf

echo
echo "all tests passed in $(( $(date +%s) - start )) s"
