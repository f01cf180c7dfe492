#!/usr/bin/env bash
# Installs the Debian 12 packages aogen builds and tests with, skipping those already
# installed. Runs as root (or through sudo when it is there). Debian packages only.
set -euo pipefail

packages=(
  build-essential cmake pkg-config
  python3                     # test scripts read JSON and bytes
  catch2                      # tests (Catch2 v2)
  nlohmann-json3-dev          # the command line's JSON
  libcli11-dev                # the command line's arguments
  glslang-dev glslang-tools   # GLSL -> SPIR-V, and the reflection oracle
  spirv-tools                 # validator and optimizer
  spirv-cross libspirv-cross-c-shared-dev   # SPIR-V -> GLSL/ESSL/HLSL/MSL
  libembree-dev               # Embree 3: the ray-traced ground truth (bench/truth)
  libassimp-dev assimp-testmodels   # mesh scenes (bench/scenes) and the real meshes they use
  libstb-dev                  # PNG image strips of the report (stb_image_write)
  python3-matplotlib          # the report's error-against-time plot
  libvulkan-dev mesa-vulkan-drivers vulkan-validationlayers   # the Vulkan harness (lavapipe)
  libegl-dev libgl-dev libgles-dev libegl-mesa0 libgl1-mesa-dri   # the GL runner (llvmpipe, EGL surfaceless)
  clang-14 libclang-rt-14-dev # the fuzz targets (tests/fuzz, scripts/fuzz.sh): libFuzzer, ASan, UBSan
  llvm-14                     # llvm-symbolizer: function names and lines in the fuzz targets' reports
)

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q 'install ok installed' || missing+=("$p")
done
[ ${#missing[@]} -eq 0 ] && exit 0

as_root=()
[ "$(id -u)" -eq 0 ] || as_root=(sudo)
echo "install-deps: installing ${missing[*]}" >&2
export DEBIAN_FRONTEND=noninteractive
"${as_root[@]}" apt-get update -q
"${as_root[@]}" apt-get install -y -q --no-install-recommends "${missing[@]}"
