#!/usr/bin/env bash
# Installs what is missing, builds, and runs every test; then fuzzes the JSON readers for
# 25 s each (scripts/fuzz.sh: its own build in build-fuzz/, about 2 minutes in all).
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh
scripts/build.sh
ctest --test-dir build --output-on-failure --parallel "$(nproc)"
AOGEN_FUZZ_STRICT=1 scripts/fuzz.sh 25   # strict: any exception but aogen::error is a finding
