// aogen/wgsl_dawn.hpp — a variant's WGSL executed on a real WebGPU implementation.
//
//     const aogen::codegen::plan p = aogen::plan_for(aogen::codegen::make_plan(v), aogen::compile::target::wgsl);
//     std::vector<std::string> texts = aogen::emitted_texts(p, aogen::compile::target::wgsl);
//     aogen::wgsl::dawn_result r = aogen::wgsl::run_variant_on_dawn(p, texts, g, p.inputs(settings, g.width, g.height));
//     // r.ao: output_size(v, ...) pixels, one byte each; r.device: "Dawn opengles: OpenGL version OpenGL ES 3.2 Mesa ..."
//
// Dawn (npm webgpu) runs the WGSL through Tint's GLSL ES writer on its OpenGL ES backend —
// Mesa's llvmpipe here (Dawn refuses this machine's lavapipe as a Vulkan device) — with the
// webgpu binding model's bind groups (bindings.hpp), the same G-buffer, noise and uniform
// bytes the Vulkan harness uploads. Compute passes dispatch into rgba8unorm storage textures,
// fragment passes draw the fullscreen triangle into r8unorm targets. run_variant_frames_on_dawn
// runs frame after frame, a history pass (-hist, -histmv) keeping its two rgba16float history
// images from frame to frame.
#pragma once

#include "bindings.hpp"
#include "chain_inputs.hpp"
#include "plan.hpp"
#include "wgsl.hpp"

namespace aogen::wgsl {

// `p`: the plan the texts were emitted from; its passes, bindings and pixels per invocation
// are what the runner binds and dispatches. `frames`: each frame's inputs (plan.inputs of that
// frame's settings), run one after the other on one G-buffer, a history pass keeping its
// history; every frame's output.
inline std::vector<dawn_result> run_variant_frames_on_dawn(const codegen::plan& p, const std::vector<std::string>& texts, const gbuffer& g,
                                                           const std::vector<chain_inputs>& frames)
{
    const variant& v = p.variant();
    if (has_prefilter_pass(v))
        fail("wgsl on dawn", to_name(v) + " has a depth MIP chain, which this runner does not build yet",
             "valid: variants without -mip<N> (the Vulkan harness runs those with one)");
    const std::vector<pass_kind>& ps = p.passes();
    const size_t per_pass = v.stage == pipeline_stage::compute ? 1 : 2; // codegen's order: vertex, then fragment
    if (frames.empty()) fail("wgsl on dawn", to_name(v) + ": no frame", "valid: one chain_inputs per frame, at least one");
    for (const chain_inputs& in : frames)
        if (texts.size() != ps.size() * per_pass || in.uniforms.size() != ps.size())
            fail("wgsl on dawn", to_name(v) + ": " + std::to_string(texts.size()) + " texts, " + std::to_string(in.uniforms.size()) + " uniform blocks",
                 "valid: a text per shader and a block per pass, " + std::to_string(ps.size()) + " passes");
    const auto [tw, th] = p.target_size(g.width, g.height);
    const auto webgpu = [](pass_kind pass, resource_role role) { return int(binding_of(family_of(pass), role, binding_model::webgpu)); };
    std::vector<dawn_pass> dawn;
    for (size_t i = 0; i < ps.size(); ++i) {
        const bool screen = ps[i] == pass_kind::upsample;
        dawn_pass d;
        d.wgsl = texts[per_pass * i + per_pass - 1];
        d.vertex_wgsl = per_pass == 2 ? texts[2 * i] : std::string();
        d.width = screen ? g.width : tw, d.height = screen ? g.height : th;
        d.pixels_per_invocation = p.pass_shader(i).pixels_per_invocation;
        for (const chain_inputs& in : frames) d.uniforms.push_back(in.uniforms[i]);
        if (reads_albedo(v, ps[i])) d.albedo_binding = webgpu(ps[i], resource_role::gbuffer_albedo);
        if (ps[i] == pass_kind::history) {
            // A fragment history pass writes its history as colour target 1, no binding: -1.
            d.history_binding = webgpu(ps[i], resource_role::history);
            d.history_output_binding = per_pass == 1 ? webgpu(ps[i], resource_role::history_output) : -1;
            if (v.history == history_mode::motion_vectors) d.motion_binding = webgpu(ps[i], resource_role::motion);
        }
        dawn.push_back(std::move(d));
    }
    return run_on_dawn(g.width, g.height, g.depth, g.normals, g.albedo, g.motion, frames[0].noise_size, frames[0].noise, dawn);
}

// One frame of run_variant_frames_on_dawn (a history pass with a cleared history writes this frame alone).
inline dawn_result run_variant_on_dawn(const codegen::plan& p, const std::vector<std::string>& texts, const gbuffer& g, const chain_inputs& in)
{
    return run_variant_frames_on_dawn(p, texts, g, {in}).front();
}

} // namespace aogen::wgsl
