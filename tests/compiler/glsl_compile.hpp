// tests/compiler/glsl_compile.hpp — test helper: GLSL or HLSL source → SPIR-V with glslang.
//
// Only for tests: compiles one compute shader (compile_compute, GLSL or HLSL) or one GLSL
// shader of any stage (compile_glsl) for Vulkan 1.0 / SPIR-V 1.0, returns the words or the
// info logs. glslang's process-wide state is initialised once.
#pragma once

#include <aogen/variant.hpp>

#include <glslang/Public/ResourceLimits.h>
#include <glslang/Public/ShaderLang.h>
#include <glslang/SPIRV/GlslangToSpv.h>

#include <cstdint>
#include <mutex>
#include <string>
#include <vector>

namespace aogen_test {

struct spirv_result {
    bool ok = false;
    std::string log;             // glslang's info and debug logs when !ok
    std::vector<uint32_t> words; // the SPIR-V module when ok
};

enum class source_language { glsl, hlsl };

inline void init_glslang()
{
    static std::once_flag once;
    std::call_once(once, [] { glslang::InitializeProcess(); });
}

// Compiles one shader of `stage` for Vulkan 1.0 / SPIR-V 1.0. GLSL: `#version` comes
// from the source. HLSL: entry point `entry`, cbuffer offsets packed by HLSL's rules
// (EShMsgHlslOffsets; without it glslang lays HLSL cbuffers out by std140). The log
// holds glslang's info and debug logs (warnings too: a clean compile leaves it empty),
// whose messages name the file and line of the source's `#line N "file"` directives.
inline spirv_result compile_shader(const std::string& source, EShLanguage stage,
                                   source_language lang = source_language::glsl, const char* entry = "main")
{
    init_glslang();
    spirv_result result;
    glslang::TShader shader(stage);
    const char* text = source.c_str();
    shader.setStrings(&text, 1);
    int messages = EShMsgSpvRules | EShMsgVulkanRules;
    if (lang == source_language::hlsl) {
        shader.setEnvInput(glslang::EShSourceHlsl, stage, glslang::EShClientVulkan, 100);
        shader.setEntryPoint(entry);
        messages |= EShMsgReadHlsl | EShMsgHlslOffsets;
    } else {
        shader.setEnvInput(glslang::EShSourceGlsl, stage, glslang::EShClientVulkan, 100);
    }
    shader.setEnvClient(glslang::EShClientVulkan, glslang::EShTargetVulkan_1_0);
    shader.setEnvTarget(glslang::EShTargetSpv, glslang::EShTargetSpv_1_0);
    if (!shader.parse(GetDefaultResources(), lang == source_language::hlsl ? 100 : 450, false,
                      static_cast<EShMessages>(messages))) {
        result.log = std::string("parse: ") + shader.getInfoLog() + shader.getInfoDebugLog();
        return result;
    }
    glslang::TProgram program;
    program.addShader(&shader);
    if (!program.link(static_cast<EShMessages>(messages))) {
        result.log = std::string("link: ") + program.getInfoLog() + program.getInfoDebugLog();
        return result;
    }
    std::vector<unsigned int> words;
    glslang::SpvOptions options;
    options.validate = false;
    options.disableOptimizer = true;
    glslang::GlslangToSpv(*program.getIntermediate(stage), words, &options);
    result.words.assign(words.begin(), words.end());
    result.ok = !result.words.empty();
    if (!result.ok) result.log = "GlslangToSpv produced no words";
    result.log += shader.getInfoLog();
    return result;
}

// A compute shader in GLSL or HLSL.
inline spirv_result compile_compute(const std::string& source, source_language lang = source_language::glsl,
                                    const char* entry = "main")
{
    return compile_shader(source, EShLangCompute, lang, entry);
}

// One GLSL shader of any stage (EShLangCompute, EShLangVertex, EShLangFragment, ...).
inline spirv_result compile_glsl(const std::string& source, EShLanguage stage)
{
    return compile_shader(source, stage);
}

// glslang's stage for one of aogen's.
inline EShLanguage language_of(aogen::shader_stage s)
{
    switch (s) {
    case aogen::shader_stage::compute: return EShLangCompute;
    case aogen::shader_stage::vertex: return EShLangVertex;
    case aogen::shader_stage::fragment: return EShLangFragment;
    }
    return EShLangCount;
}

} // namespace aogen_test
