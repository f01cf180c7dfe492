// aogen/reflect.hpp — what a SPIR-V module declares, and its blocks against aogen's layouts.
//
// WHAT
//   Reflection of a SPIR-V module through SPIRV-Cross, as plain values (`reflection`):
//
//     bindings          every descriptor: set, binding, kind (after VkDescriptorType), GLSL
//                       type, array count, storage image format, readable / writable
//     blocks            uniform, storage and push-constant blocks, each member with the
//                       SPIR-V's offset, size, array and matrix stride
//     inputs, outputs   user-defined stage variables, by location (built-ins are not listed)
//     workgroup_size    a compute shader's LocalSize
//     entry_points      each compiled target's entry point, as its text spells it
//     spirv_words, ...  SPIR-V size figures: words and instructions, before and after spirv-opt
//
//   and the check of a reflected block against an aogen layout (layout.hpp): names, types,
//   offsets, array counts and strides, matrix strides and sizes, member by member.
//
//   reflect() alone gives entry_points for target::spv only, MSL indices no_index and the
//   unoptimized figures 0. compile() (compile.hpp) reflects the SPIR-V it produced and
//   fills those in: every compiled target's entry point, glslang's module size, and the
//   MSL argument indices SPIRV-Cross assigned (`descriptor_binding::msl_buffer` etc.,
//   `buffer_block::msl_buffer`). The namespace is compile.hpp's, aogen::compile; the stage and
//   target enums (entry_points is keyed by target) are stages.hpp's and targets.hpp's.
//
// USAGE
//     #include <aogen/reflect.hpp>      // CMake: target_link_libraries(... aogen::compiler)
//     namespace cc = aogen::compile;    // compile.hpp includes this header
//
//     cc::reflection refl = cc::reflect(spirv, cc::shader_stage::compute, "ssao-s16-...-cs ao");
//     // or cc::compile(...).refl, with every target's entry point and the MSL indices
//     refl.workgroup_size;                         // {8, 8, 1}
//     const cc::descriptor_binding* d = cc::find_binding(refl, 0, 1);   // set 0, binding 1
//     const cc::buffer_block* b = cc::find_block(refl, "SsaoUniforms");
//     cc::check_layout(*b, aogen::layout::compute(desc, aogen::layout::rules::std140));
//
//     reflect(words, stage, name)             reflection (entry_points: spv only)
//     count_instructions(words)               instructions after the 5-word header
//     find_block(refl, name) / find_binding(refl, set, binding)       nullptr when absent
//     layout_mismatches(block, layout) / check_layout(block, layout)   SPIR-V vs layout.hpp
//
//   Orders: bindings by set, then binding; blocks the same, push constants last; stage
//   inputs and outputs by location. The same module gives the same reflection.
//
//   Errors are aogen::error. reflect() and count_instructions() name the caller's `name`:
//   a module that is not SPIR-V at the word level, or one SPIRV-Cross cannot reflect (with
//   SPIRV-Cross's message). check_layout() names the block and the rule set, and every
//   mismatch by member path:
//     block SsaoUniforms (std140): the SPIR-V does not match the layout: SsaoUniforms.radius: offset SPIR-V 16, layout 20 (valid: the offsets and strides aogen::layout::compute gives)
//
// THREADS
//   No shared state: every function may run on several threads at once.
//
// WHY
//   The reflection comes from the SPIR-V that every text was generated from, after
//   optimization — so a binding or a block member that the optimizer would have dropped
//   cannot appear in one target and not in another.
#pragma once

#include "error.hpp"
#include "layout.hpp"
#include "names.hpp"
#include "targets.hpp"

#include <spirv_cross/spirv_cross.hpp>

#include <algorithm>
#include <array>
#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <tuple>
#include <vector>

namespace aogen::compile {

// ---------------------------------------------------------------------------------
// Stages and targets
// ---------------------------------------------------------------------------------

// shader_stage and target are stages.hpp's.

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

// ---------------------------------------------------------------------------------
// Implementation details
// ---------------------------------------------------------------------------------

namespace detail {

// execution_model, indent_lines and image_format_name serve compile.hpp too.

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

} // namespace detail

// ---------------------------------------------------------------------------------
// Reflecting a module
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
// Reflected blocks against aogen's layouts
// ---------------------------------------------------------------------------------

// The block whose type name is `name`; nullptr when there is none.
inline const buffer_block* find_block(const reflection& refl, std::string_view name)
{
    for (const buffer_block& b : refl.blocks)
        if (b.name == name) return &b;
    return nullptr;
}

// The block of struct type `name` as a block of its own: the block itself, or the block that
// wraps such a struct as its only member (naga's SPIR-V wraps every WGSL uniform struct so).
inline std::optional<buffer_block> find_struct_block(const reflection& refl, std::string_view name)
{
    if (const buffer_block* b = find_block(refl, name)) return *b;
    for (const buffer_block& b : refl.blocks)
        if (b.members.size() == 1 && b.members[0].type == name && b.members[0].array.empty() && b.members[0].offset == 0) {
            buffer_block inner = b;
            inner.name = b.members[0].type;
            inner.size = b.members[0].size;
            inner.members = b.members[0].members;
            return inner;
        }
    return std::nullopt;
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
