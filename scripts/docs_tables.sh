#!/usr/bin/env bash
# Rewrites the settings tables in docs/*.md from the settings tables in marker/limits/: every
# block between "<!-- settings: ID -->" and "<!-- end settings -->" becomes what
# `marker options --markdown ID` prints. The settings test (tests/marker/cli/settings_table_test.cpp)
# fails while a docs table differs; run this after changing a setting.
#   scripts/docs_tables.sh [path/to/marker]   (default: build/marker/marker)
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
marker="${1:-$root/build/marker/marker}"
[ -x "$marker" ] || { echo "docs_tables: no marker program at $marker (build it first)" >&2; exit 1; }

for doc in "$root"/docs/*.md; do
  grep -q '<!-- settings: ' "$doc" || continue
  tmp="$(mktemp "$doc.XXXXXX")"
  in_block=0
  while IFS= read -r line || [ -n "$line" ]; do
    if [[ $line =~ ^\<\!--\ settings:\ ([a-z-]+)\ --\>$ ]]; then
      printf '%s\n' "$line" >>"$tmp"
      "$marker" options --markdown "${BASH_REMATCH[1]}" >>"$tmp"
      in_block=1
    elif [[ $line == '<!-- end settings -->' ]]; then
      printf '%s\n' "$line" >>"$tmp"
      in_block=0
    elif ((!in_block)); then
      printf '%s\n' "$line" >>"$tmp"
    fi
  done <"$doc"
  if ((in_block)); then rm -f "$tmp"; echo "docs_tables: $doc: a settings block is not closed" >&2; exit 1; fi
  if ! cmp -s "$tmp" "$doc"; then cat "$tmp" >"$doc"; echo "docs_tables: rewrote $doc"; fi
  rm -f "$tmp"
done
