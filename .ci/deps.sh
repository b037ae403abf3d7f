# .ci/deps.sh: sourced by run.sh, test.sh and .ci/run. Debian 12 packages Starbow builds with.
#   starbow_ensure_deps   installs what is missing when run as root (apt-get), otherwise
#                         prints the apt-get line to run and returns 1.
STARBOW_DEBIAN_PACKAGES="cmake ninja-build g++ libgtest-dev libbenchmark-dev libsdl2-dev libglm-dev libpng-dev zlib1g-dev xvfb xauth"
# The test suite also cross-builds for aarch64 and armhf and runs them under qemu-user
# (test.sh, .ci/run). quakespasm and darkplaces-server: the "other engines load it" test.
STARBOW_TEST_PACKAGES="g++-aarch64-linux-gnu g++-arm-linux-gnueabihf qemu-user googletest quakespasm darkplaces-server"

starbow_missing_packages() {
  local missing="" p
  for p in $STARBOW_DEBIAN_PACKAGES; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing="$missing $p"
  done
  echo "${missing# }"
}

starbow_ensure_deps() {
  if ! command -v dpkg-query >/dev/null 2>&1; then
    echo "note: not a Debian system; make sure these (or equivalents) are installed: $STARBOW_DEBIAN_PACKAGES"
    return 0
  fi
  local missing
  missing="$(starbow_missing_packages)"
  [ -z "$missing" ] && return 0
  if [ "$(id -u)" = "0" ]; then
    echo "installing: $missing"
    export DEBIAN_FRONTEND=noninteractive
    apt-get update -q && apt-get install -y -q --no-install-recommends $missing
  else
    echo "missing Debian packages: $missing"
    echo "install them with:"
    echo "  sudo apt-get install -y --no-install-recommends $missing"
    return 1
  fi
}
