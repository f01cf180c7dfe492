#!/usr/bin/env bash
# Configures and builds aogen into build/ (Release): every target, or the ones named
# (scripts/build.sh aogen). Every part must be found (AOGEN_REQUIRE_ALL): the scripts
# install all dependencies, so a missing one is an error here, not a silently smaller build.
set -euo pipefail
cd "$(dirname "$0")/.."
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release -DAOGEN_REQUIRE_ALL=ON >/dev/null
targets=()
for t in "$@"; do targets+=(--target "$t"); done
cmake --build build --parallel "$(nproc)" "${targets[@]}"
