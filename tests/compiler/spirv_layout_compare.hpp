// tests/compiler/spirv_layout_compare.hpp — test helper: compares an aogen layout with
// the Offset / ArrayStride / MatrixStride decorations of a SPIR-V block, as SPIRV-Cross
// reflects them, and validates modules with spirv-val's library.
#pragma once

#include <aogen/layout.hpp>

#include <spirv-tools/libspirv.hpp>
#include <spirv_cross/spirv_cross.hpp>

#include <cstdint>
#include <string>
#include <vector>

namespace aogen_test {

// spirv-val with the block layout the module claims (scalar needs its own switch).
inline std::string validate_spirv(const std::vector<uint32_t>& words, bool scalar_layout)
{
    spvtools::SpirvTools tools(SPV_ENV_VULKAN_1_0);
    std::string messages;
    tools.SetMessageConsumer([&](spv_message_level_t, const char*, const spv_position_t& p, const char* m) {
        messages += "word " + std::to_string(p.index) + ": " + m + "\n";
    });
    spvtools::ValidatorOptions options;
    options.SetScalarBlockLayout(scalar_layout);
    if (tools.Validate(words.data(), words.size(), options)) return {};
    return messages.empty() ? std::string("invalid") : messages;
}

// Bytes up to the end of the last member, recursing into a trailing struct without its
// tail padding: what SPIRV-Cross's get_declared_struct_size reports (it has no notion of
// a struct's alignment, so it cannot round up).
inline uint32_t unpadded_end(const std::vector<aogen::layout::member_layout>& members)
{
    if (members.empty()) return 0;
    const aogen::layout::member_layout& last = members.back();
    if (last.is_struct() && !last.is_array()) return last.offset + unpadded_end(last.members);
    return last.offset + last.size;
}

// The block's struct type among the module's uniform or storage buffers, by type name.
inline const spirv_cross::SPIRType* find_block_type(const spirv_cross::Compiler& c, const std::string& name)
{
    const spirv_cross::ShaderResources resources = c.get_shader_resources();
    for (const auto* list : {&resources.uniform_buffers, &resources.storage_buffers})
        for (const spirv_cross::Resource& res : *list)
            if (c.get_name(res.base_type_id) == name) return &c.get_type(res.base_type_id);
    return nullptr;
}

// Appends one line per disagreement between `ours` and the SPIR-V struct `type`, each
// naming the member path. `hlsl` arrays end unpadded in aogen but SPIRV-Cross's member
// size is stride × count; no HLSL test uses arrays, so it is simply not compared there.
inline void compare_members(const spirv_cross::Compiler& c, const spirv_cross::SPIRType& type,
                            const std::vector<aogen::layout::member_layout>& ours, const std::string& path,
                            std::vector<std::string>& errors)
{
    auto mismatch = [&](const std::string& member, const std::string& what, uint64_t spirv, uint64_t aogen) {
        errors.push_back(member + ": " + what + " SPIR-V " + std::to_string(spirv) + ", aogen " + std::to_string(aogen));
    };
    if (type.member_types.size() != ours.size()) {
        mismatch(path, "member count", type.member_types.size(), ours.size());
        return;
    }
    for (uint32_t i = 0; i < ours.size(); ++i) {
        const aogen::layout::member_layout& m = ours[i];
        const std::string member = path + "." + m.name;
        const std::string spirv_name = c.get_member_name(type.self, i);
        if (spirv_name != m.name) errors.push_back(member + ": SPIR-V member " + std::to_string(i) + " is '" + spirv_name + "'");
        const spirv_cross::SPIRType& mt = c.get_type(type.member_types[i]);

        const uint32_t offset = c.type_struct_member_offset(type, i);
        if (offset != m.offset) mismatch(member, "offset", offset, m.offset);

        if (mt.array.empty() == m.is_array()) {
            errors.push_back(member + ": SPIR-V says " + (mt.array.empty() ? "not an array" : "an array"));
            continue;
        }
        if (m.is_array()) {
            if (mt.array.size() != 1 || !mt.array_size_literal.back()) {
                errors.push_back(member + ": SPIR-V array is not one literal dimension");
                continue;
            }
            if (mt.array.back() != *m.count) mismatch(member, "array count", mt.array.back(), *m.count);
            const uint32_t stride = c.type_struct_member_array_stride(type, i);
            if (stride != m.array_stride) mismatch(member, "array stride", stride, m.array_stride);
        }
        if (mt.columns > 1) {
            const uint32_t stride = c.type_struct_member_matrix_stride(type, i);
            if (stride != m.matrix_stride) mismatch(member, "matrix stride", stride, m.matrix_stride);
        }
        // Member size. SPIRV-Cross: arrays stride × count (0 for a runtime array), structs
        // their unpadded end, matrices stride × columns, vectors components × 4.
        const size_t size = c.get_declared_struct_member_size(type, i);
        const uint32_t expected = m.is_struct() && !m.is_array() ? unpadded_end(m.members) : m.size;
        if (size != expected) mismatch(member, "member size", size, expected);

        if (m.is_struct()) {
            if (mt.basetype != spirv_cross::SPIRType::Struct) {
                errors.push_back(member + ": SPIR-V member is not a struct");
                continue;
            }
            compare_members(c, c.get_type(mt.self), m.members, member, errors);
        }
    }
}

// The whole block: members recursively, then its size. SPIRV-Cross's struct size ends
// at the last member (no tail padding); aogen's size is that rounded up to the block's
// alignment, so the comparable facts are: SPIRV-Cross's size == aogen's unpadded end,
// and aogen's size == round_up(SPIRV-Cross's size, aogen's alignment).
inline std::vector<std::string> compare_block(const spirv_cross::Compiler& c, const spirv_cross::SPIRType& type,
                                              const aogen::layout::struct_layout& l)
{
    std::vector<std::string> errors;
    compare_members(c, type, l.members, l.name, errors);
    const size_t size = c.get_declared_struct_size(type);
    if (size != unpadded_end(l.members))
        errors.push_back(l.name + ": struct size SPIR-V " + std::to_string(size) + ", aogen unpadded end " +
                         std::to_string(unpadded_end(l.members)));
    const size_t rounded = (size + l.align - 1) / l.align * l.align;
    if (rounded != l.size)
        errors.push_back(l.name + ": struct size SPIR-V " + std::to_string(size) + " rounded to aogen's alignment " +
                         std::to_string(l.align) + " is " + std::to_string(rounded) + ", aogen size " + std::to_string(l.size));
    if (!l.members.empty() && l.members.back().is_runtime_array()) {
        const size_t stride = c.get_declared_struct_size_runtime_array(type, 1) - c.get_declared_struct_size_runtime_array(type, 0);
        if (stride != l.members.back().array_stride)
            errors.push_back(l.name + "." + l.members.back().name + ": runtime array element size SPIR-V " +
                             std::to_string(stride) + ", aogen stride " + std::to_string(l.members.back().array_stride));
    }
    return errors;
}

// A GLSL expression reading one scalar of the block through its first member, so that
// glslang keeps the block (and with it every member: a used block is emitted whole).
inline std::string first_scalar_access(const std::vector<aogen::layout::member_layout>& members, std::string prefix)
{
    const aogen::layout::member_layout& m = members.front();
    prefix += "." + m.name;
    if (m.is_array()) prefix += "[0]";
    if (m.is_struct()) return first_scalar_access(m.members, prefix);
    if (m.value->is_matrix()) return prefix + "[0][0]";
    if (m.value->is_vector()) return prefix + ".x";
    return prefix;
}

// A `#version 450` compute shader around a GLSL block declaration (from
// aogen::layout::declare with instance `instance`) that reads the block.
inline std::string glsl_shader_using(const std::string& declaration, const aogen::layout::struct_layout& l,
                                     const std::string& instance)
{
    return "#version 450\n" + declaration +
           "layout(local_size_x = 1) in;\n"
           "layout(std430, set = 1, binding = 0) buffer AogenTestOut { float value; } aogen_test_out;\n"
           "void main() { aogen_test_out.value = float(" + first_scalar_access(l.members, instance) + "); }\n";
}

inline std::string join_lines(const std::vector<std::string>& lines)
{
    std::string out;
    for (const std::string& l : lines) out += "  " + l + "\n";
    return out;
}

} // namespace aogen_test
