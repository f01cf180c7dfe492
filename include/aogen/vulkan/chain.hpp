// aogen/vulkan/chain.hpp — one variant's chain (AO → blur passes): compiled once, bound to
// G-buffers, run.
//
// WHAT
//   chain compiles every pass of a variant into a pipeline once (passes.hpp: compute
//   pipelines, or fullscreen-triangle graphics pipelines for fragment variants). Then
//     bind(g, settings)   binds it to an uploaded G-buffer (inputs.hpp's gpu_gbuffer) with
//                         the kernel and noise tile the params name and the std140 uniform
//                         bytes of uniforms::pack_* (inputs_for): a bound_chain
//                         (bound_chain.hpp) that can be recorded and dispatched any number
//                         of times — what timing.hpp times;
//     run(g, settings)    the convenience on top: upload, bind, run once, read back the AO
//                         as floats with each pass's GPU time.
//   Compute and fragment variants share everything but the pipelines and how a pass is
//   recorded (a dispatch, or a draw into a colour attachment), so both give the same AO for
//   the same axes. With chain_options::diagnostics the passes are built with
//   codegen::options::diagnostics: each also stores its raw, unguarded value, and run()
//   returns what those held (chain_result::raw: NaN, Inf, below 0, above 1 per pass).
//
//   Inputs: depth as raw depth-buffer values in an R32_SFLOAT colour image (the default)
//   or a D32_SFLOAT depth image sampled through its depth aspect (run_options::depth;
//   shaders read .r either way and the AO is bit-identical; D32 holds only [0, 1], so
//   other values are an error there); normals as RGBA32F (xyz; ignored by
//   reconstructed-normal variants); the noise tile as RGBA32F.
//   Between passes, the AO is an R8_UNORM image of the AO target size: the G-buffer's
//   size, or ((w + 1) / 2, (h + 1) / 2) at half resolution (a storage image for compute,
//   a colour attachment for fragment); a half-resolution variant's upsample pass writes
//   one of the G-buffer's size (output_size: the size of what the chain returns). run_options::clear fills every
//   AO image before the passes; running with two clear values and comparing shows that
//   every pixel was written.
//
// USAGE
//     aogen::vulkan::context ctx({true});
//     aogen::variant v;                                   // ssao-s16-half-bilateral-...
//     aogen::vulkan::chain c(ctx, v);                     // any stage: compute or fragment
//     aogen::vulkan::gbuffer g{w, h, depth, normals};     // row-major, top row first
//     aogen::vulkan::chain_settings s;                    // params + camera
//     aogen::vulkan::chain_result r = c.run(g, s);        // r.ao (r.width × r.height), r.pass_ms
//     // once bound, dispatched many times (timing.hpp):
//     aogen::vulkan::gpu_gbuffer uploaded(ctx, g);
//     std::unique_ptr<aogen::vulkan::bound_chain> b = c.bind(uploaded, s);
//
// ERRORS
//   aogen::error: G-buffer sizes that do not match, depth outside [0, 1] for D32_SFLOAT, a
//   compile error, a fragment variant on a device without a graphics queue, a failing
//   Vulkan call.
#pragma once

#include "../kernel.hpp"
#include "../noise.hpp"
#include "../uniforms.hpp"
#include "bound_chain.hpp"
#include "device.hpp"
#include "inputs.hpp"
#include "passes.hpp"

#include <memory>
#include <string>
#include <vector>

namespace aogen::vulkan {

struct chain_settings {
    ssao_params ssao;   // ssao.samples is taken from the variant
    gtao_params gtao;
    vbao_params vbao;
    blur_params blur;
    uniforms::camera camera;
};

struct run_options {
    float clear = 0.0f;                             // value every AO image holds before its pass writes it
    depth_format depth = depth_format::r32_sfloat;  // how the depth buffer reaches the shaders
};

struct chain_options {
    bool diagnostics = false; // every pass also stores its raw value (codegen::options::diagnostics)
};

// The AO target size of `v` for a G-buffer of w × h.
inline std::pair<int, int> target_size(const variant& v, int w, int h)
{
    return v.half_resolution ? std::pair<int, int>{(w + 1) / 2, (h + 1) / 2} : std::pair<int, int>{w, h};
}

// The size of `v`'s output for a G-buffer of w × h: the screen's when the chain ends with
// the depth-aware upsample pass, the AO target's otherwise.
inline std::pair<int, int> output_size(const variant& v, int w, int h)
{
    return has_upsample_pass(v) ? std::pair<int, int>{w, h} : target_size(v, w, h);
}

// What `v`'s passes read besides the G-buffer, for settings `s` and an AO target of
// target_w × target_h: each pass's std140 uniform block, the noise tile the params name
// (4×4 for GTAO and VBAO) and, for SSAO, the kernel inside its block.
inline chain_inputs inputs_for(const variant& v, const chain_settings& s, int target_w, int target_h)
{
    constexpr layout::rules rules = layout::rules::std140;
    ssao_params ssao = s.ssao;
    ssao.samples = v.ssao_samples;
    chain_inputs in;
    in.noise_size = has_slices(v.tech) ? 4 : ssao.noise_size;
    in.noise = noise::encode(noise::rotations(in.noise_size, ssao.noise_seed), noise::encoding::rgba32f);
    const vec2 tsize{float(target_w), float(target_h)};
    for (pass_kind pass : passes(v)) {
        if (pass != pass_kind::ao) in.uniforms.push_back(uniforms::pack_blur(s.blur, s.camera.proj, tsize, rules));
        else if (v.tech == technique::gtao) in.uniforms.push_back(uniforms::pack_gtao(s.gtao, s.camera, tsize, rules, in.noise_size));
        else if (v.tech == technique::vbao) in.uniforms.push_back(uniforms::pack_vbao(s.vbao, s.camera, tsize, rules, in.noise_size));
        else {
            const std::vector<vec4> k = kernel::generate(kernel::distribution_from_name(ssao.kernel), ssao.samples, ssao.kernel_seed);
            in.uniforms.push_back(uniforms::pack_ssao(ssao, s.camera, k, tsize, rules));
        }
    }
    return in;
}

class chain {
public:
    chain(context& ctx, const variant& v, const chain_options& o = {}, spirv_cache* cache = nullptr)
        : ctx_(ctx), v_(v), passes_(ctx, v, codegen_options(o), cache)
    {
        if (o.diagnostics) counter_ = std::make_unique<raw_counter>(ctx, cache);
    }

    const variant& var() const { return v_; }
    const pass_pipelines& passes() const { return passes_; }

    // The chain bound to `g` with settings `s` (inputs_for), ready to record and dispatch.
    std::unique_ptr<bound_chain> bind(const gpu_gbuffer& g, const chain_settings& s) const
    {
        const auto [tw, th] = target_size(v_, g.width(), g.height());
        return std::make_unique<bound_chain>(ctx_, passes_, g, inputs_for(v_, s, tw, th), tw, th, counter_.get());
    }

    // Uploads `g`, binds, runs once and reads the AO back (see the header comment).
    chain_result run(const gbuffer& g, const chain_settings& s, const run_options& o = {}) const
    {
        const gpu_gbuffer uploaded(ctx_, g, o.depth);
        return bind(uploaded, s)->run_once(o.clear);
    }

private:
    static codegen::options codegen_options(const chain_options& o)
    {
        codegen::options c;
        c.diagnostics = o.diagnostics;
        return c;
    }

    context& ctx_;
    variant v_;
    pass_pipelines passes_;
    std::unique_ptr<raw_counter> counter_; // diagnostics only
};

} // namespace aogen::vulkan
