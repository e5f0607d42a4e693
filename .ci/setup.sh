#!/usr/bin/env bash
# One-command set-up on a fresh Debian 12 machine (run from the project root).
#   bash .ci/setup.sh demo   installs what is missing, builds, runs the main demo on built-in data
#   bash .ci/setup.sh test   installs what is missing, builds, runs the whole test suite
set -euo pipefail
mode="${1:-test}"
cd "$(dirname "$0")/.."

SUDO=""
if [ "$(id -u)" != "0" ]; then SUDO="sudo"; fi

PACKAGES=(build-essential cmake git pkg-config
          libmrpt-dev mrpt-apps
          libeigen3-dev libopencv-dev liboctomap-dev nlohmann-json3-dev
          libgtest-dev libgmock-dev googletest libbenchmark-dev
          xvfb xauth imagemagick)
missing=()
for p in "${PACKAGES[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ "${#missing[@]}" -gt 0 ]; then
  echo "[setup] installing: ${missing[*]}"
  $SUDO apt-get update -q
  DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -q --no-install-recommends "${missing[@]}"
fi

BUILD_DIR="${BUILD_DIR:-build}"
WERROR=OFF
if [ "${CI:-}" = "true" ]; then WERROR=ON; fi
cmake -S . -B "$BUILD_DIR" -DCMAKE_BUILD_TYPE=Release -DSIMP_WERROR="$WERROR"
cmake --build "$BUILD_DIR" -j"$(nproc)"

case "$mode" in
  test)
    cd "$BUILD_DIR"
    ctest --output-on-failure -j"$(nproc)" --timeout 900
    ;;
  demo)
    if [ -x "$BUILD_DIR/bin/simp-demo" ]; then
      "$BUILD_DIR/bin/simp-demo" --out demo_out
    else
      # Until the simulator's demo exists: the first app on data it generates, read by MRPT's own tool.
      "$BUILD_DIR/bin/simp-example-rawlog" --out demo_out/example.rawlog --frames 20
      rawlog-edit --plugins "$BUILD_DIR/lib/libsimp_obs.so" --info -i demo_out/example.rawlog
    fi
    ;;
  *) echo "usage: bash .ci/setup.sh demo|test" >&2; exit 2 ;;
esac
