#!/usr/bin/env bash
# Installs every Debian package impulse2d needs (idempotent), then configures and builds.
# Usage: scripts/setup.sh [build-dir]     (default build dir: build)
set -euo pipefail
cd "$(dirname "$0")/.."

packages=(
  build-essential cmake pkg-config git
  libosmesa6-dev libegl-dev libegl-mesa0 libglm-dev libstb-dev libgtest-dev
  nlohmann-json3-dev libcli11-dev libdeflate-dev zlib1g-dev
  gnuplot-nox libbox2d-dev libchipmunk-dev
  clang libclang-rt-14-dev doxygen
  ffmpeg chromium fonts-dejavu-core
)

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ "${#missing[@]}" -gt 0 ]; then
  echo "setup: installing ${missing[*]}"
  sudo_cmd=""
  [ "$(id -u)" -eq 0 ] || sudo_cmd="sudo"
  export DEBIAN_FRONTEND=noninteractive
  $sudo_cmd apt-get update -qq
  $sudo_cmd apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
fi

build_dir="${1:-build}"
cmake -S . -B "$build_dir" -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build "$build_dir" -j "$(nproc)"
