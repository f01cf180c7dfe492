#!/bin/bash
# bench/device/pack.sh — makes .carry/pack.tar.xz, what the H200 scripts unpack (setup.sh):
# bin/ (aogen_report, aogen_clock_probe, aogen_vulkan_tests from build/, stripped), lib/ (the
# shared libraries ldd lists that the device image lacks: embree, assimp, tbb, draco,
# minizip) and models/ (the assimp test models the built-in mesh scenes read; the mesh
# scenes timed there). Run from the repository root after scripts/build.sh.
set -euo pipefail
stage=$(mktemp -d)
trap 'rm -rf "$stage"' EXIT
mkdir -p "$stage/bin" "$stage/lib" .carry
for b in report/aogen_report report/aogen_clock_probe tests/aogen_vulkan_tests; do
  cp "build/$b" "$stage/bin/" && strip "$stage/bin/$(basename "$b")"
done
for l in libembree3 libassimp libtbb libdraco libminizip; do
  cp -L "$(ldd build/report/aogen_report | awk -v l="$l" '$1 ~ "^"l"\\." {print $3}')" "$stage/lib/"
done
models=/usr/share/assimp/models
for m in Collada/teapots.DAE glTF2/2CylinderEngine-glTF-Binary/2CylinderEngine.glb TER/RealisticTerrain_Large.ter; do
  mkdir -p "$stage/models/$(dirname "$m")" && cp "$models/$m" "$stage/models/$m"
done
tar -cJf .carry/pack.tar.xz -C "$stage" .
ls -l .carry/pack.tar.xz
