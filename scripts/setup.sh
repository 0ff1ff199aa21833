#!/bin/sh
# Installs the Debian packages ecoview needs (idempotent), then configures and builds it in build/:
# the ecoview binary alone, or with `tests` every target, the test programs ctest runs included.
# Set ECOVIEW_SKIP_APT=1 to skip the package step on a machine that already has them.
set -eu
cd "$(dirname "$0")/.."

usage="usage: scripts/setup.sh [tests]
  builds build/ecoview; with tests, every target (the test programs ctest runs too).
  ECOVIEW_SKIP_APT=1 skips installing the Debian packages."
case "$#:${1:-}" in
  0:) target=ecoview ;;
  1:tests) target=all ;;
  1:-h | 1:--help) echo "$usage"; exit 0 ;;
  *) printf 'setup: unexpected arguments: %s\n%s\n' "$*" "$usage" >&2; exit 2 ;;
esac

packages="build-essential cmake pkg-config python3 python3-glad
  libglfw3-dev libglm-dev libegl-dev libegl1-mesa-dev libgl1-mesa-dri libosmesa6-dev
  libopenmesh-dev libtinygltf-dev nlohmann-json3-dev libstb-dev libcli11-dev libgtest-dev libembree-dev libimgui-dev
  libavcodec-dev libavformat-dev libavutil-dev libswscale-dev libopenexr-dev
  xvfb xauth xdotool parallel
  python3-matplotlib"

if [ "${ECOVIEW_SKIP_APT:-0}" != 1 ]; then
  sudo=""
  [ "$(id -u)" = 0 ] || sudo="sudo"
  echo "setup: installing Debian packages"
  $sudo apt-get update -qq
  # shellcheck disable=SC2086
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends $packages >/dev/null
fi

echo "setup: configuring and building target $target in build/"
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build build --parallel "$(nproc)" --target "$target"
