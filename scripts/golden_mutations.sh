#!/usr/bin/env bash
# Measures what the built-in golden suite catches: each mutation of the table below (a one-line
# sed on one source file) is applied to a scratch copy of the committed HEAD, the suite's
# programs are rebuilt incrementally, every built-in golden is checked
# (test_golden --gtest_filter='Golden/GoldenScenes.*', the same check `ctest -R GoldenScenes`
# runs), and the goldens are counted per failure class (docs/golden.md, "Failure classes").
# The unmutated HEAD is measured first as the baseline row.
#
# Usage: scripts/golden_mutations.sh [--work DIR] [--only ID[,ID...]] [--jobs N] [--list]
#
#   --work DIR   scratch worktree (DIR/src), build (DIR/build) and per-row logs and artifacts
#                (DIR/runs/<id>/); reused by the next run, so only the first run builds
#                everything (default: ${TMPDIR:-/tmp}/impulse2d-mutations)
#   --only IDS   measure only these mutations (the baseline row is always measured)
#   --jobs N     parallel compile jobs (default 2)
#   --list       print the mutation table and exit
#
# Prints on stdout, once every row is measured (an interrupted run prints nothing), a Markdown
# table of the counts and a list of the goldens whose class is not the one the mutation's
# family aims at; progress goes to stderr. Only committed HEAD is measured, never the work tree's
# uncommitted changes. Goldens are never written: the check runs with CI=1 (GOLDEN_UPDATE
# forced to none) and IMPULSE2D_REQUIRE_PIXELS=1 (on a renderer without baselines every golden
# shows as "renderer baseline required" instead of being checked by its physics only).
# Exit status: 0 when every row was measured (whatever the counts), 1 when a sed left its file
# unchanged, a mutation did not build or the suite did not run every golden, 2 bad usage.
# Needs git, cmake, a C++ toolchain, GoogleTest, OSMesa, jq and util-linux's setsid.
set -euo pipefail

# id | family | file | sed expression (GNU sed, run with --sandbox) | what it changes
# Families: physics and rendering must fail some golden (physics as behaviour changed,
# rendering as rasterisation differs); a refactor must pass every golden; a reordering
# (rounding only) may be numerical noise or cannot tell, never a physics or pixel change.
# A field holds no '|'.
mutations=(
  "friction-mix|physics|core/material.cpp|/GeometricMean: return/s/std::sqrt(a \* b)/0.5f * (a + b)/|friction mixing: the geometric mean becomes the average"
  "restitution-threshold|physics|core/solver/solver_context.cpp|s/= settings.restitution_threshold;/= 0.9f * settings.restitution_threshold;/|restitution threshold -10 %"
  "contact-hertz|physics|core/solver/solver_context.cpp|s/std::min(settings.contact_hertz,/std::min(1.05f * settings.contact_hertz,/|soft contact stiffness (contact_hertz) +5 %"
  "slop|physics|core/solver/position_correction.cpp|s/std::max(depth - settings.slop,/std::max(depth - 1.05f * settings.slop,/|linear projection's slop +5 % (the tutorial's position correction)"
  "gravity|physics|core/solver/solver_bodies.cpp|s/+ settings.gravity \* body.gravity_scale/+ 1.05f * settings.gravity * body.gravity_scale/|gravity +5 % in the soft step's integration"
  "velocity-iterations|physics|core/solver/solver_context.cpp|s/= settings.velocity_iterations;/= settings.velocity_iterations - 1;/|one velocity iteration fewer"
  "polygon-inertia|physics|core/shape.cpp|s/mass_data.inertia = density \* (/mass_data.inertia = 1.05f * density * (/|polygon inertia +5 %"
  "joint-spring|physics|core/solver/joint_solver.cpp|s/spring_softness = make_soft(joint.hertz,/spring_softness = make_soft(1.05f * joint.hertz,/|joint spring frequency +5 % (every joint spring but the weld's)"
  "fill-colour|rendering|render/palette.cpp|s/d.dynamic_fill = rgb(190, 214, 236);/d.dynamic_fill = rgb(190, 214, 237);/|light theme's dynamic-body fill: blue channel +1"
  "outline-width|rendering|render/primitive_renderer.cpp|s/shape.origin\[2\] = 0.5f \* style_.line_width;/shape.origin[2] = 0.55f * style_.line_width;/|polygon outline 10 % wider"
  "circle-mark|rendering|render/primitive_renderer.cpp|s/push_segment(center, center + axis \* radius,/push_segment(center, center + axis * (0.9f * radius),/|circle's orientation mark 10 % shorter"
  "legend-text|rendering|render/hud.cpp|s/{p.contact_point, \"point\"}/{p.contact_point, \"points\"}/|overlay legend: \"point\" reads \"points\""
  "rename|refactor|core/shape.cpp|s/twice_triangle_area/doubled_triangle_area/g|polygon mass: a local variable renamed"
  "commute|refactor|core/shape.cpp|s/mass_data.area = pi \* radius \* radius;/mass_data.area = radius * pi * radius;/|circle area: a product's operands commuted (exact in IEEE arithmetic)"
  "fan-order|reordering|core/shape.cpp|/Triangle fan from vertex 0/,/second_moment +=/s/for (int i = 0; i < count; ++i) {/for (int i = count - 1; i >= 0; --i) {/|polygon mass: the triangle fan summed in the opposite order"
  "circle-inertia|reordering|core/shape.cpp|s/= 0.5f \* mass_data.mass \* radius \* radius;/= 0.5f * mass_data.mass * (radius * radius);/|circle inertia: ((m / 2) r) r computed as (m / 2) (r r)"
  "box-inertia|reordering|core/shape.cpp|s#mass_data.mass \* (width \* width + height \* height) / 12.0f;#mass_data.mass / 12.0f * (width * width + height * height);#|box inertia, which no step uses (axis-aligned boxes never rotate): m (w^2 + h^2) / 12 computed as m / 12 (w^2 + h^2)"
)

# The classes counted in their own column, in docs/golden.md's words; any other class (and a
# golden the suite did not report) is counted under "other" with its name.
columns=(passed numerical_noise cannot_tell behaviour_changed simulation_diverged
         rasterisation_differs nondeterminism)
headings=("passed" "numerical noise" "cannot tell" "behaviour changed" "simulation diverged"
          "rasterisation differs" "nondeterminism")

usage() {
  echo "usage: $0 [--work DIR] [--only ID[,ID...]] [--jobs N] [--list]" >&2
  exit 2
}

work="${TMPDIR:-/tmp}/impulse2d-mutations"
only=""
jobs=2
list=0
while [ $# -gt 0 ]; do
  case "$1" in
    --work) [ $# -ge 2 ] || usage; work="$2"; shift 2 ;;
    --only) [ $# -ge 2 ] || usage; only="$2"; shift 2 ;;
    --jobs) [ $# -ge 2 ] || usage; jobs="$2"; shift 2 ;;
    --list) list=1; shift ;;
    *) usage ;;
  esac
done
[[ "$jobs" =~ ^[1-9][0-9]*$ ]] || { echo "golden_mutations: --jobs wants a positive integer" >&2; exit 2; }

# Splits one table line into the globals id, family, file, expression, description.
split_row() {
  IFS='|' read -r id family file expression description <<< "$1"
}

known_ids=" "
for row in "${mutations[@]}"; do
  split_row "$row"
  known_ids+="$id "
done
selected=" "
if [ -n "$only" ]; then
  IFS=',' read -r -a wanted <<< "$only"
  for want in "${wanted[@]}"; do
    [[ "$known_ids" == *" $want "* ]] || { echo "golden_mutations: no mutation '$want' (--list)" >&2; exit 2; }
    selected+="$want "
  done
fi

if [ "$list" -eq 1 ]; then
  echo "| mutation | family | file | sed | change |"
  echo "| --- | --- | --- | --- | --- |"
  for row in "${mutations[@]}"; do
    split_row "$row"
    echo "| $id | $family | $file | \`$expression\` | $description |"
  done
  exit 0
fi

for tool in git cmake jq sed setsid; do
  command -v "$tool" > /dev/null || { echo "golden_mutations: needs $tool" >&2; exit 1; }
done

repo="$(cd "$(dirname "$0")/.." && git rev-parse --show-toplevel)"
commit="$(git -C "$repo" rev-parse HEAD)"
mkdir -p "$work"
work="$(cd "$work" && pwd)"
src="$work/src"
build="$work/build"
runs="$work/runs"

# The mutated file of the row being measured, restored on any exit (a signal included), and
# the process group of the build or suite running (ended on a signal).
applied=""
child=""
restore() {
  if [ -n "$applied" ]; then
    git -C "$src" checkout --quiet -- "$applied" || true
    applied=""
  fi
}
# shellcheck disable=SC2317  # reached through the traps below
on_signal() {
  trap - INT TERM HUP
  if [ -n "$child" ]; then
    kill -TERM -- "-$child" 2> /dev/null || true
    wait "$child" 2> /dev/null || true
  fi
  echo "golden_mutations: interrupted; no table printed, scratch copy restored ($src)" >&3
  restore
  exit "$1"
}
exec 3>&2  # the traps' stderr: a signal may come while a command's output goes to its log
trap restore EXIT
trap 'on_signal 130' INT
trap 'on_signal 143' TERM
trap 'on_signal 129' HUP

# The scratch worktree at HEAD: created once, then moved to the commit being measured (files
# that differ get new times, so the build recompiles exactly them).
if [ ! -e "$src/.git" ]; then
  echo "golden_mutations: scratch worktree $src at ${commit:0:12}" >&2
  git -C "$repo" worktree add --quiet --detach "$src" "$commit"
else
  git -C "$src" checkout --quiet --force --detach "$commit"
  git -C "$src" clean --quiet -fdx
fi
if [ ! -f "$build/CMakeCache.txt" ]; then
  cmake -S "$src" -B "$build" -DCMAKE_BUILD_TYPE=Release -DIMPULSE2D_BUILD_TESTS=ON > "$work/cmake.log" 2>&1 \
    || { echo "golden_mutations: cmake failed, see $work/cmake.log" >&2; exit 1; }
fi
suite="$build/tests/golden/test_golden"
filter='Golden/GoldenScenes.*'

# Runs a command in its own process group and waits for it, so that a signal is handled at
# once (the trap ends the group: a build's compilers, the suite's second processes).
run_child() {
  local status=0
  setsid "$@" &
  child=$!
  wait "$child" || status=$?
  child=""
  return "$status"
}

# Measures the source as it stands into $runs/$1/; sets the globals `cells` (the row's count
# cells) and `measured` (goldens reported). Returns 1 when the suite did not build (nothing
# measured), 2 when it did not report every golden (the row says how many are missing).
measure() {
  local run="$runs/$1"
  rm -rf "$run"
  mkdir -p "$run"
  run_child cmake --build "$build" -j "$jobs" --target test_golden > "$run/build.log" 2>&1 || return 1
  local expected
  expected="$("$suite" --gtest_list_tests --gtest_filter="$filter" | grep -c '^  ')"
  # The suite exits 1 when a golden fails: that is what is being measured.
  run_child env -C "$run" -u GOLDEN_UPDATE -u GOLDEN_REPEAT -u GOLDEN_IMAGES_DIR CI=1 \
    IMPULSE2D_REQUIRE_PIXELS=1 GOLDEN_ARTIFACT_DIR="$run/artifacts" \
    "$suite" --gtest_filter="$filter" --gtest_output="xml:$run/results.xml" > "$run/suite.log" 2>&1 || true
  # One line per golden reported: "<scene>/<name> passed|skipped|failed".
  : > "$run/verdicts.txt"
  if [ -f "$run/results.xml" ]; then
    awk '/<testcase / {
           if (id != "") print id, verdict
           match($0, /value_param="[^"]*"/)
           id = substr($0, RSTART + 13, RLENGTH - 14)
           verdict = ($0 ~ /result="skipped"/) ? "skipped" : "passed"
         }
         /<failure/ { verdict = "failed" }
         END { if (id != "") print id, verdict }' "$run/results.xml" > "$run/verdicts.txt"
  fi
  # Each golden's class: the artifact's metrics.json for a failure, else the test's verdict.
  : > "$run/classes.txt"
  local golden verdict class
  while read -r golden verdict; do
    if [ -f "$run/artifacts/$golden/metrics.json" ]; then
      class="$(jq -r '.class' "$run/artifacts/$golden/metrics.json")"
    elif [ "$verdict" = passed ]; then
      class=passed
    elif [ "$verdict" = skipped ]; then
      class=no_baseline_for_this_renderer
    else
      class=failed_without_artifacts
    fi
    echo "$golden $class" >> "$run/classes.txt"
  done < "$run/verdicts.txt"
  measured="$(wc -l < "$run/classes.txt")"
  local missing=$((expected - measured))
  cells=""
  local column count
  for column in "${columns[@]}"; do
    count="$(awk -v c="$column" '$2 == c' "$run/classes.txt" | wc -l)"
    cells+=" $count |"
  done
  local other
  other="$(awk -v known=" ${columns[*]} " 'index(known, " " $2 " ") == 0 { n[$2]++ }
           END { for (c in n) printf "%s%d %s", (s++ ? ", " : ""), n[c], c }' "$run/classes.txt" | tr '_' ' ')"
  if [ "$missing" -gt 0 ]; then
    other="${other:+$other, }$missing not reported (suite.log)"
  fi
  cells+=" ${other:-0} |"
  [ "$missing" -eq 0 ] || return 2
}

# Whether a row's classes are what its family should give (see the table's comment).
verdict_for() {
  local family="$1" classes
  classes="$(cut -d' ' -f2 "$runs/$2/classes.txt" | sort -u | tr '\n' ' ')"
  local physics=0 pixels=0 other=0 class
  for class in $classes; do
    case "$class" in
      passed) ;;
      behaviour_changed|simulation_diverged) physics=1 ;;
      rasterisation_differs) pixels=1 ;;
      numerical_noise|cannot_tell) ;;
      *) other=1 ;;
    esac
  done
  case "$family" in
    baseline|refactor) [ "$classes" = "passed " ] && echo "yes" || echo "**no**" ;;
    physics) [ "$physics" -eq 1 ] && [ "$other" -eq 0 ] && echo "yes" || echo "**no**" ;;
    rendering) [ "$pixels" -eq 1 ] && [ "$physics" -eq 0 ] && [ "$other" -eq 0 ] && echo "yes" || echo "**no**" ;;
    reordering) [ "$physics" -eq 0 ] && [ "$pixels" -eq 0 ] && [ "$other" -eq 0 ] && echo "yes" || echo "**no**" ;;
  esac
}

# The goldens of a row whose class is not the one its family aims at, as "class: golden,
# golden; class: ..." (empty when there are none): a physics change that some golden takes for
# rounding, a rendering change that moved the physics, a refactor or reordering that failed.
odd_goldens() {
  local family="$1" run="$runs/$2" aimed
  case "$family" in
    physics) aimed=" passed behaviour_changed simulation_diverged " ;;
    rendering) aimed=" passed rasterisation_differs " ;;
    reordering) aimed=" passed numerical_noise cannot_tell " ;;
    *) aimed=" passed " ;;
  esac
  awk -v aimed="$aimed" 'index(aimed, " " $2 " ") == 0 {
         if (count[$2]++ == 0) { order[++n] = $2; list[$2] = $1 } else list[$2] = list[$2] ", " $1
       }
       END {
         for (i = 1; i <= n; ++i) {
           class = order[i]
           gsub(/_/, " ", class)
           printf "%s%s: %s", (i > 1 ? "; " : ""), class, list[order[i]]
         }
       }' "$run/classes.txt"
}

started=$SECONDS
notes=""
status=0
table="| mutation | family | change |"
rule="| --- | --- | --- |"
for heading in "${headings[@]}"; do
  table+=" $heading |"
  rule+=" ---: |"
done
table+=" other | as expected |"$'\n'"$rule --- | --- |"

echo "golden_mutations: baseline (HEAD ${commit:0:12}, unmutated)" >&2
outcome=0
measure baseline || outcome=$?
if [ "$outcome" -eq 1 ]; then
  echo "golden_mutations: HEAD did not build, see $runs/baseline/build.log" >&2
  exit 1
elif [ "$outcome" -eq 2 ]; then
  echo "golden_mutations: baseline: not every golden was reported, see $runs/baseline/suite.log" >&2
  status=1
fi
table+=$'\n'"| none (HEAD) | baseline | unmutated |$cells $(verdict_for baseline baseline) |"
odd="$(odd_goldens baseline baseline)"
[ -z "$odd" ] || notes+=$'\n'"- baseline: $odd"

for row in "${mutations[@]}"; do
  split_row "$row"
  if [ -n "$only" ] && [[ "$selected" != *" $id "* ]]; then continue; fi
  row_started=$SECONDS
  target="$src/$file"
  [ -f "$target" ] || { echo "golden_mutations: $id: no file $file" >&2; exit 1; }
  applied="$file"
  sed --sandbox -e "$expression" "$target" > "$target.mutated"
  if cmp -s "$target" "$target.mutated"; then
    rm -f "$target.mutated"
    restore
    echo "golden_mutations: $id: the sed changed nothing in $file (the code moved?)" >&2
    exit 1
  fi
  cat "$target.mutated" > "$target"  # keeps the file's mode; its new time makes it recompile
  rm -f "$target.mutated"
  echo "golden_mutations: $id ($family): $description" >&2
  outcome=0
  measure "$id" || outcome=$?
  if [ "$outcome" -eq 1 ]; then
    echo "golden_mutations: $id did not build, see $runs/$id/build.log" >&2
    exit 1
  elif [ "$outcome" -eq 2 ]; then
    echo "golden_mutations: $id: not every golden was reported, see $runs/$id/suite.log" >&2
    status=1
  fi
  restore
  table+=$'\n'"| \`$id\` | $family | $description |$cells $(verdict_for "$family" "$id") |"
  odd="$(odd_goldens "$family" "$id")"
  [ -z "$odd" ] || notes+=$'\n'"- \`$id\`: $odd"
  echo "golden_mutations: $id measured in $((SECONDS - row_started)) s" >&2
done

echo "golden_mutations: done in $((SECONDS - started)) s (logs and artifacts: $runs/)" >&2
elapsed=$((SECONDS - started))
echo "Measured at ${commit:0:12} on $(date -u +%Y-%m-%d) by \`scripts/golden_mutations.sh\` ($measured built-in goldens per row; the run took $((elapsed / 60)) min $((elapsed % 60)) s)."
echo
echo "$table"
if [ -n "$notes" ]; then
  echo
  echo "Goldens whose class is not the one the mutation's family aims at:"
  echo "${notes#$'\n'}"
fi
exit "$status"
