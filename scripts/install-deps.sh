#!/usr/bin/env bash
# Installs the Debian 12 packages aogen builds and tests with, skipping those already
# installed, then the WGSL target's npm packages (wgsl/package-lock.json: naga-wasm and
# webgpu at pinned versions) into wgsl/node_modules. Runs as root (or through sudo when it is
# there). Debian packages and the npm registry only; nothing is fetched after install.
set -euo pipefail
cd "$(dirname "$0")/.."

packages=(
  build-essential cmake pkg-config
  python3                     # test scripts read JSON and bytes
  catch2                      # tests (Catch2 v2)
  nlohmann-json3-dev          # the command line's JSON
  libcli11-dev                # the command line's arguments
  glslang-dev glslang-tools   # GLSL -> SPIR-V, and the reflection oracle
  spirv-tools                 # validator and optimizer
  spirv-cross libspirv-cross-c-shared-dev   # SPIR-V -> GLSL/ESSL/HLSL/MSL
  libembree-dev               # Embree 3: the ray-traced ground truth (truth)
  libassimp-dev assimp-testmodels   # mesh scenes (scenes) and the real meshes they use
  libstb-dev                  # PNG image strips of the report (stb_image_write)
  chromium                    # the report's page tested in a real browser (headless)
  libvulkan-dev mesa-vulkan-drivers vulkan-validationlayers   # the Vulkan harness (lavapipe)
  libegl-dev libgl-dev libgles-dev libegl-mesa0 libgl1-mesa-dri   # the GL runner (llvmpipe, EGL surfaceless)
  clang-14 libclang-rt-14-dev # the fuzz targets (tests/fuzz, scripts/fuzz.sh): libFuzzer, ASan, UBSan
  llvm-14                     # llvm-symbolizer: function names and lines in the fuzz targets' reports
)

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q 'install ok installed' || missing+=("$p")
done
# The WGSL target runs naga and Tint in Node.js: Debian 12's nodejs (18) and npm run both
# packages (their "engines" field asks for Node 24, which only their build needs). A machine
# that already has a node and npm of 18 or later (another distribution's) keeps them.
node_major=$(node --version 2>/dev/null | sed -n 's/^v\([0-9]*\).*/\1/p')
if [ -z "$node_major" ] || [ "$node_major" -lt 18 ] || ! command -v npm >/dev/null; then
  missing+=(nodejs npm)
fi

if [ ${#missing[@]} -gt 0 ]; then
  as_root=()
  [ "$(id -u)" -eq 0 ] || as_root=(sudo)
  echo "install-deps: installing ${missing[*]}" >&2
  export DEBIAN_FRONTEND=noninteractive
  "${as_root[@]}" apt-get update -q
  "${as_root[@]}" apt-get install -y -q --no-install-recommends "${missing[@]}"
fi

# The npm packages, exactly as wgsl/package-lock.json pins them, unless npm finds them all
# installed at the versions wgsl/package.json names.
if ! (cd wgsl && npm ls --all >/dev/null 2>&1); then
  echo "install-deps: installing the WGSL tools' npm packages into wgsl/node_modules" >&2
  (cd wgsl && npm ci --no-audit --no-fund --ignore-scripts --loglevel=error)
fi
