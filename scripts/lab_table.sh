#!/usr/bin/env bash
# Prints the lab's Markdown table of scenarios (docs/lab.md's "Joints" and "Chains"): for each
# scenario its exact answer, unit and threshold, the error of each solver at its own budget and
# of each peer, read from a lab run's lab.csv.
# Usage: scripts/lab_table.sh OUT_DIR SCENARIO[,SCENARIO...]   (OUT_DIR holds lab.csv)
# Run from the repository's root (the scenarios' answers are read from lab/scenarios/).
set -euo pipefail
out=$1
scenarios=$2
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
