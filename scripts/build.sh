#!/usr/bin/env bash
# Configures and builds matbricks into build/ (the CLI lands in build/bin/matbricks).
set -euo pipefail
cd "$(dirname "$0")/.."
BUILD_DIR="${BUILD_DIR:-build}"
GENERATOR=()
if command -v ninja >/dev/null 2>&1; then GENERATOR=(-G Ninja); fi
# A fresh build directory is configured as a unity build (CMake's CMAKE_UNITY_BUILD: the sources
# of each target compiled in batches of 8, so the headers they share are parsed and their inline
# code compiled once a batch): a clean build spends about half the CPU time
# (bench/README.md "Build time"). A build directory configured otherwise keeps its settings;
# for editing one file at a time, `-DCMAKE_UNITY_BUILD=OFF` recompiles just that file.
if [ ! -f "$BUILD_DIR/CMakeCache.txt" ]; then
  cmake -S . -B "$BUILD_DIR" "${GENERATOR[@]}" -DCMAKE_BUILD_TYPE=Release -DCMAKE_UNITY_BUILD=ON
fi
cmake --build "$BUILD_DIR" -j "$(nproc)"
