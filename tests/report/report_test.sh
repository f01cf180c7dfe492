#!/usr/bin/env bash
# End-to-end tests of aogen_report, one case per ctest test:
#   report_test.sh AOGEN_REPORT CASE AOGEN_PAGE_TESTS
#   run     a small report, twice: every file is there, the errors of the two runs are
#           identical (only times may differ), the reference's noise is well below the
#           errors, no NaN/Inf (raw or shipped), every time has its spread and fetch floor,
#           the Pareto marks agree with the numbers; report.html opens in chromium
#           (AOGEN_PAGE_TESTS' "a report made by aogen_report") without a console error,
#           a marker per timed variant, and every scene's images for a selected row.
#   partial a report killed after its first scene keeps results.json and report.md of
#           that scene, marked partial; run with no timing options, it timed with the CPU
#           device protocol (lavapipe) and says so.
#   errors  bad arguments: one line on stderr naming what is wrong, non-zero exit,
#           nothing written.
#   suite   the stability suite, every built-in case on every default variant, with
#           --check: it passes (its report.html opened in chromium too), its results hold the four defects issue 11 found fixed
#           (absolute figures, which the old shaders miss), and a planted failing case
#           file makes --check exit 1 and the report name it.
#   tune    aogen_tune's smallest search: the settings it evaluates, its JSON and table.
set -uo pipefail
report=$(realpath "$1") case=$2 page_tests=${3:-}
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
  variants=ssao-s8-half-box-gbufworld-std-persp-cs,gtao-1x2-half-noblur-gbufworld-std-persp-cs,ssao-s16-full-noblur-recon-std-persp-cs,vbao-1x2-half-noblur-gbufworld-std-persp-cs
  for run in 1 2; do
    # The first run has nothing on its PATH: no Python, no plotter, no browser — the whole
    # report, page and plot included, is aogen_report's own work.
    path=$PATH; [ "$run" -eq 1 ] && path=/var/empty
    PATH=$path "$report" --scenes crease,wall,stairs --variants "$variants" --size 64x36 --rays 1024 --rounds 2 --iterations 1 --warmup-ms 0 \
      --validation --out "$work/r$run" 2>"$work/progress$run" || { fail "run $run exited non-zero"; cat "$work/progress$run"; }
  done
  grep -q "\[scene 3/3\] stairs: timing" "$work/progress1" || fail "no progress on stderr"
  for f in report.html report.md results.json error_vs_time.svg motion_vs_time.svg; do [ -s "$work/r1/$f" ] || fail "$f missing"; done
  [ -e "$work/r1/error_vs_time.png" ] && fail "error_vs_time.png is made (the plot is SVG, drawn without Python)"
  AOGEN_PAGE="$work/r1/report.html" "$page_tests" "page: a report made by aogen_report" >"$work/page" 2>&1 ||
    { fail "report.html in chromium"; tail -30 "$work/page"; }
  ls "$work"/r1/strips/*.png >/dev/null 2>&1 || fail "no image strips"
  python3 - "$work/r1/results.json" "$work/r2/results.json" <<'PY' || fail "results.json checks"
import json, sys
a, b = (json.load(open(p)) for p in sys.argv[1:3])
def errors(r):  # everything but the times
    return [(v["name"], [(s["scene"], s.get("default"), s.get("calibrated"), s.get("power"), s.get("skipped"))
                         for s in v["scenes"]]) for v in r["variants"]]
assert errors(a) == errors(b), "errors differ between two runs"
assert [s["truth_noise_rms"] for s in a["scenes"]] == [s["truth_noise_rms"] for s in b["scenes"]]
assert a["rays_per_pixel"] == 1024 and len(a["scenes"]) == 3 and len(a["variants"]) == 4 and a["complete"] is True
# In motion: stairs (the one scene with a camera path) and the default motion variants, the
# same figures both runs; the history pass steadies every twin (less flicker).
m = a["motion"]
assert m["frames"] == 12 and m["first_scored"] == 6 and m["rays_per_pixel"] == 256, m
assert [r["scene"] for r in m["runs"]] == ["stairs"] * 8, [r["scene"] for r in m["runs"]]
untimed = lambda motion: [{k: v for k, v in r.items() if k != "ms"} for r in motion["runs"]]  # everything but the times
assert untimed(m) == untimed(b["motion"]), "the report in motion differs between two runs"
assert all(r["ms"] is not None and r["ms"] > 0 for r in m["runs"]), "a chain in motion was not timed"
by = {r["variant"]: r for r in m["runs"]}
for name, r in by.items():
    assert len(r["rmse"]) == 6 and all(0 <= r[k] < 1 for k in ("error", "ghosting", "flicker")), r
    if name.endswith(("-hist", "-histmv")):
        twin = by[name.rsplit("-", 1)[0]]
        assert r["flicker"] < twin["flicker"], (name, r["flicker"], twin["flicker"])
# Asked for by hand: the protocol as asked, on a CPU device too (cpu_device says which ran it).
assert {k: t for k, t in a["timing"].items() if k != "cpu_device"} == {"rounds": 2, "iterations": 1, "warmup_ms": 0, "budget_ms": 1000, "fetch_floor": True}, a["timing"]
assert all(s["iterations"] == 1 for s in a["scenes"])
ran = [s for v in a["variants"] for s in v["scenes"] if "skipped" not in s]
assert len(ran) == 12, len(ran)
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
    assert s["bandwidth_ms"] is not None and s["bandwidth_ms"] > 0, s
    assert len(s["raw"]) == len(s["pass_ms"]) and all(r == {"nan": 0, "inf": 0, "below_zero": 0, "above_one": 0, "max_excess": 0} for r in s["raw"]), s
for v in a["variants"]:
    assert v["raw"]["measured"] and v["raw"]["nan"] == 0 and v["raw"]["inf"] == 0, v["name"]
    assert v["floor_ratio"] is not None and v["floor_ratio"] > 0, v["name"]
    assert v["bandwidth_ratio"] is not None and v["bandwidth_ratio"] > 0, v["name"]
# Each technique against the truth, end to end, two-sided (measured on lavapipe 2026-12-02; SSAO
# 2026-12-05 with its tuned defaults, which read 0.7-1.1 of the true occlusion where the seeds'
# values read 0.12-0.24):
# the RMSE at most 1.15 x as measured, and the occlusion ratio mean(1 - AO) / mean(1 - truth)
# within +-10 % of where it reads, so that occlusion a fifth stronger or weaker fails.
expected = {  # variant prefix: {scene: (rmse, occlusion ratio)}
    "ssao-s8-half-box": {"crease": (0.0669, 0.851), "wall": (0.0753, 0.715), "stairs": (0.0605, 0.905)},
    "gtao-1x2-half-noblur": {"crease": (0.0706, 0.858), "wall": (0.0803, 0.909), "stairs": (0.0915, 1.036)},
    "ssao-s16-full-noblur-recon": {"crease": (0.0937, 1.133), "wall": (0.0973, 0.968), "stairs": (0.0942, 1.075)},
    "vbao-1x2-half-noblur": {"crease": (0.0727, 0.879), "wall": (0.0771, 0.781), "stairs": (0.0835, 0.852)},
}
truth_occlusion = {s["name"]: 1 - s["truth_mean"] for s in a["scenes"]}
for v in a["variants"]:
    (prefix,) = [p for p in expected if v["name"].startswith(p)]
    for s in v["scenes"]:
        rmse, ratio = expected[prefix][s["scene"]]
        occlusion = truth_occlusion[s["scene"]] - s["default"]["mean_signed"]
        got = occlusion / truth_occlusion[s["scene"]]
        assert s["default"]["rmse"] <= 1.15 * rmse, (v["name"], s["scene"], s["default"]["rmse"], rmse)
        assert abs(got - ratio) <= 0.1 * ratio, (v["name"], s["scene"], got, ratio)
        for k in (0.8, 1.2):  # the band rejects the same image a fifth lighter or darker
            assert abs(k * got - ratio) > 0.1 * ratio, (v["name"], s["scene"], k)
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
  # Killed once the first scene is written: what it measured stays, marked partial. No
  # timing options: lavapipe, a CPU device, gets run.hpp's cpu_timing (one round of one
  # iteration, no warm-up), and results.json says so.
  "$report" --scenes crease,wall,stairs,room,groove,plank --variants gtao-1x2-half-noblur-gbufworld-std-persp-cs --size 64x36 \
    --rays 4096 --out "$work/p" 2>"$work/progress" &
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
t = r["timing"]
assert t["cpu_device"] is True and (t["rounds"], t["iterations"], t["warmup_ms"]) == (1, 1, 0), t
PY
  grep -q "Partial report" "$work/p/report.md" || fail "the partial report.md does not say so"
  grep -q "Partial report" "$work/p/report.html" || fail "the partial report.html does not say so"
  ls "$work/p" | grep -q tmp && fail "a temporary file was left behind"
  ;;
errors)
  expect_error "unknown scene" "built-in scene: 'hallway' is not known \\(valid: crease, " --scenes hallway
  expect_error "unknown variant" 'ssao-s9000' --variants ssao-s9000-half-box-gbufworld-std-persp-cs
  expect_error "bad size" "--size: '320by180' is not a size \\(valid: WIDTHxHEIGHT" --size 320by180
  expect_error "too few rays" '--rays: 100 is not a valid ray count \(valid: the square of an even number' --rays 100
  expect_error "history blend out of range" '--history.blend: 2 is out of range \(valid: ' --history blend=2
  expect_error "unknown history setting" "--history: 'sharpness' is not a setting of the history pass \(valid: blend, clamp, " --history sharpness=1
  expect_error "unknown history clamp" '--history clamp: .box. is not' --history clamp=box
  expect_error "unknown motion variant" 'ssao-s9000' --motion-variants ssao-s9000-half-box-gbufworld-std-persp-cs
  echo '{"geometry": [' >"$work/broken.json"
  expect_error "malformed scene" 'broken.json: is not valid JSON' --scenes "$work/broken.json"
  expect_error "unknown stability case" "built-in stability case: 'fov_1000' is not known \\(valid: grazing_floor, " --suite stability --cases fov_1000
  expect_error "suite option without --suite" "--check: goes with --suite stability" --check
  expect_error "report option with --suite" "--size: is an option of the error-against-time report" --suite stability --size 64x36
  echo '{"name": "x", "scene": {}, "twin": {}, "extra": 1}' >"$work/case.json"
  expect_error "unknown key in a case file" 'case.json.*extra' --suite stability --cases "$work/case.json"
  expect_error "no such device" 'no-such-gpu' --device no-such-gpu --scenes crease --variants gtao-1x2-half-noblur-gbufworld-std-persp-cs --size 16x16 --rays 1024
  ;;
suite)
  "$report" --suite stability --check --out "$work/s" 2>"$work/progress" || { fail "the stability suite failed"; tail -3 "$work/progress"; }
  python3 - "$work/s/results.json" <<'PY' || fail "stability results.json checks"
import json, sys
r = json.load(open(sys.argv[1]))
cases = {c["name"]: c for c in r["cases"]}
assert len(cases) == 31 and r["failures"] == 0, (len(cases), r["failures"])
for c in cases.values():
    assert len(c["runs"]) >= 70, (c["name"], len(c["runs"]))
    for run in c["runs"]:
        assert run["pass"] and run["raw"]["nan"] == 0 and run["raw"]["inf"] == 0, (c["name"], run["variant"])
        assert run["background_not_one"] == 0, (c["name"], run)
        if c["criterion"]["compare_error"]:
            assert run["rmse"] <= run["error_limit"], (c["name"], run)
        if "twin_pixel_max" in run:  # the faults: nothing changed beyond their reach, pixel by pixel
            assert run["twin_pixel_max"] <= 1 / 255 and run["changed_reach"] <= c["criterion"]["fault_reach"], (c["name"], run)
assert not cases["depth_conventions"]["criterion"]["compare_error"]  # judged by its per-pixel comparison only
assert cases["nan_depth_texel"]["criterion"]["fault_reach"] == 10
fp16 = [x for x in cases["depth_past_fp16"]["runs"] if x["variant"].endswith("-fp16")]
assert len(fp16) == 4 and all(x["pass"] for x in fp16), fp16  # the suite's default set has fp16 twins
def runs(case, prefix):
    return [x for x in cases[case]["runs"] if x["variant"].startswith(prefix)]
# The defects, in absolute figures (the old shaders: 0.37, 0.28, 0.21, and a refusal).
assert max(x["rmse"] for x in runs("fov_175", "gtao")) < 0.05, "GTAO darkens the open floor at 175 degrees"
assert max(x["rmse"] for x in runs("fov_120", "gtao")) < 0.08, "GTAO darkens the open floor at 120 degrees"
assert max(x["rmse"] for x in runs("image_8x8", "gtao-")) < 0.12, "half-resolution GTAO too dark at 8x8"
for case in ("radius_past_screen", "radius_huge"):  # no worse than the largest radius that fits the screen
    for x in runs(case, ""):  # (stability.hpp: why 0.03, where the depth-aware upsample improved the twins most)
        assert x["rmse"] <= 1.25 * x["twin_rmse"] + 0.03, (case, x["variant"], x["rmse"], x["twin_rmse"])
assert len(runs("sub_millimetre", "")) >= 70  # an AO radius of 1e-6 runs (it was refused)
assert all(x["depth_max"] <= 3 / 255 for x in cases["depth_conventions"]["runs"])
scale = [x for x in cases["scale_invariance"]["runs"] if "skipped" not in x]  # 1e-6 ... 1e6 of the box
assert len(scale) >= 100 and all(x["scale_max"] <= 1 / 255 for x in scale), max(x["scale_max"] for x in scale)
import re  # the largest radius the settings take: 1e15 / 2.6875 (params.hpp's max_world_length, SAO's tuned radius factor)
assert float(re.search(r"\(([0-9.e+]+)\)", cases["radius_huge"]["about"]).group(1)) > 3.7e14, cases["radius_huge"]["about"]
PY
  grep -q "| 31 | scale_invariance |" "$work/s/report.md" || fail "report.md lacks the case table"
  grep -q '<td class="num">31</td><td>scale_invariance</td>' "$work/s/report.html" || fail "report.html lacks the case table"
  AOGEN_PAGE="$work/s/report.html" "$page_tests" "page: a stability suite page made by aogen_report" >"$work/page" 2>&1 ||
    { fail "the suite's report.html in chromium"; tail -30 "$work/page"; }
  grep -q "^None\.$" "$work/s/report.md" || fail "report.md lists failures"
  # A planted failure: a criterion no variant can meet (RMSE <= 0) fails --check, named.
  cat >"$work/impossible.json" <<'JSON'
{"name": "impossible", "about": "a planted failure",
 "scene": {"name": "box", "geometry": [{"type": "box", "min": [-0.5, -0.5, 0], "max": [0.5, 0.5, 1]}, {"type": "plane", "point": [0, 0, 0], "normal": [0, 0, 1]}],
           "camera": {"eye": [2.5, -3.5, 2.2], "target": [0, 0, 0.4], "up": [0, 0, 1], "width": 32, "height": 18}, "ao_radius": 0.5},
 "twin": {"name": "box", "geometry": [{"type": "box", "min": [-0.5, -0.5, 0], "max": [0.5, 0.5, 1]}, {"type": "plane", "point": [0, 0, 0], "normal": [0, 0, 1]}],
          "camera": {"eye": [2.5, -3.5, 2.2], "target": [0, 0, 0.4], "up": [0, 0, 1], "width": 32, "height": 18}, "ao_radius": 0.5},
 "criterion": {"error_ratio": 0, "error_slack": 0}}
JSON
  "$report" --suite stability --check --cases grazing_floor,"$work/impossible.json" --variants gtao-1x2-half-noblur-gbufworld-std-persp-cs \
    --out "$work/f" 2>"$work/stderr" && fail "--check exited 0 with a failing case"
  grep -q "stability suite: 1 run failed" "$work/stderr" || { fail "--check's message:"; cat "$work/stderr"; }
  grep -q "impossible.*gtao-1x2-half-noblur" "$work/f/report.md" || fail "report.md does not name the failing case and variant"
  AOGEN_PAGE="$work/f/report.html" "$page_tests" "page: a stability suite page made by aogen_report" >"$work/page" 2>&1 ||
    { fail "the failing suite's report.html in chromium"; tail -30 "$work/page"; }
  "$report" --suite stability --cases "$work/impossible.json" --variants gtao-1x2-half-noblur-gbufworld-std-persp-cs --out "$work/g" 2>/dev/null ||
    fail "without --check a failing case must not fail the run"
  ;;
tune)
  # aogen_tune (AOGEN_REPORT names aogen_report; aogen_tune is built beside it): a tiny search,
  # 2 points per axis and 1 round, on one training and one validation scene.
  tune="$(dirname "$report")/aogen_tune"
  "$tune" --variants gtao-1x2-half-noblur-gbufworld-std-persp-cs,ssao-s8-half-box-gbufworld-std-persp-cs --train crease --validate wall \
    --size 48x27 --rays 1024 --points 2 --rounds 1 --out "$work/tune.json" >"$work/tune.md" 2>"$work/progress" || { fail "aogen_tune failed"; cat "$work/progress"; }
  python3 - "$work/tune.json" <<'PY' || fail "tune.json checks"
import json, math, sys
r = json.load(open(sys.argv[1]))
g, s = r["variants"]
assert g["variants"] == ["gtao-1x2-half-noblur-gbufworld-std-persp-cs"] and g["evaluations"] == 64, g  # 2^6 settings
assert s["evaluations"] == 8, s                                                                      # 2^3
assert g["best"]["strength"] in (0.25, 3.0) and g["best"]["radius_scale"] in (0.5, 2.0), g["best"]  # grid corners
assert all(abs(g["defaults"][k] - x) < 1e-7 for k, x in {"radius_scale": 0.78125, "strength": 1.109375, "thickness_bias": 0.075,
                                                         "falloff_range": 0.0, "thin_occluder": 0.0, "blur_sharpness": 10.0}.items()), g["defaults"]
for v in (g, s):
    for k in ("train_rmse", "validate_rmse", "default_train_rmse", "default_validate_rmse"):
        assert 0 < v[k] < 0.5 and math.isfinite(v[k]), (k, v[k])
PY
  grep -q "| \`gtao-1x2-half-noblur-gbufworld-std-persp-cs\` | radius_scale, strength, thickness_bias, falloff_range, thin_occluder, blur_sharpness |" "$work/tune.md" ||
    fail "the table lacks the GTAO row"
  # --axes: only the named parameters are searched, in the order given; an unknown one is refused by name.
  "$tune" --variants gtao-1x2-half-noblur-gbufworld-std-persp-cs --axes thin_occluder,falloff_range --train crease --validate wall \
    --size 48x27 --rays 1024 --points 2 --rounds 1 --out "$work/axes.json" >"$work/axes.md" 2>"$work/progress" || fail "aogen_tune --axes failed"
  python3 -c 'import json,sys; g=json.load(open(sys.argv[1]))["variants"][0]; assert g["evaluations"] == 4 and sorted(g["best"]) == ["falloff_range", "thin_occluder"], g' \
    "$work/axes.json" || fail "--axes did not search just the two named parameters"
  if "$tune" --variants gtao-1x2-half-noblur-gbufworld-std-persp-cs --axes bias --train crease --validate wall --out "$work/bad.json" 2>"$work/err"; then
    fail "an unknown --axes name was accepted"
  fi
  grep -q "bias.*is not a parameter of gtao.*valid: radius_scale, strength, thickness_bias, falloff_range, thin_occluder, blur_sharpness" "$work/err" ||
    fail "the unknown axis error does not name it and the valid ones: $(cat "$work/err")"
  [ ! -e "$work/bad.json" ] || fail "a refused search wrote its output"
  ;;
*) echo "unknown case $case"; exit 2 ;;
esac
[ "$failures" -eq 0 ] || { echo "$failures failure(s)"; exit 1; }
echo "ok"
