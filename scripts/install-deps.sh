#!/usr/bin/env bash
# Installs every build and run-time dependency of matbricks from Debian 12's
# registry. Safe to run twice: only packages that are missing are installed.
# clang and libclang-rt-14-dev: the sanitizer pass and the libFuzzer targets (docs/fuzzing.md);
# clang-format: the house style (.clang-format), checked by the CTest test `format`.
# libcurl4-openssl-dev: the remote HTTP compile cache (--cache-url); nginx-light: the local
# WebDAV server its tests run against (docs/targets.md "Remote cache").
# libstb-dev: PNG writing and reading (stb_image_write, stb_image) for `matbricks preview`
# and `matbricks report` (docs/preview.md, docs/report.md).
# libegl-dev libgles-dev libopengl-dev libegl-mesa0 libgl1-mesa-dri: OpenGL 4.5 and OpenGL ES 3.1
# on llvmpipe through EGL's surfaceless platform, which runs the GLSL 450 and ESSL 3.10 targets
# (`validate --target glsl450|essl310`, docs/targets.md "Executed").
# chromium: the headless browser the report's CTest test opens it in (docs/report.md).
set -euo pipefail

PACKAGES=(
  build-essential cmake ninja-build pkg-config git
  glslang-dev glslang-tools spirv-tools spirv-headers
  libspirv-cross-c-shared-dev spirv-cross
  libvulkan-dev vulkan-validationlayers mesa-vulkan-drivers vulkan-tools
  nlohmann-json3-dev catch2 libcli11-dev libxxhash-dev
  clang libclang-rt-14-dev clang-format
  libcurl4-openssl-dev nginx-light
  libstb-dev chromium
  libegl-dev libgles-dev libopengl-dev libegl-mesa0 libgl1-mesa-dri
)

missing=()
for p in "${PACKAGES[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done

if [ "${#missing[@]}" -eq 0 ]; then
  echo "install-deps: all ${#PACKAGES[@]} packages present"
  exit 0
fi

SUDO=""
if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi
echo "install-deps: installing ${missing[*]}"
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq
$SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}"
