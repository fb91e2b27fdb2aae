#!/usr/bin/env bash
# Formats every tracked C++ file with .clang-format (clang-format from Debian's clang-format
# package). `scripts/format.sh --check` changes nothing and exits 1 if a file is not formatted.
set -euo pipefail
cd "$(dirname "$0")/.."
mapfile -t files < <(git ls-files '*.cpp' '*.hpp')
if [ "${1:-}" = "--check" ]; then
  clang-format --dry-run --Werror "${files[@]}"
else
  clang-format -i "${files[@]}"
fi
