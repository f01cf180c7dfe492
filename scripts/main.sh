#!/usr/bin/env bash
# The main job: installs what is missing, builds, and writes the data of the seeds'
# default configurations (kernels, noise tiles, uniform bytes and declarations per
# language) into out/seeds (or the directory given as the first argument).
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh
scripts/build.sh aogen
build/generator/aogen seeds --out "${1:-out/seeds}"
