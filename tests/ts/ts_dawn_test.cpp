// tests/ts/ts_dawn_test.cpp — the TypeScript module's AoChain on Dawn against the SPIR-V on the
// Vulkan harness, bit for bit.
//
// For each of the module's thirteen variants (module_variants.txt: every block, both stages, both
// resolutions, a history variant of each stage) and for every variant of the default matrix
// (the module `aogen generate --targets wgsl,ts` writes when no variant is named),
// tests/ts/ts_dawn.mjs makes the chain with AoChain.create, writes its uniforms and noise tile
// with update() -- bytes the module computes itself -- and records it with record() on Dawn (npm
// webgpu, its OpenGL ES backend on Mesa's llvmpipe); C++ gives only the G-buffer. The oracle is
// the variant's SPIR-V run on the Vulkan harness with the same settings: every pixel equal, frame
// after frame for the history variants (their history kept by AoChain across record() calls).
//
// One difference, explained: the 3x3 denoise at full resolution (gtao-3x3-full-denoise3-..., in
// both lists) on Dawn gives one pixel of the 2560 1/255 from the SPIR-V's, with aogen's own Dawn
// runner (wgsl_dawn.hpp: C++'s bytes, aogen_wgsl.mjs's pipelines) as with the module's chain
// (byte for byte the same, checked), while its WGSL translated back by naga runs bit for bit like
// the SPIR-V on the Vulkan harness (checked here): the WGSL means what the SPIR-V means, and the
// rounding differs in Dawn's OpenGL ES path (Tint's GLSL ES on Mesa's GL driver, where the other
// passes -- the half-resolution 3x3 denoises among them -- agree to the bit). Found by this test
// (the WGSL tests' variants hold no -denoise3); the 3x3's WGSL on a GPU's Vulkan or D3D backend
// is not measured here.
#include "ts/ts_support.hpp"
#include "vulkan/harness.hpp"

#include <aogen/ao_difference.hpp>
#include <aogen/emitted.hpp>
#include <aogen/matrix.hpp>
#include <aogen/vulkan/wgsl_round_trip.hpp>
#include <aogen/wgsl_dawn.hpp>

using namespace aogen_test;

namespace {

// `g` as ts_dawn.mjs reads it, and `frames` as its chain.json.
void write_chain(const std::string& dir, const std::string& variant_name, const vulkan::gbuffer& g, const std::vector<vulkan::chain_settings>& frames)
{
    const auto floats = [&](const std::string& name, const std::vector<float>& v) {
        if (!v.empty()) wgsl::detail::write_all(dir + "/" + name, std::string(reinterpret_cast<const char*>(v.data()), v.size() * sizeof(float)));
    };
    floats("depth.f32", g.depth), floats("normals.f32", g.normals), floats("albedo.f32", g.albedo), floats("motion.f32", g.motion);
    json j = {{"variant", variant_name}, {"width", g.width}, {"height", g.height}, {"frames", json::array()}};
    for (const vulkan::chain_settings& s : frames) {
        json f = {{"camera", camera_json(s.camera)}, {"settings", settings_json(s)}, {"frame", s.frame},
                  {"frameSequence", temporal::to_name(s.frame_sequence)}, {"resetHistory", s.reset_history}};
        if (s.previous_camera) f["previousCamera"] = camera_json(*s.previous_camera);
        j["frames"].push_back(f);
    }
    wgsl::detail::write_all(dir + "/chain.json", j.dump());
}

// The variants whose Dawn run differs from the SPIR-V's (see the header), at most this much.
const std::vector<std::string> dawn_rounds_differently{"gtao-3x3-full-denoise3-gbufview-revinf-persp-cs", // module_variants'
                                                       "gtao-3x3-full-denoise3-gbufworld-std-persp-cs"};  // the default matrix's

// The frames a variant is run for: one still frame, or for a history variant four with the
// camera moving sideways (harness.hpp's sideways_frames, as settings).
std::vector<vulkan::chain_settings> frames_for(const variant& v, const vulkan::chain_settings& still)
{
    if (!has_history_pass(v)) return {still};
    std::vector<vulkan::chain_settings> out;
    for (uint32_t f = 0; f < 4; ++f) {
        vulkan::chain_settings s = still;
        s.frame = f;
        s.camera.world_to_view.columns[3].x -= 0.02f * float(f);
        s.previous_camera = still.camera;
        s.previous_camera->world_to_view.columns[3].x -= 0.02f * float(f > 0 ? f - 1 : 0);
        out.push_back(s);
    }
    return out;
}

// A variant's chain as ts_dawn.mjs runs it: its G-buffer and frames, written to its folder.
struct dawn_case {
    std::string name;
    vulkan::gbuffer g;
    std::vector<vulkan::chain_settings> frames;
    std::string dir;
};

// Case `c`'s Dawn output against its SPIR-V run, frame by frame; how many frames.
size_t compare(vulkan::context& ctx, const dawn_case& c)
{
    INFO(c.name);
    const int W = c.g.width, H = c.g.height;
    const codegen::plan p = codegen::make_plan(variant_from_name(c.name));
    std::vector<chain_inputs> inputs;
    for (const vulkan::chain_settings& s : c.frames) inputs.push_back(p.inputs(s, W, H));
    const std::vector<vulkan::chain_result> expected = spirv_frames(ctx, vulkan::chain(ctx, p), c.g, inputs);
    const bool differs = std::find(dawn_rounds_differently.begin(), dawn_rounds_differently.end(), c.name) != dawn_rounds_differently.end();
    for (size_t f = 0; f < c.frames.size(); ++f) {
        INFO("frame " << f);
        const std::string bytes = wgsl::detail::read_all(c.dir + "/out" + std::to_string(f) + ".bin");
        std::vector<float> ao(bytes.size());
        for (size_t i = 0; i < ao.size(); ++i) ao[i] = uint8_t(bytes[i]) / 255.0f;
        REQUIRE(ao.size() == expected[f].ao.size());
        CHECK(*std::min_element(expected[f].ao.begin(), expected[f].ao.end()) < 0.98f); // not two blank images
        const ao_difference d = difference_of(ao, expected[f].ao);
        std::cout << "ts AoChain on Dawn, " << c.name << " frame " << f << ": " << d.identical << " of " << d.pixels
                  << " pixels bit-identical, largest difference " << d.largest * 255 << "/255\n";
        if (!differs) {
            CHECK(first_difference(ao, expected[f].ao) == "");
            continue;
        }
        CHECK(d.pixels - d.identical <= 1);
        CHECK(d.largest <= 1.0f / 255 + 1e-6f);
        // ... the same bytes as aogen's own Dawn runner (C++'s bytes, aogen_wgsl.mjs's pipelines) ...
        const std::vector<wgsl::dawn_result> own =
            wgsl::run_variant_frames_on_dawn(plan_for(p, compile::target::wgsl), emitted_texts(p, compile::target::wgsl), c.g, inputs);
        CHECK(bytes == std::string(own[f].ao.begin(), own[f].ao.end()));
        // ... while its WGSL through naga's SPIR-V runs bit for bit like the SPIR-V.
        vulkan::wgsl_round_trips trips({p});
        const vulkan::gpu_gbuffer gpu(ctx, c.g);
        const vulkan::chain_result naga = vulkan::bound_chain(ctx, *trips.passes(ctx, p), gpu, inputs[f]).run_once();
        CHECK(first_difference(naga.ao, expected[f].ao) == "");
    }
    return c.frames.size();
}

// Variant `name` on the moving crease at 64 x 40, in folder `k` of the module's scratch.
dawn_case prepare(const compiled_module& m, const std::string& name, size_t k)
{
    const int W = 64, H = 40;
    const mat4 proj = perspective(0.6f, float(W) / H, 0.1f, 100.0f);
    const variant v = variant_from_name(name);
    dawn_case c{name, crease_in_motion(W, H, proj, -0.01f, 0.004f), {}, m.dir.path() + "/dawn" + std::to_string(k)};
    if (v.normals == normal_source::reconstructed) c.g.normals.clear();
    if (v.multi_bounce != multi_bounce_mode::gbuffer_albedo) c.g.albedo.clear();
    if (v.history != history_mode::motion_vectors) c.g.motion.clear();
    vulkan::chain_settings still = settings_for(proj);
    still.ssao.radius = 0.6f, still.gtao.radius = 0.6f; // a radius the 64 x 40 crease shows
    if (has_prefilter_pass(v)) still.gtao.radius = 4.0f; // taps 20 pixels and more away: MIP levels 1 and up (depth_mips.hpp)
    if (v.projection == projection_kind::orthographic) still.camera.proj = orthographic(-1.5f, 1.5f, -1, 1, 0.1f, 100.0f);
    c.frames = frames_for(v, still);
    std::filesystem::remove_all(c.dir);
    std::filesystem::create_directory(c.dir);
    write_chain(c.dir, name, c.g, c.frames);
    return c;
}

// Variants `names` made, updated and recorded by the module's AoChain on Dawn (one process, one
// device), each against its SPIR-V frame by frame (see the header); how many frames were compared.
size_t check_on_dawn(vulkan::context& ctx, const compiled_module& m, const std::vector<std::string>& names)
{
    std::vector<dawn_case> cases;
    std::vector<std::string> args{m.tools.node, std::string(AOGEN_TS_TESTS_DIR) + "/ts_dawn.mjs", m.js(), m.tools.dir};
    for (const std::string& name : names) args.push_back(cases.emplace_back(prepare(m, name, cases.size())).dir);
    run(args, m.dir.file("dawn.log"));
    size_t frames = 0;
    for (const dawn_case& c : cases) frames += compare(ctx, c);
    return frames;
}

} // namespace

TEST_CASE("ts: AoChain on Dawn, every uniform byte its own, gives the SPIR-V's AO bit for bit")
{
    vulkan::context* ctx = shared_context();
    if (!ctx) return;
    std::vector<std::string> still;
    for (const std::string& name : module_variants)
        if (!has_history_pass(variant_from_name(name))) still.push_back(name);
    CHECK(check_on_dawn(*ctx, the_module(), still) == module_variants.size() - 2);
    require_clean(*ctx);
}

TEST_CASE("ts: AoChain keeps a history variant's history on Dawn, bit for bit like the SPIR-V frame after frame")
{
    vulkan::context* ctx = shared_context();
    if (!ctx) return;
    std::vector<std::string> history;
    for (const std::string& name : module_variants)
        if (has_history_pass(variant_from_name(name))) history.push_back(name);
    CHECK(check_on_dawn(*ctx, the_module(), history) == 2 * 4); // a compute and a fragment history variant, four frames each
    require_clean(*ctx);
}

TEST_CASE("ts: AoChain on Dawn runs every variant of the default matrix bit for bit like the SPIR-V")
{
    vulkan::context* ctx = shared_context();
    if (!ctx) return;
    const compiled_module matrix(AOGEN_TS_MATRIX_MODULE_DIR); // `aogen generate --targets wgsl,ts` of no names
    std::vector<std::string> names;
    for (const variant& v : default_matrix()) names.push_back(to_name(v));
    CHECK(check_on_dawn(*ctx, matrix, names) >= names.size());
    require_clean(*ctx);
}

TEST_CASE("ts: AoChain refuses a texture of the wrong format or size, or a missing one, by name")
{
    const compiled_module& m = the_module();
    const int W = 64, H = 40;
    const mat4 proj = perspective(0.6f, float(W) / H, 0.1f, 100.0f);
    const std::string name = "ssao-s16-half-bilateral-gbufworld-std-persp-cs";
    vulkan::gbuffer g = crease(W, H, 0.6f, proj);
    g.albedo.clear(), g.motion.clear();
    const std::string dir = m.dir.path() + "/bad";
    std::filesystem::remove_all(dir);
    std::filesystem::create_directory(dir);
    write_chain(dir, name, g, {settings_for(proj)});
    const std::vector<std::pair<json, std::string>> cases{
        {{{"depth", "rgba8unorm"}}, "AogenError: AoChain.record textures.depth: is rgba8unorm 64x40 (valid: r32float or depth32float, 64x40)"},
        {{{"depth", {32, 20}}}, "AogenError: AoChain.record textures.depth: is r32float 32x20 (valid: r32float or depth32float, 64x40)"},
        {{{"normals", nullptr}}, "AogenError: AoChain.record textures.normals: is missing (" + name + " reads it) (valid: rgba16float or rgba32float, 64x40)"},
        {{{"output", "r32float"}}, "AogenError: AoChain.record textures.output: is r32float 64x40 (valid: rgba8unorm, 64x40)"},
        {{{"output", {32, 20}}}, "AogenError: AoChain.record textures.output: is rgba8unorm 32x20 (valid: rgba8unorm, 64x40)"},
    };
    json bad = json::array();
    for (const auto& c : cases) bad.push_back(c.first);
    wgsl::detail::write_all(dir + "/bad.json", bad.dump());
    run({m.tools.node, std::string(AOGEN_TS_TESTS_DIR) + "/ts_dawn.mjs", m.js(), m.tools.dir, dir}, m.dir.file("bad.log"));
    const json said = json::parse(wgsl::detail::read_all(dir + "/bad_out.json"));
    REQUIRE(said.size() == cases.size());
    for (size_t i = 0; i < cases.size(); ++i) CHECK(said[i].get<std::string>() == cases[i].second);
}
