#!/usr/bin/env bash
# Fuzzes `aogen`'s option parsing: random command lines made of its subcommands, options and
# values — good ones, wrong ones and hostile ones — and the promise of bad_inputs.sh for each:
# an exit status below 124 (no signal, no crash) within `timeout 20` (no hang), and where it
# fails, exactly one line on stderr, "aogen: <what the user wrote>: ... (valid: ...)", in
# which none of CLI11's internal words ("INT:INT", "REQUIRED") leak.
#   fuzz_args.sh AOGEN [COUNT]        COUNT command lines (default 300)
# The seed is random each run and printed; AOGEN_FUZZ_SEED=<n> repeats a run. Each failing
# command line is printed with the seed, so it can be pasted back.
set -uo pipefail
aogen=$(realpath "${1:?usage: fuzz_args.sh AOGEN [COUNT]}")
count=${2:-300}
seed=${AOGEN_FUZZ_SEED:-$(od -An -N4 -tu4 /dev/urandom | tr -d ' ')}
echo "fuzz_args: seed $seed (AOGEN_FUZZ_SEED=$seed to repeat), $count command lines"
work=$(mktemp -d "${TMPDIR:-/tmp}/aogen-fuzz-args.XXXXXX")
trap 'rm -rf "$work"' EXIT
cd "$work" || exit 1
printf '{"name": "B", "members": [{"name": "a", "type": "float"}]}' >struct.json
printf '{"normals": "gbuffer_view"}' >scene.json
printf '{"variants": ["gtao-2x3-half-bilateral-gbufworld-std-persp-cs"]}' >spec.json
printf '[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[' >nested.json

commands=(layout kernel noise seeds list generate "" bogus --help --help-all)
options=(--binding --count --emit --encoding --format --help --instance --kind --name --out --pattern --quiet --rules
         --scale --scene --seed --set --size --targets --variants -h --nope -- -)
values=(0 1 -1 16 256 257 1e9 1e400 nan inf -0 0x10 " " "" a "é" "$(printf 'a\tb')" std140 std430 scalar wgsl hlsl msl cpp
        glsl json text spv essl "spv,hlsl" "wgsl,spv,nope" struct.json scene.json spec.json nested.json /dev/null /nonexistent
        out out/x "ssao-s16-half-bilateral-gbufworld-std-persp-cs" "gtao-99x99-half" "ssao-s0" "*" "ssao-*" ","
        "$(head -c 400 /dev/zero | tr '\0' x)")

RANDOM=$((seed % 32768))
pick() { local -n list=$1; printf '%s' "${list[RANDOM % ${#list[@]}]}"; }

failures=0
for ((i = 0; i < count; i++)); do
  args=()
  cmd=$(pick commands)
  [ -n "$cmd" ] && args+=("$cmd")
  for ((k = 0; k < RANDOM % 6; k++)); do
    case $((RANDOM % 3)) in
      0) args+=("$(pick options)") ;;
      1) args+=("$(pick options)" "$(pick values)") ;;
      2) args+=("$(pick values)") ;;
    esac
  done
  rm -rf out
  timeout 20 "$aogen" "${args[@]}" >stdout 2>stderr
  rc=$?
  shown=$(printf '%q ' "${args[@]}")
  why=""
  if [ "$rc" -ge 124 ]; then why="exit $rc (a signal, a crash or a hang)"
  elif [ "$rc" -ne 0 ]; then
    lines=$(wc -l <stderr)
    if [ "$lines" -ne 1 ]; then why="$lines lines on stderr"
    elif ! grep -qE '^aogen: .*\(valid: ' stderr; then why="not one line 'aogen: ... (valid: ...)'"
    elif grep -qE 'INT:|TEXT:|FLOAT:|UINT:|REQUIRED|\[Option' stderr; then why="CLI11's internal words leak"
    fi
  fi
  if [ -n "$why" ]; then
    echo "FAILED (seed $seed, line $i): aogen $shown: $why"
    head -c 300 stderr | sed 's/^/  /'
    failures=$((failures + 1))
  fi
done
[ "$failures" -eq 0 ] || { echo "fuzz_args: $failures of $count command lines failed (AOGEN_FUZZ_SEED=$seed to repeat)"; exit 1; }
echo "fuzz_args: $count command lines, every one exited cleanly"
