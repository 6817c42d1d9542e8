#!/usr/bin/env bash
# Installs the Debian packages impulse2d needs (idempotent, saying what apt does), then
# configures a Release build and builds the given targets (every target when none is given).
# Usage: scripts/setup.sh [--program] [build-dir [target...]]     (default build dir: build)
#   --program   only what the impulse2d program needs (scripts/run.sh): its packages, and a
#               build with the tests switched off; without it, every package and the tests on.
set -euo pipefail
cd "$(dirname "$0")/.."

# The program: compiler, CMake, and the libraries it links.
program_packages=(
  build-essential cmake pkg-config
  libosmesa6-dev libegl-dev libegl-mesa0 libglm-dev libstb-dev
  nlohmann-json3-dev libcli11-dev libdeflate-dev
)
# Everything else: tests, peers, charts, video, the browser viewer's test, the sanitizer build.
other_packages=(
  git libgtest-dev
  gnuplot-nox libbox2d-dev libchipmunk-dev
  clang libclang-rt-14-dev doxygen
  ffmpeg chromium fonts-dejavu-core
)
program_only=0
if [ "${1:-}" = "--program" ]; then
  program_only=1
  shift
fi
packages=("${program_packages[@]}")
[ "$program_only" -eq 1 ] || packages+=("${other_packages[@]}")

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ "${#missing[@]}" -gt 0 ]; then
  sudo_cmd=""
  [ "$(id -u)" -eq 0 ] || sudo_cmd="sudo"
  export DEBIAN_FRONTEND=noninteractive
  echo "setup: ${#missing[@]} Debian packages are missing: ${missing[*]}"
  echo "setup: apt-get update (reading the package lists)"
  $sudo_cmd apt-get update
  echo "setup: apt-get install (downloading, unpacking and setting up each package; a few minutes)"
  $sudo_cmd apt-get install -y --no-install-recommends "${missing[@]}"
  echo "setup: packages installed"
fi

build_dir="${1:-build}"
shift || true
echo "setup: configuring a Release build in $build_dir/"
if [ "$program_only" -eq 1 ]; then
  tests=OFF
else
  tests=ON
fi
cmake -S . -B "$build_dir" -DCMAKE_BUILD_TYPE=Release -DIMPULSE2D_BUILD_TESTS="$tests" >/dev/null
if [ "$#" -gt 0 ]; then
  echo "setup: building $* in $build_dir/"
  cmake --build "$build_dir" -j "$(nproc)" --target "$@"
else
  echo "setup: building every target in $build_dir/"
  cmake --build "$build_dir" -j "$(nproc)"
fi
