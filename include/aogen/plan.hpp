// aogen/plan.hpp — a variant planned once: validated, canonical, and what each shader is made of.
//
// WHAT
//   make_plan(v, o) validates a variant and the codegen options once, puts the variant in
//   canonical form and works out everything its shaders are made of: the canonical name,
//   the passes, and per shader (a pass's compute shader, or its vertex and fragment shaders)
//   the #defines, the descriptors, the template files, the constants from params.hpp, the
//   uniform block and its std140 layout (laid out here, once), the workgroup and the pixels
//   per invocation. Only make_plan makes a plan, so holding one means holding a valid variant:
//   codegen::generate(plan), the runners (Vulkan, GL, Dawn), `aogen generate` and the report
//   take the plan and never validate again (a variant used to be validated 33 times per
//   generate() of a 4-pass compute variant; now once — tests/core/test_codegen.cpp counts).
//   The plan is also what a chain reads at run time:
//     plan.inputs(settings, w, h)   each pass's uniform bytes, written into the planned
//                                   layouts (a frame loop lays nothing out), and the noise tile
//     plan.target_size(w, h), plan.output_size(w, h)   the AO target's and the output's size
//     plan.with_options(o)          the same plan under other options (a target's binding
//                                   model or output format, diagnostics, a template reader):
//                                   only the resources are worked out again
//
//   The parts one level down stay public for a caller that wants one of them —
//   uniform_block(v, pass), resources(v, pass, stage, o), template_files(v, pass, stage),
//   constants(v, pass), aogen::defines(v, pass) — and each validates what it is given, as
//   every public entry point does. A plan's shaders hold exactly what these return.
//
// RESOURCES (descriptor set 0 / bind group 0; aogen/bindings.hpp's table)
//   resources(v, pass, stage, o) lists what one shader binds, each with its role, kind,
//   binding and GLSL name; codegen declares them from that list. The names the templates use:
//     u (the uniform block: SsaoUniforms, GtaoUniforms, VbaoUniforms or BlurUniforms),
//     u_depth, u_normals (G-buffer variants), u_noise, u_ao_input (filter passes),
//     u_output (compute passes), u_raw (options::diagnostics)
//   options::model picks the binding model (bindings.hpp):
//     vulkan   every texture a combined sampler2D (what GLSL, ESSL, HLSL and MSL are made from)
//     webgpu   textures as texture2D; a gathered one (u_depth, u_ao_input) with a sampler at
//              the next binding. What the WGSL target is made from (aogen/wgsl.hpp).
//
// OPTIONS (codegen::options; the defaults are what make_plan(v) uses)
//   output_format   the format qualifier of compute passes' output image:
//                     r8       (default) one 8-bit unorm channel: Vulkan, desktop GL, D3D, Metal
//                     rgba8    for OpenGL ES 3.1 and WebGPU (neither has an r8 storage
//                              format): the AO is in .r, written as (ao, 0, 0, 1)
//                     r32f, rgba16f   float targets
//                   Anything else is an aogen::error naming these four. Every compute pass of
//                   a variant gets the same format; the filter passes read the AO pass's .r.
//                   A bent-normal variant (-bn) writes four channels, AO in .r and its bent
//                   normal in .gba (output_format_of): r8 widens to rgba8 for it, rgba8 and
//                   rgba16f stay, r32f is an error.
//   diagnostics     true: every pass also stores the value it computed before ao_finalize's
//                   guard (NaN and out-of-range values included) to an r32f image `raw` —
//                   for a harness that checks the numerics, not for a renderer.
//   model           the binding model (RESOURCES).
//   templates       empty (default): the embedded templates. A reader (directory_reader(dir)
//                   in codegen.hpp, or any function from path to text) replaces them wherever
//                   the options travel, so a template under development, or a test's planted
//                   fault in one (tests/mutants/), runs through every consumer unchanged.
//
// USAGE
//     #include <aogen/plan.hpp>
//     const aogen::codegen::plan p = aogen::codegen::make_plan(v);   // aogen::error if invalid
//     p.name();                                     // "ssao-s16-half-bilateral-gbufworld-std-persp-cs"
//     for (const aogen::codegen::shader_plan& s : p.shaders())
//         // s.pass, s.stage, s.name ("<variant>.ao.comp"), s.defines, s.resources, s.files, ...
//     aogen::codegen::generate(p);                  // the GLSL (codegen.hpp)
//     aogen::chain_inputs in = p.inputs(settings, w, h);   // every frame: its uniform bytes
//
// ERRORS
//   aogen::error: an invalid variant (validate()), an output format not in the list above,
//   a pass or stage the variant does not have.
#pragma once

#include "bindings.hpp"
#include "chain_inputs.hpp"
#include "error.hpp"
#include "layout.hpp"
#include "names.hpp"
#include "params.hpp"
#include "stages.hpp"
#include "techniques.hpp"
#include "uniforms.hpp"
#include "variant.hpp"

#include <algorithm>
#include <array>
#include <atomic>
#include <cstdint>
#include <functional>
#include <string>
#include <string_view>
#include <vector>

namespace aogen::codegen {

using aogen::shader_stage; // stages.hpp, shared with the compiler
using aogen::file_extension;

// ---------------------------------------------------------------------------------
// Options
// ---------------------------------------------------------------------------------

// Reads a template by its path relative to the templates directory ("common/core.glsl").
using template_reader = std::function<std::string(const std::string& path)>;

// How the sources are generated, beyond the variant (see OPTIONS above).
struct options {
    std::string output_format = "r8"; // compute passes' output image: r8, rgba8, r32f, rgba16f
    bool diagnostics = false;         // every pass also stores its raw, unguarded value
    binding_model model = binding_model::vulkan; // combined samplers, or WebGPU's separate ones
    template_reader templates;        // where the templates are read; empty: the embedded ones
};

// A storage image format aogen writes: its GLSL format qualifier (options::output_format, a
// resource's format) and WGSL's texel format of it, which a WebGPU engine's storage texture
// has ("" for r8: core WebGPU has none). The graphics APIs' enums live with the harnesses that
// make the images, keyed by the qualifier (vulkan/passes.hpp, gl/chain.hpp).
struct storage_format {
    std::string_view qualifier;
    std::string_view webgpu;
};

// The output formats options::output_format accepts, in the order error messages list them.
inline constexpr std::array<storage_format, 4> output_formats{{{"r8", ""}, {"rgba8", "rgba8unorm"}, {"r32f", "r32float"}, {"rgba16f", "rgba16float"}}};

// The WebGPU texel format of storage format `qualifier`; an aogen::error naming the valid ones.
inline std::string webgpu_format(const std::string& qualifier)
{
    std::string valid;
    for (const storage_format& f : output_formats) {
        if (f.qualifier == qualifier && !f.webgpu.empty()) return std::string(f.webgpu);
        if (!f.webgpu.empty()) valid += (valid.empty() ? "" : ", ") + std::string(f.qualifier);
    }
    fail("storage format", quote(qualifier) + " has no WebGPU storage texture format", "valid: " + valid);
}

// aogen::error unless every option is valid.
inline void validate(const options& o)
{
    names::require_listed(binding_model_names, o.model, "binding model");
    const bool known = std::find_if(output_formats.begin(), output_formats.end(), [&](const storage_format& f) { return f.qualifier == o.output_format; }) !=
                       output_formats.end();
    std::string valid;
    for (const storage_format& f : output_formats) valid += (valid.empty() ? "" : ", ") + std::string(f.qualifier);
    if (!known) fail("output format", quote(o.output_format) + " is not a storage image format aogen writes", "valid: " + valid);
    // Core WebGPU's storage textures have no one-channel 8-bit format (r8unorm).
    if (o.model == binding_model::webgpu && o.output_format == "r8")
        fail("output format", "r8 is not a storage texture format of core WebGPU", "valid: rgba8, r32f, rgba16f");
}

// The history's format (history.glsl): .r the AO, .g log2 of the view depth, .b the frames it
// holds. 16-bit floats, not 8-bit unorm: a blend of 0.1 moves an 8-bit history only when this
// frame differs from it by more than 0.5 / 255 / 0.1 = 0.02 -- it sticks that far from
// where it should converge -- where 16 bits stick within 0.0025; log2 depth keeps 16 bits'
// relative precision from micrometres to kilometres. rgba16f is a storage format of every
// target (core WebGPU and OpenGL ES 3.1 have no rg16f storage).
inline constexpr const char* history_format = "rgba16f";

// The format the AO passes of `v` write: o.output_format, widened to four channels for a
// bent-normal variant, whose passes write (AO, bent normal), and for a -denoise3 variant,
// whose AO pass writes (AO, the edges to its right and lower neighbours: common/edges.glsl)
// -- r8 becomes rgba8, the same 8-bit unorm channels; rgba8 and rgba16f are kept. r32f has
// no four-channel format here: an aogen::error naming what is valid.
inline std::string output_format_of(const variant& v, const options& o)
{
    const bool wide = v.bent_normals || v.blur == blur_mode::denoise3;
    if (!wide || o.output_format == "rgba8" || o.output_format == "rgba16f") return o.output_format;
    if (o.output_format == "r8") return "rgba8";
    if (v.bent_normals)
        fail("output format", quote(o.output_format) + " has one channel, and a bent-normal variant (-bn) writes four (AO, normal)",
             "valid with -bn: r8 (widened to rgba8), rgba8, rgba16f");
    fail("output format", quote(o.output_format) + " has one channel, and a -denoise3 variant's AO pass writes three (AO, right edge, lower edge)",
         "valid with -denoise3: r8 (widened to rgba8), rgba8, rgba16f");
}

// ---------------------------------------------------------------------------------
// Resources
// ---------------------------------------------------------------------------------

enum class resource_kind { uniform_buffer, combined_image_sampler, sampled_image, sampler, storage_image };
inline constexpr std::array<enum_name<resource_kind>, 5> resource_kind_names{{
    {resource_kind::uniform_buffer, "uniform_buffer"},
    {resource_kind::combined_image_sampler, "combined_image_sampler"},
    {resource_kind::sampled_image, "sampled_image"},
    {resource_kind::sampler, "sampler"},
    {resource_kind::storage_image, "storage_image"},
}};
static_assert(names::distinct(resource_kind_names));

inline const char* to_name(resource_kind k) { return names::name_of(resource_kind_names, k, "resource kind"); }

// One descriptor a shader declares (RESOURCES). `name` is its role's name ("depth"), or
// "<role>_sampler" for the sampler WebGPU pairs with a gathered texture; codegen also
// writes its binding as #define AO_BINDING_<NAME>.
struct resource {
    uint32_t set = 0;
    uint32_t binding = 0;
    resource_kind kind = resource_kind::combined_image_sampler;
    std::string name;
    std::string block;  // uniform buffers: the block's type name (SsaoUniforms, ...)
    std::string format; // storage images: the format qualifier (options::output_format)
    resource_role role = resource_role::depth;
};

// The stages a variant's pass runs as: compute, or vertex + fragment.
inline std::vector<shader_stage> stages(const variant& v)
{
    names::require_listed(pipeline_stage_names, v.stage, "stage");
    if (v.stage == pipeline_stage::compute) return {shader_stage::compute};
    return {shader_stage::vertex, shader_stage::fragment};
}

namespace detail {

inline void require_stage(const variant& v, shader_stage stage)
{
    names::require_listed(shader_stage_names, stage, "shader stage");
    const bool ok = v.stage == pipeline_stage::compute ? stage == shader_stage::compute
                                                       : stage != shader_stage::compute;
    if (!ok)
        fail("shader stage", std::string(to_name(stage)) + " is not a stage of a " +
                                 names::name_of(pipeline_stage_names, v.stage, "stage") + " variant",
             v.stage == pipeline_stage::compute ? "valid: compute" : "valid: vertex, fragment");
}

inline void require_pass(const variant& v, pass_kind pass)
{
    names::require_listed(pass_kind_names, pass, "pass");
    for (pass_kind p : passes(v))
        if (p == pass) return;
    std::string valid;
    for (pass_kind p : passes(v)) valid += (valid.empty() ? "" : ", ") + std::string(names::name_of(pass_kind_names, p, "pass"));
    fail("pass", std::string(names::name_of(pass_kind_names, pass, "pass")) + " is not a pass of " + aogen::to_name(v),
         "valid: " + valid);
}

// The parts of one shader, for a variant, pass, stage and options already validated.

inline layout::block_desc uniform_block_of(const variant& v, pass_kind pass)
{
    if (pass == pass_kind::ao) return technique_of(v.tech).block(v);
    return pass == pass_kind::history ? uniforms::history_block() : uniforms::blur_block();
}

inline std::vector<resource> resources_of(const variant& v, pass_kind pass, shader_stage stage, const options& o)
{
    if (stage == shader_stage::vertex) return {};
    using k = resource_kind;
    const pass_family family = family_of(pass);
    std::vector<resource> r;
    for (resource_role role : pass_roles(family)) {
        const bool declared = role == resource_role::normals          ? v.normals != normal_source::reconstructed
                              : role == resource_role::output         ? stage == shader_stage::compute
                              : role == resource_role::history_output ? stage == shader_stage::compute // fragment: colour attachment 1
                              : role == resource_role::raw            ? o.diagnostics
                              : role == resource_role::depth_mips     ? has_prefilter_pass(v)
                              : role == resource_role::gbuffer_albedo ? reads_albedo(v, pass)
                              : role == resource_role::motion         ? v.history == history_mode::motion_vectors
                                                                      : true;
        if (!declared) continue;
        const uint32_t binding = binding_of(family, role, o.model);
        const std::string name = aogen::to_name(role);
        if (role == resource_role::uniforms) r.push_back({0, binding, k::uniform_buffer, name, uniform_block_of(v, pass).root.name, "", role});
        else if (role == resource_role::output)
            // The prefilter writes raw depth, whatever format the AO images have.
            r.push_back({0, binding, k::storage_image, name, "", pass == pass_kind::prefilter ? "r32f" : output_format_of(v, o), role});
        else if (role == resource_role::raw) r.push_back({0, binding, k::storage_image, name, "", "r32f", role});
        else if (role == resource_role::history_output) r.push_back({0, binding, k::storage_image, name, "", history_format, role});
        else if (o.model == binding_model::vulkan) r.push_back({0, binding, k::combined_image_sampler, name, "", "", role});
        else {
            r.push_back({0, binding, k::sampled_image, name, "", "", role});
            if (auto s = sampler_binding_of(family, role, o.model)) r.push_back({0, *s, k::sampler, name + "_sampler", "", "", role});
        }
    }
    return r;
}

inline std::vector<std::string> template_files_of(const variant& v, pass_kind pass, shader_stage stage)
{
    if (stage == shader_stage::vertex) return {"common/fullscreen_vertex.glsl"};
    std::vector<std::string> files{"common/core.glsl", "common/depth.glsl"};
    switch (pass) {
    case pass_kind::ao:
        files.insert(files.end(), {"common/normals.glsl", "common/noise.glsl"});
        if (v.blur == blur_mode::denoise3) files.push_back("common/edges.glsl"); // the edges blur_denoise3.glsl reads
        for (std::string& f : technique_of(v.tech).files(v)) files.push_back(std::move(f));
        break;
    case pass_kind::blur_x:
    case pass_kind::blur_y: files.push_back("blur_bilateral.glsl"); break;
    case pass_kind::blur_box: files.push_back("blur_box.glsl"); break;
    case pass_kind::blur_denoise: files.push_back("blur_denoise.glsl"); break;
    case pass_kind::blur_denoise3: files.push_back("blur_denoise3.glsl"); break;
    case pass_kind::upsample: files.push_back("upsample.glsl"); break;
    case pass_kind::history: files.push_back("history.glsl"); break;
    case pass_kind::prefilter: files.push_back("prefilter.glsl"); return files; // its own entry point
    }
    files.push_back(stage == shader_stage::compute ? "entry_compute.glsl" : "entry_fragment.glsl");
    return files;
}

inline std::vector<define> constants_of(const variant& v, pass_kind pass)
{
    std::vector<define> c;
    if (pass == pass_kind::blur_x || pass == pass_kind::blur_y) {
        for (size_t i = 0; i < blur_params::bilateral_weights.size(); ++i)
            c.push_back({"AO_BLUR_WEIGHT_" + std::to_string(i), glsl_float(blur_params::bilateral_weights[i])});
    } else if (pass == pass_kind::blur_box) {
        c.push_back({"AO_BLUR_BOX_SIZE", std::to_string(blur_params::box_size)});
    } else if (pass == pass_kind::blur_denoise) {
        c.push_back({"AO_DENOISE_RADIUS", std::to_string(blur_params::denoise_radius)});
        for (size_t i = 0; i < blur_params::denoise_weights.size(); ++i)
            c.push_back({"AO_DENOISE_WEIGHT_" + std::to_string(i), glsl_float(blur_params::denoise_weights[i])});
    } else if (pass == pass_kind::blur_denoise3) {
        for (size_t i = 0; i < blur_params::denoise3_weights.size(); ++i)
            c.push_back({"AO_DENOISE3_WEIGHT_" + std::to_string(i), glsl_float(blur_params::denoise3_weights[i])});
    }
    if (pass == pass_kind::ao && v.blur == blur_mode::denoise3)
        c.push_back({"AO_EDGE_SHARPNESS", glsl_float(blur_params::denoise3_edge_sharpness)});
    if (pass == pass_kind::ao && has_prefilter_pass(v)) c.push_back({"AO_MIP_LEVEL_OFFSET", glsl_float(depth_mips::level_offset)});
    if (pass == pass_kind::ao)
        for (define& d : technique_of(v.tech).constants(v)) c.push_back(std::move(d));
    return c;
}


// The #defines the templates read for one pass of `v` (a validated one: a plan's). Names are
// AO_<AXIS>_<VALUE> for choices (exactly one of each group is defined) and AO_<AXIS> N for
// counts; the AO pass's technique adds its own (its row's defines).
inline std::vector<define> defines_of(const variant& v, pass_kind pass)
{
    std::vector<define> d;
    auto count = [&d](const char* name, int value) { d.push_back({name, std::to_string(value)}); };

    d.push_back(choice_define("STAGE", names::name_of(pipeline_stage_names, v.stage, "stage")));
    if (v.stage == pipeline_stage::compute) {
        const auto [wx, wy] = workgroup_of(v, pass);
        count("AO_WORKGROUP_X", wx), count("AO_WORKGROUP_Y", wy);
    }
    d.push_back(choice_define("DEPTH", names::name_of(depth_convention_names, v.depth, "depth")));
    d.push_back(choice_define("PROJECTION", names::name_of(projection_kind_names, v.projection, "projection")));
    if (v.half_resolution) d.push_back({"AO_HALF_RESOLUTION", ""});
    d.push_back(choice_define("PASS", names::name_of(pass_kind_names, pass, "pass")));
    if ((pass == pass_kind::ao || pass == pass_kind::prefilter) && has_prefilter_pass(v)) count("AO_MIP_LEVELS", v.depth_mips);
    if (pass == pass_kind::ao && v.deinterleaved) count("AO_DEINTERLEAVED_LAYERS", deinterleaved_layers);
    if (applies_multi_bounce(v, pass)) d.push_back({"AO_MULTI_BOUNCE", ""}); // the finalize step of the last pass
    if (v.bent_normals && pass != pass_kind::prefilter) d.push_back({"AO_BENT_NORMALS", ""}); // every pass that reads or writes AO
    if (pass == pass_kind::ao) {
        d.push_back(choice_define("TECHNIQUE", names::name_of(technique_names, v.tech, "technique")));
        d.push_back(choice_define("NORMALS", names::name_of(normal_source_names, v.normals, "normals")));
        if (v.fp16) d.push_back({"AO_FP16", ""});
        if (v.blur == blur_mode::denoise3) d.push_back({"AO_WRITE_EDGES", ""}); // common/edges.glsl
        for (define& t : technique_of(v.tech).defines(v)) d.push_back(std::move(t));
    } else if (pass == pass_kind::blur_x || pass == pass_kind::blur_y) {
        d.push_back(choice_define("BILATERAL_DEPTH", names::name_of(bilateral_depth_names, v.blur_depth, "bilateral depth")));
    } else if (pass == pass_kind::history) {
        d.push_back(choice_define("HISTORY", names::name_of(history_mode_names, v.history, "history")));
    }
    return d;
}

} // namespace detail

// The uniform block of a variant's pass (aogen/uniforms.hpp).
inline layout::block_desc uniform_block(const variant& v, pass_kind pass)
{
    validate(v);
    detail::require_pass(v, pass);
    return detail::uniform_block_of(v, pass);
}

// The descriptors one shader of a variant's pass declares, by binding (bindings.hpp).
inline std::vector<resource> resources(const variant& v, pass_kind pass, shader_stage stage, const options& o = {})
{
    validate(v);
    validate(o);
    output_format_of(v, o);
    detail::require_pass(v, pass);
    detail::require_stage(v, stage);
    return detail::resources_of(v, pass, stage, o);
}

// The template files of one shader, in the order they are concatenated.
inline std::vector<std::string> template_files(const variant& v, pass_kind pass, shader_stage stage)
{
    validate(v);
    detail::require_pass(v, pass);
    detail::require_stage(v, stage);
    return detail::template_files_of(v, pass, stage);
}

// The constants a pass's templates take from aogen's headers, as (name, GLSL value).
inline std::vector<define> constants(const variant& v, pass_kind pass)
{
    validate(v);
    detail::require_pass(v, pass);
    return detail::constants_of(v, pass);
}

// ---------------------------------------------------------------------------------
// The plan
// ---------------------------------------------------------------------------------

// What one shader of a variant is made of. A vertex shader (fragment variants' fullscreen
// triangle) has files only: no defines, constants, resources or block of its own.
struct shader_plan {
    pass_kind pass = pass_kind::ao;
    shader_stage stage = shader_stage::compute;
    std::string name;                // "<variant name>.<pass>.<comp|vert|frag>"
    std::vector<define> defines;     // aogen::defines(v, pass)
    std::vector<resource> resources; // its descriptors (set 0), by binding
    std::vector<define> constants;   // from params.hpp (constants(v, pass))
    std::vector<std::string> files;  // the template files, in order
    layout::block_desc block;        // the uniform block (uniform_block(v, pass))
    layout::struct_layout layout;    // `block` under std140, laid out once: what the shader
                                     // declares and what plan::inputs writes, every frame
    std::pair<int, int> workgroup{0, 0}; // a compute shader's workgroup (workgroup_of)
    int pixels_per_invocation = 1;   // output pixels each invocation writes along x and y
};

class plan;
plan make_plan(const variant& v, const options& o = {});

namespace detail {

// How many plans make_plan has made in this process. Not a feature: it lets a test pin that
// `aogen generate` and the report plan each variant once.
inline std::atomic<unsigned long>& plans_made()
{
    static std::atomic<unsigned long> count{0};
    return count;
}

} // namespace detail

// A variant planned once (see WHAT). Read-only; make_plan is the only way to make one.
class plan {
public:
    const aogen::variant& variant() const { return variant_; } // the variant, canonical
    const std::string& name() const { return name_; }          // its canonical name
    const options& source_options() const { return options_; } // what the sources are generated with
    const std::vector<pass_kind>& passes() const { return passes_; }
    // Per pass in passes() order: the compute shader, or the vertex then the fragment shader.
    const std::vector<shader_plan>& shaders() const { return shaders_; }
    // The shader of pass `i` (passes()[i]) that binds its resources: the compute or fragment one.
    const shader_plan& pass_shader(size_t i) const { return shaders_.at((i + 1) * per_pass() - 1); }

    // The AO target for a G-buffer of w × h: its size, or half of it rounded up.
    std::pair<int, int> target_size(int w, int h) const { return aogen::target_size(variant_, w, h); }
    // What the chain returns for a G-buffer of w × h: the screen's size after an upsample pass.
    std::pair<int, int> output_size(int w, int h) const { return aogen::output_size(variant_, w, h); }

    // What the chain reads besides a w × h G-buffer with settings `s`: each pass's uniform
    // bytes, written into the layout planned once (nothing is laid out again, frame after
    // frame), and the noise tile (chain_inputs.hpp). aogen::error on a setting out of range.
    chain_inputs inputs(const chain_settings& s, int w, int h) const
    {
        std::vector<const layout::struct_layout*> blocks;
        for (size_t i = 0; i < passes_.size(); ++i) blocks.push_back(&pass_shader(i).layout);
        return aogen::detail::pack_inputs(variant_, s, w, h, blocks);
    }

    // This plan under other options (a target's binding model or output format, diagnostics,
    // a template reader): the variant is neither validated nor planned again; the options
    // are validated, and what they decide -- each shader's resources -- is worked out anew.
    plan with_options(const options& o) const
    {
        validate(o);
        output_format_of(variant_, o);
        plan p = *this;
        p.options_ = o;
        for (shader_plan& s : p.shaders_)
            if (s.stage != shader_stage::vertex) s.resources = detail::resources_of(variant_, s.pass, s.stage, o);
        return p;
    }

private:
    plan() = default;
    friend plan make_plan(const aogen::variant& v, const options& o);
    size_t per_pass() const { return variant_.stage == pipeline_stage::compute ? 1 : 2; }
    aogen::variant variant_;
    std::string name_;
    options options_;
    std::vector<pass_kind> passes_;
    std::vector<shader_plan> shaders_;
};

// Validates `v` and `o` (aogen::error naming what is wrong) and plans every shader.
inline plan make_plan(const variant& v, const options& o)
{
    validate(v);
    validate(o);
    output_format_of(v, o); // the pair: a -bn variant's four channels
    ++detail::plans_made();
    plan p;
    p.variant_ = canonical(v);
    p.name_ = aogen::detail::name_of(p.variant_);
    p.options_ = o;
    p.passes_ = aogen::passes(p.variant_);
    for (pass_kind pass : p.passes_)
        for (shader_stage stage : stages(p.variant_)) {
            shader_plan s;
            s.pass = pass;
            s.stage = stage;
            s.name = p.name_ + "." + names::name_of(pass_kind_names, pass, "pass") + "." + file_extension(stage);
            s.files = detail::template_files_of(p.variant_, pass, stage);
            if (stage != shader_stage::vertex) {
                s.defines = detail::defines_of(p.variant_, pass);
                s.resources = detail::resources_of(p.variant_, pass, stage, o);
                s.constants = detail::constants_of(p.variant_, pass);
                s.block = detail::uniform_block_of(p.variant_, pass);
                s.layout = layout::compute(s.block, layout::rules::std140);
                s.pixels_per_invocation = pixels_per_invocation(pass, p.variant_.stage);
                if (stage == shader_stage::compute) s.workgroup = workgroup_of(p.variant_, pass);
            }
            p.shaders_.push_back(std::move(s));
        }
    return p;
}

} // namespace aogen::codegen

namespace aogen {

// The #defines the templates read for one pass of `v` (codegen::detail::defines_of, after
// validating `v`).
inline std::vector<define> defines(const variant& v, pass_kind pass)
{
    validate(v);
    return codegen::detail::defines_of(v, pass);
}

} // namespace aogen
