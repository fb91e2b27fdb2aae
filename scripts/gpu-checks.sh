#!/usr/bin/env bash
# The real-GPU checks of docs/devices.md ("NVIDIA H200, run here"), as one script for a machine
# that has a GPU and nothing else: pack the CLI with `../shared/tools/gpu-bundle.sh` (or
# `cmake --install` anywhere), copy the tree with .gpu/ to the GPU machine, and run
#   bash scripts/gpu-checks.sh [OUT_DIR] [DEVICE_SUBSTRING] [STEP_REGEX]
# (STEP_REGEX, e.g. '0[1-3]|1[2-5]', runs only the steps whose names match: a short lease.)
# Each command's output goes to OUT_DIR/NN-name.txt with its exit status and wall time; the
# whole directory is packed into OUT_DIR/all.tgz (some runners bring back few files). A command
# that runs past its limit is stopped (exit 124) and the script goes on.
set -uo pipefail
cd "$(dirname "$0")/.." || exit 2
O=${1:-${OUT:-gpu-checks}}
DEVICE=${2:-nvidia}
ONLY=${3:-.}
mkdir -p "$O"
MB=.gpu/mb
[ -x "$MB" ] || { echo "gpu-checks: $MB not found: run ../shared/tools/gpu-bundle.sh first" >&2; exit 2; }
bash .gpu/setup.sh > "$O/00-setup.txt" 2>&1
M=.gpu/share/matbricks/materials
LTC=(--brick tube_ltc_polygon --brick tube_ltc_cv --brick sphere_ltc_polygon --brick sphere_ltc_cv)
mapfile -t STANDARD < <(grep -l '"model": "standard"' "$M"/*.json)  # the model with rect and disk lights
PLANAR=(--brick rect_ltc_polygon --brick rect_ltc_cv --brick disk_ltc_polygon --brick disk_ltc_cv)
SHEEN=(--brick rect_ltc_sheen_cv --brick disk_ltc_sheen_cv --brick sphere_ltc_sheen_cv --brick tube_ltc_sheen_cv)
step() {  # name, limit in seconds, command...
  local name=$1 limit=$2
  shift 2
  [[ $name =~ $ONLY ]] || return 0
  local start
  start=$(date +%s)
  timeout "$limit" "$@" > "$O/$name.txt" 2>&1
  echo "rc=$? wall_s=$(($(date +%s) - start))" >> "$O/$name.txt"
  echo "$name $(tail -1 "$O/$name.txt")"
}
step 01-validate-materials 60 "$MB" --device "$DEVICE" validate "$M"/*.json
step 02-validate-bricks 120 "$MB" --device "$DEVICE" validate --all-bricks
step 03-validate-ltc 120 "$MB" --device "$DEVICE" validate "${LTC[@]}" --samples 50000
step 04-validate-fp16-driver 60 "$MB" --device "$DEVICE" validate "$M"/*.json --precision fp16 --fp16 driver
step 05-stress-fp16-driver 120 "$MB" --device "$DEVICE" stress --all-bricks --precision fp16 --fp16 driver
step 06-stress-materials-fp16-driver 120 "$MB" --device "$DEVICE" stress "$M"/*.json --precision fp16 --fp16 driver
step 07-preview-studio 90 "$MB" --device "$DEVICE" preview "$M"/*.json -o "$O/preview-studio"
step 08-preview-sky 60 "$MB" --device "$DEVICE" preview "$M"/*.json --environment sky -o "$O/preview-sky"
step 09-lut 30 "$MB" --device "$DEVICE" lut
step 11-beckmann-fp16-driver 40 "$MB" --device "$DEVICE" eval --brick d_beckmann --precision fp16 --fp16 driver --input bench/gpu/beckmann_grazing.csv
step 10-bench-area-lights 60 "$MB" --device "$DEVICE" bench --slot sphere_light_ltc --slot tube_light_ltc \
  --slot tube_light_ltc_cv --slot sphere_light_ltc_cv --slot sphere_light_d --slot tube_light_point --repeats 9
step 12-validate-planar-ltc 60 "$MB" --device "$DEVICE" validate "${PLANAR[@]}" --samples 50000
step 13-validate-rect-disk 90 "$MB" --device "$DEVICE" validate "${STANDARD[@]}" --lights rect,disk --samples 50000
step 14-validate-rect-disk-fp16-driver 60 "$MB" --device "$DEVICE" validate "${STANDARD[@]}" --lights rect,disk \
  --precision fp16 --fp16 driver
step 15-stress-ltc-fp16-driver 60 "$MB" --device "$DEVICE" stress "${LTC[@]}" "${PLANAR[@]}" --precision fp16 --fp16 driver
step 16-preview-rect-disk 60 "$MB" --device "$DEVICE" preview "${STANDARD[@]}" --lights rect,disk -o "$O/preview-rect-disk"
step 17-validate-sphere-tube-ltc 150 "$MB" --device "$DEVICE" validate "${STANDARD[@]}" --lights sphere,tube \
  --samples 50000
step 18-validate-sphere-tube-fp16-driver 60 "$MB" --device "$DEVICE" validate "${STANDARD[@]}" --lights sphere,tube \
  --environment none --precision fp16 --fp16 driver
step 19-preview-sphere-tube 60 "$MB" --device "$DEVICE" preview "${STANDARD[@]}" --lights sphere,tube \
  -o "$O/preview-sphere-tube"
step 20-validate-sheen-ltc 90 "$MB" --device "$DEVICE" validate "${SHEEN[@]}" --samples 50000
step 21-validate-sheen-lights 90 "$MB" --device "$DEVICE" validate "$M"/satin_sheen.json \
  --lights rect,disk,sphere,tube --samples 50000
step 22-stress-sheen-fp16-driver 60 "$MB" --device "$DEVICE" stress "${SHEEN[@]}" --precision fp16 --fp16 driver
# The emitted GLSL 450 and ESSL 3.10 through the driver's own GLSL compiler (EGL, surfaceless), and
# the HLSL through glslang's HLSL front end to the device's Vulkan: docs/targets.md.
# Two materials with all seven lights and no environment: the NVIDIA GL driver's compile of one such
# permutation took 15-66 s on the H200 (docs/devices.md), so all 35 do not fit a lease.
TWO=("$M"/satin_sheen.json "$M"/worn_car_paint.json)
step 23-validate-glsl450 90 "$MB" validate "${TWO[@]}" --target glsl450 --environment none
step 24-validate-essl310 90 "$MB" validate "${TWO[@]}" --target essl310 --environment none
step 25-validate-hlsl 90 "$MB" --device "$DEVICE" validate "${TWO[@]}" --target hlsl --environment none
tar czf "$O.tgz" -C "$O" . && mv "$O.tgz" "$O/all.tgz"
