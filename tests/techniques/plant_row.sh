#!/usr/bin/env bash
# The tables' guards, planted (tests/CMakeLists.txt: "techniques: …", "targets: …"): compiles
# a TU that includes the table's header, first as it is (it must compile), then from a copy
# with one edit (it must not, and the compiler must say the table's message).
#   plant_row.sh CXX SOURCE_DIR GENERATED_INCLUDE_DIR WORK_DIR EDIT
# EDIT, of include/aogen/techniques.hpp: drop-vbao (a row left out), swap-gtao-vbao (two rows
#       out of order), unset-sao (a row with its members unset);
#       of include/aogen/targets.hpp: drop-msl-ios (a target's row left out).
set -euo pipefail
cxx=$1 src=$2 generated=$3 work=$4 edit=$5
case $edit in
  drop-msl-ios) file=targets.hpp message="one row per target of target_names" ;;
  *) file=techniques.hpp message="every technique of technique_names needs its row" ;;
esac
header=$src/include/aogen/$file
rm -rf "$work" && mkdir -p "$work/aogen"
printf '#include <aogen/%s>\nint main() { return 0; }\n' "$file" > "$work/tu.cpp"
compile() { "$cxx" -std=c++17 -fsyntax-only -I"$work" -I"$src/include" -I"$src/include/aogen" -I"$generated" "$work/tu.cpp" 2>&1; }

# The control: the table as it is compiles.
rm -f "$work/aogen/$file"
if ! out=$(compile); then echo "plant_row: the unedited table does not compile:"; echo "$out" | head -20; exit 1; fi

case $edit in
  drop-vbao) sed '/^    techniques::vbao,$/d' "$header" > "$work/aogen/techniques.hpp" ;;
  swap-gtao-vbao) sed -e 's/^    techniques::gtao,$/    techniques::TMP,/' -e 's/^    techniques::vbao,$/    techniques::gtao,/' \
                      -e 's/^    techniques::TMP,$/    techniques::vbao,/' "$header" > "$work/aogen/techniques.hpp" ;;
  unset-sao) sed 's/^    techniques::sao,$/    technique_desc{technique::sao, nullptr, nullptr, nullptr, nullptr, nullptr, nullptr, nullptr, nullptr},/' "$header" > "$work/aogen/techniques.hpp" ;;
  drop-msl-ios) sed '/^    {target::msl_ios, "ios.metal"/d' "$header" > "$work/aogen/targets.hpp" ;;
  *) echo "plant_row: unknown edit '$edit' (valid: drop-vbao, swap-gtao-vbao, unset-sao, drop-msl-ios)"; exit 2 ;;
esac
if cmp -s "$header" "$work/aogen/$file"; then echo "plant_row: the edit $edit changed nothing: its anchor is gone from $file"; exit 1; fi

if out=$(compile); then echo "plant_row: $file with $edit still compiles: the table's guard is gone"; exit 1; fi
if ! grep -q "$message" <<<"$out"; then
  echo "plant_row: $file with $edit fails, but not at the table's guard:"; echo "$out" | head -20; exit 1
fi
echo "plant_row: $edit refused at compile time, as it must be"
