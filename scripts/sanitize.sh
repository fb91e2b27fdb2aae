#!/usr/bin/env bash
# The sanitizer pass of the test command (issue 16, docs/fuzzing.md): builds the asan preset
# (clang, AddressSanitizer + UndefinedBehaviorSanitizer, the libFuzzer targets) into build-asan/
# and runs, under the sanitizers, the fuzz regression inputs (label `fuzz`) and every test not
# tagged [vulkan], with no Vulkan device installed (label `no-device`, tests/CMakeLists.txt).
#
#   scripts/sanitize.sh          the CI pass
#   scripts/sanitize.sh --all    the whole suite under the sanitizers, on lavapipe (ctest --preset asan)
set -euo pipefail
cd "$(dirname "$0")/.."
SELECT=(-L "no-device|fuzz")
if [ "${1:-}" = "--all" ]; then SELECT=(-LE no-device); fi
./scripts/install-deps.sh
[ -f build-asan/CMakeCache.txt ] || cmake --preset asan
cmake --build build-asan -j "$(nproc)"
source ./scripts/sanitizer-env.sh
ctest --test-dir build-asan --output-on-failure -j "$(nproc)" "${SELECT[@]}"
