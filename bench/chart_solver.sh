#!/usr/bin/env bash
# Speed against accuracy of the solver families on the 20-row pyramid, as a chart.
# Runs bench_solver --sweep and plots error (log) against ms/step (log) with gnuplot.
# Usage: bench/chart_solver.sh [build-dir] [output.png]
set -euo pipefail
cd "$(dirname "$0")/.."
build_dir="${1:-build}"
chart="${2:-docs/solver_speed_vs_accuracy.png}"
if ! command -v gnuplot >/dev/null; then
  echo "chart_solver: installing gnuplot-nox"
  sudo_cmd=""
  [ "$(id -u)" -eq 0 ] || sudo_cmd="sudo"
  DEBIAN_FRONTEND=noninteractive $sudo_cmd apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $sudo_cmd apt-get install -y -qq --no-install-recommends gnuplot-nox >/dev/null
fi
csv="$build_dir/solver_sweep.csv"
"$build_dir/bench/bench_solver" --sweep --csv "$csv"
tmp="$chart.tmp.png"
gnuplot <<GNUPLOT
set terminal pngcairo size 900,560 font ",11" noenhanced
set output "$tmp"
set datafile separator ","
set title "20-row pyramid, 10 s: speed against accuracy (labels: iterations or substeps)"
set xlabel "time per step, ms (log)"
set ylabel "worst box out of place after 10 s, m (log)"
set logscale xy
set grid
set key top right box opaque
set yrange [0.001:1000]
series(key) = "< awk -F, '\$1==\"" . key . "\"' $csv"
plot series("tutorial") using 4:5 with linespoints lw 2 pt 7 title "tutorial per-iteration + linear projection", \
     series("cold") using 4:5 with linespoints lw 2 pt 5 title "accumulated, no warm start + linear", \
     series("warm") using 4:5 with linespoints lw 2 pt 9 title "accumulated + warm start + block + NGS", \
     series("substeps") using 4:5 with linespoints lw 2 pt 11 title "accumulated, 1 iteration x substeps", \
     series("soft_step") using 4:5 with linespoints lw 2 pt 13 title "soft step (the default at 4), 1 + 1 relax x substeps", \
     "< tail -n +2 $csv" using 4:5:(\$3>1 ? sprintf("%ds", \$3) : sprintf("%d", \$2)) with labels offset 0.9,0.7 font ",8" notitle
GNUPLOT
mv "$tmp" "$chart"
echo "chart_solver: wrote $chart (data: $csv)"
