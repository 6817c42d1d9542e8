#!/usr/bin/env bash
# The lab's joint scenarios (pendulums, a spring, the 20-link chain at rest and under a 1:100
# load, a slack rope, a prismatic slide, a welded cantilever) run by every method, Box2D 2.4.1 and Chipmunk 7.0.3 into docs/lab/joints/
# (lab.csv, charts/, and the stability map with its chain_load and chain_time_step rows:
# stability.csv, stability.png), then printed as the Markdown table of docs/lab.md ("Joints"):
# scenario, exact answer, threshold, the error of each solver at its own budget and of each peer.
# Usage: scripts/lab_joints.sh [build dir (default build)] [output dir (default docs/lab/joints)]
# About two minutes on two cores; needs a built `impulse2d` (scripts/setup.sh builds it).
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build}
out=${2:-docs/lab/joints}
scenarios=pendulum_small,pendulum_large,spring_mass,chain_20_rest,chain_20_heavy_load,rope_slack,prismatic_slide,weld_cantilever
"$build/impulse2d" lab --only "$scenarios" --clean --quiet --out "$out" >&2

scripts/lab_table.sh "$out" "$scenarios"
