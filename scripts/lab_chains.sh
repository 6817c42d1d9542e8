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

echo '| scenario | exact answer | error (unit), threshold | default `soft_step 4s x1i` | `accumulated 16i` | `per_iteration 16i` | Box2D 2.4.1 (8/3) | Chipmunk 7.0.3 (10) |'
echo '|---|---|---|---|---|---|---|---|'
for scenario in ${scenarios//,/ }; do
  answer=$(sed -n 's/^ *"answer": "\(.*\)",$/\1/p' "lab/scenarios/$scenario.json")
  awk -F, -v scenario="$scenario" -v answer="$answer" '
    function cell(row) {
      if (!(row in error)) return "-"
      if (failure[row] ~ /not supported/) return "not supported"
      if (failure[row] ~ /run failed/) return "run failed"
      return sprintf("%.3g %s", error[row], pass[row] == 1 ? "✓" : "✗")
    }
    NR > 1 && $2 == scenario {
      key = $3 == "impulse2d" ? $4 : $3
      error[key] = $26; unit = $27; threshold = $28; pass[key] = $29
      failure[key] = $32; for (i = 33; i <= NF; ++i) failure[key] = failure[key] "," $i
    }
    END {
      printf "| `%s` | %s | %s, %.3g | %s | %s | %s | %s | %s |\n", scenario, answer, unit, threshold,
             cell("soft_step 4s x1i"), cell("accumulated 16i"), cell("per_iteration 16i"),
             cell("box2d"), cell("chipmunk")
    }' "$out/lab.csv"
done
