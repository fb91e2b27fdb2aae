#!/usr/bin/env bash
# README command (b): install what is missing, build, and run the whole test suite
# (lavapipe with the Khronos validation layer on; see tests/CMakeLists.txt), then the sanitizer
# pass: the asan preset's build and its tests under ASan + UBSan (scripts/sanitize.sh,
# docs/fuzzing.md).
set -euo pipefail
cd "$(dirname "$0")/.."
./scripts/install-deps.sh
./scripts/build.sh
(cd "${BUILD_DIR:-build}" && ctest --output-on-failure -j "$(nproc)")
./scripts/sanitize.sh
