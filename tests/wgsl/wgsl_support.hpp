// tests/wgsl/wgsl_support.hpp — what the WGSL tests share: the ray-cast crease, the comparison
// of a WGSL chain with the SPIR-V, naga's layout of a WGSL struct, and the planted-fault edits.
#pragma once

#include "vulkan/harness.hpp"

#include <aogen_report/settings.hpp>
#include <aogen_scenes/gbuffer.hpp>

#include <aogen/ao_difference.hpp>
#include <aogen/emitted.hpp>
#include <aogen/vulkan/wgsl_round_trip.hpp>
#include <aogen/wgsl_dawn.hpp>

#include <regex>

namespace aogen_test {

using namespace aogen;


// The report's ray-cast `crease` scene at 160 × 90, as aogen_report renders it for `v`.
struct ray_cast_crease {
    scenes::scene scene = [] {
        scenes::scene s = scenes::builtin_scene("crease");
        s.camera.width = 160, s.camera.height = 90;
        return s;
    }();
    std::unique_ptr<truth::scene> tracer = scenes::make_tracer(scene);

    vulkan::gbuffer for_variant(const variant& v) const
    {
        scenes::gbuffer_options go;
        go.use_scene_normals = false;
        go.face_camera = false;
        go.normals = v.normals == normal_source::gbuffer_view ? scenes::normal_space::view : scenes::normal_space::world;
        return with_test_albedo(scenes::to_gbuffer<vulkan::gbuffer>(scenes::render_gbuffer(aogen_report::for_variant(scene, v), *tracer, go)));
    }
};

// `passes` (a WGSL round trip) against `v`'s SPIR-V chain `spirv` on G-buffer `g` with settings `s`.
inline ao_difference against_spirv(vulkan::context& ctx, const vulkan::pass_pipelines& passes, const vulkan::chain& spirv, const variant& v,
                                   const vulkan::gbuffer& g, const vulkan::chain_settings& s)
{
    const vulkan::gpu_gbuffer gpu(ctx, g);
    const vulkan::chain_result got = vulkan::bound_chain(ctx, passes, gpu, passes.plan().inputs(s, g.width, g.height)).run_once();
    const vulkan::chain_result expected = spirv.run(g, s);
    REQUIRE(got.width == expected.width);
    REQUIRE(got.height == expected.height);
    // The crease is occluded: the comparison is not between two blank images.
    CHECK(*std::min_element(expected.ao.begin(), expected.ao.end()) < 0.98f);
    CHECK(first_difference(got.bent_normal, expected.bent_normal) == ""); // a -bn variant's, byte for byte (empty otherwise)
    CHECK(got.bent_normal.size() == (v.bent_normals ? 3 * got.ao.size() : 0));
    return difference_of(got.ao, expected.ao);
}

// against_spirv against the variant's own SPIR-V chain, made here.
inline ao_difference against_spirv(vulkan::context& ctx, const vulkan::pass_pipelines& passes, const variant& v, const vulkan::gbuffer& g,
                                   const vulkan::chain_settings& s)
{
    return against_spirv(ctx, passes, chain_under_test(ctx, v), v, g, s);
}

// `v`'s WGSL `texts` run on Dawn against its SPIR-V chain `spirv` on G-buffer `g` with settings `s`.
inline ao_difference dawn_against_spirv(const vulkan::chain& spirv, const variant& v, const std::vector<std::string>& texts, const vulkan::gbuffer& g,
                                        const vulkan::chain_settings& s)
{
    const codegen::plan p = plan_for(codegen::make_plan(v), compile::target::wgsl);
    const wgsl::dawn_result got = wgsl::run_variant_on_dawn(p, texts, g, p.inputs(s, g.width, g.height));
    std::vector<float> ao(got.ao.size());
    for (size_t i = 0; i < ao.size(); ++i) ao[i] = got.ao[i] / 255.0f;
    const vulkan::chain_result expected = spirv.run(g, s);
    REQUIRE(ao.size() == expected.ao.size());
    CHECK(*std::min_element(expected.ao.begin(), expected.ao.end()) < 0.98f); // not two blank images
    if (v.bent_normals) { // its rgba8 texels' .gba, byte for byte
        REQUIRE(got.texels.size() == 4 * ao.size());
        CHECK(first_difference(decode_bent_normals(got.texels.data(), ao.size()), expected.bent_normal) == "");
    }
    return difference_of(ao, expected.ao);
}

// dawn_against_spirv against the variant's own SPIR-V chain, made here.
inline ao_difference dawn_against_spirv(vulkan::context& ctx, const variant& v, const std::vector<std::string>& texts, const vulkan::gbuffer& g,
                                        const vulkan::chain_settings& s)
{
    return dawn_against_spirv(chain_under_test(ctx, v), v, texts, g, s);
}

// A block as naga lays it out, read from naga's SPIR-V of a WGSL text.
inline compile::buffer_block naga_block(const std::string& wgsl, shader_stage stage, const std::string& block)
{
    const std::vector<uint32_t> words = wgsl::to_spirv({{block, stage, wgsl}}).front();
    const std::optional<compile::buffer_block> b = compile::find_struct_block(compile::reflect(words, stage, block), block);
    REQUIRE(b);
    return *b;
}

// Names, offsets and sizes, member by member (nested structs too).
inline void require_same_members(const std::vector<compile::block_member>& a, const std::vector<compile::block_member>& b)
{
    REQUIRE(a.size() == b.size());
    for (size_t i = 0; i < a.size(); ++i) {
        INFO("member " << a[i].name);
        CHECK(a[i].name == b[i].name);
        CHECK(a[i].type == b[i].type);
        CHECK(a[i].offset == b[i].offset);
        CHECK(a[i].size == b[i].size);
        CHECK(a[i].array == b[i].array);
        CHECK(a[i].array_stride == b[i].array_stride);
        require_same_members(a[i].members, b[i].members);
    }
}

// A compute shader that declares `declaration` (a WGSL uniform struct and its variable) and
// reads it, so that naga keeps it.
inline std::string shader_using(const std::string& declaration, const std::string& instance)
{
    return declaration + "\n@compute @workgroup_size(1)\nfn main() {\n    _ = " + instance + ";\n}\n";
}

// `text` with the variable `name` moved to binding `binding` (a planted fault).
inline std::string rebind(const std::string& text, const std::string& name, uint32_t binding)
{
    const std::string moved =
        std::regex_replace(text, std::regex("@binding\\(\\d+\\)(\\s*var(<[a-z_, ]*>)? " + name + ":)"), "@binding(" + std::to_string(binding) + ")$1");
    REQUIRE(moved != text); // the mutant really is one
    return moved;
}

// `text` with the first match of `from` replaced by `to` (a planted fault).
inline std::string replace_first(const std::string& text, const std::string& from, const std::string& to)
{
    const size_t at = text.find(from);
    REQUIRE(at != std::string::npos);
    return text.substr(0, at) + to + text.substr(at + from.size());
}

// The index of pass `pass`'s compute or fragment shader among `v`'s shaders.
inline size_t shader_index(const variant& v, pass_kind pass)
{
    const std::vector<codegen::shader_source> sources = codegen::generate(codegen::make_plan(v, options_for(compile::target::wgsl)));
    for (size_t i = 0; i < sources.size(); ++i)
        if (sources[i].pass == pass && sources[i].stage != shader_stage::vertex) return i;
    FAIL("no such pass");
    return 0;
}

} // namespace aogen_test
