#!/usr/bin/env bash
# README command (b): install what is missing, build, and run the test suite (lavapipe with the
# Khronos validation layer on; see tests/CMakeLists.txt), then the sanitizer pass: the asan
# preset's build and its tests under ASan + UBSan (scripts/sanitize.sh, docs/fuzzing.md).
#
# Each test runs once: the tests that need no device (CTest label `host`, tests/CMakeLists.txt)
# run in the sanitizer pass, which runs exactly those under ASan + UBSan, so the Release part
# runs the rest: the device tests (label `device`), the host tests that sweep every shipped
# material (label `release-pass`; tests/CMakeLists.txt says why) and the tests CMake registers
# itself.
#
#   scripts/test.sh          CI's run: every test but the opt-in sweeps (CTest label `sweep`)
#   scripts/test.sh --all    the sweeps too, and the host tests in the Release build as well
set -euo pipefail
cd "$(dirname "$0")/.."
SELECT=(-LE "sweep|host")
if [ "${1:-}" = "--all" ]; then SELECT=(); fi
# Each step's wall time is printed as it ends, so a CI log says where the time went.
step() {
  local name="$1" start=$SECONDS
  shift
  "$@"
  echo "test.sh: $name took $((SECONDS - start)) s (total $SECONDS s)"
}
step install-deps ./scripts/install-deps.sh
step build ./scripts/build.sh
step ctest bash -c 'cd "$1" && shift && ctest --output-on-failure -j "$(nproc)" "$@"' _ "${BUILD_DIR:-build}" "${SELECT[@]}"
step sanitize ./scripts/sanitize.sh
