#!/usr/bin/env bash
# Regenerates the pictures the README shows (docs/images/previews-*): a few shipped materials
# rendered by `matbricks preview` through their fragment shaders on lavapipe, beside the CPU
# reference render and the difference heatmap, in both procedural environments, and a
# roughness sweep. Needs a built tree (scripts/build.sh). Each output directory is replaced
# as a whole (it carries matbricks' output marker).
set -euo pipefail
cd "$(dirname "$0")/.."
export VK_ICD_FILENAMES="${VK_ICD_FILENAMES:-/usr/share/vulkan/icd.d/lvp_icd.x86_64.json}"
MB=./build/bin/matbricks
MATERIALS=(materials/filament_plastic.json materials/brushed_metal.json materials/clearcoat_metal.json
           materials/velvet_green.json)
for env in studio sky; do
  "$MB" preview "${MATERIALS[@]}" --size 160 --environment "$env" -o "docs/images/previews-$env"
done
"$MB" preview materials/ue4_metal.json --size 128 --environment studio --sweep roughness \
  -o docs/images/previews-sweep
