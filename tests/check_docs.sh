#!/usr/bin/env bash
# The docs test. For README.md and every docs/*.md page:
#  - every command line of its ```sh blocks runs as written, in order, in one scratch working
#    directory per page (so a page's commands are tested as the sequence a reader types), with
#    copies of the source tree's examples/, demos/ and lab/ in it, `build/impulse2d` and
#    `impulse2d` on PATH both being the program under test; each must exit 0 (or the status a
#    trailing `# exits N` comment gives). The exceptions are listed below, each with its reason:
#    lines that are not run at all, and impulse2d commands run with --dry-run only.
#    `scripts/run.sh ARGS` runs `impulse2d ARGS` (its build half is CI's job).
#  - every local link and image resolves;
# and README.md is at most 250 lines, and its table of contents lists every "## " section.
# Usage: tests/check_docs.sh <impulse2d executable> <source dir>
set -uo pipefail
shopt -s nullglob
cli="$(cd "$(dirname "$1")" && pwd)/$(basename "$1")"
source_dir="$(cd "$2" && pwd)"
failures=0
fail() {
  echo "check_docs: $*" >&2
  failures=$((failures + 1))
}

# Lines not run (an extended regular expression on the command line, then the reason).
not_run=(
  '^(sudo |apt-get |apt )'            'installs packages: scripts/setup.sh does it, CI runs it'
  '^([A-Z_]+=[^ ]+ )*scripts/(setup|test|lab|fuzz)\.sh'  'builds (and tests) everything: CI runs scripts/test.sh'
  '^scripts/docs\.sh'                 'regenerates the figures in the source tree (minutes)'
  '^scripts/promote_goldens\.sh'      'needs the artifacts of a failing golden run'
  '^(CC=[^ ]+ )*(CXX=[^ ]+ )*cmake '  'configures, builds or installs: CI builds, tests/consumer installs'
  '^([A-Z_]+=[^ ]+ )*ctest '          'the test suite itself: CI runs it'
  '^git '                             'git clone/add/commit: nothing to test'
  '^doxygen '                         'the api_reference test runs it'
  '^c\+\+ '                           'compiles against an installed impulse2d: the consumer_installed test does it'
  '^(\./)?crate$'                     'the program the previous line compiles'
  '(^| )build/bench/'                 'benchmark programs, not the impulse2d target (minutes); bench_compare_smoke runs one'
  '^([A-Z_]+=[^ ]+ )*valgrind '       'instruction counts: minutes under valgrind, which no sanitizer build can run under and setup.sh does not install'
)
# impulse2d commands run with --dry-run only (regex, reason).
dry_run_only=(
  'impulse2d lab( --out [^ ]+| -o [^ ]+)?$'  'the whole lab takes 3-5 min; the lab_quick test runs the quick lab'
  'impulse2d lab --quick'                     'about 40 s; the lab_quick test runs it'
)
if ! command -v ffmpeg >/dev/null 2>&1; then
  dry_run_only+=('--video' 'ffmpeg is not installed here (test_cli encodes real videos where it is)')
fi

# The lines of a page's ```sh blocks as "line number<TAB>command" (continued lines joined;
# blank and comment-only lines dropped).
commands_of() {
  awk '
    /^[ \t]*```sh[ \t]*$/ { inside = 1; next }
    /^[ \t]*```/ { inside = 0; next }
    inside {
      line = $0
      if (pending != "") { line = pending " " line; pending = "" } else { start = NR }
      if (line ~ /\\$/) { pending = substr(line, 1, length(line) - 1); next }
      sub(/^[ \t]+/, "", line)
      if (line == "" || line ~ /^#/) next
      print start "\t" line
    }' "$1"
}

# The first pattern of a (regex, reason) list that the command matches, as its index, or -1.
match_index() {
  local command="$1"
  shift
  local list=("$@") i
  for ((i = 0; i < ${#list[@]}; i += 2)); do
    if [[ "$command" =~ ${list[i]} ]]; then
      echo "$i"
      return
    fi
  done
  echo -1
}

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
mkdir -p "$work/bin"
ln -s "$cli" "$work/bin/impulse2d"
declare -A used_dry_run=()
count=0
real=0
dry=0
skipped=0
started=$SECONDS
pages=("$source_dir/README.md" "$source_dir"/docs/*.md)
for page in "${pages[@]}"; do
  name="${page#$source_dir/}"
  entries=$(commands_of "$page")
  [ -z "$entries" ] && continue
  dir="$work/pages/${name//\//_}"
  mkdir -p "$dir/build"
  ln -s "$cli" "$dir/build/impulse2d"
  for input in examples demos lab; do
    [ -d "$source_dir/$input" ] && cp -r "$source_dir/$input" "$dir/$input"
  done
  script="$work/${name//\//_}.sh"
  status="$work/${name//\//_}.status"
  : > "$status"
  {
    echo "cd '$dir' || exit 99"
    echo "export PATH='$work/bin':\"\$PATH\""
  } > "$script"
  n=0
  while IFS=$'\t' read -r line command; do
    n=$((n + 1))
    count=$((count + 1))
    # Patterns see the command without a trailing comment.
    bare=$(printf '%s\n' "$command" | sed -E 's/[[:space:]]+#.*$//')
    if [ "$(match_index "$bare" "${not_run[@]}")" -ge 0 ]; then
      skipped=$((skipped + 1))
      continue
    fi
    run="$command"
    # Plain `scripts/run.sh ARGS` is `build/impulse2d ARGS` once built.
    if [[ "$run" =~ ^scripts/run\.sh($|[[:space:]]) ]]; then
      run="build/impulse2d${run#scripts/run.sh}"
    fi
    index=$(match_index "$(printf '%s\n' "$run" | sed -E 's/[[:space:]]+#.*$//')" "${dry_run_only[@]}")
    if [ "$index" -ge 0 ]; then
      used_dry_run[$index]=1
      dry=$((dry + 1))
      run=$(printf '%s\n' "$run" | sed -E 's#(^|[ ;&|(])((build/)?impulse2d)( |$)#\1\2 --dry-run\4#g')
    else
      case "$run" in
        *impulse2d*) real=$((real + 1)) ;;
      esac
    fi
    expected=0
    if [[ "$command" =~ \#.*exits\ ([0-9]+) ]]; then
      expected="${BASH_REMATCH[1]}"
    fi
    # Braces keep cd and export in force for the next lines; the newline ends a trailing comment.
    {
      printf '{ %s\n} > %q 2>&1\n' "$run" "$work/out.$n"
      printf 'rc=$?; [ "$rc" = %s ] || printf "%%s\\t%%s\\t%%s\\n" %q %q "$rc" >> %q\n' \
        "$expected" "$line" "$n" "$status"
    } >> "$script"
  done <<< "$entries"
  # As a user runs them on their own machine: outside CI (under CI `golden update` refuses).
  timeout 100 env -u CI bash "$script" < /dev/null > /dev/null 2>&1
  rc=$?
  [ "$rc" -eq 124 ] && fail "$name: its commands took over 100 s and were stopped"
  [ "$rc" -eq 99 ] && fail "$name: could not enter the scratch directory"
  while IFS=$'\t' read -r line n code; do
    [ -z "$line" ] && continue
    fail "$name:$line: \`$(sed -n "${line}p" "$page" | sed 's/^[ \t]*//')\` exited $code: $(tail -n 5 "$work/out.$n")"
  done < "$status"
  rm -f "$work"/out.*
done
for ((i = 0; i < ${#dry_run_only[@]}; i += 2)); do
  [ -n "${used_dry_run[$i]:-}" ] ||
    fail "the --dry-run exception '${dry_run_only[i]}' matches no command any more: remove it"
done
[ "$real" -gt 0 ] || fail "found no impulse2d command to run in the pages' sh blocks"

# Local links and images: [text](path) and ![alt](path), relative to the page, outside fenced
# code blocks (where `[&](BodyId id)` is a lambda, not a link).
links=0
for page in "${pages[@]}"; do
  page_dir=$(dirname "$page")
  while IFS= read -r target; do
    [ -z "$target" ] && continue
    case "$target" in
      http://* | https://* | mailto:* | \#*) continue ;;
    esac
    links=$((links + 1))
    path="${target%%#*}"
    [ -e "$page_dir/$path" ] || fail "${page#$source_dir/}: the link '$target' leads nowhere"
  done < <(awk '/^```/ { fenced = !fenced; next } !fenced' "$page" | grep -o '\]([^)]*)' |
    sed 's/^](//; s/)$//; s/ .*$//')
done

# The README fits on a few screens, and its table of contents lists every section.
readme_lines=$(wc -l < "$source_dir/README.md")
[ "$readme_lines" -le 250 ] || fail "README.md has $readme_lines lines (at most 250: move detail into docs/)"
while IFS= read -r heading; do
  title="${heading#\#\# }"
  title="${title//\`/}"
  grep -qF -- "- [$title](#" "$source_dir/README.md" ||
    fail "README.md: the section '$title' is missing from the table of contents"
done < <(awk '/^```/ { inside = !inside; next } !inside && /^## / && $0 != "## Contents"' \
  "$source_dir/README.md")

echo "check_docs: ${#pages[@]} pages: $count sh lines ($real impulse2d commands run, $dry with" \
  "--dry-run only, $skipped not run), $links local links and images, $((SECONDS - started)) s"
if [ "$failures" -gt 0 ]; then
  echo "check_docs: $failures problem(s)" >&2
  exit 1
fi
