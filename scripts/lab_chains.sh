#!/usr/bin/env bash
# The lab's chain scenarios (a box sliding across the seams of a flat chain: vertical speed,
# spin, stopping distance; the same slide on tiled boxes; a disc rolling down a 5 degree chain:
# acceleration and speed across the slope) run by every method, Box2D 2.4.1 and Chipmunk 7.0.3
# into docs/lab/chains/ (lab.csv, charts/; no stability map: no stressor is about chains), then
# printed as the Markdown table of docs/lab.md ("Chains"): scenario, exact answer, threshold,
# the error of each solver at its own budget and of each peer.
# Usage: scripts/lab_chains.sh [build dir (default build)] [output dir (default docs/lab/chains)]
# About a minute on two cores; needs a built `impulse2d` (scripts/setup.sh builds it).
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build}
out=${2:-docs/lab/chains}
scenarios=seam_slide,seam_slide_spin,seam_slide_stop,seam_slide_tiles,chain_roll,chain_roll_bump
"$build/impulse2d" lab --only "$scenarios" --no-stability --clean --quiet --out "$out" >&2

scripts/lab_table.sh "$out" "$scenarios"
