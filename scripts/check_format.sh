#!/usr/bin/env bash
# Fails (exit 1) when a C++ file (.cpp, .h, .inc) of the repository differs from what clang-format makes of it
# (.clang-format); prints the files. `bash scripts/check_format.sh --fix` rewrites them instead.
# The files: tracked ones and new ones not yet added (but not those .gitignore leaves out), so a
# file is checked before its first commit, not only in CI's clean clone.
set -euo pipefail
cd "$(dirname "$0")/.."
mapfile -t files < <(git ls-files --cached --others --exclude-standard '*.cpp' '*.h' '*.inc')
if [ "${1:-}" = "--fix" ]; then
  clang-format -i "${files[@]}"
  exit 0
fi
bad=()
for f in "${files[@]}"; do
  clang-format --dry-run -Werror "$f" >/dev/null 2>&1 || bad+=("$f")
done
if [ ${#bad[@]} -gt 0 ]; then
  echo "check_format: ${#bad[@]} file(s) not in the house style (bash scripts/check_format.sh --fix):" >&2
  printf '  %s\n' "${bad[@]}" >&2
  exit 1
fi
echo "check_format: ${#files[@]} files in the house style"
