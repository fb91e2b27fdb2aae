#!/usr/bin/env bash
# README command (b): install what is missing, build, and run the test suite (lavapipe with the
# Khronos validation layer on; see tests/CMakeLists.txt), then the sanitizer pass: the asan
# preset's build and its tests under ASan + UBSan (scripts/sanitize.sh, docs/fuzzing.md).
#
#   scripts/test.sh          CI's run: every test but the opt-in sweeps (CTest label `sweep`)
#   scripts/test.sh --all    the sweeps too
set -euo pipefail
cd "$(dirname "$0")/.."
SELECT=(-LE sweep)
if [ "${1:-}" = "--all" ]; then SELECT=(); fi
./scripts/install-deps.sh
./scripts/build.sh
(cd "${BUILD_DIR:-build}" && ctest --output-on-failure -j "$(nproc)" "${SELECT[@]}")
./scripts/sanitize.sh
