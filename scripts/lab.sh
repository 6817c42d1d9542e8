#!/usr/bin/env bash
# Regenerates every CSV and chart of the speed-accuracy lab into docs/lab/ from a clean clone:
# installs what is missing and builds (scripts/setup.sh), then runs `impulse2d lab`.
# Usage: scripts/lab.sh [extra impulse2d lab options, e.g. --quick]
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh build
build/impulse2d lab --out docs/lab "$@"
