#!/usr/bin/env bash
# The layout test: every arrow between the project's folders points down. Reads each source
# file's project includes ("folder/...") and fails on an include into a folder that the file's
# own folder may not use (the table below is the README's architecture diagram). Also: core's
# public headers (core/*.h) include only public headers, and no header whose name says it is
# internal (internal, kernel) is among the staged public headers that are installed.
# Usage: tests/check_layout.sh <source dir> [<staged include dir>]
set -uo pipefail
source_dir="$1"
staged_dir="${2:-}"
failures=0
fail() {
  echo "check_layout: $*" >&2
  failures=$((failures + 1))
}

# Folder -> the folders it may include besides itself. Order is the build order, bottom up.
declare -A may_use=(
  [core]=""
  [gameplay]="core"
  [scene]="core gameplay"
  [demos]="core gameplay scene"
  [image]=""
  [golden]="image"
  [render]="core image"
  [frames]="core gameplay scene render image golden"
  [golden/scenes]="core gameplay scene demos render image golden frames"
  [lab]="core gameplay scene demos render image golden frames"
  [app]="core gameplay scene demos render image golden frames golden/scenes lab"
  [bench]="core gameplay scene demos render image golden frames lab"
  [examples]="core gameplay scene render"
  [tests]="core gameplay scene demos render image golden frames golden/scenes lab bench tests"
)
# The one exception: the program's spelling suggestions are unit-tested in tests/app/.
allowed_exception="tests/app/test_cli_units.cpp:app/spelling.h"

# The folder an include names ("golden/scenes/x.h" -> golden/scenes, "core/solver/x.h" -> core).
include_folder() {
  case "$1" in
    golden/scenes/*) echo golden/scenes ;;
    *) echo "${1%%/*}" ;;
  esac
}
file_folder() {
  case "$1" in
    golden/scenes/*) echo golden/scenes ;;
    *) echo "${1%%/*}" ;;
  esac
}

checked=0
cd "$source_dir" || exit 1
while IFS= read -r file; do
  folder=$(file_folder "$file")
  [ -z "${may_use[$folder]+set}" ] && continue
  checked=$((checked + 1))
  while IFS= read -r included; do
    target=$(include_folder "$included")
    [ "$target" = "$folder" ] && continue
    [ -z "${may_use[$target]+set}" ] && [ "$target" != "app" ] && continue  # not a project folder
    if [[ " ${may_use[$folder]} " != *" $target "* ]] &&
       [ "$file:$included" != "$allowed_exception" ]; then
      fail "$file includes \"$included\": $folder/ may not use $target/ (allowed: ${may_use[$folder]:-nothing})"
    fi
  done < <(sed -n 's/^[[:space:]]*#[[:space:]]*include[[:space:]]*"\([a-z_]*\/[^"]*\)".*/\1/p' "$file")
done < <(git ls-files '*.h' '*.cpp' 2>/dev/null || find . -name '*.h' -o -name '*.cpp' | sed 's|^\./||')
[ "$checked" -lt 100 ] && fail "checked only $checked files: is $source_dir the source tree?"

# core's public headers include only public headers.
for header in core/*.h; do
  while IFS= read -r included; do
    case "$included" in
      core/*/*) fail "$header (public) includes the internal \"$included\"" ;;
    esac
  done < <(sed -n 's/^[[:space:]]*#[[:space:]]*include[[:space:]]*"\([a-z_]*\/[^"]*\)".*/\1/p' "$header")
done

# No internal header is staged for installation.
if [ -n "$staged_dir" ]; then
  if [ ! -d "$staged_dir/impulse2d/core" ]; then
    fail "no staged headers in $staged_dir (build the libraries first)"
  else
    while IFS= read -r header; do
      fail "internal header installed: ${header#"$staged_dir"/}"
    done < <(find "$staged_dir" -name '*.h' \( -name '*internal*' -o -name '*kernel*' \))
  fi
fi

if [ "$failures" -gt 0 ]; then
  echo "check_layout: $failures problem(s) in $checked files" >&2
  exit 1
fi
echo "check_layout: $checked files, every include points down"
