// aogen/vulkan/wgsl_round_trip.hpp — variants' passes built from their emitted WGSL translated
// back to SPIR-V by naga, to run the WGSL on the Vulkan harness.
//
//     aogen::vulkan::wgsl_round_trips trips(plans);             // one batch for all of them
//     std::unique_ptr<aogen::vulkan::pass_pipelines> p = trips.passes(ctx, plan);
//     aogen::vulkan::bound_chain(ctx, *p, g, plan.inputs(s, w, h)).run_once(); // as the variant's own
//     // WGSL texts of your own for the plan's shaders (a test's mutant, say):
//     p = aogen::vulkan::wgsl_passes(ctx, plan, texts);
//
// Each pass's WebGPU-model GLSL (emitted.hpp's options_for(wgsl): separate textures and
// samplers, an rgba8 output) goes to SPIR-V, to WGSL through naga (validated by naga and
// Tint, as `aogen generate --targets wgsl` writes it) and back to SPIR-V through naga's WGSL
// front end and SPIR-V writer; the passes keep the WebGPU resources, which bound_chain binds
// as separate sampled images and samplers. What it checks: the WGSL's meaning as naga reads
// it — one WGSL front end, and the text a WebGPU engine loads — not Tint's code generation
// (Dawn on this machine has no device that executes: see docs/webgpu.md § WebGPU).
#pragma once

#include <aogen/emitted.hpp>
#include "passes.hpp"

#include <map>
#include <memory>

namespace aogen::vulkan {

// The passes of plan `p` from WGSL texts of its shaders (one per shader, the plan's order),
// each translated to SPIR-V by naga; they bind as the WebGPU-model sources' resources.
inline std::unique_ptr<pass_pipelines> wgsl_passes(context& ctx, const codegen::plan& p, const std::vector<std::string>& texts)
{
    const codegen::plan planned = plan_for(p, compile::target::wgsl);
    std::vector<codegen::shader_source> sources = codegen::generate(planned);
    if (texts.size() != sources.size())
        fail("wgsl passes of " + p.name(), std::to_string(texts.size()) + " texts", "valid: one per shader, " + std::to_string(sources.size()));
    std::vector<wgsl::wgsl_job> jobs;
    for (size_t i = 0; i < sources.size(); ++i) jobs.push_back({sources[i].name, sources[i].stage, texts[i]});
    const std::vector<std::vector<uint32_t>> words = wgsl::to_spirv(jobs);
    spirv_cache cache;
    for (size_t i = 0; i < sources.size(); ++i) {
        sources[i].glsl = texts[i];
        cache.put(sources[i], words[i]);
    }
    return std::make_unique<pass_pipelines>(ctx, planned, sources, &cache, p.name() + " (wgsl)");
}

class wgsl_round_trips {
public:
    // Translates every shader of `plans` (identical texts once) in one batch of the WGSL tools.
    explicit wgsl_round_trips(const std::vector<codegen::plan>& plans)
    {
        std::vector<codegen::shader_source> unique;
        std::map<std::pair<shader_stage, std::string>, size_t> index; // by (stage, GLSL text)
        for (const codegen::plan& p : plans) {
            translated t{plan_for(p, compile::target::wgsl), {}};
            t.sources = codegen::generate(t.plan);
            for (const codegen::shader_source& s : t.sources)
                if (index.emplace(std::make_pair(s.stage, s.glsl), unique.size()).second) unique.push_back(s);
            translated_.emplace(p.name(), std::move(t));
        }
        spirv_cache glsl;
        glsl.compile_all(unique);
        std::vector<std::vector<uint32_t>> words;
        for (const codegen::shader_source& s : unique) words.push_back(glsl.get(s));
        const std::vector<std::string> texts = wgsl_texts(unique, words);
        std::vector<wgsl::wgsl_job> back;
        for (size_t i = 0; i < unique.size(); ++i) back.push_back({unique[i].name, unique[i].stage, texts[i]});
        const std::vector<std::vector<uint32_t>> round_tripped = wgsl::to_spirv(back);
        for (auto& [name, t] : translated_)
            for (codegen::shader_source& s : t.sources) {
                const size_t i = index.at(std::make_pair(s.stage, s.glsl));
                s.glsl = texts[i]; // the cache's key: the pass's text is the WGSL now
                wgsl_.put(s, round_tripped[i]);
            }
    }

    // The passes of plan `p` (one of the plans given) from naga's SPIR-V of its WGSL.
    std::unique_ptr<pass_pipelines> passes(context& ctx, const codegen::plan& p)
    {
        const translated& t = find(p);
        return std::make_unique<pass_pipelines>(ctx, t.plan, t.sources, &wgsl_, p.name() + " (wgsl round trip)");
    }

    // The WGSL texts of plan `p`, one per shader in the plan's order.
    std::vector<std::string> texts(const codegen::plan& p) const
    {
        std::vector<std::string> out;
        for (const codegen::shader_source& s : find(p).sources) out.push_back(s.glsl);
        return out;
    }

private:
    struct translated {
        codegen::plan plan;                          // the plan under the WGSL target's options
        std::vector<codegen::shader_source> sources; // its shaders; .glsl holds the WGSL
    };

    const translated& find(const codegen::plan& p) const
    {
        const auto found = translated_.find(p.name());
        if (found == translated_.end()) fail("wgsl round trip", p.name() + " was not translated", "valid: a plan given to wgsl_round_trips");
        return found->second;
    }

    std::map<std::string, translated> translated_; // by variant name
    spirv_cache wgsl_;                             // naga's SPIR-V, by WGSL text
};

} // namespace aogen::vulkan
