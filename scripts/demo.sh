#!/usr/bin/env bash
# README command (a): install what is missing, build, then run the main job on the shipped
# example library: compile every material (JSON and macro forms) and the glTF examples into
# packages, compile exactly what each example scene needs to every target (with the counts
# of --explain) and verify the packages against the scenes, and validate every permutation on
# lavapipe against the double-precision references; finally write the HTML report of the
# shipped materials (docs/report.md) and print its path.
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
for scene in showroom mobile gallery; do
  echo "== matbricks compile --scene examples/scenes/$scene.json --explain --targets spirv,glsl450,essl310,hlsl,msl -o out/scene-$scene"
  ./build/bin/matbricks compile --scene "examples/scenes/$scene.json" --explain \
    --targets spirv,glsl450,essl310,hlsl,msl -o "out/scene-$scene"
  echo "== matbricks verify --scene examples/scenes/$scene.json out/scene-$scene"
  ./build/bin/matbricks verify --scene "examples/scenes/$scene.json" "out/scene-$scene"
  echo
done
echo "== matbricks validate materials/*   (every light type the model shades, each environment mode)"
./build/bin/matbricks validate materials/*
echo
echo "== matbricks report -o out/report   (the shipped materials: errors, costs, charts, LUT; docs/report.md)"
# A failed check is shown in the report (and exits 1): print where it is either way.
rc=0
./build/bin/matbricks report -o out/report || rc=$?
echo "report: file://$(pwd)/out/report/index.html"
exit "$rc"
