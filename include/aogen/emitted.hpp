// aogen/emitted.hpp — a variant's shaders as one target's texts, as `aogen generate` writes them.
//
//     const aogen::codegen::plan p = aogen::codegen::make_plan(v);
//     std::vector<std::string> glsl = aogen::emitted_texts(p, aogen::compile::target::glsl);
//     std::vector<std::string> wgsl = aogen::emitted_texts(p, aogen::compile::target::wgsl);
//     auto each = aogen::emitted_texts(std::vector{p, q}, aogen::compile::target::wgsl);  // one batch
//
// One text per shader of the plan, in its order (per pass: a compute shader, or a vertex and
// a fragment shader), each compiled by compile.hpp to `target`, from the sources of
// plan_for(p, target), the plan under options_for(target): ESSL and WGSL have no r8 storage format (their compute
// passes write rgba8, the AO in .r), and WGSL comes from WebGPU's binding model. The WGSL texts
// of a variant -- or of several plans, given together -- are translated in one batch (aogen/wgsl.hpp). What aogen::gl::run, the HLSL and
// WGSL round trips and `aogen generate` take.
#pragma once

#include "codegen.hpp"
#include "compile.hpp"

#include <cstddef>
#include <string>
#include <vector>

namespace aogen {

// `o` with what target `t`'s row (targets.hpp) needs: rgba8 outputs where it has no r8
// storage format, WebGPU's binding model where its textures and samplers are separate; the
// diagnostics and the template reader are kept.
inline codegen::options options_for(compile::target t, codegen::options o = {})
{
    const compile::target_info& row = compile::info(t);
    if (row.four_channel_output) o.output_format = "rgba8";
    if (row.separate_samplers) o.model = binding_model::webgpu;
    return o;
}

// The plan of target `t`'s texts: `p` under options_for(t) (plan::with_options: the variant
// is not planned again).
inline codegen::plan plan_for(const codegen::plan& p, compile::target t)
{
    return p.with_options(options_for(t, p.source_options()));
}

// SPIR-V → WGSL for every source (WebGPU's binding model), in one batch.
inline std::vector<std::string> wgsl_texts(const std::vector<codegen::shader_source>& sources,
                                           const std::vector<std::vector<uint32_t>>& spirv)
{
    std::vector<wgsl::spirv_job> jobs;
    for (size_t i = 0; i < sources.size(); ++i) {
        compile::require_wgsl_input(spirv[i], sources[i].name);
        jobs.push_back({sources[i].name, sources[i].stage, spirv[i]});
    }
    return wgsl::from_spirv(jobs);
}

inline std::vector<std::vector<std::string>> emitted_texts(const std::vector<codegen::plan>& plans, compile::target target);

// The texts of `p`'s shaders as target `t` takes them, in plan order: generate(plan_for(p, t)),
// each compiled to `t` (WGSL: the whole plan in one batch, below).

inline std::vector<std::string> emitted_texts(const codegen::plan& p, compile::target target)
{
    if (target == compile::target::wgsl) return emitted_texts(std::vector<codegen::plan>{p}, target).front();
    std::vector<std::string> out;
    for (const codegen::shader_source& s : codegen::generate(plan_for(p, target)))
        out.push_back(compile::compile(s.glsl, s.stage, s.name, {target}).text.at(target));
    return out;
}

// emitted_texts of each of `plans`, in their order: for WGSL every plan's shaders in one batch
// (one Node.js process for all, where a plan at a time starts one a plan).
inline std::vector<std::vector<std::string>> emitted_texts(const std::vector<codegen::plan>& plans, compile::target target)
{
    std::vector<std::vector<std::string>> out;
    if (target != compile::target::wgsl) {
        for (const codegen::plan& p : plans) out.push_back(emitted_texts(p, target));
        return out;
    }
    std::vector<codegen::shader_source> sources;
    std::vector<std::vector<uint32_t>> spirv;
    std::vector<size_t> counts;
    for (const codegen::plan& p : plans) {
        const std::vector<codegen::shader_source> plan_sources = codegen::generate(plan_for(p, target));
        counts.push_back(plan_sources.size());
        for (const codegen::shader_source& s : plan_sources) {
            spirv.push_back(compile::compile(s.glsl, s.stage, s.name, {compile::target::spv}).spirv);
            sources.push_back(s);
        }
    }
    const std::vector<std::string> texts = wgsl_texts(sources, spirv);
    size_t next = 0;
    for (size_t n : counts) {
        out.emplace_back(texts.begin() + std::ptrdiff_t(next), texts.begin() + std::ptrdiff_t(next + n));
        next += n;
    }
    return out;
}

} // namespace aogen
