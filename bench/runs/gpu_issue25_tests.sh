#!/bin/bash
# Issue 25's GPU tests on NVIDIA's driver: the frame index's oracle (a turned noise tile),
# multi-bounce against the paper's fit, and the deinterleaved twin, unvalidated (the image
# has no validation layer: AOGEN_TESTS_OPTIONAL_DEPS=1). Carries .carry/pack.tar.xz.
cd "$(dirname "$0")/../.."
. bench/device/setup.sh
nvidia-smi --query-gpu=name,clocks.sm,clocks.max.sm --format=csv >> $L 2>&1
AOGEN_TESTS_OPTIONAL_DEPS=1 timeout 200 $B/aogen_vulkan_tests "vulkan: frame f*,vulkan: a -mb*,vulkan: an albedo*,vulkan: a -deint*" >> $L 2>&1; echo "rc $?" >> $L
