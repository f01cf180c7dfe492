// aogen/vulkan/hlsl_round_trip.hpp — a variant's passes built from its emitted HLSL compiled
// back to SPIR-V, to run its HLSL on the Vulkan harness (issue 13's round trip).
//
//     std::unique_ptr<aogen::vulkan::pass_pipelines> p =
//         aogen::vulkan::hlsl_round_trip(ctx, v, aogen::compile::target::hlsl60);
//     aogen::vulkan::bound_chain(ctx, *p, g, inputs, tw, th).run_once();   // as the variant's own
//
// Each pass's GLSL goes to `target` (hlsl or hlsl60) through compile.hpp, as `aogen generate`
// writes it, and back to SPIR-V through compile::hlsl_to_spirv (glslang's HLSL front end); the
// passes keep the variant's resources, so they bind and run like its SPIR-V. What it checks:
// the HLSL's meaning as glslang reads it, not DXC's or FXC's code generation.
#pragma once

#include <aogen/compile.hpp>
#include <aogen/emitted.hpp>
#include "passes.hpp"

#include <memory>

namespace aogen::vulkan {

// The passes of plan `p` built from `hlsl`, its `target` texts in the plan's order
// (emitted_texts(p, target), or a copy a test has edited).
inline std::unique_ptr<pass_pipelines> hlsl_passes(context& ctx, const codegen::plan& p, compile::target target, const std::vector<std::string>& hlsl)
{
    if (target != compile::target::hlsl && target != compile::target::hlsl60)
        fail("hlsl round trip target", compile::to_name(target), "valid: hlsl, hlsl60");
    const codegen::plan planned = plan_for(p, target);
    spirv_cache cache;
    std::vector<codegen::shader_source> sources = codegen::generate(planned);
    if (hlsl.size() != sources.size())
        fail("hlsl round trip of " + p.name(), std::to_string(hlsl.size()) + " texts", "valid: one per shader, " + std::to_string(sources.size()));
    for (size_t i = 0; i < sources.size(); ++i) {
        codegen::shader_source& s = sources[i];
        s.glsl = hlsl[i]; // the cache's key: the pass's text is the HLSL now
        cache.put(s, compile::hlsl_to_spirv(s.glsl, s.stage, s.name + "." + compile::to_name(target)));
    }
    return std::make_unique<pass_pipelines>(ctx, planned, sources, &cache, p.name() + " (" + compile::to_name(target) + " round trip)");
}

// The passes of plan `p` built from its emitted HLSL of `target` (hlsl or hlsl60).
inline std::unique_ptr<pass_pipelines> hlsl_round_trip(context& ctx, const codegen::plan& p, compile::target target)
{
    return hlsl_passes(ctx, p, target, emitted_texts(p, target));
}

} // namespace aogen::vulkan
