#!/usr/bin/env bash
# Tests of the `aogen` command line, one case per ctest test:
#   cli_test.sh AOGEN SOURCE_DIR CASE
# Oracles: golden files checked by hand (tests/golden/), glslangValidator for the GLSL
# the command line prints, and the file system for "nothing half-written".
set -uo pipefail
aogen=$(realpath "$1") source=$(realpath "$2") case=$3
golden=$source/tests/golden
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failures=0

check() { # check DESCRIPTION COMMAND... : the command must succeed
  if ! "${@:2}"; then echo "FAILED: $1"; failures=$((failures + 1)); fi
}

# expect_error DESCRIPTION PATTERN ARGS...: run in an empty directory; exit non-zero, one
# line on stderr matching PATTERN, nothing on stdout, and no file left behind. Inputs
# are named by absolute path ($in/...).
in=$work/in
mkdir -p "$in"
expect_error() {
  local description=$1 pattern=$2; shift 2
  local dir; dir=$(mktemp -d -p "$work")
  (cd "$dir" && "$aogen" "$@" >"$work/stdout" 2>"$work/stderr"); local rc=$?
  local lines; lines=$(wc -l <"$work/stderr")
  if [ "$rc" -eq 0 ]; then echo "FAILED: $description: exit 0"; failures=$((failures + 1));
  elif [ "$lines" -ne 1 ]; then echo "FAILED: $description: $lines lines on stderr:"; cat "$work/stderr"; failures=$((failures + 1));
  elif ! grep -qE -- "$pattern" "$work/stderr"; then echo "FAILED: $description: stderr lacks /$pattern/:"; cat "$work/stderr"; failures=$((failures + 1));
  elif [ -s "$work/stdout" ]; then echo "FAILED: $description: wrote to stdout"; failures=$((failures + 1));
  fi
  local left; left=$(ls -A "$dir")
  if [ -n "$left" ]; then echo "FAILED: $description: left files behind: $left"; failures=$((failures + 1)); fi
}

case $case in
help)
  for sub in "" layout kernel noise seeds list generate; do
    check "aogen $sub --help" bash -c "'$aogen' $sub --help | grep -q Usage"
  done
  expect_error "no command" "command: is missing \\(valid: layout, kernel"
  ;;
layout_golden)
  check "std140 JSON" diff -u "$golden/params.std140.json" <("$aogen" layout --rules std140 "$golden/params.json")
  check "hlsl declaration" diff -u "$golden/params.hlsl" <("$aogen" layout --rules hlsl-cbuffer --emit hlsl "$golden/params.json")
  check "glsl declaration" diff -u "$golden/params.glsl" <("$aogen" layout --rules std140 --emit glsl --binding 3 "$golden/params.json")
  "$aogen" layout --rules std430 --emit cpp --out "$work/params.hpp" "$golden/params.json"
  check "cpp declaration compiles with its static_asserts" c++ -std=c++17 -fsyntax-only -x c++ "$work/params.hpp"
  ;;
layout_errors)
  cp "$golden/params.json" "$in/input.json"
  expect_error "unknown rules" "layout rules: 'std150' is not a known name \(valid: std140" layout --rules std150 "$in/input.json"
  expect_error "unknown language" "'glsl2'.*valid: glsl, hlsl" layout --rules std140 --emit glsl2 "$in/input.json"
  expect_error "language without its rules" "cannot express std140.*valid rules: hlsl-cbuffer" layout --rules std140 --emit hlsl "$in/input.json"
  expect_error "missing file" "nope.json: does not exist" layout --rules std140 --out out.json "$in/nope.json"
  printf '{"name": "P", "members": [{"name": "a", "type": "flaot"}]}' >"$in/input_type.json"
  expect_error "unknown type" "P.a: unknown type 'flaot'.*valid: float" layout --rules std140 --out out.json "$in/input_type.json"
  printf '{"name": "P", "members": [' >"$in/input_broken.json"
  expect_error "malformed JSON" "input_broken.json: is not valid JSON" layout --rules std140 --out out.json "$in/input_broken.json"
  printf '{"name": "P", "members": [{"name": "a", "type": "float", "count": -2}]}' >"$in/input_count.json"
  expect_error "negative count" "members\[0\].count: -2 is out of range.*0..1048576" layout --rules std140 --out out.json "$in/input_count.json"
  printf '{"name": "P", "members": [{"name": "a", "type": "float", "cout": 2}]}' >"$in/input_key.json"
  expect_error "unknown key" "members\[0\].cout: is not a known key.*valid: name, type, count" layout --rules std140 "$in/input_key.json"
  printf '{"name": "P", "members": [{"name": "a", "type": "vec4", "count": 0}]}' >"$in/input_runtime.json"
  expect_error "runtime array in a uniform block" "P.a: .*runtime-sized array.*rules: std140" layout --rules std140 "$in/input_runtime.json"
  printf '{"name": "P", "members": [{"name": "a", "type": "float", "count": 4}]}' >"$in/input_stride.json"
  expect_error "WGSL uniform array stride" "P.a: array stride 4 is not a multiple of 16.*rules: wgsl-uniform" layout --rules wgsl-uniform "$in/input_stride.json"
  ;;
kernel)
  "$aogen" kernel --kind crytek --count 16 --seed 3 --format bin --out "$work/k.bin"
  check "bin is 16 vec4s" test "$(stat -c %s "$work/k.bin")" -eq 256
  check "same seed, same bytes" cmp "$work/k.bin" <("$aogen" kernel --kind crytek --count 16 --seed 3 --format bin)
  check "another seed, other bytes" bash -c "! cmp -s '$work/k.bin' <('$aogen' kernel --kind crytek --count 16 --seed 4 --format bin)"
  for kind in crytek cosine hammersley; do
    { echo '#version 450'; "$aogen" kernel --kind $kind --count 8 --format glsl;
      echo 'layout(local_size_x = 1) in; layout(std430, binding = 0) buffer O { vec4 o[]; }; void main() { o[0] = aogen_kernel[7]; }'; } >"$work/k_$kind.comp"
    check "$kind GLSL constant compiles" glslangValidator -V -o "$work/k.spv" "$work/k_$kind.comp" >/dev/null
  done
  "$aogen" kernel --format cpp --count 4 >"$work/k.cpp"
  check "cpp constant compiles" c++ -std=c++17 -fsyntax-only "$work/k.cpp"
  "$aogen" kernel --format json --count 5 >"$work/k.json"
  check "json holds 5 samples" python3 -c "import json; assert len(json.load(open('$work/k.json'))['samples']) == 5"
  expect_error "count 0" "--count: '0' is out of range \(valid: 1..256\)" kernel --count 0 --format bin --out k.bin
  expect_error "count 257" "--count: '257' is out of range \(valid: 1..256\)" kernel --count 257
  expect_error "unknown kind" "kernel distribution.*valid: crytek, cosine, hammersley" kernel --kind blue
  expect_error "unknown format" "--format: 'yaml'.*valid: json, cpp, glsl, wgsl, bin" kernel --format yaml --out k.txt
  ;;
noise)
  "$aogen" noise --size 4 --seed 2 --encoding rgba8_unorm --format bin --out "$work/n.bin"
  check "rgba8 4x4 is 64 bytes" test "$(stat -c %s "$work/n.bin")" -eq 64
  "$aogen" noise --size 8 --encoding rgba16f --format bin --out "$work/n16.bin"
  check "rgba16f 8x8 is 512 bytes" test "$(stat -c %s "$work/n16.bin")" -eq 512
  check "every rgba8_unorm texel has z = 128, w = 255" python3 -c "
b = open('$work/n.bin', 'rb').read()
assert all(b[i + 2] == 128 and b[i + 3] == 255 for i in range(0, 64, 4)), b"
  "$aogen" noise --format cpp --pattern r2 >"$work/n.cpp"
  check "cpp array compiles" c++ -std=c++17 -fsyntax-only "$work/n.cpp"
  expect_error "size 0" "--size: '0' is out of range \(valid: 1..64\)" noise --size 0
  expect_error "unknown encoding" "rgba8_srgb.*valid: rgba32f" noise --encoding rgba8_srgb --out n.bin
  ;;
seeds)
  "$aogen" seeds --out "$work/seeds" >"$work/first.txt"
  check "wrote 95 files" grep -q "^95 files in .* (95 written, 0 unchanged)" "$work/first.txt"
  "$aogen" seeds --out "$work/seeds" >"$work/second.txt"
  check "second run rewrites nothing" grep -q "(0 written, 95 unchanged)" "$work/second.txt"
  check "golden bytes" diff -u "$golden/seeds.sha256" <(cd "$work/seeds" && find . -type f | LC_ALL=C sort | xargs sha256sum)
  check "no temporary files" bash -c "! find '$work/seeds' -name '*.tmp*' | grep -q ."
  check "seed 004's block is 144 bytes" test "$(stat -c %s "$work/seeds/pointcloud_viewer_ssao/uniforms.wgsl-uniform.bin")" -eq 144
  for f in "$work"/seeds/*/uniforms.glsl; do
    { echo '#version 450'; cat "$f"; echo 'layout(local_size_x = 1) in; void main() {}'; } >"$work/u.comp"
    check "$f compiles" glslangValidator -V -o "$work/u.spv" "$work/u.comp" >/dev/null
  done
  for f in "$work"/seeds/*/uniforms.hlsl; do
    { cat "$f"; echo '[numthreads(1, 1, 1)] void main() {}'; } >"$work/u.hlsl"
    check "$f compiles" glslangValidator -V -D -e main -S comp -o "$work/u.spv" "$work/u.hlsl" >/dev/null
  done
  for f in "$work"/seeds/*/uniforms.std430.hpp; do
    check "$f compiles" c++ -std=c++17 -fsyntax-only -x c++ "$f"
  done
  ;;
list)
  "$aogen" list >"$work/axes.txt"
  check "axes list the default variant" grep -q "^default variant: ssao-s16-half-bilateral-gbufworld-std-persp-cs$" "$work/axes.txt"
  check "axes list every depth convention" grep -q "standard, reversed, reversed_infinite" "$work/axes.txt"
  check "axes list XeGTAO's quality presets" grep -qx "GTAO and VBAO quality presets (XeGTAO's levels; slices x steps): low 1x2 medium 2x2 high 3x3 ultra 9x3" "$work/axes.txt"
  "$aogen" list --variants >"$work/variants.txt"
  check "the default matrix has 123 variants" test "$(wc -l <"$work/variants.txt")" -eq 123
  check "variant names are unique" test "$(sort -u "$work/variants.txt" | wc -l)" -eq 123
  check "the seeds' point-cloud variant is in it" grep -qx "ssao-s64-full-noblur-recon-std-persp-fs-pc-rc004-step" "$work/variants.txt"
  check "VBAO's High preset is in it, at half and full resolution" grep -qx "vbao-3x3-full-bilateral-gbufworld-std-persp-cs" "$work/variants.txt"
  check "axes list vbao" grep -q "ssao | gtao | vbao" "$work/axes.txt"
  check "axes list both multi-bounce extras" grep -q "off, on, gbuffer .*-mb | -mbg$" "$work/axes.txt"
  check "axes list bent normals" grep -q "^bent normals .*-bn$" "$work/axes.txt"
  ;;
generate)
  v1=ssao-s16-half-bilateral-gbufworld-std-persp-cs
  v2=gtao-2x3-full-box-recon-rev-ortho-fs
  "$aogen" generate --quiet --out "$work/gen" --targets spv,glsl,hlsl,hlsl60,msl,msl_ios $v1 $v2
  check "manifest lists both variants" python3 -c "
import json; m = json.load(open('$work/gen/manifest.json'))
names = [v['name'] for v in m['variants']]
assert names == ['$v1', '$v2'], names
ao = m['variants'][0]
assert ao['bindings'][0]['kind'] == 'uniform_buffer' and ao['uniforms']['name'] == 'SsaoUniforms', ao['bindings']
assert ao['uniforms']['size'] == 496 and ao['passes'][0]['workgroup_size'] == [8, 8, 1]
assert [p['pass'] for p in ao['passes']] == ['ao', 'blur_x', 'blur_y', 'upsample']
assert [p['pixels_per_invocation'] for p in ao['passes']] == [1, 1, 1, 2], 'the upsample writes 2x2 pixels per invocation'
assert ao['verification'] == {'spv': 'executed', 'glsl': 'executed', 'hlsl': 'round_tripped', 'hlsl60': 'round_tripped', 'msl': 'validated', 'msl_ios': 'validated'}, ao['verification']
fs = m['variants'][1]
assert [(p['pass'], p['stage']) for p in fs['passes']] == [('ao', 'vertex'), ('ao', 'fragment'), ('blur_box', 'vertex'), ('blur_box', 'fragment')]
assert not any(b['binding'] == 2 for b in fs['bindings']), 'reconstructed normals declare no normal buffer'
assert any(f['feature'] == 'normal buffer input' for f in fs['left_out'])
assert fs['verification'] == ao['verification'], 'fragment passes are executed on GL and round-tripped through HLSL as compute passes are'
assert 'quality' not in ao and 'quality' not in fs, 'SSAO and GTAO 2x3 match no quality preset'
"
  "$aogen" generate --quiet --out "$work/q" --targets spv gtao-3x3-half-bilateral-gbufworld-std-persp-cs
  check "the manifest names a GTAO variant's quality preset" python3 -c "
import json; assert json.load(open('$work/q/manifest.json'))['variants'][0]['quality'] == 'high'
"
  "$aogen" generate --quiet --out "$work/f16" --targets spv,hlsl gtao-3x3-half-bilateral-gbufworld-std-persp-cs-fp16
  check "an fp16 variant's HLSL is validated, not round-tripped (glslang reads min16float as 32-bit)" python3 -c "
import json; assert json.load(open('$work/f16/manifest.json'))['variants'][0]['verification'] == {'spv': 'executed', 'hlsl': 'validated'}
"
  "$aogen" generate --quiet --out "$work/wgsl" --targets spv,wgsl $v1 $v2
  check "WGSL: a file per shader, WebGPU's bindings in the manifest, round_tripped" python3 -c "
import json, os; m = json.load(open('$work/wgsl/manifest.json'))
cs, fs = m['variants']
assert cs['verification'] == {'spv': 'executed', 'wgsl': 'executed'}, cs['verification']
assert fs['verification'] == {'spv': 'executed', 'wgsl': 'executed'}, fs['verification']
ao = cs['passes'][0]
assert ao['outputs']['wgsl'] == '$v1/ao.comp.wgsl' and ao['entry_points']['wgsl'] == 'main'
text = open(os.path.join('$work/wgsl', ao['outputs']['wgsl'])).read()
assert '@compute' in text and 'texture_storage_2d<rgba8unorm, write>' in text.replace(',write', ', write'), text[:400]
b = {(x['binding'], x['kind']) for x in ao['wgsl_bindings']}
assert b == {(0, 'uniform_buffer'), (1, 'sampled_image'), (2, 'sampler'), (3, 'sampled_image'), (4, 'sampled_image'), (5, 'storage_image')}, b
up = cs['passes'][3]
assert {(x['binding'], x['kind']) for x in up['wgsl_bindings']} >= {(3, 'sampled_image'), (4, 'sampler')}, up['wgsl_bindings']
assert [p['outputs']['wgsl'].split('/')[-1] for p in fs['passes']] == ['ao.vert.wgsl', 'ao.frag.wgsl', 'blur_box.vert.wgsl', 'blur_box.frag.wgsl']
"
  check "WGSL beside every other target (a shader whose WebGPU form is its ordinary one once lost its HLSL: map::at)" \
    "$aogen" generate --quiet --out "$work/alltargets" --targets spv,glsl,essl,hlsl,msl,wgsl ssao-s8-half-box-gbufview-rev-ortho-fs-pc-powint
  check "the header has the WGSL binding numbers" grep -q "ao_comp_wgsl_binding_u_depth_sampler = 2;" "$work/wgsl/aogen_variants.hpp"
  expect_error "an fp16 variant has no WGSL" "fp16.ao.comp: does 16-bit float arithmetic.*shader-f16" generate --targets wgsl --out "$work/no16" gtao-3x3-half-bilateral-gbufworld-std-persp-cs-fp16
  check "and nothing was written" test ! -e "$work/no16"
  if AOGEN_NODE=/nonexistent/node "$aogen" generate --quiet --targets wgsl --out "$work/nonode" $v1 2>"$work/nonode.err"; then
    echo "FAILED: wgsl without Node.js exited 0"; failures=$((failures + 1))
  fi
  check "without Node.js, wgsl fails in one line naming what is missing" grep -q "^aogen: wgsl target: needs Node.js" "$work/nonode.err"
  check "... and nothing was written" test ! -e "$work/nonode"
  AOGEN_NODE=/nonexistent/node "$aogen" generate --quiet --targets spv,glsl,hlsl --out "$work/nonode_other" $v1
  check "... while every other target works without it" test -s "$work/nonode_other/$v1/ao.comp.sm50.hlsl"
  printf '#include "aogen_variants.hpp"\nstatic_assert(aogen_variants::%s::ao_comp_spv[0] == 0x07230203u);\n' "${v1//-/_}" >"$work/use.cpp"
  check "the header compiles" c++ -std=c++17 -fsyntax-only -I"$work/gen" "$work/use.cpp"
  touch "$work/marker"
  "$aogen" generate --quiet --out "$work/gen" --targets spv,glsl,hlsl,hlsl60,msl,msl_ios $v1 $v2
  check "a second run rewrites nothing" test -z "$(find "$work/gen" -type f -newer "$work/marker")"
  printf '{"point_clouds": false, "normals": "gbuffer_view", "blur": "none"}' >"$in/scene.json"
  "$aogen" generate --quiet --out "$work/scene" --targets spv --scene "$in/scene.json" ssao-s16-half-bilateral-gbufworld-std-persp-cs-pc
  check "the scene selects the variant and says what it left out" python3 -c "
import json; v = json.load(open('$work/scene/manifest.json'))['variants'][0]
assert v['name'] == 'ssao-s16-half-noblur-gbufview-std-persp-cs', v['name']
why = {f['feature']: f['why'] for f in v['left_out']}
assert why['point-cloud fallback'] == 'the scene has no point clouds', why
assert why['world-to-view normal rotation'] == 'the G-buffer normals are already in view space', why
"
  printf '{"matrices": [{"technique": ["ssao"], "samples": [8, 16], "blur": ["box", "none"]}], "variants": ["gtao-1x1-half-noblur-gbufworld-std-persp-cs"]}' >"$in/spec.json"
  "$aogen" generate --quiet --out "$work/spec" --targets spv --variants "$in/spec.json"
  check "a spec expands its matrices" python3 -c "
import json; names = [v['name'] for v in json.load(open('$work/spec/manifest.json'))['variants']]
assert len(names) == 5 and 'ssao-s8-half-box-gbufworld-std-persp-cs' in names, names
"
  # multi_bounce: a spec key for the -mb and -mbg extras; its values are off, on and gbuffer.
  printf '{"matrices": [{"technique": ["gtao"], "blur": ["denoise"], "multi_bounce": ["off", "on", "gbuffer"]}]}' >"$in/mb_spec.json"
  "$aogen" generate --quiet --out "$work/mb" --targets spv --variants "$in/mb_spec.json"
  check "a spec's multi_bounce makes the -mb twin" python3 -c "
import json; names = [v['name'] for v in json.load(open('$work/mb/manifest.json'))['variants']]
assert names == ['gtao-2x3-half-denoise-gbufworld-std-persp-cs', 'gtao-2x3-half-denoise-gbufworld-std-persp-cs-mb', 'gtao-2x3-half-denoise-gbufworld-std-persp-cs-mbg'], names
"
  printf '{"matrices": [{"multi_bounce": ["yes"]}]}' >"$in/bad_mb_spec.json"
  expect_error "multi_bounce neither off, on nor gbuffer" "matrices\[0\].multi_bounce\[0\].*off.*on.*gbuffer" generate --variants "$in/bad_mb_spec.json" --out gen
  # bent_normals: a spec key for the -bn extra; GTAO's and VBAO's compute variants take it, the others skip it.
  printf '{"matrices": [{"technique": ["gtao", "ssao", "vbao"], "blur": ["denoise"], "stage": ["compute", "fragment"], "bent_normals": ["on"]}]}' >"$in/bn_spec.json"
  "$aogen" generate --quiet --out "$work/bn" --targets spv --variants "$in/bn_spec.json"
  check "a spec's bent_normals makes -bn GTAO and VBAO compute variants and skips the others" python3 -c "
import json; names = [v['name'] for v in json.load(open('$work/bn/manifest.json'))['variants']]
assert names == ['gtao-2x3-half-denoise-gbufworld-std-persp-cs-bn', 'vbao-2x3-half-denoise-gbufworld-std-persp-cs-bn'], names
"
  expect_error "unknown variant" "'blurry' is not a known name" generate --out gen ssao-s16-half-blurry-gbufworld-std-persp-cs
  expect_error "unknown target" "--targets: 'dxil' is not a known name.*valid: spv" generate --targets spv,dxil --out gen
  printf '{"matrices": [{"samples": [0]}]}' >"$in/bad_spec.json"
  expect_error "sample count out of range in a spec" "matrices\[0\].samples\[0\]: 0 is out of range" generate --variants "$in/bad_spec.json" --out gen
  printf '{"normals": "bent"}' >"$in/bad_scene.json"
  expect_error "unknown normals in a scene" "bad_scene.json.normals: 'bent' is not a known name" generate --scene "$in/bad_scene.json" --out gen ssao-s16-half-bilateral-gbufworld-std-persp-cs
  ;;
generate_default)
  # The default matrix for every target; then every distinct output re-validated by a
  # real compiler: SPIR-V by spirv-val, GLSL and ESSL by glslangValidator, HLSL by
  # glslang's HLSL front end. MSL has no compiler on Linux: it must name its entry point.
  "$aogen" generate --quiet --out "$work/all"
  check "123 variants" python3 -c "import json; assert len(json.load(open('$work/all/manifest.json'))['variants']) == 123"
  cd "$work/all"
  declare -A seen glsl
  checked=0
  # One sha256sum over every file, in path order (a process per file cost more than the checks).
  while read -r sum f; do
    [ -n "${seen[$sum]:-}" ] && continue; seen[$sum]=1
    name=${f##*/}; stage=${name#*.}; stage=${stage%%.*} # ao.comp.spv -> comp
    case $f in
      *.spv) check "$f" spirv-val --target-env vulkan1.0 "$f" ;;
      *.glsl|*.essl) glsl[$stage]+="$f " ;; # below, a stage at a time
      *.hlsl) check "$f" glslangValidator -D -e main -S "$stage" -V -o /dev/null "$f" >/dev/null ;;
      *.metal) check "$f" grep -q "main0(" "$f" ;;
    esac
    checked=$((checked + 1))
  done < <(find . -type f ! -name manifest.json ! -name '*.hpp' -print0 | LC_ALL=C sort -z | xargs -0 sha256sum)
  # GLSL and ESSL: one glslangValidator a stage over all its files, each compiled on its own
  # (no -l: nothing linked), its output naming a file that fails; a process per file cost 25 s.
  # (HLSL stays a file at a time: -V links the files it is given into one stage.)
  for stage in "${!glsl[@]}"; do
    read -ra files <<< "${glsl[$stage]}"
    said=$(glslangValidator -S "$stage" "${files[@]}" 2>&1) ||
      { echo "FAILED: glslangValidator -S $stage over ${#files[@]} files:"; grep -B2 ERROR <<< "$said" | head -20; failures=$((failures + 1)); }
  done
  echo "re-validated $checked distinct outputs"
  cd - >/dev/null
  ;;
*) echo "unknown case $case"; exit 2 ;;
esac

[ "$failures" -eq 0 ] && echo "cli $case: passed" || { echo "cli $case: $failures failed"; exit 1; }
