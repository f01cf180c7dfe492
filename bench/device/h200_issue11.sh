#!/bin/bash
# The H200 run behind BENCHMARKS.md's issue-11 figures (device tool): the default matrix and
# ten fp16 twins at 1080p in one report, then the vulkan tests. The image has no matplotlib:
# a stand-in plotter (the PNG is not used).
# How: build here, pack bin/ (aogen_report, aogen_vulkan_tests), lib/ (what ldd lists beyond
# the system: embree, assimp, tbb, draco, minizip) and models/ (the assimp test models) into
# .carry/pack.tar.xz, the Debian loader debs (libvulkan1, libglvnd family) into .gl/, and
# run this script through the device tool with carry [".gl", ".carry"].
cd "$(dirname "$0")/../.."
for f in .gl/*.deb; do dpkg -x $f /; done; ldconfig
mkdir -p /tmp/a && tar -xJf .carry/pack.tar.xz -C /tmp/a
export LD_LIBRARY_PATH=/tmp/a/lib
[ -f /usr/local/nvidia/share/vulkan/icd.d/nvidia_icd.json ] && export VK_DRIVER_FILES=/usr/local/nvidia/share/vulkan/icd.d/nvidia_icd.json
mkdir -p /usr/share/assimp/models && cp -r /tmp/a/models/* /usr/share/assimp/models/
B=/tmp/a/bin
L=$OUT/log.txt
{ date; nvidia-smi; nvidia-smi -q -d CLOCK | head -40; } > $OUT/smi.txt 2>&1
printf '#!/bin/bash\n[ "$1" = "-c" ] && exit 0\necho none > "$3"\n' > /tmp/fakepy; chmod +x /tmp/fakepy
echo "== all 1080p" >> $L; timeout 420 $B/aogen_report --size 1920x1080 --rays 1024 --scenes room,stairs,engine,teapots,terrain --variants bench/device/h200_all.json --python /tmp/fakepy --out /tmp/a1080 >> $L 2>&1; echo "rc $?" >> $L
echo "== vulkan tests" >> $L; timeout 90 $B/aogen_vulkan_tests >> $L 2>&1; echo "rc $?" >> $L
cd /tmp && tar -czf $OUT/reports.tar.gz a1080/results.json a1080/report.md 2>>$L
