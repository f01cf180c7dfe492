#!/usr/bin/env bash
# The catalogue of bad inputs: what `aogen` and `aogen_report` must do with every input
# they cannot use. One ctest test per group:
#   bad_inputs.sh GROUP AOGEN [AOGEN_REPORT]     (AOGEN '-' for the report group alone)
#   GROUP: command layout kernel noise seeds list generate report, or all
# tests/CMakeLists.txt registers each group as "cli: bad inputs GROUP".
#
# The promise under test, for every bad input:
#   - a non-zero exit status below 128 (no signal, no crash), within `timeout 20` (no hang);
#   - exactly one line on stderr, shorter than 300 bytes, starting with the program's name
#     and a colon ("aogen: ", "aogen_report: "), with no raw control characters, naming
#     what the user wrote (the option, or the file and the field: `s.json: camera.near`
#     or `s.json.camera.near`) and what would be valid ("(valid: ...)");
#   - nothing on stdout;
#   - the case's folder byte-for-byte as it was: every entry's path, type, mode and link
#     target, and every regular file's SHA-256, before and after. The folder holds the
#     inputs and the output paths, so a pre-existing good generation must survive a
#     failing run untouched, and a run into a new folder must leave no folder and no
#     temporary file behind.
# aogen_report's progress lines ("aogen_report 0.4s ...") are set aside only in the cases
# marked -P, which necessarily fail after the work has started (the plot step, a scene
# whose geometry nothing on screen hits); everywhere else a progress line means the
# input was not refused before the work began. `aogen generate` runs with --quiet.
#
# A few cases are the other side of the same promise (an output path that works must
# work): a pipe on stdout, --out /dev/stdout into a pipe, --out a FIFO with a reader,
# --out through a symbolic link (written through to the target, or refused — the link
# must stay a link either way).
#
# Each failing case prints one line: "FAILED: GROUP/CASE: what was wrong; ... — stderr: ...".
set -uo pipefail
group=${1:?usage: bad_inputs.sh GROUP AOGEN [AOGEN_REPORT]}
aogen=${2:?usage: bad_inputs.sh GROUP AOGEN [AOGEN_REPORT]} # '-': none (the report group needs only AOGEN_REPORT)
[ "$aogen" = - ] || aogen=$(realpath "$aogen")
report=${3:+$(realpath "$3")}
work=$(mktemp -d "${TMPDIR:-/tmp}/aogen-bad-inputs.XXXXXX")
background=()
cleanup() {
  local p
  for p in "${background[@]}"; do kill "$p" 2>/dev/null; done
  rm -rf "$work"
}
trap cleanup EXIT
cases=0 failures=0
limit_line=300

# --- helpers -------------------------------------------------------------------------

# Every entry under $1 (path, type, mode, link target) and every regular file's SHA-256.
snapshot() {
  (cd "$1" && find . -printf '%p %y %m %l\n' | LC_ALL=C sort &&
    find . -type f -print0 | LC_ALL=C sort -z | xargs -0r sha256sum)
}

# The text as an ERE matching itself.
re() { sed 's/[][\.*^$+?(){}|]/\\&/g' <<<"$1"; }
# A field of a file as messages may write it: "in.json: members[0].count" or "in.json.members[0].count".
field() { echo "$(re "$1")(: ?|\.)$(re "$2")"; }

# new_case NAME: a fresh, empty folder $c for the case's inputs and outputs.
new_case() {
  name=$1
  c=$work/$name
  mkdir -p "$c"
  cases=$((cases + 1))
  err=/dev/null setup_problem=""
}

problems=()
problem() { problems+=("$*"); }

# setup COMMAND...: a step that makes a case's inputs (an earlier good generation, say);
# when it fails, the case fails saying so instead of running.
setup() {
  "$@" >/dev/null 2>"$work/setup.stderr" && return 0
  [ -n "$setup_problem" ] || setup_problem="setup failed: $(basename "$1") ${*:2:3}: $(head -c 100 "$work/setup.stderr" | tr '\n' ' ')"
  return 1
}
# A case whose setup failed: report it and do not run.
setup_failed() {
  [ -n "$setup_problem" ] || return 1
  problem "$setup_problem"
  finish
}

# Reports the case: passed, or one line with every problem and the start of stderr.
finish() {
  if [ ${#problems[@]} -gt 0 ]; then
    failures=$((failures + 1))
    local all="" p
    for p in "${problems[@]}"; do all+="${all:+; }$p"; done
    local excerpt
    excerpt=$(head -c 160 "$err" 2>/dev/null | cat -v | tr '\n' '|')
    echo "FAILED: $group/$name: $all — stderr: ${excerpt:-(empty)}"
  else
    echo "ok: $group/$name"
  fi
  problems=()
}

# run -- COMMAND...: runs COMMAND in $c, stdin /dev/null, under `timeout 20`; sets rc,
# ms (wall time), prog (the program's name), out and err (its stdout and stderr).
run_limit=20
run() {
  shift
  prog=$(basename "$1")
  out=$work/$name.stdout err=$work/$name.stderr
  local t0
  t0=$(date +%s%N)
  { (cd "$c" && exec timeout -k 5 "$run_limit" "$@" </dev/null >"$out" 2>"$err"); } 2>/dev/null # not bash's "Segmentation fault"
  rc=$?
  ms=$((($(date +%s%N) - t0) / 1000000))
}

# succeeded: a problem unless the run just made exited 0.
succeeded() {
  if [ "$rc" -eq 124 ] || [ "$rc" -eq 137 ]; then problem "hung: killed after ${run_limit} s"
  elif [ "$rc" -ne 0 ]; then problem "exit $rc"
  fi
}

# check_refusal [-m ERE]... [-x CODE] [-s SECONDS] [-P]: the checks of a refused input,
# on the run just made; adds a problem for each one that does not hold.
check_refusal() {
  local patterns=() code="" seconds="" progress=0
  while [ $# -gt 0 ]; do
    case $1 in
      -m) patterns+=("$2"); shift 2 ;;
      -x) code=$2; shift 2 ;;
      -s) seconds=$2; shift 2 ;;
      -P) progress=1; shift ;;
      *) echo "check_refusal: unknown option $1"; exit 2 ;;
    esac
  done
  if [ "$rc" -eq 124 ] || [ "$rc" -eq 137 ]; then problem "hung: killed after ${run_limit} s"
  elif [ "$rc" -ge 128 ]; then problem "crashed: exit $rc (signal $((rc - 128)))"
  elif [ "$rc" -eq 0 ]; then problem "exit 0"
  elif [ -n "$code" ] && [ "$rc" -ne "$code" ]; then problem "exit $rc (expected $code)"
  fi
  if [ -n "$seconds" ] && [ "$ms" -gt $((seconds * 1000)) ]; then problem "took $ms ms (expected under $seconds s)"; fi

  local lines=$work/$name.lines
  if [ "$progress" -eq 1 ]; then grep -avE "^$prog [0-9]+\.[0-9]s " "$err" >"$lines"; else cp "$err" "$lines"; fi
  local n
  n=$(wc -l <"$lines")
  if [ -s "$lines" ] && [ "$(tail -c 1 "$lines" | od -An -c | tr -d ' ')" != '\n' ]; then
    n=$((n + 1))
    problem "stderr does not end in a newline"
  fi
  [ "$n" -eq 1 ] || problem "$n lines on stderr"
  local first longest
  first=$(head -n 1 "$lines")
  longest=$(LC_ALL=C awk '{ if (length($0) > m) m = length($0) } END { print m + 0 }' "$lines")
  [ "$longest" -lt "$limit_line" ] || problem "a stderr line of $longest bytes (limit $limit_line)"
  case $first in
    "$prog: "*) ;;
    *) [ "$n" -eq 0 ] || problem "stderr does not start with '$prog: '" ;;
  esac
  if tr -d '\n' <"$lines" | LC_ALL=C grep -aq '[[:cntrl:]]'; then problem "raw control characters on stderr"; fi
  grep -aqF '(valid: ' "$lines" || problem "no '(valid: ...)'"
  local p
  for p in "${patterns[@]}"; do grep -aqE -e "$p" "$lines" || problem "lacks /$p/"; done
  [ ! -s "$out" ] || problem "wrote $(wc -c <"$out") bytes to stdout: $(head -c 60 "$out" | cat -v | tr '\n' '|')"
}

# changed BEFORE: a problem naming the first entries that differ from the snapshot BEFORE.
changed() {
  local now diff
  now=$(snapshot "$c")
  if [ "$now" != "$1" ]; then
    diff=$(diff <(echo "$1") <(echo "$now") | grep -a '^[<>]' | head -n 4 | cut -c1-90 | tr '\n' ' ')
    problem "the folder changed: $diff"
  fi
}

# expect_fail [check_refusal options] -- COMMAND...: COMMAND, run in $c, must refuse its
# input as the promise says and leave $c as it was.
expect_fail() {
  local checks=()
  while [ "$1" != -- ]; do
    case $1 in
      -P) checks+=("$1"); shift ;;
      *) checks+=("$1" "$2"); shift 2 ;;
    esac
  done
  shift
  setup_failed && return
  local before
  before=$(snapshot "$c")
  run -- "$@"
  check_refusal "${checks[@]}"
  changed "$before"
  finish
}

# expect_link_kept LINK EXPECTED -- COMMAND...: COMMAND writes to the symbolic link LINK
# (relative to $c). Either it writes through (exit 0, LINK still the same link, its target
# holding EXPECTED's bytes) or it refuses (expect_fail's checks, $c unchanged).
expect_link_kept() {
  local link=$1 expected=$2
  shift 3
  setup_failed && return
  local before target
  before=$(snapshot "$c")
  target=$(readlink "$c/$link")
  run -- "$@"
  if [ "$rc" -eq 0 ]; then
    if [ ! -L "$c/$link" ]; then problem "replaced the link $link by a $(stat -c %F "$c/$link" 2>/dev/null)"
    elif [ "$(readlink "$c/$link")" != "$target" ]; then problem "the link $link now points elsewhere"
    elif ! cmp -s "$c/$link" "$expected"; then problem "the link's target does not hold the output"
    fi
    [ -z "$(find "$c" -name '*tmp*')" ] || problem "left a temporary file: $(find "$c" -name '*tmp*' | head -n 1)"
  else
    check_refusal
    changed "$before"
  fi
  finish
}

# python3 writes a JSON input: py FILE CODE (CODE writes to `f`).
py() { python3 -c "import json, sys
with open(sys.argv[1], 'w') as f:
$(sed 's/^/    /' <<<"$2")" "$1"; }
# A variant spec whose one matrix expands to 27 648 distinct variants: 12 sample counts ×
# 4 blurs (bilateral with either depth term, box, none) × 3 normals × 2 point-cloud × 3 depth
# × 2 projections × 2 resolutions × 2 stages × 2 range checks × 2 outputs.
big_spec() {
  py "$1" 'json.dump({"matrices": [{"technique": ["ssao"], "samples": list(range(1, 13)),
    "blur": ["bilateral", "box", "none"], "bilateral_depth": ["seed_raw", "linear"],
    "normals": ["gbuffer_world", "gbuffer_view", "reconstructed"], "point_cloud": ["on", "off"],
    "depth": ["standard", "reversed", "reversed_infinite"], "projection": ["perspective", "orthographic"],
    "resolution": ["half", "full"], "stage": ["compute", "fragment"], "range_check": ["taos", "seed004"],
    "output": ["strength", "power_intensity"]}]}, f)'
}
# A JSON value nested N arrays deep: '[' * N + '1' + ']' * N.
nested() { python3 -c "import sys; n = int(sys.argv[1]); sys.stdout.write('[' * n + '1' + ']' * n)" "$1"; }

good_struct='{"name": "P", "members": [{"name": "a", "type": "float"}, {"name": "k", "type": "vec4", "count": 4}]}'
struct_file() { printf '%s' "${1:-$good_struct}" >"$c/in.json"; }
esc=$'\x1b[31m'

# --- command: the top level ----------------------------------------------------------
group_command() {
  new_case unknown-command
  expect_fail -m frobnicate -m layout -m kernel -m noise -m seeds -m generate -- "$aogen" frobnicate
  new_case no-command
  expect_fail -m layout -m kernel -m generate -- "$aogen"
  new_case unknown-option
  expect_fail -m '--frob' -- "$aogen" --frob list
  new_case control-characters-in-command
  expect_fail -m 'list|layout' -- "$aogen" "lis${esc}t"
}

# --- layout: struct files and the declaration options --------------------------------
group_layout() {
  new_case count-nested-10000
  printf '{"name": "P", "members": [{"name": "a", "type": "float", "count": %s}]}' "$(nested 10000)" >"$c/in.json"
  # The field's range, or the JSON reader's depth limit (64 levels): each names what is valid.
  expect_fail -m "$(field in.json 'members[0].count')" -m '0\.\.1048576|deeper than 64 levels' -- "$aogen" layout --rules std140 in.json

  new_case count-nested-100000
  nested 100000 >"$c/n"
  { printf '{"name": "P", "members": [{"name": "a", "type": "float", "count": '; cat "$c/n"; printf '}]}'; } >"$c/in.json"
  rm "$c/n"
  expect_fail -m "$(field in.json 'members[0].count')" -- "$aogen" layout --rules std140 in.json

  new_case count-beyond-a-double
  struct_file '{"name": "P", "members": [{"name": "a", "type": "float", "count": 1e400}]}'
  expect_fail -m "$(field in.json 'members[0].count')" -- "$aogen" layout --rules std140 in.json

  new_case member-name-over-1024-characters
  py "$c/in.json" 'json.dump({"name": "P", "members": [{"name": "m" * 1100, "type": "float"}]}, f)'
  expect_fail -m "$(field in.json 'members[0].name')|P\.m" -m 1024 -- "$aogen" layout --rules std140 in.json

  new_case duplicate-key-top-level
  struct_file '{"name": "P", "members": [{"name": "a", "type": "float"}], "members": [{"name": "b", "type": "vec4"}]}'
  expect_fail -m "$(field in.json members)" -m 'duplicate|more than once|twice|repeated' -- "$aogen" layout --rules std140 in.json

  new_case duplicate-key-in-a-member
  struct_file '{"name": "P", "members": [{"name": "a", "type": "float", "type": "vec4"}]}'
  expect_fail -m "$(field in.json 'members[0].type')" -m 'duplicate|more than once|twice|repeated' -- "$aogen" layout --rules std140 in.json

  new_case unknown-type-in-an-unused-struct
  struct_file '{"name": "P", "members": [{"name": "a", "type": "float"}], "structs": [{"name": "L", "members": [{"name": "b", "type": "flaot"}]}]}'
  expect_fail -m 'flaot' -m 'valid: .*float' -- "$aogen" layout --rules std140 in.json

  new_case struct-name-not-an-identifier
  struct_file '{"name": "1abc", "members": [{"name": "a", "type": "float"}]}'
  expect_fail -m "$(field in.json name)|1abc" -m 'identifier|letter' -- "$aogen" layout --rules std140 --emit glsl in.json

  new_case member-name-with-a-space
  struct_file '{"name": "P", "members": [{"name": "a b", "type": "float"}]}'
  expect_fail -m "$(field in.json 'members[0].name')|P\.a b" -- "$aogen" layout --rules std140 --emit glsl in.json

  new_case member-name-with-control-characters
  struct_file '{"name": "P", "members": [{"name": "a\u001b[31m", "type": "float"}]}'
  expect_fail -m "$(field in.json 'members[0].name')|P\.a" -- "$aogen" layout --rules std140 --emit glsl in.json

  new_case struct-file-is-a-directory
  mkdir "$c/in.json"
  expect_fail -m 'in\.json' -m 'director' -- "$aogen" layout --rules std140 in.json

  new_case binding-without-emit
  struct_file
  expect_fail -m '--binding' -m '--emit' -- "$aogen" layout --rules std140 --binding 3 in.json

  new_case set-without-emit
  struct_file
  expect_fail -m '--set' -m '--emit' -- "$aogen" layout --rules std140 --set 1 in.json

  new_case binding-negative
  struct_file
  expect_fail -m '--binding' -- "$aogen" layout --rules std140 --emit glsl --binding -1 in.json

  new_case binding-not-a-number
  struct_file
  expect_fail -m '--binding' -- "$aogen" layout --rules std140 --emit glsl --binding abc in.json

  new_case instance-not-an-identifier
  struct_file
  expect_fail -m '--instance' -m 'identifier|letter' -- "$aogen" layout --rules std140 --emit glsl --instance 'x;y' in.json

  new_case missing-rules
  struct_file
  expect_fail -m '--rules' -m 'std140' -- "$aogen" layout in.json

  new_case out-empty
  struct_file
  expect_fail -m '--out' -- "$aogen" layout --rules std140 --out '' in.json

  new_case out-is-a-directory
  struct_file
  mkdir "$c/o.json"
  expect_fail -m 'o\.json' -- "$aogen" layout --rules std140 --out o.json in.json

  new_case out-under-a-file
  struct_file
  touch "$c/file"
  expect_fail -m 'file' -- "$aogen" layout --rules std140 --out file/o.json in.json

  new_case out-through-a-symlink
  struct_file
  "$aogen" layout --rules std140 "$c/in.json" >"$work/layout.expected" || setup false "aogen layout of a good struct"
  echo old >"$c/target.json"
  ln -s target.json "$c/link.json"
  expect_link_kept link.json "$work/layout.expected" -- "$aogen" layout --rules std140 --out link.json in.json

  # Already right today: typos, unknown keys, wrong types, bad values.
  new_case unknown-rules
  struct_file
  expect_fail -m 'std150' -m 'std140' -- "$aogen" layout --rules std150 in.json
  new_case unknown-key
  struct_file '{"name": "P", "members": [{"name": "a", "type": "float", "cout": 2}]}'
  expect_fail -m "$(field in.json 'members[0].cout')" -m 'valid: name, type, count' -- "$aogen" layout --rules std140 in.json
  new_case count-is-a-string
  struct_file '{"name": "P", "members": [{"name": "a", "type": "float", "count": "4"}]}'
  expect_fail -m "$(field in.json 'members[0].count')" -- "$aogen" layout --rules std140 in.json
  new_case count-not-an-integer
  struct_file '{"name": "P", "members": [{"name": "a", "type": "float", "count": 1.5}]}'
  expect_fail -m "$(field in.json 'members[0].count')" -- "$aogen" layout --rules std140 in.json
  new_case count-negative
  struct_file '{"name": "P", "members": [{"name": "a", "type": "float", "count": -2}]}'
  # The field's range, or the JSON reader's depth limit (64 levels): each names what is valid.
  expect_fail -m "$(field in.json 'members[0].count')" -m '0\.\.1048576|deeper than 64 levels' -- "$aogen" layout --rules std140 in.json
  new_case unknown-type
  struct_file '{"name": "P", "members": [{"name": "a", "type": "flaot"}]}'
  expect_fail -m "P\.a" -m 'flaot' -- "$aogen" layout --rules std140 in.json
  new_case recursive-struct
  struct_file '{"name": "P", "members": [{"name": "a", "type": "L"}], "structs": [{"name": "L", "members": [{"name": "b", "type": "L"}]}]}'
  expect_fail -m 'L' -- "$aogen" layout --rules std140 in.json
  new_case malformed-json
  struct_file '{"name": "P", "members": ['
  expect_fail -m 'in\.json' -- "$aogen" layout --rules std140 in.json
  new_case missing-file
  expect_fail -m 'nope\.json' -- "$aogen" layout --rules std140 nope.json
}

# --- kernel and noise: the options they share, and their output paths -----------------
# shared_cases SUB OPTION RANGE NAMED ARGS...: SUB (kernel, noise) with its size OPTION
# (--count, --size) of RANGE (lo..hi), NAMED a --format that prints a --name (glsl, cpp),
# and ARGS a small binary output's arguments.
shared_cases() {
  local sub=$1 option=$2 range=$3 named=$4
  shift 4
  local small=("$aogen" "$sub" "$@") expected=$work/$sub.expected o=${option#--} r
  r=$(re "$range")
  "${small[@]}" >"$expected"
  local bytes
  bytes=$(wc -c <"$expected")

  new_case "$o-not-a-number"
  expect_fail -m "$option" -m "$r" -- "$aogen" "$sub" "$option" abc
  new_case "$o-beyond-int"
  expect_fail -m "$option" -m "$r" -- "$aogen" "$sub" "$option" 99999999999
  new_case seed-negative
  expect_fail -m '--seed' -- "${small[@]}" --seed -1
  new_case seed-beyond-64-bits
  expect_fail -m '--seed' -- "${small[@]}" --seed 18446744073709551616
  new_case name-starts-with-a-digit
  expect_fail -m '--name' -m '1abc' -- "$aogen" "$sub" --format "$named" --name 1abc
  new_case name-with-a-space
  expect_fail -m '--name' -- "$aogen" "$sub" --format "$named" --name 'a b'
  new_case name-with-control-characters
  expect_fail -m '--name' -- "$aogen" "$sub" --format "$named" --name "n${esc}"

  new_case out-empty
  expect_fail -m '--out' -- "${small[@]}" --out ''
  new_case out-is-a-directory
  mkdir "$c/o.bin"
  expect_fail -m 'o\.bin' -- "${small[@]}" --out o.bin
  new_case out-fifo-without-a-reader
  mkfifo "$c/o.bin"
  expect_fail -m 'o\.bin' -- "${small[@]}" --out o.bin

  new_case out-fifo-with-a-reader # the bytes arrive through the FIFO
  mkfifo "$c/o.bin"
  cat "$c/o.bin" >"$work/fifo.got" &
  local reader=$!
  background+=("$reader")
  run -- "${small[@]}" --out o.bin
  for _ in $(seq 50); do kill -0 "$reader" 2>/dev/null || break; sleep 0.1; done
  if kill -0 "$reader" 2>/dev/null; then kill "$reader" 2>/dev/null; problem "the reader got no end of file"; fi
  wait "$reader" 2>/dev/null
  succeeded
  cmp -s "$work/fifo.got" "$expected" || problem "the reader got $(wc -c <"$work/fifo.got") bytes, not the $bytes of the output"
  [ -p "$c/o.bin" ] || problem "o.bin is no longer a FIFO: $(stat -c %F "$c/o.bin" 2>/dev/null)"
  [ "$(ls -A "$c")" = o.bin ] || problem "left files behind: $(ls -A "$c" | tr '\n' ' ')"
  finish

  new_case stdout-a-pipe
  run -- bash -c 'set -o pipefail; "$@" | cat >"$0"' "$work/pipe.got" "${small[@]}"
  succeeded
  cmp -s "$work/pipe.got" "$expected" || problem "cat got $(wc -c <"$work/pipe.got") bytes, not the $bytes of the output"
  finish

  new_case out-dev-stdout-a-pipe
  run -- bash -c 'set -o pipefail; "$@" --out /dev/stdout | cat >"$0"' "$work/devstdout.got" "${small[@]}"
  succeeded
  cmp -s "$work/devstdout.got" "$expected" || problem "cat got $(wc -c <"$work/devstdout.got") bytes, not the $bytes of the output"
  [ -L /dev/stdout ] || problem "/dev/stdout is no longer a symbolic link"
  ! ls /dev | grep -q '^stdout\.tmp' || problem "left /dev/$(ls /dev | grep '^stdout\.tmp' | head -n 1)"
  finish

  new_case out-through-a-symlink
  echo old >"$c/target.bin"
  ln -s target.bin "$c/link.bin"
  expect_link_kept link.bin "$expected" -- "${small[@]}" --out link.bin
  new_case out-through-a-dangling-symlink
  ln -s target.bin "$c/link.bin"
  expect_link_kept link.bin "$expected" -- "${small[@]}" --out link.bin

  new_case stdout-full
  run -- bash -c 'exec "$@" >/dev/full' - "${small[@]}"
  prog=aogen
  check_refusal -m 'stdout|standard output|/dev/full'
  finish

  # Already right today.
  new_case "$o-zero"
  expect_fail -m "$o" -m "$r" -- "$aogen" "$sub" "$option" 0
  new_case "$o-negative"
  expect_fail -m "$o" -m "$r" -- "$aogen" "$sub" "$option" -5
  new_case "$o-above-the-range"
  expect_fail -m "$o" -m "$r" -- "$aogen" "$sub" "$option" $((${range#*..} + 1))
  new_case out-under-a-file
  touch "$c/file"
  expect_fail -m 'file' -- "${small[@]}" --out file/o.bin
}

group_kernel() {
  shared_cases kernel --count 1..256 glsl --format bin --count 4
  new_case unknown-kind
  expect_fail -m 'blue' -m 'crytek' -- "$aogen" kernel --kind blue
  new_case unknown-format
  expect_fail -m '--format' -m 'yaml' -- "$aogen" kernel --format yaml
  new_case unknown-scale
  expect_fail -m 'sideways' -m 'crytek' -- "$aogen" kernel --scale sideways
}

group_noise() {
  shared_cases noise --size 1..64 cpp --format bin --size 4
  new_case unknown-encoding
  expect_fail -m 'rgba8_srgb' -m 'rgba32f' -- "$aogen" noise --encoding rgba8_srgb
  new_case unknown-pattern
  expect_fail -m 'blue' -m 'r2' -- "$aogen" noise --pattern blue
  new_case unknown-format
  expect_fail -m '--format' -m 'glsl' -- "$aogen" noise --format glsl
}

# --- seeds ---------------------------------------------------------------------------
group_seeds() {
  new_case fourth-preset-fails # the files sort manifest, pointcloud_viewer_ssao, taos_gtao, taos_ssao, unique_engine_ssao
  mkdir "$c/out"
  echo 'in the way' >"$c/out/unique_engine_ssao"
  expect_fail -m 'unique_engine_ssao' -- "$aogen" seeds --out out

  new_case fourth-preset-fails-over-a-generation
  if setup "$aogen" seeds --out "$c/out"; then
    echo ' ' >>"$c/out/taos_ssao/params.json" # a stale file, which a successful run would rewrite
    rm "$c/out/unique_engine_ssao/kernel.json"
    mkdir "$c/out/unique_engine_ssao/kernel.json"
    touch "$c/out/unique_engine_ssao/kernel.json/in-the-way"
  fi
  expect_fail -m 'unique_engine_ssao/kernel\.json' -- "$aogen" seeds --out out

  new_case out-empty
  expect_fail -m '--out' -- "$aogen" seeds --out ''

  new_case out-is-a-file
  echo 'a file' >"$c/out"
  expect_fail -m 'out' -- "$aogen" seeds --out out

  new_case unexpected-argument
  expect_fail -m 'extra' -- "$aogen" seeds --out out extra

  new_case manifest-is-a-symlink
  if setup "$aogen" seeds --out "$c/out"; then
    cp "$c/out/manifest.json" "$work/seeds-manifest.expected"
    echo stale >"$c/elsewhere.json"
    rm "$c/out/manifest.json"
    ln -s ../elsewhere.json "$c/out/manifest.json"
  fi
  expect_link_kept out/manifest.json "$work/seeds-manifest.expected" -- "$aogen" seeds --out out
}

# --- list ----------------------------------------------------------------------------
group_list() {
  new_case unknown-option
  expect_fail -m '--frob' -m '--variants' -- "$aogen" list --frob
  new_case unexpected-argument
  expect_fail -m 'extra' -- "$aogen" list extra
  new_case flag-with-a-value
  expect_fail -m '--variants' -- "$aogen" list --variants=maybe
  new_case stdout-full
  run -- bash -c "exec '$aogen' list --variants >/dev/full"
  prog=aogen
  check_refusal -m 'stdout|standard output|/dev/full'
  finish
  new_case stdout-closed
  run -- bash -c "exec '$aogen' list --variants >&-"
  prog=aogen
  check_refusal -m 'stdout|standard output'
  finish
}

# --- generate: names, variant specs, selection scenes, the output folder ---------------
v1=gtao-1x1-half-noblur-gbufworld-std-persp-cs
v2=ssao-s8-full-noblur-recon-std-persp-cs # sorts after manifest.json
group_generate() {
  local gen=("$aogen" generate --quiet --targets spv)
  new_case spec-samples-nested-10000
  printf '{"matrices": [{"samples": %s}]}' "$(nested 10000)" >"$c/spec.json"
  expect_fail -m "$(field spec.json 'matrices[0].samples')" -- "${gen[@]}" --out out --variants spec.json
  new_case spec-slices-nested-100000
  nested 100000 >"$c/n"
  { printf '{"matrices": [{"technique": ["gtao"], "slices": ['; cat "$c/n"; printf ']}]}'; } >"$c/spec.json"
  rm "$c/n"
  expect_fail -m "$(field spec.json 'matrices[0].slices')" -- "${gen[@]}" --out out --variants spec.json
  new_case spec-steps-nested-10000
  printf '{"matrices": [{"technique": ["gtao"], "steps": [%s]}]}' "$(nested 10000)" >"$c/spec.json"
  expect_fail -m "$(field spec.json 'matrices[0].steps')" -- "${gen[@]}" --out out --variants spec.json

  new_case variant-name-18kB
  expect_fail -m 'variant|name' -- "${gen[@]}" --out out "ssao-s16-half-$(head -c 18000 /dev/zero | tr '\0' x)-gbufworld-std-persp-cs"
  new_case spec-variant-name-18kB
  py "$c/spec.json" 'json.dump({"variants": ["ssao-s16-" + "x" * 18000]}, f)'
  expect_fail -m "$(field spec.json 'variants[0]')" -- "${gen[@]}" --out out --variants spec.json
  new_case variant-name-with-control-characters
  expect_fail -m 'variant|name' -- "${gen[@]}" --out out "ssao-s16-half-box${esc}-gbufworld-std-persp-cs"

  new_case destination-is-a-directory-over-a-generation
  if setup "${gen[@]}" --out "$c/out" $v1; then
    mkdir -p "$c/out/$v2/ao.comp.spv"
    touch "$c/out/$v2/ao.comp.spv/in-the-way"
  fi
  expect_fail -m "$(re "$v2/ao.comp.spv")" -- "${gen[@]}" --out out $v1 $v2
  new_case destination-folder-is-a-file-over-a-generation
  setup "${gen[@]}" --out "$c/out" $v1 && echo 'in the way' >"$c/out/$v2"
  expect_fail -m "$(re "$v2")" -- "${gen[@]}" --out out $v1 $v2
  new_case new-folder-path-too-long # out/ itself can be made; out/aogen_variants.hpp is over PATH_MAX
  local long=new
  while [ ${#long} -lt 4085 ]; do long+=/$(head -c 200 /dev/zero | tr '\0' d); done
  long=${long:0:4085}
  long=${long%/}
  expect_fail -m 'aogen_variants\.hpp|too long' -- "${gen[@]}" --out "$long" $v1

  new_case spec-27648-variants
  big_spec "$c/spec.json"
  expect_fail -s 5 -m '27648|27 648|27,648' -m 'spec\.json' -- "${gen[@]}" --out out --variants spec.json

  new_case variants-empty
  expect_fail -m '--variants' -- "${gen[@]}" --out out --variants ''
  new_case samples-in-a-gtao-matrix
  printf '{"matrices": [{"technique": ["gtao"], "samples": [8, 16]}]}' >"$c/spec.json"
  expect_fail -m "$(field spec.json 'matrices[0].samples')" -m 'gtao|ssao' -- "${gen[@]}" --out out --variants spec.json
  new_case slices-in-an-ssao-matrix
  printf '{"matrices": [{"technique": ["ssao"], "slices": [1, 2]}]}' >"$c/spec.json"
  expect_fail -m "$(field spec.json 'matrices[0].slices')" -m 'gtao|ssao' -- "${gen[@]}" --out out --variants spec.json
  new_case spec-duplicate-key
  printf '{"matrices": [{"samples": [8], "samples": [16]}]}' >"$c/spec.json"
  expect_fail -m "$(field spec.json 'matrices[0].samples')" -m 'duplicate|more than once|twice|repeated' -- "${gen[@]}" --out out --variants spec.json
  new_case scene-duplicate-key
  printf '{"normals": "gbuffer_view", "normals": "reconstructed"}' >"$c/scene.json"
  expect_fail -m "$(field scene.json normals)" -m 'duplicate|more than once|twice|repeated' -- "${gen[@]}" --out out --scene scene.json $v1
  new_case spec-is-a-directory
  mkdir "$c/spec.json"
  expect_fail -m 'spec\.json' -m 'director' -- "${gen[@]}" --out out --variants spec.json
  new_case scene-is-a-directory
  mkdir "$c/scene.json"
  expect_fail -m 'scene\.json' -m 'director' -- "${gen[@]}" --out out --scene scene.json $v1
  new_case spec-number-beyond-a-double
  printf '{"matrices": [{"samples": [1e400]}]}' >"$c/spec.json"
  expect_fail -m "$(field spec.json 'matrices[0].samples')" -- "${gen[@]}" --out out --variants spec.json
  new_case scene-number-beyond-a-double
  printf '{"half_resolution_ok": 1e400}' >"$c/scene.json"
  expect_fail -m "$(field scene.json half_resolution_ok)" -- "${gen[@]}" --out out --scene scene.json $v1
  new_case out-empty
  expect_fail -m '--out' -- "${gen[@]}" --out '' $v1

  # Already right today.
  new_case unknown-variant-token
  expect_fail -m 'blurry' -- "${gen[@]}" --out out ssao-s16-half-blurry-gbufworld-std-persp-cs
  new_case unknown-target
  expect_fail -m '--targets' -m 'dxil' -- "$aogen" generate --quiet --targets spv,dxil --out out $v1
  new_case ts-without-wgsl # the TypeScript module holds the WGSL
  expect_fail -m '--targets' -m 'ts without wgsl' -m 'valid: ts with wgsl' -- "$aogen" generate --quiet --targets spv,ts --out out $v1
  new_case unknown-target-names-ts
  expect_fail -m "'typescript'" -m 'wgsl, ts with wgsl' -- "$aogen" generate --quiet --targets wgsl,typescript --out out $v1
  new_case targets-empty
  expect_fail -m '--targets' -- "$aogen" generate --quiet --targets '' --out out $v1
  new_case wgsl-fp16
  expect_fail -m 'fp16' -m 'shader-f16' -m 'valid: --targets' -- "$aogen" generate --quiet --targets spv,wgsl --out out gtao-2x3-half-bilateral-gbufworld-std-persp-cs-fp16
  new_case wgsl-without-node
  AOGEN_NODE=/nonexistent/node expect_fail -m "wgsl target" -m "Node.js" -- "$aogen" generate --quiet --targets spv,wgsl --out out $v1
  new_case wgsl-tools-missing
  AOGEN_WGSL_TOOLS=/nonexistent expect_fail -m "wgsl target" -m "aogen_wgsl.mjs" -- "$aogen" generate --quiet --targets wgsl --out out $v1
  new_case bent-normals-on-ssao # -bn comes from GTAO's horizons: refused by name with what is valid
  expect_fail -m 'bent normals' -m 'ssao' -m 'valid: gtao, vbao' -- "${gen[@]}" --out out ssao-s16-half-bilateral-gbufworld-std-persp-cs-bn
  new_case bent-normals-on-a-fragment-variant
  expect_fail -m 'bent normals' -m 'compute' -- "${gen[@]}" --out out gtao-2x3-half-bilateral-gbufworld-std-persp-fs-bn
  new_case spec-bent-normals-without-gtao-or-vbao
  printf '{"matrices": [{"technique": ["ssao", "sao"], "bent_normals": ["on"]}]}' >"$c/spec.json"
  expect_fail -m "$(field spec.json 'matrices[0].bent_normals')" -m 'gtao' -- "${gen[@]}" --out out --variants spec.json
  new_case spec-bent-normals-neither-on-nor-off
  printf '{"matrices": [{"technique": ["gtao"], "bent_normals": ["yes"]}]}' >"$c/spec.json"
  expect_fail -m "$(field spec.json 'matrices[0].bent_normals[0]')" -m 'on' -m 'off' -- "${gen[@]}" --out out --variants spec.json
  new_case two-multi-bounce-extras # -mb and -mbg are one axis: refused by name with what is valid
  expect_fail -m "'mbg' is a second multi-bounce extra" -m 'valid: one of mb, mbg' -- "${gen[@]}" --out out gtao-2x3-half-bilateral-gbufworld-std-persp-cs-mb-mbg
  new_case spec-multi-bounce-unknown
  printf '{"matrices": [{"technique": ["gtao"], "multi_bounce": ["texture"]}]}' >"$c/spec.json"
  expect_fail -m "$(field spec.json 'matrices[0].multi_bounce[0]')" -m 'off, on, gbuffer' -- "${gen[@]}" --out out --variants spec.json
  new_case spec-samples-out-of-range
  printf '{"matrices": [{"samples": [0]}]}' >"$c/spec.json"
  expect_fail -m "$(field spec.json 'matrices[0].samples[0]')" -m '1\.\.256' -- "${gen[@]}" --out out --variants spec.json
  new_case spec-unknown-key
  printf '{"matrices": [{"sample": [8]}]}' >"$c/spec.json"
  expect_fail -m "$(field spec.json 'matrices[0].sample')" -m 'samples' -- "${gen[@]}" --out out --variants spec.json
  new_case spec-samples-a-string
  printf '{"matrices": [{"samples": "8"}]}' >"$c/spec.json"
  expect_fail -m "$(field spec.json 'matrices[0].samples')" -- "${gen[@]}" --out out --variants spec.json
  new_case spec-names-no-variant
  printf '{}' >"$c/spec.json"
  expect_fail -m 'spec\.json' -- "${gen[@]}" --out out --variants spec.json
  new_case scene-unknown-normals
  printf '{"normals": "bent"}' >"$c/scene.json"
  expect_fail -m "$(field scene.json normals)" -m 'bent' -- "${gen[@]}" --out out --scene scene.json $v1
  new_case scene-unknown-key
  printf '{"normal": "gbuffer_view"}' >"$c/scene.json"
  expect_fail -m "$(field scene.json normal)" -m 'normals' -- "${gen[@]}" --out out --scene scene.json $v1
  new_case out-is-a-file
  echo 'a file' >"$c/out"
  expect_fail -m 'out' -- "${gen[@]}" --out out $v1
}

# --- report: scenes, specs, the report folder ----------------------------------------
group_report() {
  [ -n "$report" ] || { echo "the report group needs AOGEN_REPORT"; exit 2; }
  local timing=(--rounds 1 --iterations 1 --warmup-ms 0 --no-fetch-floor --no-feature-saving)
  local small=(--size 16x16 --rays 1024 "${timing[@]}")
  local gtao=gtao-1x2-half-noblur-gbufworld-std-persp-cs
  local tiny=(--size 16x16 --rays 1024)
  local rep=("$report" "${small[@]}" --variants $gtao)
  # scene GEOMETRY [EXTRA]: a scene file s.json, named, the camera at (0, -4, 2) looking at the origin.
  scene() {
    printf '{"name": "bad", "geometry": [%s], "camera": {"eye": [0, -4, 2], "target": [0, 0, 0], "up": [0, 0, 1]}%s}' \
      "$1" "${2:-}" >"$c/s.json"
  }
  local floor='{"type": "plane", "point": [0, 0, 0], "normal": [0, 0, 1]}'

  new_case plane-zero-normal
  scene '{"type": "plane", "point": [0, 0, 0], "normal": [0, 0, 0]}'
  expect_fail -m "$(field s.json 'geometry[0].normal')" -- "${rep[@]}" --scenes s.json --out out
  new_case quad-parallel-edges
  scene '{"type": "quad", "corner": [-1, -1, 0], "e1": [2, 0, 0], "e2": [4, 0, 0]}'
  expect_fail -m "$(field s.json 'geometry[0]')" -m 'e1|e2' -- "${rep[@]}" --scenes s.json --out out
  new_case box-of-1e308
  scene '{"type": "box", "min": [-1e308, -1e308, -1e308], "max": [1e308, 1e308, 1e308]}'
  expect_fail -m "$(field s.json 'geometry[0]')" -- "${rep[@]}" --scenes s.json --out out
  new_case plane-negative-half-extent
  scene '{"type": "plane", "point": [0, 0, 0], "normal": [0, 0, 1], "half_extent": -5}'
  expect_fail -m "$(field s.json 'geometry[0].half_extent')" -- "${rep[@]}" --scenes s.json --out out
  new_case geometry-all-off-camera # a sphere behind the camera: no pixel shows geometry
  scene '{"type": "sphere", "centre": [0, -10, 5], "radius": 1}'
  expect_fail -P -m 's\.json' -m 'geometry|camera|pixel' -- "${rep[@]}" --scenes s.json --out out
  new_case scene-without-a-name
  printf '{"geometry": [%s]}' "$floor" >"$c/s.json"
  expect_fail -m "$(field s.json name)" -- "${rep[@]}" --scenes s.json --out out
  new_case scene-name-with-control-characters
  printf '{"name": "a\\u001b[31mb", "geometry": [%s]}' "$floor" >"$c/s.json"
  expect_fail -m "$(field s.json name)" -- "${rep[@]}" --scenes s.json --out out
  new_case scene-duplicate-key
  scene "$floor" ', "ao_radius": 1, "ao_radius": 2'
  expect_fail -m "$(field s.json ao_radius)" -m 'duplicate|more than once|twice|repeated' -- "${rep[@]}" --scenes s.json --out out
  new_case scene-number-beyond-a-double
  printf '{"name": "bad", "geometry": [%s], "camera": {"tan_half_fov_y": 1e400}}' "$floor" >"$c/s.json"
  expect_fail -m "$(field s.json 'camera.tan_half_fov_y')" -- "${rep[@]}" --scenes s.json --out out
  new_case scene-width-nested-100000
  nested 100000 >"$c/n"
  { printf '{"name": "bad", "geometry": [%s], "camera": {"width": ' "$floor"; cat "$c/n"; printf '}}'; } >"$c/s.json"
  rm "$c/n"
  expect_fail -m "$(field s.json 'camera.width')" -m '1\.\.16384|deeper than 64 levels' -- "${rep[@]}" --scenes s.json --out out
  new_case scene-is-a-directory
  mkdir "$c/s.json"
  expect_fail -m 's\.json' -m 'director' -- "${rep[@]}" --scenes s.json --out out
  new_case ao-radius-1e308
  scene "$floor" ', "ao_radius": 1e308'
  expect_fail -s 2 -m "$(field s.json ao_radius)" -- "${rep[@]}" --scenes s.json --out out
  new_case ao-radius-1e-6 # too small for a reference of a floor reaching the horizon
  scene "$floor" ', "ao_radius": 1e-6'
  expect_fail -s 2 -m "$(field s.json ao_radius)" -- "$report" "${small[@]}" --variants gtao-1x2-half-bilateral-gbufworld-std-persp-cs --scenes s.json --out out

  new_case variants-empty
  expect_fail -m '--variants' -- "$report" "${small[@]}" --scenes crease --variants '' --out out
  new_case spec-is-a-directory
  mkdir "$c/spec.json"
  expect_fail -m 'spec\.json' -m 'director' -- "$report" "${small[@]}" --scenes crease --variants spec.json --out out
  new_case spec-27648-variants
  big_spec "$c/spec.json"
  expect_fail -s 5 -m '27648|27 648|27,648' -- "$report" "${small[@]}" --scenes crease --variants spec.json --out out
  new_case spec-samples-nested-10000
  printf '{"matrices": [{"samples": %s}]}' "$(nested 10000)" >"$c/spec.json"
  expect_fail -m "$(field spec.json 'matrices[0].samples')" -- "$report" "${small[@]}" --scenes crease --variants spec.json --out out
  new_case variant-name-18kB
  expect_fail -m 'variant|name' -- "$report" "${small[@]}" --scenes crease --variants "gtao-1x2-$(head -c 18000 /dev/zero | tr '\0' x)" --out out

  new_case out-under-a-file # refused before any tracing
  echo 'a file' >"$c/file"
  expect_fail -s 1 -m 'file' -- "${rep[@]}" --scenes crease --out file/report
  new_case out-empty
  expect_fail -s 1 -m '--out' -- "${rep[@]}" --scenes crease --out ''
  new_case page-cannot-be-written-over-a-report # a folder where report.html belongs: the earlier report's files stay as they were
  mkdir -p "$c/out/strips" "$c/out/report.html"
  echo '{"earlier": true}' >"$c/out/results.json"
  echo '# the earlier report' >"$c/out/report.md"
  echo 'earlier strip' >"$c/out/strips/crease.png"
  expect_fail -P -m 'report\.html' -- "${rep[@]}" --scenes crease --out out
  new_case python-option-is-gone # the plot is drawn without Python: --python is no option
  expect_fail -x 2 -m '--python' -- "${rep[@]}" --scenes crease --python /usr/bin/python3 --out out

  new_case parse-error-not-a-number
  expect_fail -x 2 -m '--rays' -- "$report" --variants $gtao --scenes crease --size 16x16 --rays abc "${timing[@]}" --out out
  new_case parse-error-unknown-option
  expect_fail -x 2 -m '--frob' -- "${rep[@]}" --scenes crease --frob --out out
  new_case parse-error-rounds-out-of-range
  expect_fail -x 2 -m '--rounds' -m '1\.\.1000|1 to 1000|1 - 1000' -- "$report" --variants $gtao --scenes crease "${tiny[@]}" --rounds 0 --iterations 1 --warmup-ms 0 --out out
  new_case frames-zero # the frames averaged for the accumulated error: 1..1024, named with what is valid
  expect_fail -x 2 -m '--frames' -m '1\.\.1024|1 to 1024|1 - 1024' -- "${rep[@]}" --scenes crease --frames 0 --out out
  new_case frames-too-many
  expect_fail -x 2 -m '--frames' -m '1\.\.1024|1 to 1024|1 - 1024' -- "${rep[@]}" --scenes crease --frames 1025 --out out
  new_case frames-with-the-suite # the suite scores one frame: --frames is the report's option
  expect_fail -m '--frames' -m 'suite' -- "$report" --suite stability --frames 4 --out out
  new_case parse-error-budget-negative
  expect_fail -x 2 -m '--budget-ms' -- "${rep[@]}" --scenes crease --budget-ms -5 --out out
  new_case parse-error-missing-value
  expect_fail -x 2 -m '--size' -- "$report" --variants $gtao --scenes crease --rays 1024 "${timing[@]}" --out out --size

  # Already right today.
  new_case unknown-scene
  expect_fail -m 'hallway' -m 'crease' -- "${rep[@]}" --scenes hallway --out out
  new_case bad-size
  expect_fail -m '--size' -m '320by180' -- "$report" --variants $gtao --scenes crease --size 320by180 --rays 1024 "${timing[@]}" --out out
  new_case too-few-rays
  expect_fail -m '--rays' -- "$report" --variants $gtao --scenes crease --size 16x16 --rays 100 "${timing[@]}" --out out
  new_case unknown-variant
  expect_fail -m 'ssao-s9000' -- "$report" "${small[@]}" --scenes crease --variants ssao-s9000-half-box-gbufworld-std-persp-cs --out out
  new_case scene-unknown-key
  scene "$floor" ', "ao_raduis": 1'
  expect_fail -m "$(field s.json ao_raduis)" -m 'ao_radius' -- "${rep[@]}" --scenes s.json --out out
  new_case scene-ao-radius-a-string
  scene "$floor" ', "ao_radius": "big"'
  expect_fail -m "$(field s.json ao_radius)" -- "${rep[@]}" --scenes s.json --out out
  new_case scene-ao-radius-zero
  scene "$floor" ', "ao_radius": 0'
  expect_fail -m "$(field s.json ao_radius)" -- "${rep[@]}" --scenes s.json --out out
  new_case scene-geometry-empty
  scene ''
  expect_fail -m "$(field s.json geometry)" -- "${rep[@]}" --scenes s.json --out out
  new_case scene-unknown-geometry-type
  scene '{"type": "cone"}'
  expect_fail -m "$(field s.json 'geometry[0].type')" -m 'plane' -- "${rep[@]}" --scenes s.json --out out
  new_case scene-unknown-depth
  printf '{"name": "bad", "geometry": [%s], "camera": {"depth": "reverse"}}' "$floor" >"$c/s.json"
  expect_fail -m "$(field s.json camera.depth)" -m 'reversed' -- "${rep[@]}" --scenes s.json --out out
  new_case malformed-scene
  echo '{"geometry": [' >"$c/s.json"
  expect_fail -m 's\.json' -- "${rep[@]}" --scenes s.json --out out
}

# --- main ----------------------------------------------------------------------------
groups=(command layout kernel noise seeds list generate report)
[ "$group" = all ] && selected=("${groups[@]}") || selected=("$group")
for g in "${selected[@]}"; do
  if ! declare -F "group_$g" >/dev/null; then echo "unknown group $g (valid: ${groups[*]}, all)"; exit 2; fi
  if [ "$g" = report ] && [ -z "$report" ]; then echo "skipping report: no AOGEN_REPORT given"; continue; fi
  if [ "$g" != report ] && [ "$aogen" = - ]; then echo "the $g group needs AOGEN"; exit 2; fi
  group=$g
  "group_$g"
done
echo "bad inputs ${selected[*]}: $cases cases, $failures failed"
[ "$failures" -eq 0 ]
