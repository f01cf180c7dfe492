// aogen/compile.hpp — one GLSL source to every shading language.
//
// WHAT
//   The pipeline every generated AO shader goes through:
//
//     GLSL 450 ──glslang──> SPIR-V 1.0 ──spirv-val──> spirv-opt (performance) ──spirv-val──┐
//       ┌────────────────────────────────────────────────────────────────────────────────┘
//       └─> SPIRV-Cross ─> GLSL 450, ESSL 310/300, HLSL SM 5.0 and 6.0, MSL 2.1 (macOS, iOS)
//       └─> reflection of the final SPIR-V (reflect.hpp): descriptor bindings, block
//           layouts, stage inputs and outputs, workgroup size, each target's entry point,
//           SPIR-V size figures, the MSL argument indices
//
//   Targets and their names (the command line's and manifest's spelling; names.hpp rules,
//   so '-' and '_' are the same character: "msl-ios" works):
//
//     spv        SPIR-V 1.0 for Vulkan 1.0, optimized and validated (always produced; the
//                words are `compiled::spirv`, there is no text)
//     glsl       desktop GLSL 450, OpenGL semantics (no descriptor sets: `set =` is dropped,
//                bindings stay; separate textures/samplers are combined)
//     essl       OpenGL ES: ESSL 310 for compute, ESSL 300 for vertex and fragment, with
//                `precision highp float; precision highp int;`
//     hlsl       HLSL shader model 5.0 (fxc, DXC)
//     hlsl60     HLSL shader model 6.0 (DXC)
//     msl        Metal Shading Language 2.1 for macOS
//     msl_ios    Metal Shading Language 2.1 for iOS
//     wgsl       WGSL for WebGPU, through naga (aogen/wgsl.hpp), validated by naga and Tint;
//                only from SPIR-V in WebGPU's binding model (separate textures and
//                samplers: codegen::options::model = binding_model::webgpu)
//
// USAGE
//     #include <aogen/compile.hpp>      // CMake: target_link_libraries(... aogen::compiler)
//     namespace cc = aogen::compile;
//
//     cc::compiled out = cc::compile(glsl, cc::shader_stage::compute, "ssao-s16-...-cs ao",
//                                    cc::all_targets);
//     out.spirv;                                   // std::vector<uint32_t>
//     out.text.at(cc::target::hlsl);             // the HLSL source
//     out.refl.entry_points.at(cc::target::msl_macos);   // "main0"
//     out.refl;                                    // the reflection: see reflect.hpp
//
//   The steps one by one, for callers that want only some of them:
//     glsl_to_spirv(glsl, stage, name)        glslang, SPIR-V 1.0 / Vulkan 1.0, unoptimized
//     validate_spirv(words, name, step)       spirv-val, Vulkan 1.0
//     optimize_spirv(words, name)             spirv-opt performance passes
//     cross_compile(words, stage, t, name, &entry_point, &msl_indices)   one text target
//     reflect(words, stage, name)             reflection (reflect.hpp)
//
//   Errors are aogen::error, each naming the caller's `name` and the failing step:
//     ssao-...-cs ao: glslang rejected the compute shader (valid: GLSL that compiles for Vulkan 1.0); glslang says:
//       ERROR: ssao.glsl:42: 'foo' : undeclared identifier
//       ERROR: ssao.glsl:42: '' : compilation terminated
//       ERROR: 2 compilation errors.  No code generated.
//   glslang's log lines carry the file and line of `#line N "file"` directives: every
//   source is compiled with GL_GOOGLE_cpp_style_line_directive enabled (through glslang's
//   preamble), so a template expander can emit `#line 1 "ssao.glsl"` without asking for
//   the extension (the SPIR-V then records it in an OpSourceExtension, a debug-only
//   instruction). Without a #line, the file is the caller's `name`.
//   spirv-val and spirv-opt failures carry the tools' messages; SPIRV-Cross failures name
//   the target. Compile errors are the one kind of aogen::error whose what() has several
//   lines: the first line says what failed, the following ones are the tool's log.
//
// CHOICES (the SPIRV-Cross options, and why)
//   - glsl: version 450, es = false, vulkan_semantics = false (an OpenGL 4.5 shader);
//     build_combined_image_samplers() when the SPIR-V has separate images and samplers
//     (OpenGL has only combined ones), each combined sampler taking its image's set and
//     binding; binding decorations stay (`layout(binding = N)`), descriptor sets do not
//     exist in OpenGL and are dropped, so distinct bindings across sets are the author's job.
//     A separate image never sampled through a sampler has no OpenGL form and is left
//     out; push constants become a plain `uniform Push pc;` (set by name, glUniform*).
//   - essl: es = true, version 310 (compute needs it) or 300 (vertex, fragment); both
//     default precisions highp. ESSL's default float precision in fragment shaders is
//     mediump otherwise — SPIRV-Cross would write `precision mediump float;`, which breaks
//     depth reconstruction and kernel sums. Every ESSL text states
//     `precision highp float; precision highp int;` (compute and vertex shaders are highp
//     by default; the statements are added anyway). ESSL 300 has no `layout(binding)`:
//     its blocks and samplers are bound by name (glUniformBlockBinding, glUniform1i).
//     ESSL 310 knows only the image formats rgba32f, rgba16f, r32f, rgba8, rgba8_snorm
//     and the rgba32/16/8 and r32 integer ones: a storage image in another format (r8,
//     r16f, ...) is an aogen::error for the essl target, naming the image.
//   - glsl, essl: vertex.support_nonzero_base_instance = false, so that no hidden
//     SPIRV_Cross_BaseInstance uniform appears in the output (gl_InstanceIndex becomes
//     gl_InstanceID: AO draws one instance, at base 0).
//   - glsl, essl: SPIR-V with the Float16 capability (fp16 variants) is an aogen::error:
//     SPIRV-Cross writes OpenGL's 16-bit floats only through GL_AMD_gpu_shader_half_float
//     or GL_NV_gpu_shader5 (#error otherwise), which no portable shader may assume. HLSL
//     gets min16float, MSL half.
//   - hlsl / hlsl60: shader_model 50 / 60 (SPIRV-Cross's default is 30, where compute
//     shaders and UAVs do not exist). Registers come from the bindings (b/t/s/u N); SM 5.1+
//     adds `space<set>`; SM 5.0 has no spaces, so there bindings must be distinct across
//     sets (a register two resources share is an aogen::error for hlsl, naming both).
//     Push constants become a cbuffer without a register; readonly storage buffers
//     ByteAddressBuffer (t), writable ones RWByteAddressBuffer (u). Uniform blocks become
//     cbuffers with a packoffset per member, at the SPIR-V offsets. The entry point stays
//     "main" (the body is renamed comp_main, frag_main, vert_main).
//   - msl_macos / msl_ios: platform macOS / iOS, msl_version 2.1. SPIRV-Cross renames
//     `main` to `main0` (main is reserved in Metal's C++). Buffer/texture/sampler indices
//     are SPIRV-Cross's automatic ones, in its own order (push constants first, not by
//     binding number); compile() copies them from the first MSL text it writes into the
//     reflection, per binding (`descriptor_binding::msl_buffer` etc.) and per block
//     (`buffer_block::msl_buffer`).
//   - Vertex outputs keep Vulkan's clip-space conventions in every target (no
//     fixup_clipspace, no flip_vert_y): y down, z in [0, w].
//   - spirv-opt: RegisterPerformancePasses() with preserve_bindings and
//     preserve_spec_constants, so every declared descriptor stays in the interface (a
//     pipeline layout written from the reflection matches every variant) and spec
//     constants stay settable. Note that the performance passes do not fold spec
//     constants; structural choices are #defines (see variant.hpp).
//
// DETERMINISM
//   Same source, stage and targets: same SPIR-V words and same texts, byte for byte (for
//   one build of glslang, SPIRV-Tools and SPIRV-Cross; another version of them may
//   produce other, equally valid, output).
//
// THREADS
//   glslang's process state is initialised once, on first use, thread-safely; compile()
//   holds no other shared state and may run on several threads at once.
//
// WHY
//   One pipeline for every variant keeps the targets consistent with each other; compile()
//   reflects the SPIR-V that every text was generated from, after optimization (reflect.hpp
//   says why that matters).
#pragma once

#include "error.hpp"
#include "names.hpp"
#include "reflect.hpp"
#include "targets.hpp"
#include "wgsl.hpp"

#include <glslang/Public/ResourceLimits.h>
#include <glslang/Public/ShaderLang.h>
#include <glslang/SPIRV/GlslangToSpv.h>
#include <spirv-tools/libspirv.hpp>
#include <spirv-tools/optimizer.hpp>
#include <spirv_cross/spirv_cross.hpp>
#include <spirv_cross/spirv_glsl.hpp>
#include <spirv_cross/spirv_hlsl.hpp>
#include <spirv_cross/spirv_msl.hpp>

#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <map>
#include <string>
#include <tuple>
#include <vector>

namespace aogen::compile {

// ---------------------------------------------------------------------------------
// Results and options
// ---------------------------------------------------------------------------------

struct compiled {
    std::vector<uint32_t> spirv;        // target::spv: validated, optimized SPIR-V 1.0
    std::map<target, std::string> text; // one entry per requested text target
    reflection refl;
};

struct options {
    bool optimize = true; // run spirv-opt's performance passes (validated before and after)
};

// ---------------------------------------------------------------------------------
// Implementation details
// ---------------------------------------------------------------------------------

namespace detail {

inline void initialize_glslang()
{
    // glslang::InitializeProcess builds shared symbol tables; it must run before any
    // TShader exists, and a function-local static runs it exactly once, thread-safely.
    // FinalizeProcess is never called: the tables live until the process ends.
    static const bool initialized = [] { return glslang::InitializeProcess(); }();
    (void)initialized;
}

inline EShLanguage glslang_stage(shader_stage s)
{
    switch (s) {
    case shader_stage::compute: return EShLangCompute;
    case shader_stage::vertex: return EShLangVertex;
    case shader_stage::fragment: return EShLangFragment;
    }
    names::fail_unlisted(shader_stage_names, s, "shader stage");
}

// One SPIRV-Tools message per line: "error: word 12: <text>".
struct tool_messages {
    std::string text;
    void add(spv_message_level_t level, const spv_position_t& position, const char* message)
    {
        const char* kind = level <= SPV_MSG_ERROR ? "error" : level == SPV_MSG_WARNING ? "warning" : "info";
        text += std::string(kind) + ": word " + std::to_string(position.index) + ": " + message + "\n";
    }
};

// ESSL 3.10's image formats (section 4.4.7); the others (r8, rg16f, r16f, ...) are
// desktop-only, and SPIRV-Cross would refuse them with a message naming no image.
inline bool essl_image_format(spv::ImageFormat f)
{
    switch (f) {
    case spv::ImageFormatRgba32f: case spv::ImageFormatRgba16f: case spv::ImageFormatR32f:
    case spv::ImageFormatRgba8: case spv::ImageFormatRgba8Snorm:
    case spv::ImageFormatRgba32i: case spv::ImageFormatRgba16i: case spv::ImageFormatRgba8i: case spv::ImageFormatR32i:
    case spv::ImageFormatRgba32ui: case spv::ImageFormatRgba16ui: case spv::ImageFormatRgba8ui: case spv::ImageFormatR32ui:
        return true;
    default: return false;
    }
}

inline void require_essl_image_formats(const spirv_cross::Compiler& c, const spirv_cross::ShaderResources& r,
                                       const std::string& name)
{
    for (const spirv_cross::Resource& res : r.storage_images) {
        const spv::ImageFormat format = c.get_type(res.base_type_id).image.format;
        if (format == spv::ImageFormatUnknown || essl_image_format(format)) continue;
        fail(name + ": essl: storage image " + res.name,
             std::string("format ") + image_format_name(format) + " does not exist in OpenGL ES",
             "valid in ESSL 3.10: rgba32f, rgba16f, r32f, rgba8, rgba8_snorm, rgba32i, rgba16i, rgba8i, r32i, "
             "rgba32ui, rgba16ui, rgba8ui, r32ui; give the essl target one of these, or leave essl out");
    }
}

// SM 5.0 has no register spaces: SPIRV-Cross writes `register(t0)` for binding 0 of every
// set, and fxc/DXC then refuse the overlap with a message about registers, not sets.
// Reads the `name[N] : register(xK)` declarations back and names the first overlap.
inline void require_distinct_registers(const std::string& hlsl, const std::string& name)
{
    std::map<std::string, std::string> used; // "t3" -> resource name
    const std::string marker = " : register(";
    for (size_t at = hlsl.find(marker); at != std::string::npos; at = hlsl.find(marker, at + 1)) {
        const size_t open = at + marker.size();
        const size_t close = hlsl.find(')', open);
        if (close == std::string::npos || close - open < 2) continue;
        const char kind = hlsl[open];
        uint32_t first = 0;
        size_t digits = open + 1;
        while (digits < close && hlsl[digits] >= '0' && hlsl[digits] <= '9') first = first * 10 + uint32_t(hlsl[digits++] - '0');
        if (digits == open + 1 || digits != close) continue; // not "xK" (e.g. a space given)
        size_t begin = hlsl.rfind(' ', at - 1); // the declared name, with its [N] if any
        begin = begin == std::string::npos ? 0 : begin + 1;
        std::string declared = hlsl.substr(begin, at - begin);
        uint32_t count = 1;
        const size_t bracket = declared.find('[');
        if (bracket != std::string::npos) {
            count = uint32_t(std::strtoul(declared.c_str() + bracket + 1, nullptr, 10));
            declared.resize(bracket);
            if (count == 0) count = 1;
        }
        for (uint32_t i = 0; i < count; ++i) {
            const std::string reg = kind + std::to_string(first + i);
            const auto inserted = used.emplace(reg, declared);
            if (!inserted.second)
                fail(name + ": hlsl", "register " + reg + " holds both " + inserted.first->second + " and " + declared +
                                          "; shader model 5.0 has no register spaces, so bindings of different sets collide",
                     "valid: bindings distinct across descriptor sets for each register kind, or the hlsl60 target");
        }
    }
}

// Makes an ESSL text state `precision highp float;` and `precision highp int;`.
// SPIRV-Cross writes them for fragment shaders (with the options above); vertex and
// compute shaders are highp by default in ESSL, and saying so costs nothing and leaves
// no doubt. They go right after the #version line, or after the last #extension line
// (an #extension must precede everything but other directives).
inline std::string declare_highp(std::string text)
{
    const bool has_float = text.find("precision highp float;") != std::string::npos;
    const bool has_int = text.find("precision highp int;") != std::string::npos;
    if (has_float && has_int) return text;
    size_t at = text.find('\n') + 1; // after #version
    for (size_t line = at; line < text.size();) {
        const size_t end = text.find('\n', line);
        const size_t next = end == std::string::npos ? text.size() : end + 1;
        if (text.compare(line, 10, "#extension") == 0) at = next;
        line = next;
    }
    std::string lines;
    if (!has_float) lines += "precision highp float;\n";
    if (!has_int) lines += "precision highp int;\n";
    if (at < text.size() && text[at] != '\n') lines += "\n";
    return text.insert(at, lines);
}

} // namespace detail

// ---------------------------------------------------------------------------------
// The steps, each usable on its own
// ---------------------------------------------------------------------------------

// reflect() and count_instructions() are in reflect.hpp.

namespace detail {

// One source string for a glslang::TShader, named `name` in its messages. The shader keeps
// pointers to these fields, so this must outlive its parse.
struct glslang_source {
    const char* text;
    int length;
    const char* file;
    glslang_source(const std::string& source, const std::string& name)
        : text(source.c_str()), length(static_cast<int>(source.size())), file(name.c_str())
    {
    }
};

// glslang: GLSL or HLSL source -> SPIR-V 1.0 for Vulkan 1.0 (glsl_to_spirv, hlsl_to_spirv).
inline std::vector<uint32_t> glslang_to_spirv(const std::string& source, bool hlsl, shader_stage stage, const std::string& name)
{
    initialize_glslang();
    const EShLanguage language = glslang_stage(stage);
    glslang::TShader shader(language);
    const glslang_source input(source, name);
    shader.setStringsWithLengthsAndNames(&input.text, &input.length, &input.file, 1);
    if (hlsl) {
        shader.setEntryPoint("main");
        // Texture2D + SamplerState pairs (SPIRV-Cross's way of writing GLSL's sampler2D)
        // become combined image samplers again, at the texture's register.
        shader.setTextureSamplerTransformMode(EShTexSampTransUpgradeTextureRemoveSampler);
    } else {
        // #line N "file" needs this extension; enabling it for every source costs nothing
        // (it only changes what the preprocessor accepts).
        shader.setPreamble("#extension GL_GOOGLE_cpp_style_line_directive : enable\n");
    }
    shader.setEnvInput(hlsl ? glslang::EShSourceHlsl : glslang::EShSourceGlsl, language, glslang::EShClientVulkan, 100);
    shader.setEnvClient(glslang::EShClientVulkan, glslang::EShTargetVulkan_1_0);
    shader.setEnvTarget(glslang::EShTargetSpv, glslang::EShTargetSpv_1_0);
    const auto messages = static_cast<EShMessages>(EShMsgSpvRules | EShMsgVulkanRules | (hlsl ? EShMsgReadHlsl : EShMsgDefault));
    const std::string stage_name = to_name(stage);
    const std::string language_name = hlsl ? "HLSL" : "GLSL";
    if (!shader.parse(GetDefaultResources(), hlsl ? 100 : 450, false, messages))
        throw error(name + ": glslang rejected the " + stage_name + " shader (valid: " + language_name +
                    " that compiles for Vulkan 1.0); glslang says:" + indent_lines(shader.getInfoLog()) +
                    indent_lines(shader.getInfoDebugLog()));
    glslang::TProgram program;
    program.addShader(&shader);
    if (!program.link(messages))
        throw error(name + ": glslang could not link the " + stage_name +
                    " shader (valid: a complete shader whose entry point is main); glslang says:" +
                    indent_lines(program.getInfoLog()) + indent_lines(program.getInfoDebugLog()));
    std::vector<unsigned int> words;
    spv::SpvBuildLogger logger;
    glslang::SpvOptions spv_options;
    spv_options.generateDebugInfo = false;
    // spirv-opt runs separately, with our options; HLSL needs glslang's legalization passes
    // (textures and samplers passed to functions, HLSL's structured control flow).
    spv_options.disableOptimizer = !hlsl;
    spv_options.validate = false; // spirv-val runs separately, with our messages
    glslang::GlslangToSpv(*program.getIntermediate(language), words, &logger, &spv_options);
    if (words.empty())
        throw error(name + ": glslang produced no SPIR-V for the " + stage_name + " shader; glslang says:" +
                    indent_lines(logger.getAllMessages()));
    return std::vector<uint32_t>(words.begin(), words.end());
}

// glslang as an OpenGL / OpenGL ES compiler front end: `text` (SPIRV-Cross's GLSL 450 or
// ESSL 310/300, its #version line first) parsed and linked under its own version's rules, no
// SPIR-V rules. It catches what SPIRV-Cross writes that the version lacks -- bitCount in ESSL
// 3.00, say -- before a file is written, not on the user's device.
inline void validate_gl_text(const std::string& source, shader_stage stage, const std::string& version_name, const std::string& name)
{
    initialize_glslang();
    const EShLanguage language = glslang_stage(stage);
    glslang::TShader shader(language);
    const glslang_source input(source, name);
    shader.setStringsWithLengthsAndNames(&input.text, &input.length, &input.file, 1);
    const std::string stage_name = to_name(stage);
    if (!shader.parse(GetDefaultResources(), 100, false, EShMsgDefault))
        throw error(name + ": SPIRV-Cross's " + version_name + " " + stage_name + " shader does not compile as " + version_name +
                    " (valid: what that version has; a template feature it lacks needs another form there); glslang says:" +
                    indent_lines(shader.getInfoLog()));
    glslang::TProgram program;
    program.addShader(&shader);
    if (!program.link(EShMsgDefault))
        throw error(name + ": SPIRV-Cross's " + version_name + " " + stage_name + " shader does not link; glslang says:" +
                    indent_lines(program.getInfoLog()));
}

} // namespace detail

// glslang: GLSL (any #version glslang knows, 450 intended) -> SPIR-V 1.0 for Vulkan 1.0.
// `name` labels errors and is the file name of glslang's messages until a
// `#line N "file"` directive changes it.
inline std::vector<uint32_t> glsl_to_spirv(const std::string& glsl, shader_stage stage, const std::string& name)
{
    return detail::glslang_to_spirv(glsl, false, stage, name);
}

// glslang's HLSL front end: HLSL (SPIRV-Cross's SM 5.0/6.0 output, entry point main) -> SPIR-V
// 1.0 for Vulkan 1.0, registers as bindings (b0 -> 0, t1 -> 1, u4 -> 4) and each Texture2D +
// SamplerState pair made one combined image sampler again: the round trip that runs the
// emitted HLSL on the Vulkan harness. It checks the HLSL's meaning as glslang reads it, not
// what DXC or FXC would compile from it.
inline std::vector<uint32_t> hlsl_to_spirv(const std::string& hlsl, shader_stage stage, const std::string& name)
{
    return detail::glslang_to_spirv(hlsl, true, stage, name);
}

// spirv-val, Vulkan 1.0 rules. `step` says which module this is ("glslang's output").
inline void validate_spirv(const std::vector<uint32_t>& spirv, const std::string& name,
                           const std::string& step = "SPIR-V")
{
    spvtools::SpirvTools tools(SPV_ENV_VULKAN_1_0);
    detail::tool_messages log;
    tools.SetMessageConsumer([&log](spv_message_level_t level, const char*, const spv_position_t& position,
                                    const char* message) { log.add(level, position, message); });
    if (!tools.Validate(spirv.data(), spirv.size(), spvtools::ValidatorOptions()))
        throw error(name + ": spirv-val rejected " + step + " (valid: SPIR-V 1.0 for Vulkan 1.0); spirv-val says:" +
                    detail::indent_lines(log.text));
}

// spirv-opt's performance passes, keeping every binding and spec constant.
inline std::vector<uint32_t> optimize_spirv(const std::vector<uint32_t>& spirv, const std::string& name)
{
    spvtools::Optimizer optimizer(SPV_ENV_VULKAN_1_0);
    detail::tool_messages log;
    optimizer.SetMessageConsumer([&log](spv_message_level_t level, const char*, const spv_position_t& position,
                                        const char* message) { log.add(level, position, message); });
    optimizer.RegisterPerformancePasses();
    spvtools::OptimizerOptions opt;
    opt.set_run_validator(false); // validated before and after, by validate_spirv
    opt.set_preserve_bindings(true);
    opt.set_preserve_spec_constants(true);
    std::vector<uint32_t> out;
    if (!optimizer.Run(spirv.data(), spirv.size(), &out, opt) || out.empty())
        throw error(name + ": spirv-opt failed on the module; spirv-opt says:" + detail::indent_lines(log.text));
    return out;
}

// The MSL argument indices SPIRV-Cross assigned, per (set, binding).
// SPIRV-Cross leaves resources the shader never uses out of MSL; they get no index.
struct msl_indices {
    uint32_t buffer = no_index, texture = no_index, sampler = no_index;
};
struct msl_index_map {
    std::map<std::tuple<uint32_t, uint32_t>, msl_indices> bindings; // by (set, binding)
    uint32_t push_constant = no_index;                              // [[buffer(N)]] of the push constants
};

namespace detail {

// Reads the indices a compiled CompilerMSL assigned ([[buffer(N)]], [[texture(N)]], ...).
inline msl_index_map read_msl_indices(const spirv_cross::CompilerMSL& msl)
{
    msl_index_map map;
    auto& out = map.bindings;
    const spirv_cross::ShaderResources r = msl.get_shader_resources();
    auto key = [&msl](const spirv_cross::Resource& res) {
        return std::make_tuple(msl.get_decoration(res.id, spv::DecorationDescriptorSet),
                               msl.get_decoration(res.id, spv::DecorationBinding));
    };
    for (const auto* list : {&r.uniform_buffers, &r.storage_buffers})
        for (const auto& res : *list) out[key(res)].buffer = msl.get_automatic_msl_resource_binding(res.id);
    for (const auto* list : {&r.separate_images, &r.storage_images, &r.subpass_inputs})
        for (const auto& res : *list) out[key(res)].texture = msl.get_automatic_msl_resource_binding(res.id);
    for (const auto& res : r.separate_samplers) out[key(res)].sampler = msl.get_automatic_msl_resource_binding(res.id);
    for (const auto& res : r.sampled_images) {
        out[key(res)].texture = msl.get_automatic_msl_resource_binding(res.id);
        out[key(res)].sampler = msl.get_automatic_msl_resource_binding_secondary(res.id);
    }
    for (const auto& res : r.push_constant_buffers) map.push_constant = msl.get_automatic_msl_resource_binding(res.id);
    return map;
}

} // namespace detail

// aogen::error unless `spirv` has a WGSL form: no 16-bit floats, no combined image samplers.
inline void require_wgsl_input(const std::vector<uint32_t>& spirv, const std::string& name)
{
    spirv_cross::Compiler c(spirv);
    const auto& caps = c.get_declared_capabilities();
    if (std::find(caps.begin(), caps.end(), spv::CapabilityFloat16) != caps.end())
        fail(name, "does 16-bit float arithmetic (an fp16 variant), which WGSL has only behind `enable f16;`, the optional "
                   "shader-f16 feature many WebGPU devices lack",
             "valid: --targets spv,hlsl,hlsl60,msl,msl_ios for fp16 variants");
    if (!c.get_shader_resources().sampled_images.empty())
        fail(name, "uses combined image samplers, which WGSL does not have",
             "valid: SPIR-V generated with codegen::options::model = binding_model::webgpu");
}

// SPIRV-Cross: one text target from (validated) SPIR-V. Sets `*entry_point` to the entry
// point's name in that text and, for the MSL targets, `*msl` to the argument indices
// SPIRV-Cross assigned. target::spv has no text: an aogen::error.
inline std::string cross_compile(const std::vector<uint32_t>& spirv, shader_stage stage, target t,
                                 const std::string& name, std::string* entry_point = nullptr,
                                 msl_index_map* msl_indices_out = nullptr)
{
    names::require_listed(target_names, t, "target");
    const spv::ExecutionModel model = detail::execution_model(stage);
    try {
        switch (t) {
        case target::spv: break;
        case target::wgsl: {
            // naga, not SPIRV-Cross (which has no WGSL writer).
            require_wgsl_input(spirv, name);
            if (entry_point) *entry_point = "main";
            return wgsl::from_spirv({{name, stage, spirv}}).front();
        }
        case target::glsl:
        case target::essl: {
            spirv_cross::CompilerGLSL glsl(spirv);
            const auto& caps = glsl.get_declared_capabilities();
            if (std::find(caps.begin(), caps.end(), spv::CapabilityFloat16) != caps.end())
                fail(name, std::string("does 16-bit float arithmetic (an fp16 variant), which has no portable ") + to_name(t) +
                               " form (SPIRV-Cross would need GL_AMD_gpu_shader_half_float or GL_NV_gpu_shader5)",
                     "valid: --targets spv,hlsl,hlsl60,msl,msl_ios for fp16 variants");
            spirv_cross::CompilerGLSL::Options o = glsl.get_common_options();
            o.es = t == target::essl;
            o.version = !o.es ? 450 : stage == shader_stage::compute ? 310 : 300;
            o.vulkan_semantics = false;
            o.fragment.default_float_precision = spirv_cross::CompilerGLSL::Options::Highp;
            o.fragment.default_int_precision = spirv_cross::CompilerGLSL::Options::Highp;
            o.vertex.support_nonzero_base_instance = false;
            glsl.set_common_options(o);
            const spirv_cross::ShaderResources resources = glsl.get_shader_resources();
            if (o.es) detail::require_essl_image_formats(glsl, resources, name);
            if (!resources.separate_images.empty() || !resources.separate_samplers.empty()) {
                glsl.build_combined_image_samplers();
                for (const spirv_cross::CombinedImageSampler& cis : glsl.get_combined_image_samplers()) {
                    glsl.set_name(cis.combined_id, glsl.get_name(cis.image_id) + "_" + glsl.get_name(cis.sampler_id));
                    glsl.set_decoration(cis.combined_id, spv::DecorationDescriptorSet,
                                        glsl.get_decoration(cis.image_id, spv::DecorationDescriptorSet));
                    glsl.set_decoration(cis.combined_id, spv::DecorationBinding,
                                        glsl.get_decoration(cis.image_id, spv::DecorationBinding));
                }
            }
            std::string text = glsl.compile();
            if (o.es) text = detail::declare_highp(std::move(text));
            detail::validate_gl_text(text, stage, (o.es ? "ESSL " : "GLSL ") + std::to_string(o.version), name);
            if (entry_point) *entry_point = "main";
            return text;
        }
        case target::hlsl:
        case target::hlsl60: {
            spirv_cross::CompilerHLSL hlsl(spirv);
            spirv_cross::CompilerHLSL::Options o = hlsl.get_hlsl_options();
            o.shader_model = t == target::hlsl ? 50 : 60;
            hlsl.set_hlsl_options(o);
            std::string text = hlsl.compile();
            if (t == target::hlsl) detail::require_distinct_registers(text, name);
            if (entry_point) *entry_point = hlsl.get_cleansed_entry_point_name("main", model);
            return text;
        }
        case target::msl_macos:
        case target::msl_ios: {
            spirv_cross::CompilerMSL msl(spirv);
            spirv_cross::CompilerMSL::Options o = msl.get_msl_options();
            o.platform = t == target::msl_ios ? spirv_cross::CompilerMSL::Options::iOS
                                              : spirv_cross::CompilerMSL::Options::macOS;
            o.msl_version = spirv_cross::CompilerMSL::Options::make_msl_version(2, 1);
            msl.set_msl_options(o);
            std::string text = msl.compile();
            if (entry_point) *entry_point = msl.get_cleansed_entry_point_name("main", model);
            if (msl_indices_out) *msl_indices_out = detail::read_msl_indices(msl);
            return text;
        }
        }
    } catch (const spirv_cross::CompilerError& e) {
        throw error(name + ": SPIRV-Cross could not write " + to_name(t) + " (valid: SPIR-V every target can express); SPIRV-Cross says:" +
                    detail::indent_lines(e.what()));
    }
    fail(name, std::string("target ") + to_name(t) + " has no text", "valid: the SPIR-V words themselves");
}

// ---------------------------------------------------------------------------------
// The whole pipeline
// ---------------------------------------------------------------------------------

// GLSL -> SPIR-V (validated, optimized, validated again) -> each text target, with the
// reflection of the final SPIR-V. `name` labels every error ("<variant> <pass>").
// `targets` may repeat or include target::spv (the SPIR-V is always produced).
inline compiled compile(const std::string& glsl, shader_stage stage, const std::string& name,
                        const std::vector<target>& targets, const options& opts = {})
{
    names::require_listed(shader_stage_names, stage, name + ": shader stage");
    for (target t : targets) names::require_listed(target_names, t, name + ": target");

    compiled out;
    std::vector<uint32_t> spirv = glsl_to_spirv(glsl, stage, name);
    validate_spirv(spirv, name, "glslang's SPIR-V");
    const uint32_t unoptimized_words = static_cast<uint32_t>(spirv.size());
    const uint32_t unoptimized_instructions = count_instructions(spirv, name);
    if (opts.optimize) {
        spirv = optimize_spirv(spirv, name);
        validate_spirv(spirv, name, "spirv-opt's SPIR-V");
    }
    out.refl = reflect(spirv, stage, name);
    out.refl.unoptimized_words = unoptimized_words;
    out.refl.unoptimized_instructions = unoptimized_instructions;

    // Texts in table order, whatever the order of `targets`: the same MSL indices whichever
    // of msl / msl_ios comes first (the two platforms assign them alike).
    std::vector<target> wanted;
    for (target t : all_targets)
        if (t != target::spv && std::find(targets.begin(), targets.end(), t) != targets.end()) wanted.push_back(t);
    msl_index_map indices;
    bool have_msl = false;
    for (target t : wanted) {
        std::string entry;
        const bool first_msl = !have_msl && (t == target::msl_macos || t == target::msl_ios);
        out.text[t] = cross_compile(spirv, stage, t, name, &entry, first_msl ? &indices : nullptr);
        out.refl.entry_points[t] = entry;
        have_msl = have_msl || first_msl;
    }
    if (have_msl) {
        for (descriptor_binding& b : out.refl.bindings) {
            auto found = indices.bindings.find(std::make_tuple(b.set, b.binding));
            if (found == indices.bindings.end()) continue;
            b.msl_buffer = found->second.buffer;
            b.msl_texture = found->second.texture;
            b.msl_sampler = found->second.sampler;
        }
        for (buffer_block& b : out.refl.blocks) {
            if (b.kind == block_kind::push_constant) {
                b.msl_buffer = indices.push_constant;
                continue;
            }
            auto found = indices.bindings.find(std::make_tuple(b.set, b.binding));
            if (found != indices.bindings.end()) b.msl_buffer = found->second.buffer;
        }
    }
    out.spirv = std::move(spirv);
    return out;
}

} // namespace aogen::compile
