// aogen/bindings.hpp — what every pass binds, and at which binding number: one table per
// pass family, read by codegen (declarations and AO_BINDING_* defines), the manifest, the
// Vulkan and GL runners and the table of docs/bindings.md.
//
// WHAT
//   A pass reads and writes resources by role (resource_role): its uniform block, the depth
//   buffer, the G-buffer normals, the noise tile, the previous pass's AO, its output image,
//   — in diagnostic builds — its raw-value image and — in the last pass of a -mbg variant —
//   the G-buffer's albedo. Which roles a pass family has, in which
//   order, is pass_roles(family): the AO pass, the filter passes (blur_x, blur_y,
//   blur_box, blur_denoise, blur_denoise3, upsample) that read an AO image, and the prefilter that builds the
//   depth MIP chain (depth_mips.hpp) the AO pass then reads. A role's binding numbers follow
//   from its place in that table and the binding model:
//
//     binding_model::vulkan   (SPIR-V, GLSL, ESSL, HLSL, MSL) one binding per role; textures
//                             are combined image samplers (GLSL's sampler2D), since OpenGL and
//                             ESSL have nothing else and ESSL 300 binds them by name (u_<role>)
//     binding_model::webgpu   (WGSL) WebGPU has no combined samplers: a texture is a
//                             texture_2d (GLSL texture2D), and a texture the pass gathers from
//                             (depth, ao_input: textureGather needs a sampler) is followed by
//                             its sampler at the next binding; the noise tile and the normals
//                             are read with textureLoad and need none
//
//                    vulkan                          webgpu (group 0)
//     AO pass        0 uniforms  1 depth  2 normals   0 uniforms  1 depth  2 depth sampler
//                    3 noise  4 output  5 raw          3 normals  4 noise  5 output  6 raw
//                    6 depth_mips                      7 depth_mips  8 depth_mips sampler
//                    7 gbuffer_albedo                  9 gbuffer_albedo
//     filter passes  0 uniforms  1 depth  2 ao_input  0 uniforms  1 depth  2 depth sampler
//                    3 output  4 raw                   3 ao_input  4 ao_input sampler
//                    5 gbuffer_albedo                  5 output  6 raw  7 gbuffer_albedo
//     prefilter      0 uniforms  1 depth  2 output    0 uniforms  1 depth  2 depth sampler
//                                                      3 output
//     history        the filter passes' 0..5, then     the filter passes' 0..7, then
//                    6 history  7 history_output       8 history  9 history_output
//                    8 motion                          10 motion
//
//   A number belongs to its role whether or not a given shader declares it: a reconstructed-
//   normal variant has no binding 2 (vulkan), a fragment pass no output image, a shipped
//   pass no raw image, every pass but a -mbg chain's last no gbuffer_albedo — the others keep their
//   numbers, so one layout serves every variant.
//
// USAGE
//     for (aogen::resource_role r : aogen::pass_roles(aogen::pass_family::ao)) ...
//     aogen::binding_of(aogen::pass_family::ao, aogen::resource_role::noise, aogen::binding_model::webgpu);  // 4
//     aogen::sampler_binding_of(aogen::pass_family::filter, aogen::resource_role::ao_input,
//                               aogen::binding_model::webgpu);                                          // 4
#pragma once

#include "names.hpp"
#include "variant.hpp"

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace aogen {

enum class binding_model { vulkan, webgpu };
inline constexpr std::array<enum_name<binding_model>, 2> binding_model_names{{
    {binding_model::vulkan, "vulkan"},
    {binding_model::webgpu, "webgpu"},
}};
static_assert(names::distinct(binding_model_names));

enum class resource_role { uniforms, depth, normals, noise, ao_input, output, raw, depth_mips, gbuffer_albedo, history, history_output, motion };
inline constexpr std::array<enum_name<resource_role>, 12> resource_role_names{{
    {resource_role::uniforms, "uniforms"},
    {resource_role::depth, "depth"},
    {resource_role::normals, "normals"},
    {resource_role::noise, "noise"},
    {resource_role::ao_input, "ao_input"},
    {resource_role::output, "output"},
    {resource_role::raw, "raw"},
    {resource_role::depth_mips, "depth_mips"},
    {resource_role::gbuffer_albedo, "gbuffer_albedo"},
    {resource_role::history, "history"},
    {resource_role::history_output, "history_output"},
    {resource_role::motion, "motion"},
}};
static_assert(names::distinct(resource_role_names));
inline const char* to_name(resource_role r) { return names::name_of(resource_role_names, r, "resource role"); }

// The AO pass, one of the passes that filter its image (blurs and the upsample), the
// prefilter that builds the depth MIP chain before it, or the history pass, a filter that
// also reads and writes the history.
enum class pass_family { ao, filter, prefilter, history };
inline constexpr std::array<enum_name<pass_family>, 4> pass_family_names{{
    {pass_family::ao, "ao"},
    {pass_family::filter, "filter"},
    {pass_family::prefilter, "prefilter"},
    {pass_family::history, "history"},
}};
inline pass_family family_of(pass_kind p)
{
    if (p == pass_kind::ao) return pass_family::ao;
    if (p == pass_kind::history) return pass_family::history;
    return p == pass_kind::prefilter ? pass_family::prefilter : pass_family::filter;
}

// The roles of a family, in binding order. A role added later goes last, so that no binding
// number of an existing role moves (depth_mips, the AO pass's MIP chain, came after raw; the
// gbuffer_albedo after both; not "albedo", the uniform member's name, since HLSL puts a
// cbuffer's members and the textures in one scope). It is in both families: the last pass of a chain, which reads
// it, may be the AO pass or any filter.
inline std::vector<resource_role> pass_roles(pass_family f)
{
    using r = resource_role;
    if (f == pass_family::ao) return {r::uniforms, r::depth, r::normals, r::noise, r::output, r::raw, r::depth_mips, r::gbuffer_albedo};
    if (f == pass_family::prefilter) return {r::uniforms, r::depth, r::output};
    // The history pass is a filter (the same numbers for the same roles), then its own three.
    if (f == pass_family::history)
        return {r::uniforms, r::depth, r::ao_input, r::output, r::raw, r::gbuffer_albedo, r::history, r::history_output, r::motion};
    return {r::uniforms, r::depth, r::ao_input, r::output, r::raw, r::gbuffer_albedo};
}

// Is `role` a texture (sampled by the pass, as opposed to a buffer or a storage image)?
inline bool is_texture(resource_role role)
{
    return role == resource_role::depth || role == resource_role::normals || role == resource_role::noise ||
           role == resource_role::ao_input || role == resource_role::depth_mips || role == resource_role::gbuffer_albedo ||
           role == resource_role::history || role == resource_role::motion;
}

// Does the pass gather from it (textureGather), so that WebGPU needs a sampler beside it?
inline bool is_gathered(resource_role role)
{
    return role == resource_role::depth || role == resource_role::ao_input || role == resource_role::depth_mips;
}

// The bindings a role takes in a model: the texture, storage image or block, then its sampler.
inline uint32_t slots(resource_role role, binding_model m)
{
    return m == binding_model::webgpu && is_gathered(role) ? 2u : 1u;
}

// The binding number of `role` in family `f` under model `m` (the texture's, for a texture).
inline uint32_t binding_of(pass_family f, resource_role role, binding_model m)
{
    uint32_t next = 0;
    for (resource_role r : pass_roles(f)) {
        if (r == role) return next;
        next += slots(r, m);
    }
    fail("resource role", std::string(to_name(role)) + " is not bound by the " + names::name_of(pass_family_names, f, "pass family") + " passes",
         "valid: the roles of aogen::pass_roles");
}

// The binding of the sampler WebGPU pairs with a gathered texture; none otherwise.
inline std::optional<uint32_t> sampler_binding_of(pass_family f, resource_role role, binding_model m)
{
    if (slots(role, m) < 2) return std::nullopt;
    return binding_of(f, role, m) + 1;
}

// What a role's resource holds, in a few words (docs/bindings.md's table).
inline const char* what_it_holds(resource_role r)
{
    switch (r) {
    case resource_role::uniforms: return "the pass's uniform block (Ssao/Gtao/VbaoUniforms; BlurUniforms), std140 = WGSL uniform bytes";
    case resource_role::depth: return "the depth buffer, full resolution, raw depth in .r";
    case resource_role::normals: return "G-buffer normals, float xyz (G-buffer variants only)";
    case resource_role::noise: return "the noise tile, float texels (texelFetch / textureLoad)";
    case resource_role::ao_input: return "the previous pass's AO, in .r";
    case resource_role::output: return "the output: a storage image (compute passes only)";
    case resource_role::raw: return "raw values before the guard, r32f (codegen::options::diagnostics only)";
    case resource_role::depth_mips: return "the depth MIP chain's levels 1.. in one r32f atlas (the prefilter's output; variants with depth mips only)";
    case resource_role::gbuffer_albedo: return "G-buffer albedo, full resolution, linear reflectance in .rgb (the last pass of -mbg variants only)";
    case resource_role::history: return "the previous frame's history_output, rgba16f, the AO target's size (.r AO, .g log2 of view depth, .b frames held)";
    case resource_role::history_output: return "this frame's history, rgba16f storage image (compute passes only: a fragment pass writes it as colour attachment 1); the engine swaps it with history for the next frame";
    case resource_role::motion: return "motion vectors, full resolution, in .rg (-histmv only; history_params::motion says their convention)";
    }
    return "";
}

// The binding tables as Markdown (docs/bindings.md § Bindings holds this text, and a test
// keeps the two equal): per family, a row per role with its binding in each model.
inline std::string binding_table_markdown()
{
    std::string md = "| passes | role | holds | vulkan | webgpu |\n|---|---|---|---:|---|\n";
    for (pass_family f : {pass_family::ao, pass_family::filter, pass_family::prefilter, pass_family::history})
        for (resource_role r : pass_roles(f)) {
            const std::optional<uint32_t> s = sampler_binding_of(f, r, binding_model::webgpu);
            md += std::string("| ") + names::name_of(pass_family_names, f, "pass family") + " | `" + to_name(r) + "` | " + what_it_holds(r) + " | " +
                  std::to_string(binding_of(f, r, binding_model::vulkan)) + " | " + std::to_string(binding_of(f, r, binding_model::webgpu)) +
                  (s ? " (its sampler " + std::to_string(*s) + ")" : "") + " |\n";
        }
    return md;
}

} // namespace aogen
