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
# CI's pass builds only mb_tests (which builds the CLI it starts) and the fuzzers: the Release
# build compiles the benchmark programs already, and compiling them once more under the
# sanitizers costs ~8 % of a cold build's compile time (.ninja_log) for no test of the pass.
TARGETS=(--target mb_tests fuzzers)
if [ "${1:-}" = "--all" ]; then
  SELECT=(-LE no-device)
  TARGETS=()
fi
./scripts/install-deps.sh
# A unity build, as scripts/build.sh configures one (it says why).
[ -f build-asan/CMakeCache.txt ] || cmake --preset asan -DCMAKE_UNITY_BUILD=ON
cmake --build build-asan -j "$(nproc)" "${TARGETS[@]}"
echo "sanitize.sh: configure and build took $SECONDS s"
source ./scripts/sanitizer-env.sh
ctest --test-dir build-asan --output-on-failure -j "$(nproc)" "${SELECT[@]}"
echo "sanitize.sh: total $SECONDS s"
