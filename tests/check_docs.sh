#!/usr/bin/env bash
# The docs test: every impulse2d command the README shows in a ```sh block parses and names a
# valid scene, parameters and frames (run with --dry-run: nothing runs, nothing is written),
# every local link and image in README.md and docs/*.md resolves, and every "## " section of
# the README is in its table of contents.
# Usage: tests/check_docs.sh <impulse2d executable> <source dir>
set -uo pipefail
shopt -s nullglob
cli="$(cd "$(dirname "$1")" && pwd)/$(basename "$1")"
source_dir="$2"
failures=0
fail() {
  echo "check_docs: $*" >&2
  failures=$((failures + 1))
}

# The commands: lines of ```sh blocks that run build/demos/impulse2d or an installed impulse2d
# (continued lines joined, comments dropped; `parallel ... {} ::: 1 2` runs it with 1).
commands=$(awk '
  /^```sh/ { inside = 1; next }
  /^```/ { inside = 0; next }
  inside {
    line = $0
    if (pending != "") { line = pending " " line; pending = "" }
    if (line ~ /\\$/) { pending = substr(line, 1, length(line) - 1); next }
    sub(/[ \t]+#.*$/, "", line)
    if (match(line, /(build\/demos\/)?impulse2d( |$)/)) {
      command = substr(line, RSTART)
      if (command ~ /^impulse2d/ && RSTART > 1 && substr(line, RSTART - 1, 1) !~ /[ \t]/) next
      sub(/ :::.*$/, "", command)
      gsub(/\{\}/, "1", command)
      print NR ": " command
    }
  }' "$source_dir/README.md")
if [ -z "$commands" ]; then
  fail "found no impulse2d command in the README's sh blocks"
fi
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
ln -s "$source_dir/demos" "$work/demos"
ln -s "$source_dir/examples" "$work/examples"
count=0
while IFS= read -r entry; do
  [ -z "$entry" ] && continue
  line="${entry%%: *}"
  command="${entry#*: }"
  arguments="${command#build/demos/impulse2d}"
  arguments="${arguments#impulse2d}"
  count=$((count + 1))
  # Word splitting as the shell would, without globbing or expansion of $(...).
  read -r -a words <<< "$arguments"
  if ! output=$(cd "$work" && "$cli" --dry-run "${words[@]}" 2>&1); then
    fail "README.md:$line: \`$command\` fails: $output"
  fi
done <<< "$commands"
leftover=$(cd "$work" && find . -mindepth 1 -maxdepth 1 ! -name demos ! -name examples)
[ -n "$leftover" ] && fail "a --dry-run wrote files: $leftover"

# Local links and images: [text](path) and ![alt](path), relative to the page.
links=0
for page in "$source_dir/README.md" "$source_dir"/docs/*.md; do
  page_dir=$(dirname "$page")
  while IFS= read -r target; do
    [ -z "$target" ] && continue
    case "$target" in
      http://* | https://* | mailto:* | \#*) continue ;;
    esac
    links=$((links + 1))
    path="${target%%#*}"
    [ -e "$page_dir/$path" ] || fail "${page#$source_dir/}: the link '$target' leads nowhere"
  done < <(grep -o '\]([^)]*)' "$page" | sed 's/^](//; s/)$//; s/ .*$//')
done

# The table of contents lists every section.
while IFS= read -r heading; do
  title="${heading#\#\# }"
  title="${title//\`/}"
  grep -qF -- "- [$title](#" "$source_dir/README.md" ||
    fail "README.md: the section '$title' is missing from the table of contents"
done < <(awk '/^```/ { inside = !inside; next } !inside && /^## / && $0 != "## Contents"' \
  "$source_dir/README.md")

echo "check_docs: $count README commands, $links local links and images checked"
if [ "$failures" -gt 0 ]; then
  echo "check_docs: $failures problem(s)" >&2
  exit 1
fi
