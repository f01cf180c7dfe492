#!/usr/bin/env bash
# The technique table's guard, planted (tests/CMakeLists.txt: "techniques: …"): compiles a TU
# that includes include/aogen/techniques.hpp, first as it is (it must compile), then from a
# copy with one edit (it must not, and the compiler must say the table's message).
#   plant_row.sh CXX SOURCE_DIR GENERATED_INCLUDE_DIR WORK_DIR EDIT
# EDIT: drop-vbao (a row left out), swap-gtao-vbao (two rows out of order),
#       unset-sao (a row with its members unset).
set -euo pipefail
cxx=$1 src=$2 generated=$3 work=$4 edit=$5
header=$src/include/aogen/techniques.hpp
rm -rf "$work" && mkdir -p "$work/aogen"
printf '#include <aogen/techniques.hpp>\nint main() { return int(aogen::technique_of(aogen::technique::gtao).id); }\n' > "$work/tu.cpp"
compile() { "$cxx" -std=c++17 -fsyntax-only -I"$work" -I"$src/include" -I"$src/include/aogen" -I"$generated" "$work/tu.cpp" 2>&1; }

# The control: the table as it is compiles.
rm -f "$work/aogen/techniques.hpp"
if ! out=$(compile); then echo "plant_row: the unedited table does not compile:"; echo "$out" | head -20; exit 1; fi

case $edit in
  drop-vbao) sed '/^    techniques::vbao,$/d' "$header" > "$work/aogen/techniques.hpp" ;;
  swap-gtao-vbao) sed -e 's/^    techniques::gtao,$/    techniques::TMP,/' -e 's/^    techniques::vbao,$/    techniques::gtao,/' \
                      -e 's/^    techniques::TMP,$/    techniques::vbao,/' "$header" > "$work/aogen/techniques.hpp" ;;
  unset-sao) sed 's/^    techniques::sao,$/    technique_desc{technique::sao, nullptr, nullptr, nullptr, nullptr, nullptr, nullptr, nullptr, nullptr},/' "$header" > "$work/aogen/techniques.hpp" ;;
  *) echo "plant_row: unknown edit '$edit' (valid: drop-vbao, swap-gtao-vbao, unset-sao)"; exit 2 ;;
esac
if cmp -s "$header" "$work/aogen/techniques.hpp"; then echo "plant_row: the edit $edit changed nothing: its anchor is gone from techniques.hpp"; exit 1; fi

if out=$(compile); then echo "plant_row: techniques.hpp with $edit still compiles: the table's guard is gone"; exit 1; fi
if ! grep -q "every technique of technique_names needs its row" <<<"$out"; then
  echo "plant_row: techniques.hpp with $edit fails, but not at the table's guard:"; echo "$out" | head -20; exit 1
fi
echo "plant_row: $edit refused at compile time, as it must be"
