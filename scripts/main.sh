#!/usr/bin/env bash
# The main job: installs what is missing, builds, and makes the error-against-run-time
# report — every variant of the default matrix on every built-in scene, against
# ray-traced ground truth, timed on the Vulkan device (lavapipe when there is no GPU) —
# into out/report/. Arguments go to aogen_report (e.g. --out DIR, --size 640x360,
# --scenes room,stairs, --device H100); aogen_report --help lists them.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh
scripts/build.sh aogen_report
build/report/aogen_report "$@"
