#!/usr/bin/env bash
# Configures and builds aogen into build/ (Release): every target, or the ones named
# (scripts/build.sh aogen).
set -euo pipefail
cd "$(dirname "$0")/.."
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release >/dev/null
targets=()
for t in "$@"; do targets+=(--target "$t"); done
cmake --build build --parallel "$(nproc)" "${targets[@]}"
