// aogen/emitted.hpp — a variant's shaders as one target's texts, as `aogen generate` writes them.
//
//     std::vector<std::string> glsl = aogen::emitted_texts(v, aogen::compile::target::glsl);
//     std::vector<std::string> wgsl = aogen::emitted_texts(v, aogen::compile::target::wgsl);
//
// One text per shader codegen::generate(v, o) returns, in its order (per pass: a compute
// shader, or a vertex and a fragment shader), each compiled by compile.hpp to `target`, from
// the sources options_for(target) makes: ESSL and WGSL have no r8 storage format (their compute
// passes write rgba8, the AO in .r), and WGSL comes from WebGPU's binding model. The WGSL texts
// of a variant are translated in one batch (aogen/wgsl.hpp). What aogen::gl::run, the HLSL and
// WGSL round trips and `aogen generate` take.
#pragma once

#include "codegen.hpp"
#include "compile.hpp"

#include <string>
#include <vector>

namespace aogen {

// The codegen options a target's texts are generated with: its row's (targets.hpp) needs.
inline codegen::options options_for(compile::target t)
{
    const compile::target_info& row = compile::info(t);
    codegen::options o;
    if (row.four_channel_output) o.output_format = "rgba8";
    if (row.separate_samplers) o.model = binding_model::webgpu;
    return o;
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

inline std::vector<std::string> emitted_texts(const variant& v, compile::target target, const codegen::options& o)
{
    const std::vector<codegen::shader_source> sources = codegen::generate(v, o);
    std::vector<std::string> out;
    if (target == compile::target::wgsl) {
        std::vector<std::vector<uint32_t>> spirv;
        for (const codegen::shader_source& s : sources) spirv.push_back(compile::compile(s.glsl, s.stage, s.name, {compile::target::spv}).spirv);
        return wgsl_texts(sources, spirv);
    }
    for (const codegen::shader_source& s : sources) out.push_back(compile::compile(s.glsl, s.stage, s.name, {target}).text.at(target));
    return out;
}

inline std::vector<std::string> emitted_texts(const variant& v, compile::target target)
{
    return emitted_texts(v, target, options_for(target));
}

} // namespace aogen
