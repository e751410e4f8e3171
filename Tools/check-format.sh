#!/usr/bin/env bash
# Fails when a C++ file git tracks is not formatted as .clang-format says (issue 14, item 8), and
# names each such file. The style was written down from the code as it was, so a change only has
# to keep to it; `Tools/check-format.sh --fix` formats the files in place. clang-format-14 is the
# one Debian 12 ships: other versions break some lines differently, so this uses that one.
set -euo pipefail
cd "$(dirname "$0")/.."

formatter=clang-format-14
if ! command -v "$formatter" > /dev/null; then
  echo "check-format: $formatter is missing (Tools/install-dependencies.sh installs it)" >&2
  exit 1
fi

# Tracked files and new ones not yet added (a clean checkout has none of the latter).
mapfile -t files < <(git ls-files --cached --others --exclude-standard '*.h' '*.cpp' '*.cxx')
if [ "${1:-}" = --fix ]; then
  "$formatter" -i "${files[@]}"
  echo "check-format: formatted ${#files[@]} files"
  exit 0
fi

unformatted=()
for file in "${files[@]}"; do
  if ! "$formatter" --dry-run --Werror "$file" > /dev/null 2>&1; then
    unformatted+=("$file")
  fi
done
if [ "${#unformatted[@]}" -gt 0 ]; then
  printf 'check-format: not formatted as .clang-format says: %s\n' "${unformatted[@]}" >&2
  echo "check-format: ${#unformatted[@]} of ${#files[@]} files; run Tools/check-format.sh --fix" >&2
  exit 1
fi
echo "check-format: ${#files[@]} files formatted as .clang-format says"
