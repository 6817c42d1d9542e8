#!/usr/bin/env bash
# Promotes reviewed actual images into the golden set.
#
# Usage: scripts/promote_goldens.sh [--dry-run] ARTIFACT_DIR [SCENE/GOLDEN ...]
#
# ARTIFACT_DIR is a golden-test artifact root (GOLDEN_ARTIFACT_DIR): each failure lives in
# ARTIFACT_DIR/<scene>/<golden>/ with actual.png and its sidecar actual.json. Each such pair
# is copied to golden_images/<scene>/<golden>.png and .json (golden_images/ of this checkout,
# or $GOLDEN_IMAGES_DIR). Naming goldens promotes only those. Failures classed as
# nondeterminism are never promoted. Exits non-zero, copying nothing, when there is nothing
# to promote or a named golden has no promotable actual.
set -euo pipefail

usage() {
  echo "usage: $0 [--dry-run] ARTIFACT_DIR [SCENE/GOLDEN ...]" >&2
  exit 2
}

dry_run=0
if [ "${1:-}" = "--dry-run" ]; then
  dry_run=1
  shift
fi
[ $# -ge 1 ] || usage
artifact_dir="${1%/}"
shift
[ -d "$artifact_dir" ] || { echo "promote: '$artifact_dir' is not a directory" >&2; exit 1; }
golden_dir="${GOLDEN_IMAGES_DIR:-$(cd "$(dirname "$0")/.." && pwd)/golden_images}"

# Every <name> under the artifact dir with an actual.png, sorted.
mapfile -t candidates < <(cd "$artifact_dir" && find . -name actual.png -type f \
  | sed -e 's|^\./||' -e 's|/actual\.png$||' | LC_ALL=C sort)

if [ $# -gt 0 ]; then
  selected=()
  for name in "$@"; do
    name="${name%/}"
    if [ ! -f "$artifact_dir/$name/actual.png" ]; then
      echo "promote: no actual image for '$name' in $artifact_dir" >&2
      exit 1
    fi
    selected+=("$name")
  done
else
  selected=("${candidates[@]}")
fi

promotable=()
for name in "${selected[@]}"; do
  source_dir="$artifact_dir/$name"
  if [ ! -f "$source_dir/actual.json" ]; then
    echo "promote: skipping '$name': no actual.json sidecar beside actual.png" >&2
    continue
  fi
  if ! grep -q '"state_hash"' "$source_dir/actual.json"; then
    echo "promote: skipping '$name': actual.json is not a golden sidecar (no state_hash)" >&2
    continue
  fi
  if [ -f "$source_dir/metrics.json" ] &&
     grep -q '"class": *"nondeterminism"' "$source_dir/metrics.json"; then
    echo "promote: skipping '$name': its frame renders nondeterministically; fix that first" >&2
    continue
  fi
  promotable+=("$name")
done

if [ $# -gt 0 ] && [ "${#promotable[@]}" -ne $# ]; then
  echo "promote: not every named golden is promotable; nothing copied" >&2
  exit 1
fi
if [ "${#promotable[@]}" -eq 0 ]; then
  echo "promote: nothing to promote in $artifact_dir" >&2
  exit 1
fi

for name in "${promotable[@]}"; do
  target="$golden_dir/$name"
  status="new"
  [ -f "$target.png" ] && status="replaces existing"
  echo "promote: $name ($status)"
  echo "  $artifact_dir/$name/actual.png  -> $target.png"
  echo "  $artifact_dir/$name/actual.json -> $target.json"
  [ "$dry_run" -eq 1 ] && continue
  mkdir -p "$(dirname "$target")"
  for extension in png json; do
    cp "$artifact_dir/$name/actual.$extension" "$target.$extension.tmp.$$"
    mv -f "$target.$extension.tmp.$$" "$target.$extension"
  done
done

if [ "$dry_run" -eq 1 ]; then
  echo "promote: dry run, ${#promotable[@]} golden(s) would be copied"
else
  echo "promote: copied ${#promotable[@]} golden(s) into $golden_dir; review with git diff and commit"
fi
