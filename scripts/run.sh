#!/usr/bin/env bash
# Installs what is missing, builds, and runs the main job: renders the default demo's frames.
# Usage: scripts/run.sh [impulse2d arguments...]   (no arguments: the default demo into out/)
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh build
exec build/impulse2d "$@"
