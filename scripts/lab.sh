#!/usr/bin/env bash
# Regenerates every CSV and chart of the speed-accuracy lab into docs/lab/ from a clean clone:
# installs what is missing and builds (scripts/setup.sh), then runs `impulse2d lab`.
# Usage: scripts/lab.sh [extra impulse2d lab options, e.g. --quick]
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh build
# --clean: the new run replaces the one in docs/lab (all or nothing, at the end).
build/impulse2d lab --clean --out docs/lab "$@"
