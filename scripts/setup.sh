#!/bin/sh
# Installs the Debian packages ecoview needs (idempotent), then configures and builds it in build/.
# Set ECOVIEW_SKIP_APT=1 to skip the package step on a machine that already has them.
set -eu
cd "$(dirname "$0")/.."

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

echo "setup: configuring and building in build/"
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build build --parallel "$(nproc)"
