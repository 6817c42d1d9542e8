#!/usr/bin/env bash
# Installs what the program needs, builds the impulse2d program (that target only: no test,
# no benchmark), and runs the main job: `build/impulse2d` with the arguments given; with none, the
# default demo (the tutorial scene with the contact normals, impulses and penetration overlays)
# rendered into out/.
# Usage: scripts/run.sh [impulse2d arguments...]
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh --program build impulse2d
exec build/impulse2d "$@"
