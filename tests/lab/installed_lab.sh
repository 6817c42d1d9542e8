#!/usr/bin/env bash
# The installed `impulse2d lab` finds its scenarios in its own prefix (share/impulse2d/lab,
# relative to bin/impulse2d), from another working directory and after the prefix is moved:
# installs the build into a scratch prefix, trims the installed scenarios to one (so a run that
# read the source tree's instead would be caught), and runs a --quick lab on it.
# Usage: tests/lab/installed_lab.sh <build dir> <scratch dir>
set -euo pipefail
build_dir="$1"
scratch="$2"
rm -rf "$scratch"
mkdir -p "$scratch/elsewhere"
cmake --install "$build_dir" --prefix "$scratch/prefix" >/dev/null
data="$scratch/prefix/share/impulse2d/lab"
[ -f "$data/scenarios/projectile.json" ] || { echo "not installed: $data/scenarios/projectile.json" >&2; exit 1; }
[ -d "$data/tuned" ] || { echo "not installed: $data/tuned" >&2; exit 1; }
find "$data/scenarios" -name '*.json' ! -name projectile.json -delete

check() {
  local program="$1" label="$2"
  cd "$scratch/elsewhere"
  "$program" lab --quick --only projectile --no-stability --no-charts --repeats 1 --out "out_$label" -q
  [ -s "out_$label/lab.csv" ] || { echo "$label: no lab.csv" >&2; exit 1; }
  # Only the installed copy lacks stack_10: the message names the directory that was read.
  if "$program" lab --quick --only stack_10 --out "bad_$label" 2>"err_$label.txt"; then
    echo "$label: read a scenario the installed directory does not hold" >&2
    exit 1
  fi
  grep -q "no such scenario in .*share/impulse2d/lab/scenarios" "err_$label.txt" ||
    { echo "$label: unexpected message:" >&2; cat "err_$label.txt" >&2; exit 1; }
}
check "$scratch/prefix/bin/impulse2d" installed
mv "$scratch/prefix" "$scratch/moved"
check "$scratch/moved/bin/impulse2d" moved
echo "installed_lab: the installed program reads $data/scenarios, also after a move"
