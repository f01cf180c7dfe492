# bench/device/setup.sh — sourced by the H200 run scripts (bench/runs/), from the repository root: unpacks
# what the device tool carried (carry [".gl", ".carry"]) and sets B (the binaries), L (the log)
# and /tmp/fakepy (the stand-in plotter that run scripts from before issue 24 pass as --python;
# aogen_report draws its plot itself now and has no --python).
# What to carry: build here, pack bin/ (aogen_report, aogen_vulkan_tests), lib/ (what ldd
# lists beyond the system: embree, assimp, tbb, draco, minizip) and models/ (the assimp test
# models) into .carry/pack.tar.xz, and the Debian loader debs (libvulkan1, the libglvnd
# family) into .gl/.
for f in .gl/*.deb; do dpkg -x "$f" /; done; ldconfig
mkdir -p /tmp/a && tar -xJf .carry/pack.tar.xz -C /tmp/a
export LD_LIBRARY_PATH=/tmp/a/lib
[ -f /usr/local/nvidia/share/vulkan/icd.d/nvidia_icd.json ] && export VK_DRIVER_FILES=/usr/local/nvidia/share/vulkan/icd.d/nvidia_icd.json
mkdir -p /usr/share/assimp/models && cp -r /tmp/a/models/* /usr/share/assimp/models/
B=/tmp/a/bin
L=$OUT/log.txt
printf '#!/bin/bash\n[ "$1" = "-c" ] && exit 0\necho none > "$3"\n' > /tmp/fakepy; chmod +x /tmp/fakepy
# The GPU's clocks and power now, appended to the log (run scripts call it around each phase).
clocks() { nvidia-smi --query-gpu=name,clocks.sm,clocks.max.sm,clocks.mem,power.draw --format=csv >> $L 2>&1; }
