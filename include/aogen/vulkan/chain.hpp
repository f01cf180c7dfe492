// aogen/vulkan/chain.hpp — one variant's chain (AO → blur passes): compiled once, bound to
// G-buffers, run.
//
// WHAT
//   chain compiles every pass of a variant into a pipeline once (passes.hpp: compute
//   pipelines, or fullscreen-triangle graphics pipelines for fragment variants). Then
//     bind(g, settings)   binds it to an uploaded G-buffer (inputs.hpp's gpu_gbuffer) with
//                         the kernel and noise tile the params name and the std140 uniform
//                         bytes the plan writes (plan.inputs): a bound_chain
//                         (bound_chain.hpp) that can be recorded and dispatched any number
//                         of times — what timing.hpp times;
//     run(g, settings)    the convenience on top: upload, bind, run once, read back the AO
//                         as floats with each pass's GPU time.
//   Compute and fragment variants share everything but the pipelines and how a pass is
//   recorded (a dispatch, or a draw into a colour attachment), so both give the same AO for
//   the same axes. From a plan made with codegen::options::diagnostics each pass also stores its raw, unguarded value, and run()
//   returns what those held (chain_result::raw: NaN, Inf, below 0, above 1 per pass).
//
//   Inputs: depth as raw depth-buffer values in an R32_SFLOAT colour image (the default)
//   or a D32_SFLOAT depth image sampled through its depth aspect (run_options::depth;
//   shaders read .r either way and the AO is bit-identical; D32 holds only [0, 1], so
//   other values are an error there); normals as RGBA32F (xyz; ignored by
//   reconstructed-normal variants); the noise tile as RGBA32F.
//   Between passes, the AO is an R8_UNORM image (R8G8B8A8_UNORM for a -bn variant's passes
//   and with the rgba8 output format: passes.hpp) of the AO target size: the G-buffer's
//   size, or ((w + 1) / 2, (h + 1) / 2) at half resolution (a storage image for compute,
//   a colour attachment for fragment); a half-resolution variant's upsample pass writes
//   one of the G-buffer's size (plan.output_size: the size of what the chain returns). run_options::clear fills every
//   AO image before the passes; running with two clear values and comparing shows that
//   every pixel was written.
//
// USAGE
//     aogen::vulkan::context ctx({true});
//     aogen::variant v;                                   // ssao-s16-half-bilateral-...
//     aogen::vulkan::chain c(ctx, aogen::codegen::make_plan(v)); // any stage: compute or fragment
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

#include <aogen/kernel.hpp>
#include <aogen/noise.hpp>
#include <aogen/uniforms.hpp>
#include "bound_chain.hpp"
#include "device.hpp"
#include "inputs.hpp"
#include "passes.hpp"

#include <memory>
#include <string>
#include <vector>

namespace aogen::vulkan {

struct run_options {
    float clear = 0.0f;                             // value every AO image holds before its pass writes it
    depth_format depth = depth_format::r32_sfloat;  // how the depth buffer reaches the shaders
};

// chain_settings and gbuffer are aogen/chain_inputs.hpp's; the sizes and the uniform bytes
// come from the plan (plan.target_size, plan.output_size, plan.inputs).
using aogen::chain_settings;

class chain {
public:
    // The chain of a planned variant: its options decide the sources (options::diagnostics:
    // chain_result::raw; options::templates: where the templates are read).
    chain(context& ctx, const codegen::plan& p, spirv_cache* cache = nullptr)
        : ctx_(ctx), passes_(ctx, p, codegen::generate(p), cache)
    {
        if (p.source_options().diagnostics) counter_ = std::make_unique<raw_counter>(ctx, cache);
    }

    const codegen::plan& plan() const { return passes_.plan(); }
    const pass_pipelines& passes() const { return passes_; }
    // The kernel that counts the raw images of a diagnostic chain (nullptr otherwise): a caller
    // that binds the chain's passes itself passes it on, so the kernel is built once per chain.
    const raw_counter* counter() const { return counter_.get(); }

    // The chain bound to `g` with settings `s` (plan.inputs), ready to record and dispatch.
    std::unique_ptr<bound_chain> bind(const gpu_gbuffer& g, const chain_settings& s) const
    {
        return std::make_unique<bound_chain>(ctx_, passes_, g, plan().inputs(s, g.width(), g.height()), counter_.get());
    }

    // Uploads `g`, binds, runs once and reads the AO back (see the header comment).
    chain_result run(const gbuffer& g, const chain_settings& s, const run_options& o = {}) const
    {
        const gpu_gbuffer uploaded(ctx_, g, o.depth);
        return bind(uploaded, s)->run_once(o.clear);
    }

private:
    context& ctx_;
    pass_pipelines passes_;
    std::unique_ptr<raw_counter> counter_; // diagnostics only
};

} // namespace aogen::vulkan
