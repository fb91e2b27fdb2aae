#!/usr/bin/env bash
# README command (a): install what is missing, build, then run the main job on the shipped
# example library: compile every material (JSON and macro forms) and the glTF examples into
# packages, and validate every permutation on lavapipe against the double-precision
# references.
set -euo pipefail
cd "$(dirname "$0")/.."
./scripts/install-deps.sh
./scripts/build.sh
export VK_ICD_FILENAMES="${VK_ICD_FILENAMES:-/usr/share/vulkan/icd.d/lvp_icd.x86_64.json}"
echo "== matbricks compile materials/*.json -o out/package --lights dir,point,spot --environment ibl_lut"
./build/bin/matbricks compile materials/*.json -o out/package --lights dir,point,spot --environment ibl_lut
echo
echo "== the macro forms of the same materials (same SPIR-V hashes as above)"
./build/bin/matbricks compile materials/*.mat -o out/package-macro --lights dir,point,spot --environment ibl_lut
echo
echo "== matbricks compile examples/gltf/showroom.gltf examples/gltf/textured_props.gltf -o out/gltf-package"
./build/bin/matbricks compile examples/gltf/showroom.gltf examples/gltf/textured_props.gltf -o out/gltf-package
echo
echo "== matbricks validate materials/*   (every light type the model shades, each environment mode)"
./build/bin/matbricks validate materials/*
