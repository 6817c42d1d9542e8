#!/usr/bin/env bash
# Regenerates every figure and image the README and docs/*.md show, each with the command its
# caption gives, from the build in build/ (scripts/setup.sh makes it).
# Usage: scripts/docs.sh [--quick] [build-dir]
#   --quick   only the contact sheets and the overlay frames (seconds); without it also the
#             speed-accuracy lab's charts and maps (docs/lab/, 3-5 min), the solver chart
#             (docs/solver_speed_vs_accuracy.png, about a minute) and bench_compare's table
#             and scaling chart (docs/bench/, about 5 min).
# Not regenerated: docs/golden_report.png, a browser screenshot of the report of a
# deliberately failing golden run (docs/golden.md, "Review a failure", says what it shows).
set -euo pipefail
cd "$(dirname "$0")/.."
quick=0
if [ "${1:-}" = "--quick" ]; then
  quick=1
  shift
fi
build_dir="${1:-build}"
cli="$build_dir/impulse2d"
for tool in "$cli" "$build_dir/bench/render_example"; do
  if [ ! -x "$tool" ]; then
    echo "docs.sh: $tool is missing; build first (scripts/setup.sh $build_dir)" >&2
    exit 1
  fi
done

run() {
  echo "docs.sh: $*"
  "$@"
}

run "$cli" sheet tutorial --frames 0:900:128 --overlays normals,impulses,penetration \
  -o docs/contact_sheet_tutorial.png --quiet
run "$cli" sheet shape_pairs --count 4 --tile 480x640 -o docs/contact_sheet_shape_pairs.png --quiet
run "$cli" sheet bullet --count 4 --tile 400x260 -o docs/contact_sheet_bullet.png --quiet
run "$cli" sheet shape_pairs -p rows=3 --frames 24:24,60:60 --columns 2 --tile 640x480 \
  --overlays points,normals,normal_impulses,penetration,ids --arrow-scale 4 --highlight 4 \
  -o docs/overlays_readable.png --quiet
run "$cli" sheet --scenes pendulum,double_pendulum,rope_bridge,car,ragdolls,catapult,heavy_chain,mouse_drag \
  --frames 120 --tile 320x240 --overlays joints -o docs/images/joint_scenes.png --quiet
run "$cli" sheet platformer -f 40,150,190,214,350,455,486,556,760,1000,1040,1100 --columns 3 \
  --tile 480x300 -o docs/images/platformer_contact_sheet.png --quiet
run "$build_dir/bench/render_example" docs/overlays.png
small_dir="$(mktemp -d)"
run "$cli" render shape_pairs -p rows=3 --size 320x240 --overlays all -f 180 -o "$small_dir" --quiet
cp "$small_dir/shape_pairs_00000.png" docs/overlays_small.png
rm -r "$small_dir"
if [ "$quick" -eq 0 ]; then
  run "$cli" lab -o docs/lab
  run bench/chart_solver.sh "$build_dir" docs/solver_speed_vs_accuracy.png
  run "$build_dir/bench/bench_compare" --out docs/bench
fi
echo "docs.sh: done (docs/golden_report.png is a screenshot and was left as it is)"
