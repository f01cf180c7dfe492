#!/usr/bin/env bash
# End-to-end tests of aogen_report, one case per ctest test:
#   report_test.sh AOGEN_REPORT CASE
#   run     a small report, twice: every file is there, the errors of the two runs are
#           identical (only times may differ), the reference's noise is well below the
#           errors, no NaN/Inf (raw or shipped), every time has its spread and fetch floor,
#           the Pareto marks agree with the numbers.
#   partial a report killed after its first scene keeps results.json and report.md of
#           that scene, marked partial.
#   errors  bad arguments: one line on stderr naming what is wrong, non-zero exit,
#           nothing written.
set -uo pipefail
report=$(realpath "$1") case=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failures=0
fail() { echo "FAILED: $*"; failures=$((failures + 1)); }

expect_error() { # DESCRIPTION PATTERN ARGS...
  local description=$1 pattern=$2; shift 2
  local dir; dir=$(mktemp -d -p "$work")
  (cd "$dir" && "$report" --out out "$@" >"$work/stdout" 2>"$work/stderr"); local rc=$?
  local lines; lines=$(wc -l <"$work/stderr")
  if [ "$rc" -eq 0 ]; then fail "$description: exit 0"
  elif [ "$lines" -ne 1 ]; then fail "$description: $lines lines on stderr:"; cat "$work/stderr"
  elif ! grep -qE -- "$pattern" "$work/stderr"; then fail "$description: stderr lacks /$pattern/:"; cat "$work/stderr"
  fi
  [ -z "$(ls -A "$dir")" ] || fail "$description: left files behind: $(ls -A "$dir")"
}

case $case in
run)
  variants=ssao-s8-half-box-gbufworld-std-persp-cs,gtao-1x2-half-noblur-gbufworld-std-persp-cs,ssao-s16-full-noblur-recon-std-persp-cs
  for run in 1 2; do
    "$report" --scenes crease,wall,stairs --variants "$variants" --size 64x36 --rays 1024 --rounds 2 --iterations 1 --warmup-ms 0 \
      --validation --out "$work/r$run" 2>"$work/progress$run" || { fail "run $run exited non-zero"; cat "$work/progress$run"; }
  done
  grep -q "\[scene 3/3\] stairs: timing" "$work/progress1" || fail "no progress on stderr"
  for f in report.md results.json error_vs_time.png; do [ -s "$work/r1/$f" ] || fail "$f missing"; done
  ls "$work"/r1/strips/*.png >/dev/null 2>&1 || fail "no image strips"
  python3 - "$work/r1/results.json" "$work/r2/results.json" <<'PY' || fail "results.json checks"
import json, sys
a, b = (json.load(open(p)) for p in sys.argv[1:3])
def errors(r):  # everything but the times
    return [(v["name"], [(s["scene"], s.get("default"), s.get("calibrated"), s.get("power"), s.get("skipped"))
                         for s in v["scenes"]]) for v in r["variants"]]
assert errors(a) == errors(b), "errors differ between two runs"
assert [s["truth_noise_rms"] for s in a["scenes"]] == [s["truth_noise_rms"] for s in b["scenes"]]
assert a["rays_per_pixel"] == 1024 and len(a["scenes"]) == 3 and len(a["variants"]) == 3 and a["complete"] is True
assert a["timing"] == {"rounds": 2, "iterations": 1, "warmup_ms": 0, "budget_ms": 1000, "fetch_floor": True}, a["timing"]
assert all(s["iterations"] == 1 for s in a["scenes"])
ran = [s for v in a["variants"] for s in v["scenes"] if "skipped" not in s]
assert len(ran) == 9, len(ran)
smallest = min(s["default"]["rmse"] for s in ran)
for s in a["scenes"]:
    assert 0 < s["truth_noise_rms"] < 0.01, s
    assert s["truth_noise_rms"] < smallest / 3, (s, smallest)
for s in ran:
    assert s["default"]["non_finite"] == 0 and s["default"]["pixels"] > 1000, s
    assert 0 <= s["calibrated"]["rmse"] < 0.5 and 0.125 <= s["power"] <= 8, s
    assert s["ms"] is not None and s["ms"] > 0, s
    assert s["ms_p10"] <= s["ms"] <= s["ms_p90"], s
    assert s["floor_ms"] is not None and s["floor_ms"] > 0, s
    assert len(s["raw"]) == len(s["pass_ms"]) and all(r == {"nan": 0, "inf": 0, "below_zero": 0, "above_one": 0, "max_excess": 0} for r in s["raw"]), s
for v in a["variants"]:
    assert v["raw"]["measured"] and v["raw"]["nan"] == 0 and v["raw"]["inf"] == 0, v["name"]
    assert v["floor_ratio"] is not None and v["floor_ratio"] > 0, v["name"]
vs = a["variants"]
for v in vs:  # a Pareto mark means no other variant is both faster and more accurate
    beaten = any(w["ms"] <= v["ms"] and w["rmse"] <= v["rmse"] and (w["ms"] < v["ms"] or w["rmse"] < v["rmse"]) for w in vs if w is not v)
    assert v["pareto"] == (not beaten), v["name"]
assert [f["selected"] for f in a["feature_saving"]] == [vs[0]["name"], vs[2]["name"]]
for f in a["feature_saving"]:
    assert f["everything_on"] == f["selected"] + "-pc"
    assert f["selected_instructions"] < f["everything_on_instructions"], f
PY
  grep -q "| \`gtao-1x2-half-noblur-gbufworld-std-persp-cs\` |" "$work/r1/report.md" || fail "report.md lacks the variant table"
  grep -q "Partial report" "$work/r1/report.md" && fail "the finished report.md says partial"
  ;;
partial)
  # Killed once the first scene is written: what it measured stays, marked partial.
  "$report" --scenes crease,wall,stairs,room,groove,plank --variants gtao-1x2-half-noblur-gbufworld-std-persp-cs --size 64x36 \
    --rays 4096 --rounds 1 --iterations 1 --warmup-ms 0 --out "$work/p" 2>"$work/progress" &
  pid=$!
  for _ in $(seq 600); do grep -q "scenes so far" "$work/progress" && break; sleep 0.05; done
  kill -9 "$pid" 2>/dev/null; wait "$pid" 2>/dev/null
  grep -q "wrote /" "$work/progress" && fail "the run finished before it could be interrupted"
  python3 - "$work/p/results.json" <<'PY' || fail "partial results.json checks"
import json, sys
r = json.load(open(sys.argv[1]))
assert r["complete"] is False and 1 <= len(r["scenes"]) < 6, (r["complete"], len(r["scenes"]))
v = r["variants"][0]
assert len(v["scenes"]) == len(r["scenes"]) and v["scenes"][0]["default"]["pixels"] > 1000
PY
  grep -q "Partial report" "$work/p/report.md" || fail "the partial report.md does not say so"
  ls "$work/p" | grep -q tmp && fail "a temporary file was left behind"
  ;;
errors)
  expect_error "unknown scene" "built-in scene: 'hallway' is not known \\(valid: crease, " --scenes hallway
  expect_error "unknown variant" 'ssao-s9000' --variants ssao-s9000-half-box-gbufworld-std-persp-cs
  expect_error "bad size" "--size: '320by180' is not a size \\(valid: WIDTHxHEIGHT" --size 320by180
  expect_error "too few rays" '--rays: 100 is not a valid ray count \(valid: the square of an even number' --rays 100
  echo '{"geometry": [' >"$work/broken.json"
  expect_error "malformed scene" 'broken.json: is not valid JSON' --scenes "$work/broken.json"
  expect_error "no such device" 'no-such-gpu' --device no-such-gpu --scenes crease --variants gtao-1x2-half-noblur-gbufworld-std-persp-cs --size 16x16 --rays 1024
  ;;
*) echo "unknown case $case"; exit 2 ;;
esac
[ "$failures" -eq 0 ] || { echo "$failures failure(s)"; exit 1; }
echo "ok"
