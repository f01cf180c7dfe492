// The WGSL target (issue 19): every emitted WGSL text is naga's translation of the variant's
// WebGPU-model SPIR-V, validated by naga and by Tint; translated back to SPIR-V by naga and run
// under the variant's own passes on the Vulkan harness, it gives the SPIR-V's AO bit for bit.
// Oracles: naga's and Tint's front ends and validators, naga's own struct layouter (each WGSL
// uniform struct naga emits, and aogen's WGSL declaration of it, read back through naga's
// SPIR-V), the SPIR-V run, and seed 004's shader. Two planted faults — a wrong binding, a
// changed constant — are permanent tests: the comparison must see them.
#include "wgsl_support.hpp"

#include <aogen/presets.hpp>
#include <aogen/uniforms.hpp>

#include <iostream>

using namespace aogen;
using namespace aogen_test;


TEST_CASE("wgsl: the emitted WGSL, validated by naga and Tint and round-tripped through naga, gives the SPIR-V's AO bit for bit")
{
    vulkan::context* ctx = shared_context();
    if (!ctx) return;
    std::vector<codegen::plan> plans;
    for (const char* name : emitted_target_variants) plans.push_back(codegen::make_plan(variant_from_name(name)));
    vulkan::wgsl_round_trips trips(plans); // translation and both validators: throws on any refusal
    const int W = 64, H = 40;
    const mat4 proj = perspective(0.6f, float(W) / H, 0.1f, 100.0f);
    const vulkan::gbuffer analytic = crease(W, H, 0.6f, proj);
    const ray_cast_crease scene;
    for (const codegen::plan& p : plans) {
        const variant& v = p.variant();
        INFO(p.name());
        const std::unique_ptr<vulkan::pass_pipelines> passes = trips.passes(*ctx, p);
        for (const std::string& text : trips.texts(p)) CHECK((text.find("@group(0)") != std::string::npos || text.find("@vertex") != std::string::npos));
        const vulkan::chain spirv = chain_under_test(*ctx, v); // compiled once, run on both G-buffers
        const ao_difference a = against_spirv(*ctx, *passes, spirv, v, analytic, settings_for(proj));
        const ao_difference r = against_spirv(*ctx, *passes, spirv, v, scene.for_variant(v), aogen_report::default_settings(v, scene.scene));
        std::cout << "wgsl round trip " << to_name(v) << ": analytic crease " << a.identical << " of " << a.pixels << ", ray-cast crease "
                  << r.identical << " of " << r.pixels << " pixels bit-identical\n";
        CHECK(a.bit_identical());
        CHECK(r.bit_identical());
    }
    require_clean(*ctx);
}

TEST_CASE("wgsl: Dawn executes the emitted WGSL (Tint's GLSL ES on llvmpipe), compute and fragment, bit for bit like the SPIR-V")
{
    vulkan::context* ctx = shared_context();
    if (!ctx) return;
    const int W = 64, H = 40;
    const mat4 proj = perspective(0.6f, float(W) / H, 0.1f, 100.0f);
    const ray_cast_crease scene;
    std::vector<codegen::plan> plans;
    for (const char* name : emitted_target_variants) plans.push_back(codegen::make_plan(variant_from_name(name)));
    const std::vector<std::vector<std::string>> all_texts = emitted_texts(plans, compile::target::wgsl); // one batch
    for (size_t k = 0; k < plans.size(); ++k) {
        const variant& v = plans[k].variant();
        const std::string name = plans[k].name();
        INFO(name);
        const std::vector<std::string>& texts = all_texts[k];
        const vulkan::chain spirv = chain_under_test(*ctx, v); // compiled once, run on both G-buffers
        for (int g = 0; g < 2; ++g) {
            const vulkan::gbuffer gb = g == 0 ? crease(W, H, 0.6f, proj) : scene.for_variant(v);
            const vulkan::chain_settings s = g == 0 ? settings_for(proj) : aogen_report::default_settings(v, scene.scene);
            const ao_difference d = dawn_against_spirv(spirv, v, texts, gb, s);
            std::cout << "wgsl on Dawn, " << name << (g == 0 ? " analytic" : " ray-cast") << " crease: " << d.identical << " of " << d.pixels
                      << " pixels bit-identical, largest difference " << d.largest * 255 << "/255\n";
            CHECK(d.bit_identical()); // Tint's GLSL ES on llvmpipe does the SPIR-V's float operations
        }
    }
}

TEST_CASE("wgsl: every uniform block's WGSL declaration is the struct naga emits, member by member")
{
    // The blocks the shaders declare, as naga emits them in a variant's WGSL, against aogen's
    // own WGSL declaration of the block (declare.hpp) — both read back through naga's layouter.
    const struct {
        const char* variant;
        pass_kind pass;
        layout::block_desc block;
    } cases[] = {
        {"ssao-s16-full-noblur-gbufworld-std-persp-cs", pass_kind::ao, uniforms::ssao_block(16)},
        {"ssao-s64-full-noblur-recon-std-persp-fs-pc-rc004", pass_kind::ao, uniforms::ssao_block(64)},
        {"ssao-s8-full-noblur-gbufworld-std-persp-cs", pass_kind::ao, uniforms::ssao_block(8)},
        {"gtao-2x3-full-noblur-gbufworld-std-persp-cs", pass_kind::ao, uniforms::gtao_block()},
        {"vbao-3x3-full-noblur-gbufworld-std-persp-cs", pass_kind::ao, uniforms::vbao_block()},
        {"gtao-2x3-half-bilateral-gbufworld-std-persp-cs", pass_kind::blur_x, uniforms::blur_block()},
    };
    for (const auto& c : cases) {
        INFO(c.variant << " " << c.block.root.name);
        const variant v = variant_from_name(c.variant);
        const std::vector<codegen::shader_source> sources = codegen::generate(codegen::make_plan(v, options_for(compile::target::wgsl)));
        const std::vector<std::string> texts = emitted_texts(codegen::make_plan(v), compile::target::wgsl);
        size_t k = 0;
        while (sources[k].pass != c.pass || sources[k].stage == shader_stage::vertex) ++k;
        const compile::buffer_block emitted = naga_block(texts[k], sources[k].stage, c.block.root.name);
        const layout::struct_layout l = layout::compute(c.block, layout::rules::wgsl_uniform);
        layout::declaration_options o;
        o.instance = "u";
        const compile::buffer_block declared =
            naga_block(shader_using(layout::declare(l, layout::language::wgsl, o), "u"), shader_stage::compute, c.block.root.name);
        require_same_members(declared.members, emitted.members);
        CHECK(declared.size == emitted.size);
        compile::check_layout(emitted, l); // and both are aogen's layout engine's offsets
    }
}

TEST_CASE("wgsl: seed 004's variant has the seed's texture and sampler types, its SsaoUniform offsets, and says where its bindings differ")
{
    const variant v = variant_from_name("ssao-s64-full-noblur-recon-std-persp-fs-pc-rc004"); // the point-cloud viewer's shader
    const std::vector<codegen::shader_source> sources = codegen::generate(codegen::make_plan(v, options_for(compile::target::wgsl)));
    const std::vector<std::string> texts = emitted_texts(codegen::make_plan(v), compile::target::wgsl);
    size_t k = 0;
    while (sources[k].pass != pass_kind::ao || sources[k].stage != shader_stage::fragment) ++k;
    const std::string& ao = texts[k];
    INFO(ao.substr(0, 2000));
    const auto declares = [&](const std::string& pattern) { return std::regex_search(ao, std::regex(pattern)); };
    // Seed 004: @binding(0) depth_tex: texture_depth_2d, @binding(1) depth_samp: sampler,
    // @binding(2) noise_tex: texture_2d<f32>, @binding(3) noise_samp: sampler,
    // @binding(4) kernel: array<vec4<f32>> (storage), @binding(5) params: SsaoUniform.
    // The same: the depth is a texture with its sampler at the next binding, the noise tile a
    // float texture, everything in group 0, a fragment entry point writing one f32.
    CHECK(declares("@group\\(0\\) @binding\\(1\\)\\s*var u_depth_texture: texture_2d<f32>;"));
    CHECK(declares("@group\\(0\\) @binding\\(2\\)\\s*var u_depth_sampler: sampler;"));
    CHECK(declares("@group\\(0\\) @binding\\(4\\)\\s*var u_noise: texture_2d<f32>;"));
    CHECK(declares("@fragment\\s*fn main\\("));
    CHECK(declares("-> @location\\(0\\) f32"));
    // Where it differs, and why:
    // - the uniform block is binding 0, as in every aogen pass of both binding models
    //   (bindings.hpp), so one bind group layout prefix serves the AO and filter passes;
    CHECK(declares("@group\\(0\\) @binding\\(0\\)\\s*var<uniform> u: SsaoUniforms;"));
    // - the depth is texture_2d<f32>, not texture_depth_2d: the same depth32float texture binds
    //   to either (WebGPU's 'unfilterable-float' sample type), and GLSL has no non-comparison
    //   depth texture type for naga to translate into texture_depth_2d;
    CHECK_FALSE(declares("texture_depth_2d"));
    // - no noise sampler: the tile is read texel for texel with textureLoad (p mod its size);
    CHECK_FALSE(declares("var u_noise_sampler"));
    // - no kernel storage buffer: the 64 samples are SsaoUniforms.kernel, in the one uniform
    //   block (1024 bytes, far below WebGPU's 64 KiB uniform binding limit);
    CHECK(declares("kernel: array<vec4<f32>, 64>"));
    CHECK_FALSE(declares("var<storage"));
    // - SsaoUniforms is aogen's block (proj first, the camera and every SSAO setting). Seed 004's
    //   SsaoUniform, for a renderer that runs the seed's own shader, is
    //   uniforms::pointcloud_block(), packed by pack_pointcloud(rules::wgsl_uniform): its WGSL
    //   declaration, read back through naga, has the seed's offsets and size.
    const layout::struct_layout seed = layout::compute(uniforms::pointcloud_block(), layout::rules::wgsl_uniform);
    layout::declaration_options o;
    o.binding = 5, o.instance = "params";
    const compile::buffer_block b = naga_block(shader_using(layout::declare(seed, layout::language::wgsl, o), "params"), shader_stage::compute, "SsaoUniform");
    REQUIRE(b.members.size() == 5);
    const std::pair<const char*, uint32_t> expected[] = {{"inv_proj", 0}, {"proj", 64}, {"radius", 128}, {"bias", 132}, {"_pad", 136}};
    for (size_t i = 0; i < 5; ++i) {
        CHECK(b.members[i].name == expected[i].first);
        CHECK(b.members[i].offset == expected[i].second);
    }
    CHECK(b.members[0].type == "mat4");
    CHECK(b.members[2].type == "float");
    CHECK(b.members[4].type == "vec2");
    CHECK(seed.size == 144);
    CHECK(uniforms::pack_pointcloud(presets::pointcloud_viewer_ssao().settings.ssao, perspective(0.6f, 1.5f, 0.1f, 100.0f), layout::rules::wgsl_uniform).size() ==
          144);
}

TEST_CASE("wgsl: a variant without a WGSL form is refused by name, with the reason")
{
    const variant v = variant_from_name("gtao-2x3-half-bilateral-gbufworld-std-persp-cs-fp16");
    try {
        emitted_texts(codegen::make_plan(v), compile::target::wgsl);
        FAIL("an fp16 variant was translated to WGSL");
    } catch (const error& e) {
        const std::string what = e.what();
        CHECK(what.find("gtao-2x3-half-bilateral-gbufworld-std-persp-cs-fp16.ao.comp") != std::string::npos);
        CHECK(what.find("shader-f16") != std::string::npos);
    }
    // Vulkan-model SPIR-V (combined samplers) has no WGSL form either, and says what to use.
    const variant plain = variant_from_name("ssao-s16-full-noblur-gbufworld-std-persp-cs");
    const codegen::shader_source s = codegen::generate(codegen::make_plan(plain)).front();
    try {
        compile::compile(s.glsl, s.stage, s.name, {compile::target::wgsl});
        FAIL("combined image samplers were translated to WGSL");
    } catch (const error& e) {
        CHECK(std::string(e.what()).find("binding_model::webgpu") != std::string::npos);
    }
}

// A history variant's frames on Dawn (run_variant_frames_on_dawn: its two rgba16float history
// images kept from frame to frame) against the SPIR-V on one Vulkan binding frame after frame,
// each frame with its own camera (moving sideways) and frame index on the analytic crease with
// motion vectors: every frame's every pixel bit for bit.
TEST_CASE("wgsl: Dawn runs a history variant's frames, its history kept, bit for bit like the SPIR-V frame after frame")
{
    vulkan::context* ctx = shared_context();
    if (!ctx) return;
    const int W = 64, H = 40;
    const mat4 proj = perspective(0.6f, float(W) / H, 0.1f, 100.0f);
    const vulkan::gbuffer g = crease_in_motion(W, H, proj, -0.01f, 0.004f);
    for (const char* name : {"gtao-2x2-half-denoise-gbufworld-std-persp-cs-histmv", "ssao-s16-full-box-gbufworld-std-persp-cs-hist",
                             "gtao-1x4-half-noblur-gbufworld-std-persp-fs-histmv"}) { // fragment: two colour targets
        INFO(name);
        const variant v = variant_from_name(name);
        const codegen::plan p = codegen::make_plan(v);
        const std::vector<chain_inputs> frames = sideways_frames(p, settings_for(proj), W, H, 4);
        const std::vector<wgsl::dawn_result> got = wgsl::run_variant_frames_on_dawn(plan_for(p, compile::target::wgsl),
                                                                                    emitted_texts(p, compile::target::wgsl), g, frames);
        REQUIRE(got.size() == frames.size());
        std::vector<float> history;
        const std::vector<vulkan::chain_result> expected = spirv_frames(*ctx, vulkan::chain(*ctx, p), g, frames, &history);
        for (size_t f = 0; f < frames.size(); ++f) {
            INFO("frame " << f);
            std::vector<float> ao(got[f].ao.size());
            for (size_t i = 0; i < ao.size(); ++i) ao[i] = got[f].ao[i] / 255.0f;
            const ao_difference d = difference_of(ao, expected[f].ao);
            std::cout << "history frame " << f << ": " << d.identical << " of " << d.pixels << " pixels bit-identical, largest difference "
                      << d.largest * 255 << "/255\n";
            CHECK(first_difference(ao, expected[f].ao) == "");
        }
        const auto [held, surface] = held_of(history, float(frames.size()));
        CHECK(held * 2 > surface); // the history was used: most surface texels hold every frame
    }
    require_clean(*ctx);
}
