#!/usr/bin/env bash
# check_header.sh CXX HEADER FLAGS... — compiles HEADER alone (C++17, syntax only) with the
# include path FLAGS and nothing else of aogen's: its layer and the layers below
# (tests/layers/CMakeLists.txt). Fails, with the compiler's message, when it needs a header
# that path does not hold.
set -euo pipefail
cxx=$1 header=$2
shift 2
if ! out=$(printf '#include "%s"\n' "$header" | "$cxx" -std=c++17 -fsyntax-only "$@" -x c++ - 2>&1); then
  echo "$header does not compile with only its layer and the layers below on the include path:" >&2
  echo "$out" | grep -E "error|fatal" | head -5 >&2
  exit 1
fi
