// aogen/compile.hpp — one GLSL source to every shading language, with reflection.
//
// WHAT
//   The pipeline every generated AO shader goes through:
//
//     GLSL 450 ──glslang──> SPIR-V 1.0 ──spirv-val──> spirv-opt (performance) ──spirv-val──┐
//       ┌────────────────────────────────────────────────────────────────────────────────┘
//       └─> SPIRV-Cross ─> GLSL 450, ESSL 310/300, HLSL SM 5.0 and 6.0, MSL 2.1 (macOS, iOS)
//       └─> reflection: descriptor bindings, uniform/storage block layouts, stage inputs and
//           outputs, workgroup size, each target's entry point, SPIR-V size figures
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
//
// USAGE
//     #include <aogen/compile.hpp>      // CMake: target_link_libraries(... aogen::compiler)
//     namespace cc = aogen::compile;
//
//     cc::compiled out = cc::compile(glsl, cc::shader_stage::compute, "ssao-s16-...-cs ao",
//                                    cc::all_targets);
//     out.spirv;                                   // std::vector<uint32_t>
//     out.text.at(cc::target::hlsl50);             // the HLSL source
//     out.refl.entry_points.at(cc::target::msl_macos);   // "main0"
//     out.refl.workgroup_size;                     // {8, 8, 1}
//     const cc::buffer_block* b = cc::find_block(out.refl, "SsaoUniforms");
//     cc::check_layout(*b, aogen::layout::compute(desc, aogen::layout::rules::std140));
//
//   The steps one by one, for callers that want only some of them:
//     glsl_to_spirv(glsl, stage, name)        glslang, SPIR-V 1.0 / Vulkan 1.0, unoptimized
//     validate_spirv(words, name, step)       spirv-val, Vulkan 1.0
//     optimize_spirv(words, name)             spirv-opt performance passes
//     cross_compile(words, stage, t, name, &entry_point, &msl_indices)   one text target
//     reflect(words, stage, name)             reflection (entry_points: spv only)
//     count_instructions(words)               instructions after the 5-word header
//     layout_mismatches(block, layout) / check_layout(block, layout)   SPIR-V vs layout.hpp
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
//   - hlsl50 / hlsl60: shader_model 50 / 60 (SPIRV-Cross's default is 30, where compute
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
//     binding number); they are reflected per binding (`descriptor_binding::msl_buffer`
//     etc.) and per block (`buffer_block::msl_buffer`).
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
//   One pipeline for every variant keeps the targets consistent with each other, and the
//   reflection comes from the SPIR-V that every text was generated from, after
//   optimization — so a binding or a block member that the optimizer would have dropped
//   cannot appear in one target and not in another.
#pragma once

#include "error.hpp"
#include "layout.hpp"
#include "names.hpp"
#include "variant.hpp"

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
#include <array>
#include <cstdint>
#include <cstdlib>
#include <map>
#include <string>
#include <string_view>
#include <tuple>
#include <vector>

namespace aogen::compile {

// ---------------------------------------------------------------------------------
// Stages and targets
// ---------------------------------------------------------------------------------

using aogen::shader_stage; // defined in variant.hpp, shared with codegen.hpp
using aogen::shader_stage_from_name;

// The stage of a variant's AO pass (its fragment passes also need a vertex shader).
inline shader_stage stage_of(pipeline_stage s)
{
    switch (s) {
    case pipeline_stage::compute: return shader_stage::compute;
    case pipeline_stage::fragment: return shader_stage::fragment;
    }
    names::fail_unlisted(pipeline_stage_names, s, "stage");
}

enum class target { spv, glsl, essl, hlsl50, hlsl60, msl_macos, msl_ios };
inline constexpr std::array<enum_name<target>, 7> target_names{{
    {target::spv, "spv"},
    {target::glsl, "glsl"},
    {target::essl, "essl"},
    {target::hlsl50, "hlsl"},
    {target::hlsl60, "hlsl60"},
    {target::msl_macos, "msl"},
    {target::msl_ios, "msl_ios"},
}};
static_assert(names::distinct(target_names));

// Every target, in table order.
inline const std::vector<target> all_targets = [] {
    constexpr auto values = names::values(target_names);
    return std::vector<target>(values.begin(), values.end());
}();

inline const char* to_name(target t) { return names::name_of(target_names, t, "target"); }
inline target target_from_name(std::string_view name, std::string_view subject = "target")
{
    return names::value_of(target_names, name, subject);
}
// "spv, glsl, essl, hlsl, hlsl60, msl, msl_ios".
inline std::string target_list() { return names::list(target_names); }

// ---------------------------------------------------------------------------------
// Reflection
// ---------------------------------------------------------------------------------

// What a descriptor binding holds, named after Vulkan's VkDescriptorType.
enum class descriptor_kind {
    uniform_buffer,         // uniform Block { ... }
    storage_buffer,         // buffer Block { ... }
    combined_image_sampler, // sampler2D and friends
    sampled_image,          // texture2D (a separate image)
    sampler,                // sampler / samplerShadow
    storage_image,          // image2D
    uniform_texel_buffer,   // samplerBuffer / textureBuffer
    storage_texel_buffer,   // imageBuffer
    input_attachment,       // subpassInput
};
inline constexpr std::array<enum_name<descriptor_kind>, 9> descriptor_kind_names{{
    {descriptor_kind::uniform_buffer, "uniform_buffer"},
    {descriptor_kind::storage_buffer, "storage_buffer"},
    {descriptor_kind::combined_image_sampler, "combined_image_sampler"},
    {descriptor_kind::sampled_image, "sampled_image"},
    {descriptor_kind::sampler, "sampler"},
    {descriptor_kind::storage_image, "storage_image"},
    {descriptor_kind::uniform_texel_buffer, "uniform_texel_buffer"},
    {descriptor_kind::storage_texel_buffer, "storage_texel_buffer"},
    {descriptor_kind::input_attachment, "input_attachment"},
}};
static_assert(names::distinct(descriptor_kind_names));
inline const char* to_name(descriptor_kind k) { return names::name_of(descriptor_kind_names, k, "descriptor kind"); }

// No index: MSL indices not reflected (no msl target compiled) or not applicable.
inline constexpr uint32_t no_index = ~0u;

struct descriptor_binding {
    uint32_t set = 0;
    uint32_t binding = 0;
    descriptor_kind kind = descriptor_kind::uniform_buffer;
    std::string name;        // blocks: the block's type name ("SsaoUniforms"); others: the variable's
    std::string instance;    // blocks: the instance name ("u"), may be empty; others: == name
    std::string type;        // GLSL spelling: "uniform", "buffer", "sampler2D", "image2D", "utexture3D", ...
    uint32_t count = 1;      // descriptors in the binding: an array's size; 0 for a runtime-sized array
    std::string image_format; // storage images: the format qualifier, "r8", "rgba16f", ... ("" when none)
    bool readable = true;    // storage images and buffers: not NonReadable (writeonly)
    bool writable = true;    // storage images and buffers: not NonWritable (readonly); false for others
    // MSL argument indices SPIRV-Cross assigned ([[buffer(N)]], [[texture(N)]], [[sampler(N)]]);
    // a combined image sampler has a texture and a sampler index. no_index when not
    // applicable, when no msl target was compiled, or when the shader never uses the
    // binding (SPIRV-Cross leaves unused resources out of MSL; HLSL and GLSL keep them).
    uint32_t msl_buffer = no_index, msl_texture = no_index, msl_sampler = no_index;
};

// One member of a block as the SPIR-V declares it (Offset, ArrayStride, MatrixStride).
struct block_member {
    std::string name;
    std::string type;            // GLSL spelling: float, vec3, ivec2, mat4, mat2x3, or the struct's name
    std::vector<uint32_t> array; // array dimensions, outermost first; 0: runtime-sized; empty: not an array
    uint32_t offset = 0;         // bytes from the start of the enclosing struct
    uint32_t size = 0;           // bytes it spans, as SPIRV-Cross measures: arrays stride × count (0 when
                                 // runtime-sized), matrices stride × columns (rows when row-major),
                                 // vectors 4 × components, structs up to the end of their last member
    uint32_t array_stride = 0;   // 0 when not an array
    uint32_t matrix_stride = 0;  // 0 when not a matrix
    bool row_major = false;
    std::vector<block_member> members; // a struct's members, offsets from its start
};

enum class block_kind { uniform, storage, push_constant };
inline constexpr std::array<enum_name<block_kind>, 3> block_kind_names{{
    {block_kind::uniform, "uniform"},
    {block_kind::storage, "storage"},
    {block_kind::push_constant, "push_constant"},
}};
inline const char* to_name(block_kind k) { return names::name_of(block_kind_names, k, "block kind"); }

struct buffer_block {
    block_kind kind = block_kind::uniform;
    uint32_t set = 0, binding = 0; // 0 for push constants
    std::string name;              // the block's type name
    std::string instance;          // the variable's name; may be empty
    uint32_t size = 0;             // to the end of the last member (SPIR-V has no tail padding);
                                   // a runtime-sized array counts 0 elements
    std::vector<block_member> members;
    uint32_t msl_buffer = no_index; // [[buffer(N)]] in the MSL texts (push constants included)
};

// A user-defined stage input or output (built-ins are not listed).
struct stage_variable {
    uint32_t location = 0;
    std::string name;
    std::string type; // GLSL spelling
};

struct reflection {
    shader_stage stage = shader_stage::compute;
    std::vector<descriptor_binding> bindings;     // sorted by set, then binding
    std::vector<buffer_block> blocks;  // uniform, storage and push-constant blocks, sorted like bindings
    std::vector<stage_variable> inputs, outputs; // sorted by location
    std::array<uint32_t, 3> workgroup_size{{0, 0, 0}}; // compute: LocalSize; 0s for other stages
    // Each compiled target's entry point, as its text spells it: spv, glsl, essl, hlsl "main";
    // msl "main0". Always has target::spv.
    std::map<target, std::string> entry_points;
    uint32_t spirv_words = 0;              // the final (optimized) module, header included
    uint32_t spirv_instructions = 0;
    uint32_t unoptimized_words = 0;        // glslang's module, before spirv-opt
    uint32_t unoptimized_instructions = 0;
};

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

inline spv::ExecutionModel execution_model(shader_stage s)
{
    switch (s) {
    case shader_stage::compute: return spv::ExecutionModelGLCompute;
    case shader_stage::vertex: return spv::ExecutionModelVertex;
    case shader_stage::fragment: return spv::ExecutionModelFragment;
    }
    names::fail_unlisted(shader_stage_names, s, "shader stage");
}

// Each non-empty line of `log`, indented, on a line of its own.
inline std::string indent_lines(std::string_view log)
{
    std::string out;
    size_t start = 0;
    while (start < log.size()) {
        size_t end = log.find('\n', start);
        if (end == std::string_view::npos) end = log.size();
        std::string_view line = log.substr(start, end - start);
        while (!line.empty() && (line.back() == ' ' || line.back() == '\r' || line.back() == '\t')) line.remove_suffix(1);
        if (!line.empty()) out.append("\n  ").append(line);
        start = end + 1;
    }
    return out;
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

inline std::string scalar_glsl_name(const spirv_cross::SPIRType& t)
{
    using T = spirv_cross::SPIRType;
    switch (t.basetype) {
    case T::Boolean: return "bool";
    case T::Int: return "int";
    case T::UInt: return "uint";
    case T::Float: return "float";
    case T::Double: return "double";
    case T::Half: return "float16_t";
    case T::Int64: return "int64_t";
    case T::UInt64: return "uint64_t";
    case T::Short: return "int16_t";
    case T::UShort: return "uint16_t";
    case T::SByte: return "int8_t";
    case T::UByte: return "uint8_t";
    default: return "unknown";
    }
}

// GLSL spelling of a scalar, vector or matrix type (arrays left out); a struct's name.
inline std::string value_glsl_name(const spirv_cross::Compiler& c, const spirv_cross::SPIRType& t)
{
    using T = spirv_cross::SPIRType;
    if (t.basetype == T::Struct) return c.get_name(t.self);
    const std::string scalar = scalar_glsl_name(t);
    if (t.columns > 1) {
        const std::string prefix = t.basetype == T::Double ? "dmat" : "mat";
        if (t.columns == t.vecsize) return prefix + std::to_string(t.columns);
        return prefix + std::to_string(t.columns) + "x" + std::to_string(t.vecsize);
    }
    if (t.vecsize == 1) return scalar;
    std::string prefix;
    switch (t.basetype) {
    case T::Boolean: prefix = "b"; break;
    case T::Int: prefix = "i"; break;
    case T::UInt: prefix = "u"; break;
    case T::Double: prefix = "d"; break;
    case T::Half: prefix = "f16"; break;
    case T::Float: break;
    default: return scalar + "vec" + std::to_string(t.vecsize);
    }
    return prefix + "vec" + std::to_string(t.vecsize);
}

// Array dimensions outermost first (SPIRV-Cross keeps them innermost first); 0 = runtime.
inline std::vector<uint32_t> array_dims(const spirv_cross::SPIRType& t)
{
    std::vector<uint32_t> dims;
    for (size_t i = t.array.size(); i-- > 0;) dims.push_back(t.array_size_literal[i] ? t.array[i] : 0u);
    return dims;
}

inline const char* image_format_name(spv::ImageFormat f)
{
    switch (f) {
    case spv::ImageFormatUnknown: return "";
    case spv::ImageFormatRgba32f: return "rgba32f";
    case spv::ImageFormatRgba16f: return "rgba16f";
    case spv::ImageFormatR32f: return "r32f";
    case spv::ImageFormatRgba8: return "rgba8";
    case spv::ImageFormatRgba8Snorm: return "rgba8_snorm";
    case spv::ImageFormatRg32f: return "rg32f";
    case spv::ImageFormatRg16f: return "rg16f";
    case spv::ImageFormatR11fG11fB10f: return "r11f_g11f_b10f";
    case spv::ImageFormatR16f: return "r16f";
    case spv::ImageFormatRgba16: return "rgba16";
    case spv::ImageFormatRgb10A2: return "rgb10_a2";
    case spv::ImageFormatRg16: return "rg16";
    case spv::ImageFormatRg8: return "rg8";
    case spv::ImageFormatR16: return "r16";
    case spv::ImageFormatR8: return "r8";
    case spv::ImageFormatRgba16Snorm: return "rgba16_snorm";
    case spv::ImageFormatRg16Snorm: return "rg16_snorm";
    case spv::ImageFormatRg8Snorm: return "rg8_snorm";
    case spv::ImageFormatR16Snorm: return "r16_snorm";
    case spv::ImageFormatR8Snorm: return "r8_snorm";
    case spv::ImageFormatRgba32i: return "rgba32i";
    case spv::ImageFormatRgba16i: return "rgba16i";
    case spv::ImageFormatRgba8i: return "rgba8i";
    case spv::ImageFormatR32i: return "r32i";
    case spv::ImageFormatRg32i: return "rg32i";
    case spv::ImageFormatRg16i: return "rg16i";
    case spv::ImageFormatRg8i: return "rg8i";
    case spv::ImageFormatR16i: return "r16i";
    case spv::ImageFormatR8i: return "r8i";
    case spv::ImageFormatRgba32ui: return "rgba32ui";
    case spv::ImageFormatRgba16ui: return "rgba16ui";
    case spv::ImageFormatRgba8ui: return "rgba8ui";
    case spv::ImageFormatR32ui: return "r32ui";
    case spv::ImageFormatRgb10a2ui: return "rgb10_a2ui";
    case spv::ImageFormatRg32ui: return "rg32ui";
    case spv::ImageFormatRg16ui: return "rg16ui";
    case spv::ImageFormatRg8ui: return "rg8ui";
    case spv::ImageFormatR16ui: return "r16ui";
    case spv::ImageFormatR8ui: return "r8ui";
    case spv::ImageFormatR64ui: return "r64ui";
    case spv::ImageFormatR64i: return "r64i";
    default: return "unknown";
    }
}

// GLSL spelling of an image, sampler or combined type: sampler2D, image2D, utexture3D,
// sampler2DArrayShadow, samplerBuffer, subpassInput, sampler.
inline std::string image_glsl_name(const spirv_cross::Compiler& c, const spirv_cross::SPIRType& t)
{
    using T = spirv_cross::SPIRType;
    if (t.basetype == T::Sampler) return c.get_type(t.self).image.depth ? "samplerShadow" : "sampler";
    std::string prefix;
    const T& sampled = c.get_type(t.image.type);
    if (sampled.basetype == T::Int) prefix = "i";
    if (sampled.basetype == T::UInt) prefix = "u";
    if (t.image.dim == spv::DimSubpassData) return prefix + (t.image.ms ? "subpassInputMS" : "subpassInput");
    std::string base = t.basetype == T::SampledImage ? "sampler" : t.image.sampled == 2 ? "image" : "texture";
    std::string dim;
    switch (t.image.dim) {
    case spv::Dim1D: dim = "1D"; break;
    case spv::Dim2D: dim = "2D"; break;
    case spv::Dim3D: dim = "3D"; break;
    case spv::DimCube: dim = "Cube"; break;
    case spv::DimRect: dim = "2DRect"; break;
    case spv::DimBuffer: dim = "Buffer"; break;
    default: dim = "Unknown"; break;
    }
    if (t.image.ms) dim += "MS";
    if (t.image.arrayed) dim += "Array";
    if (t.image.depth && t.basetype == T::SampledImage) dim += "Shadow";
    return prefix + base + dim;
}

inline std::vector<block_member> reflect_members(const spirv_cross::Compiler& c, const spirv_cross::SPIRType& type)
{
    std::vector<block_member> members;
    for (uint32_t i = 0; i < type.member_types.size(); ++i) {
        const spirv_cross::SPIRType& mt = c.get_type(type.member_types[i]);
        block_member m;
        m.name = c.get_member_name(type.self, i);
        m.type = value_glsl_name(c, mt);
        m.array = array_dims(mt);
        m.offset = c.type_struct_member_offset(type, i);
        m.size = static_cast<uint32_t>(c.get_declared_struct_member_size(type, i));
        if (!mt.array.empty()) m.array_stride = c.type_struct_member_array_stride(type, i);
        if (mt.columns > 1) m.matrix_stride = c.type_struct_member_matrix_stride(type, i);
        m.row_major = c.has_member_decoration(type.self, i, spv::DecorationRowMajor);
        if (mt.basetype == spirv_cross::SPIRType::Struct) m.members = reflect_members(c, c.get_type(mt.self));
        members.push_back(std::move(m));
    }
    return members;
}

inline uint32_t descriptor_count(const spirv_cross::SPIRType& t)
{
    if (t.array.empty()) return 1;
    uint32_t n = 1;
    for (size_t i = 0; i < t.array.size(); ++i) {
        if (!t.array_size_literal[i] || t.array[i] == 0) return 0; // runtime-sized or spec-constant sized
        n *= t.array[i];
    }
    return n;
}

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

// Walks a SPIR-V module: the number of instructions after the 5-word header (each
// instruction's first word holds its word count in its high 16 bits). Throws
// aogen::error for a module that is not well-formed at this level.
inline uint32_t count_instructions(const std::vector<uint32_t>& words, std::string_view name = "SPIR-V")
{
    if (words.size() < 5 || words[0] != 0x07230203u)
        fail(name, "is not a SPIR-V module (" + std::to_string(words.size()) + " words)",
             "valid: the 0x07230203 magic number and a 5-word header");
    uint32_t count = 0;
    for (size_t i = 5; i < words.size();) {
        const uint32_t length = words[i] >> 16;
        if (length == 0 || i + length > words.size())
            fail(name, "instruction at word " + std::to_string(i) + " has word count " + std::to_string(length),
                 "valid: 1.." + std::to_string(words.size() - i));
        ++count;
        i += length;
    }
    return count;
}

// glslang: GLSL (any #version glslang knows, 450 intended) -> SPIR-V 1.0 for Vulkan 1.0.
// `name` labels errors and is the file name of glslang's messages until a
// `#line N "file"` directive changes it.
inline std::vector<uint32_t> glsl_to_spirv(const std::string& glsl, shader_stage stage, const std::string& name)
{
    detail::initialize_glslang();
    const EShLanguage language = detail::glslang_stage(stage);
    glslang::TShader shader(language);
    const char* text = glsl.c_str();
    const int length = static_cast<int>(glsl.size());
    const char* file = name.c_str();
    shader.setStringsWithLengthsAndNames(&text, &length, &file, 1);
    // #line N "file" needs this extension; enabling it for every source costs nothing
    // (it only changes what the preprocessor accepts).
    shader.setPreamble("#extension GL_GOOGLE_cpp_style_line_directive : enable\n");
    shader.setEnvInput(glslang::EShSourceGlsl, language, glslang::EShClientVulkan, 100);
    shader.setEnvClient(glslang::EShClientVulkan, glslang::EShTargetVulkan_1_0);
    shader.setEnvTarget(glslang::EShTargetSpv, glslang::EShTargetSpv_1_0);
    const auto messages = static_cast<EShMessages>(EShMsgSpvRules | EShMsgVulkanRules);
    const std::string stage_name = to_name(stage);
    if (!shader.parse(GetDefaultResources(), 450, false, messages))
        throw error(name + ": glslang rejected the " + stage_name +
                    " shader (valid: GLSL that compiles for Vulkan 1.0); glslang says:" +
                    detail::indent_lines(shader.getInfoLog()) + detail::indent_lines(shader.getInfoDebugLog()));
    glslang::TProgram program;
    program.addShader(&shader);
    if (!program.link(messages))
        throw error(name + ": glslang could not link the " + stage_name +
                    " shader (valid: a complete shader whose entry point is main); glslang says:" +
                    detail::indent_lines(program.getInfoLog()) + detail::indent_lines(program.getInfoDebugLog()));
    std::vector<unsigned int> words;
    spv::SpvBuildLogger logger;
    glslang::SpvOptions spv_options;
    spv_options.generateDebugInfo = false;
    spv_options.disableOptimizer = true; // spirv-opt runs separately, with our options
    spv_options.validate = false;        // spirv-val runs separately, with our messages
    glslang::GlslangToSpv(*program.getIntermediate(language), words, &logger, &spv_options);
    if (words.empty())
        throw error(name + ": glslang produced no SPIR-V for the " + stage_name + " shader; glslang says:" +
                    detail::indent_lines(logger.getAllMessages()));
    return std::vector<uint32_t>(words.begin(), words.end());
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
        case target::glsl:
        case target::essl: {
            spirv_cross::CompilerGLSL glsl(spirv);
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
            if (entry_point) *entry_point = "main";
            return text;
        }
        case target::hlsl50:
        case target::hlsl60: {
            spirv_cross::CompilerHLSL hlsl(spirv);
            spirv_cross::CompilerHLSL::Options o = hlsl.get_hlsl_options();
            o.shader_model = t == target::hlsl50 ? 50 : 60;
            hlsl.set_hlsl_options(o);
            std::string text = hlsl.compile();
            if (t == target::hlsl50) detail::require_distinct_registers(text, name);
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

// Reflection of a SPIR-V module (entry point "main" of `stage`). entry_points holds only
// target::spv; compile() adds the other targets'. MSL indices are left as no_index.
inline reflection reflect(const std::vector<uint32_t>& spirv, shader_stage stage, const std::string& name = "SPIR-V")
{
    reflection refl;
    refl.stage = stage;
    refl.spirv_words = static_cast<uint32_t>(spirv.size());
    refl.spirv_instructions = count_instructions(spirv, name);
    refl.entry_points[target::spv] = "main";
    try {
        spirv_cross::Compiler c(spirv);
        c.set_entry_point("main", detail::execution_model(stage));
        const spirv_cross::ShaderResources r = c.get_shader_resources();

        auto add_binding = [&](const spirv_cross::Resource& res, descriptor_kind kind) {
            descriptor_binding b;
            b.set = c.get_decoration(res.id, spv::DecorationDescriptorSet);
            b.binding = c.get_decoration(res.id, spv::DecorationBinding);
            b.kind = kind;
            b.name = res.name;
            b.instance = c.get_name(res.id);
            const spirv_cross::SPIRType& type = c.get_type(res.type_id);
            const spirv_cross::SPIRType& base = c.get_type(res.base_type_id);
            b.count = detail::descriptor_count(type);
            b.writable = false;
            if (kind == descriptor_kind::uniform_buffer) b.type = "uniform";
            else if (kind == descriptor_kind::storage_buffer) {
                b.type = "buffer";
                const spirv_cross::Bitset flags = c.get_buffer_block_flags(res.id);
                b.readable = !flags.get(spv::DecorationNonReadable);
                b.writable = !flags.get(spv::DecorationNonWritable);
            } else {
                b.type = detail::image_glsl_name(c, base);
            }
            if (kind == descriptor_kind::storage_image || kind == descriptor_kind::storage_texel_buffer) {
                b.image_format = detail::image_format_name(base.image.format);
                b.readable = !c.has_decoration(res.id, spv::DecorationNonReadable);
                b.writable = !c.has_decoration(res.id, spv::DecorationNonWritable);
            }
            refl.bindings.push_back(std::move(b));
        };
        auto add_block = [&](const spirv_cross::Resource& res, block_kind kind) {
            buffer_block block;
            block.kind = kind;
            if (kind != block_kind::push_constant) {
                block.set = c.get_decoration(res.id, spv::DecorationDescriptorSet);
                block.binding = c.get_decoration(res.id, spv::DecorationBinding);
            }
            const spirv_cross::SPIRType& type = c.get_type(res.base_type_id);
            block.name = c.get_name(res.base_type_id);
            block.instance = c.get_name(res.id);
            block.size = static_cast<uint32_t>(c.get_declared_struct_size(type));
            block.members = detail::reflect_members(c, type);
            refl.blocks.push_back(std::move(block));
        };
        for (const auto& res : r.uniform_buffers) add_binding(res, descriptor_kind::uniform_buffer), add_block(res, block_kind::uniform);
        for (const auto& res : r.storage_buffers) add_binding(res, descriptor_kind::storage_buffer), add_block(res, block_kind::storage);
        for (const auto& res : r.push_constant_buffers) add_block(res, block_kind::push_constant);
        for (const auto& res : r.sampled_images)
            add_binding(res, c.get_type(res.base_type_id).image.dim == spv::DimBuffer ? descriptor_kind::uniform_texel_buffer
                                                                                       : descriptor_kind::combined_image_sampler);
        for (const auto& res : r.separate_images)
            add_binding(res, c.get_type(res.base_type_id).image.dim == spv::DimBuffer ? descriptor_kind::uniform_texel_buffer
                                                                                       : descriptor_kind::sampled_image);
        for (const auto& res : r.separate_samplers) add_binding(res, descriptor_kind::sampler);
        for (const auto& res : r.storage_images)
            add_binding(res, c.get_type(res.base_type_id).image.dim == spv::DimBuffer ? descriptor_kind::storage_texel_buffer
                                                                                       : descriptor_kind::storage_image);
        for (const auto& res : r.subpass_inputs) add_binding(res, descriptor_kind::input_attachment);

        auto add_io = [&](const spirv_cross::SmallVector<spirv_cross::Resource>& list, std::vector<stage_variable>& out) {
            for (const auto& res : list) {
                stage_variable v;
                v.location = c.get_decoration(res.id, spv::DecorationLocation);
                v.name = res.name;
                const spirv_cross::SPIRType& type = c.get_type(res.type_id);
                v.type = detail::value_glsl_name(c, type);
                for (uint32_t d : detail::array_dims(type)) v.type += "[" + std::to_string(d) + "]";
                out.push_back(std::move(v));
            }
        };
        add_io(r.stage_inputs, refl.inputs);
        add_io(r.stage_outputs, refl.outputs);

        if (stage == shader_stage::compute)
            for (uint32_t i = 0; i < 3; ++i) refl.workgroup_size[i] = c.get_execution_mode_argument(spv::ExecutionModeLocalSize, i);
    } catch (const spirv_cross::CompilerError& e) {
        throw error(name + ": SPIRV-Cross could not reflect the module; SPIRV-Cross says:" + detail::indent_lines(e.what()));
    }
    const auto by_binding = [](const auto& a, const auto& b) {
        return std::tie(a.set, a.binding, a.name) < std::tie(b.set, b.binding, b.name);
    };
    std::stable_sort(refl.bindings.begin(), refl.bindings.end(), by_binding);
    std::stable_sort(refl.blocks.begin(), refl.blocks.end(), [&](const buffer_block& a, const buffer_block& b) {
        const bool pa = a.kind == block_kind::push_constant, pb = b.kind == block_kind::push_constant;
        if (pa != pb) return pb; // push constants last
        return by_binding(a, b);
    });
    const auto by_location = [](const stage_variable& a, const stage_variable& b) {
        return std::tie(a.location, a.name) < std::tie(b.location, b.name);
    };
    std::stable_sort(refl.inputs.begin(), refl.inputs.end(), by_location);
    std::stable_sort(refl.outputs.begin(), refl.outputs.end(), by_location);
    return refl;
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

// ---------------------------------------------------------------------------------
// Reflected blocks against aogen's layouts
// ---------------------------------------------------------------------------------

// The block whose type name is `name`; nullptr when there is none.
inline const buffer_block* find_block(const reflection& refl, std::string_view name)
{
    for (const buffer_block& b : refl.blocks)
        if (b.name == name) return &b;
    return nullptr;
}

// The binding at (set, binding); nullptr when there is none.
inline const descriptor_binding* find_binding(const reflection& refl, uint32_t set, uint32_t binding_index)
{
    for (const descriptor_binding& b : refl.bindings)
        if (b.set == set && b.binding == binding_index) return &b;
    return nullptr;
}

namespace detail {

// Bytes to the end of the last member, into a trailing struct without its tail padding:
// what SPIRV-Cross's sizes measure.
inline uint32_t unpadded_end(const std::vector<layout::member_layout>& members)
{
    if (members.empty()) return 0;
    const layout::member_layout& last = members.back();
    if (last.is_struct() && !last.is_array()) return last.offset + unpadded_end(last.members);
    return last.offset + last.size;
}

inline void compare_members(const std::vector<block_member>& spirv, const std::vector<layout::member_layout>& ours,
                            const std::string& path, std::vector<std::string>& out)
{
    auto mismatch = [&out](const std::string& member, const std::string& what, const std::string& s, const std::string& l) {
        out.push_back(member + ": " + what + " SPIR-V " + s + ", layout " + l);
    };
    if (spirv.size() != ours.size()) {
        mismatch(path, "member count", std::to_string(spirv.size()), std::to_string(ours.size()));
        return;
    }
    for (size_t i = 0; i < ours.size(); ++i) {
        const block_member& s = spirv[i];
        const layout::member_layout& l = ours[i];
        const std::string member = path + "." + l.name;
        if (s.name != l.name) mismatch(member, "member " + std::to_string(i) + " name", "'" + s.name + "'", "'" + l.name + "'");
        const std::string our_type = l.value ? layout::glsl_name(*l.value) : l.type;
        if (s.type != our_type) mismatch(member, "type", s.type, our_type);
        if (s.offset != l.offset) mismatch(member, "offset", std::to_string(s.offset), std::to_string(l.offset));
        if (s.row_major) out.push_back(member + ": SPIR-V matrix is row-major; layouts are column-major");
        const bool s_array = !s.array.empty();
        if (s_array != l.is_array()) {
            mismatch(member, "array", s_array ? "yes" : "no", l.is_array() ? "yes" : "no");
        } else if (s_array) {
            if (s.array.size() != 1) mismatch(member, "array dimensions", std::to_string(s.array.size()), "1");
            else if (s.array[0] != *l.count) mismatch(member, "array count", std::to_string(s.array[0]), std::to_string(*l.count));
            if (s.array_stride != l.array_stride)
                mismatch(member, "array stride", std::to_string(s.array_stride), std::to_string(l.array_stride));
        }
        if (s.matrix_stride != l.matrix_stride)
            mismatch(member, "matrix stride", std::to_string(s.matrix_stride), std::to_string(l.matrix_stride));
        const uint32_t expected = l.is_struct() && !l.is_array() ? unpadded_end(l.members) : l.size;
        if (s.size != expected) mismatch(member, "size", std::to_string(s.size), std::to_string(expected));
        if (l.is_struct()) compare_members(s.members, l.members, member, out);
    }
}

} // namespace detail

// One line per disagreement between a reflected block and an aogen layout, each naming
// the member path ("SsaoUniforms.radius: offset SPIR-V 16, layout 20"); empty when they
// agree. Compared: names, types, offsets, array counts and strides, matrix strides, sizes
// (a struct member's and the block's up to the end of its last member, as SPIR-V has no
// tail padding; the layout's padded size must be that end rounded up to its alignment).
// Meaningful for the rule sets GLSL blocks compile with: std140, std430, scalar.
inline std::vector<std::string> layout_mismatches(const buffer_block& block, const layout::struct_layout& l)
{
    std::vector<std::string> out;
    if (block.name != l.name) out.push_back(l.name + ": block name SPIR-V '" + block.name + "', layout '" + l.name + "'");
    detail::compare_members(block.members, l.members, l.name, out);
    const uint32_t end = detail::unpadded_end(l.members);
    if (block.size != end) out.push_back(l.name + ": size SPIR-V " + std::to_string(block.size) + ", layout (to its last member's end) " + std::to_string(end));
    const uint32_t rounded = l.align ? (block.size + l.align - 1) / l.align * l.align : block.size;
    if (rounded != l.size)
        out.push_back(l.name + ": size SPIR-V " + std::to_string(block.size) + " rounded up to the layout's alignment " +
                      std::to_string(l.align) + " is " + std::to_string(rounded) + ", layout " + std::to_string(l.size));
    return out;
}

// Throws aogen::error listing every mismatch (joined by "; ") unless the block matches.
inline void check_layout(const buffer_block& block, const layout::struct_layout& l)
{
    const std::vector<std::string> mismatches = layout_mismatches(block, l);
    if (mismatches.empty()) return;
    std::string problem;
    for (const std::string& m : mismatches) problem += (problem.empty() ? "" : "; ") + m;
    fail("block " + block.name + " (" + layout::to_name(l.rule) + ")", "the SPIR-V does not match the layout: " + problem,
         "valid: the offsets and strides aogen::layout::compute gives");
}

} // namespace aogen::compile
