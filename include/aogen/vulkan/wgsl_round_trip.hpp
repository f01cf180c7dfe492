// aogen/vulkan/wgsl_round_trip.hpp — variants' passes built from their emitted WGSL translated
// back to SPIR-V by naga, to run the WGSL on the Vulkan harness.
//
//     aogen::vulkan::wgsl_round_trips trips(variants);          // one batch for all of them
//     std::unique_ptr<aogen::vulkan::pass_pipelines> p = trips.passes(ctx, v);
//     aogen::vulkan::bound_chain(ctx, *p, g, inputs, tw, th).run_once();   // as the variant's own
//     // WGSL texts of your own for v's shaders (a test's mutant, say):
//     p = aogen::vulkan::wgsl_passes(ctx, v, texts);
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

// The passes of `v` from WGSL texts of its shaders (one per shader, codegen's order), each
// translated to SPIR-V by naga; they bind as the WebGPU-model sources' resources.
inline std::unique_ptr<pass_pipelines> wgsl_passes(context& ctx, const variant& v, const std::vector<std::string>& texts)
{
    std::vector<codegen::shader_source> sources = codegen::generate(v, options_for(compile::target::wgsl));
    if (texts.size() != sources.size())
        fail("wgsl passes of " + to_name(v), std::to_string(texts.size()) + " texts", "valid: one per shader, " + std::to_string(sources.size()));
    std::vector<wgsl::wgsl_job> jobs;
    for (size_t i = 0; i < sources.size(); ++i) jobs.push_back({sources[i].name, sources[i].stage, texts[i]});
    const std::vector<std::vector<uint32_t>> words = wgsl::to_spirv(jobs);
    spirv_cache cache;
    for (size_t i = 0; i < sources.size(); ++i) {
        sources[i].glsl = texts[i];
        cache.put(sources[i], words[i]);
    }
    return std::make_unique<pass_pipelines>(ctx, to_name(v) + " (wgsl)", v.stage, v.workgroup_x, v.workgroup_y, sources, &cache,
                                            v.bent_normals);
}

class wgsl_round_trips {
public:
    // Translates every shader of `variants` (identical texts once) in one batch of the
    // WGSL tools.
    explicit wgsl_round_trips(const std::vector<variant>& variants)
    {
        const codegen::options o = options_for(compile::target::wgsl);
        std::vector<codegen::shader_source> unique;
        std::map<std::pair<shader_stage, std::string>, size_t> index; // by (stage, GLSL text)
        for (const variant& v : variants) {
            std::vector<codegen::shader_source> sources = codegen::generate(v, o);
            for (const codegen::shader_source& s : sources)
                if (index.emplace(std::make_pair(s.stage, s.glsl), unique.size()).second) unique.push_back(s);
            sources_[to_name(v)] = std::move(sources);
        }
        spirv_cache glsl;
        glsl.compile_all(unique);
        std::vector<std::vector<uint32_t>> words;
        for (const codegen::shader_source& s : unique) words.push_back(glsl.get(s));
        const std::vector<std::string> texts = wgsl_texts(unique, words);
        std::vector<wgsl::wgsl_job> back;
        for (size_t i = 0; i < unique.size(); ++i) back.push_back({unique[i].name, unique[i].stage, texts[i]});
        const std::vector<std::vector<uint32_t>> round_tripped = wgsl::to_spirv(back);
        for (auto& [name, sources] : sources_)
            for (codegen::shader_source& s : sources) {
                const size_t i = index.at(std::make_pair(s.stage, s.glsl));
                s.glsl = texts[i]; // the cache's key: the pass's text is the WGSL now
                wgsl_.put(s, round_tripped[i]);
            }
    }

    // The passes of `v` (one of the variants given) from naga's SPIR-V of its WGSL.
    std::unique_ptr<pass_pipelines> passes(context& ctx, const variant& v)
    {
        const auto found = sources_.find(to_name(v));
        if (found == sources_.end()) fail("wgsl round trip", to_name(v) + " was not translated", "valid: a variant given to wgsl_round_trips");
        return std::make_unique<pass_pipelines>(ctx, to_name(v) + " (wgsl round trip)", v.stage, v.workgroup_x, v.workgroup_y, found->second,
                                                &wgsl_, v.bent_normals);
    }

    // The WGSL texts of `v`, one per shader in codegen's order.
    std::vector<std::string> texts(const variant& v) const
    {
        std::vector<std::string> out;
        for (const codegen::shader_source& s : sources_.at(to_name(v))) out.push_back(s.glsl);
        return out;
    }

private:
    std::map<std::string, std::vector<codegen::shader_source>> sources_; // by variant name; .glsl holds the WGSL
    spirv_cache wgsl_;                                                   // naga's SPIR-V, by WGSL text
};

} // namespace aogen::vulkan
