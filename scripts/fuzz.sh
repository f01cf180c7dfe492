#!/usr/bin/env bash
# Builds the fuzz targets of the JSON readers (tests/fuzz) into build-fuzz/ with clang-14,
# AddressSanitizer and UndefinedBehaviorSanitizer, and runs each for SECONDS (default 25):
#   scripts/fuzz.sh          what scripts/test.sh runs: ~25 s a target
#   scripts/fuzz.sh 600      a hunt: ten minutes a target
# Each target first runs every input kept in tests/fuzz/findings/ (found before), then
# fuzzes. Exits non-zero when any of that fails (a crash, a sanitizer report, an exception
# that is no std::exception, a hang, running out of memory); an input the fuzzing found is
# saved as build-fuzz/findings/<target>/crash-*, timeout-*, oom-* or leak-*. Every target
# runs even after one has failed. Reproduce one on the stack they run on (below) with
#   (ulimit -s 1024; build-fuzz/tests/fuzz/aogen_fuzz_<target> FILE)
# and keep it under tests/fuzz/findings/ with a note (tests/fuzz/findings/README.md).
#
# Each target's corpus grows in build-fuzz/corpus/<target>/, kept between runs, so a run
# continues where the last one stopped; the seeds in tests/fuzz/corpus/<target>/ are read,
# never written (libFuzzer writes new inputs to the first corpus folder only).
# AOGEN_FUZZ_FLAGS adds libFuzzer flags, e.g. "-fork=1 -ignore_crashes=1" to keep going
# after a finding; AOGEN_FUZZ_STRICT=1 makes any exception but aogen::error a finding
# (tests/fuzz/fuzz_support.hpp); AOGEN_FUZZ_MAX_NESTING=1000 keeps a known, unfixed stack
# overflow by deep nesting from ending every run (tests/fuzz/nesting_mutator.cpp).
set -euo pipefail
cd "$(dirname "$0")/.."
seconds=${1:-25}
[[ "$seconds" =~ ^[1-9][0-9]*$ ]] || { echo "usage: scripts/fuzz.sh [SECONDS per target]" >&2; exit 2; }

# A folder of its own: the targets need clang, the main build (build/) uses the default compiler.
CC=clang-14 CXX=clang++-14 cmake -S . -B build-fuzz -DCMAKE_BUILD_TYPE=RelWithDebInfo -DAOGEN_FUZZ=ON \
  -DAOGEN_BUILD_GENERATOR=OFF -DAOGEN_BUILD_TESTS=OFF >/dev/null
cmake --build build-fuzz --parallel "$(nproc)" --target aogen_fuzz

# Stack traces with function names and lines; ASan looks for llvm-symbolizer on PATH, and
# Debian's llvm-14 installs it there only as llvm-symbolizer-14.
if [ -x /usr/lib/llvm-14/bin/llvm-symbolizer ]; then export ASAN_SYMBOLIZER_PATH=/usr/lib/llvm-14/bin/llvm-symbolizer; fi
export UBSAN_OPTIONS=print_stacktrace=1

# 1 MiB of stack, as a secondary thread may have (macOS gives them 512 KiB): a recursion as
# deep as the input is nested then overflows at a depth that fits in -max_len (a few
# thousand levels), rather than needing a document of hundreds of kilobytes to show the
# same fault on the main thread's 8 MiB. tests/fuzz/nesting_mutator.cpp leads the fuzzer there.
ulimit -s 1024

# What a failed run's log holds: the report, not its thousand frames of recursion (where it
# starts, its first frames, libFuzzer's last words).
show_report() {
  local log=$1 first
  first=$(grep -n -m1 -E 'ERROR: |runtime error:|aogen fuzz:' "$log" | cut -d: -f1 || true)
  if [ -n "$first" ]; then sed -n "${first},$((first + 15))p" "$log"; else tail -n 30 "$log"; fi | cut -c1-240 | sed 's/^/  /'
  grep -E '^SUMMARY|^MS:' "$log" | cut -c1-240 | sed 's/^/  /' || true
}

# A new seed each run, so that runs explore rather than repeat; printed, and AOGEN_FUZZ_SEED
# repeats a run's mutations.
# libFuzzer's -seed takes 1..2^31-1 (0 means "pick one", unprinted).
seed=${AOGEN_FUZZ_SEED:-$(( $(od -An -N4 -tu4 /dev/urandom | tr -d ' ') % 2147483647 + 1 ))}
echo "fuzz: seed $seed (AOGEN_FUZZ_SEED=$seed to repeat)"

failed=()
for target in struct variants scene; do
  corpus=build-fuzz/corpus/$target findings=build-fuzz/findings/$target log=build-fuzz/logs/$target.log
  mkdir -p "$corpus" "$findings" build-fuzz/logs
  # The known findings first, every one through every target: one not yet fixed fails the
  # run whether or not the fuzzing below happens upon it again; a fixed one guards against
  # its return. libFuzzer runs the files given and stops at the first that fails.
  if ! build-fuzz/tests/fuzz/aogen_fuzz_$target -timeout=10 -rss_limit_mb=2048 tests/fuzz/findings/*.json \
       >"build-fuzz/logs/$target.replay.log" 2>&1; then
    failed+=("$target: a known finding")
    show_report "build-fuzz/logs/$target.replay.log"
    echo "fuzz: $target: a known finding still fails: $(grep -o 'Running: .*' "build-fuzz/logs/$target.replay.log" | tail -n 1)"
  fi
  echo "fuzz: $target for ${seconds}s (log: $log)"
  start=$SECONDS
  # -seed: printed above; -timeout: seconds
  # one input may take before it counts as a hang; -max_len: room for ~16 000 levels of
  # nesting; -len_control=0: inputs may be that long at once, not only after a slow ramp.
  # shellcheck disable=SC2086 # AOGEN_FUZZ_FLAGS is a list of flags
  if build-fuzz/tests/fuzz/aogen_fuzz_$target -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 -seed="$seed" \
       -max_len=32768 -len_control=0 -dict=tests/fuzz/$target.dict -artifact_prefix="$findings/" -print_final_stats=1 \
       ${AOGEN_FUZZ_FLAGS:-} "$corpus" tests/fuzz/corpus/$target >"$log" 2>&1; then
    grep -E '^stat::(number_of_executed_units|new_units_added|peak_rss_mb)|^#[0-9]+.*DONE' "$log" | sed 's/^/  /' || true
    echo "fuzz: $target: nothing found in $((SECONDS - start))s"
  else
    failed+=("$target: fuzzing found an input (seed $seed)")
    show_report "$log"
    echo "fuzz: $target: FOUND something after $((SECONDS - start))s: $(grep -o 'Test unit written to .*' "$log" || echo "see $log")"
  fi
done
if [ ${#failed[@]} -gt 0 ]; then
  echo "fuzz: FAILED:" >&2
  printf '  %s\n' "${failed[@]}" >&2
  echo "  (known: tests/fuzz/findings/README.md; new inputs: build-fuzz/findings/)" >&2
  exit 1
fi
echo "fuzz: every known finding passes; all targets ran ${seconds}s each without a new one"
