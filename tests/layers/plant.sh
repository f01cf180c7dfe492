#!/usr/bin/env bash
# plant.sh CHECK CXX LAYER_DIR HEADER UPPER WORK FLAGS... — the layer test's planted fault: a
# copy of LAYER_DIR (the staged layer) whose HEADER also includes UPPER, a header of a layer
# above. CHECK must pass on the unplanted copy and fail on the planted one, naming UPPER.
set -euo pipefail
check=$1 cxx=$2 layer_dir=$3 header=$4 upper=$5 work=$6
shift 6
rm -rf "$work" && mkdir -p "$work/clean/aogen" "$work/planted/aogen"
for f in "$layer_dir"/*.hpp; do
  cp -L "$f" "$work/clean/aogen/"
  cp -L "$f" "$work/planted/aogen/"
done
sed -i "0,/^#pragma once/s//#pragma once\n#include \"$upper\"/" "$work/planted/aogen/$header"
grep -q "#include \"$upper\"" "$work/planted/aogen/$header" || { echo "plant.sh: could not plant the include"; exit 1; }
"$check" "$cxx" "$work/clean/aogen/$header" "$@" || { echo "plant.sh: the unplanted copy fails: no control"; exit 1; }
if out=$("$check" "$cxx" "$work/planted/aogen/$header" "$@" 2>&1); then
  echo "plant.sh: $header including $upper (a layer above) compiled: the layer test cannot fail"
  exit 1
fi
echo "$out" | grep -q "$upper" || { echo "plant.sh: failed, but not on $upper:"; echo "$out"; exit 1; }
echo "the planted include of $upper failed, as it must: $out" | head -3
