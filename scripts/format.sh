#!/usr/bin/env bash
# Formats every tracked C++ file with .clang-format (clang-format from Debian's clang-format
# package). `scripts/format.sh --check` changes nothing and exits 1 if a file is not formatted.
set -euo pipefail
cd "$(dirname "$0")/.."
if git rev-parse --is-inside-work-tree >/dev/null 2>&1; then
  mapfile -t files < <(git ls-files '*.cpp' '*.hpp')
else  # a source tree without git (an unpacked archive): the same folders
  mapfile -t files < <(find compiler shaderlib tests fuzz bench examples -name '*.[ch]pp' | sort)
fi
if [ "${1:-}" = "--check" ]; then
  clang-format --dry-run --Werror "${files[@]}"
else
  clang-format -i "${files[@]}"
fi
