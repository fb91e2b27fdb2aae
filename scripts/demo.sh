#!/usr/bin/env bash
# README command (a): install what is missing, build, then run the main job on the shipped
# example library: compile every material into a package and validate every permutation
# on lavapipe against the double-precision references.
set -euo pipefail
cd "$(dirname "$0")/.."
./scripts/install-deps.sh
./scripts/build.sh
export VK_ICD_FILENAMES="${VK_ICD_FILENAMES:-/usr/share/vulkan/icd.d/lvp_icd.x86_64.json}"
echo "== matbricks compile materials/*.json -o out/package"
./build/bin/matbricks compile materials/*.json -o out/package
echo
echo "== matbricks validate materials/*.json"
./build/bin/matbricks validate materials/*.json
