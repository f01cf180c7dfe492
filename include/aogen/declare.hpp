// aogen/declare.hpp — the declaration of a laid-out struct in each language.
//
// layout.hpp says where every member lives; this header writes the declaration that
// puts it there, so host bytes and shader agree by construction:
//
//     struct_layout l = compute(block, rules::std140);
//     std::string glsl = declare(l, language::glsl, {/*set*/ 0, /*binding*/ 1});
//     std::string cpp  = declare(l, language::cpp);
//
//   glsl  a `layout(std140|std430|scalar) uniform/buffer` block (std140 → uniform block,
//         std430 and scalar → readonly buffer block; scalar adds its #extension)
//   hlsl  a `cbuffer` (hlsl-cbuffer rules); matrices are `column_major`, one register
//         per GLSL column
//   msl   a Metal struct (msl rules), packed_float3 where the layout packed a vec3
//   wgsl  a WGSL struct and its var<uniform> or var<storage, read> (wgsl-* rules), with
//         @align/@size where the layout needs more than WGSL's natural placement
//   cpp   a C++ struct for any rule set: explicit padding members, std::array for
//         vectors and matrix columns, and a static_assert on every offset and the size
//
// Every member line carries its offset as a comment. Struct types are declared before
// the block, dependencies first, each once. A language that cannot express the rule
// set (GLSL for hlsl-cbuffer, say) is an aogen::error naming both.
#pragma once

#include "error.hpp"
#include "layout.hpp"
#include "names.hpp"

#include <array>
#include <cctype>
#include <functional>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace aogen::layout {

enum class language { glsl, hlsl, msl, wgsl, cpp };

// The languages' names, as the command line spells them (see names.hpp).
inline constexpr std::array<enum_name<language>, 5> language_table{{
    {language::glsl, "glsl"},
    {language::hlsl, "hlsl"},
    {language::msl, "msl"},
    {language::wgsl, "wgsl"},
    {language::cpp, "cpp"},
}};
static_assert(names::distinct(language_table));

// Every language, in table order.
inline constexpr std::array<language, language_table.size()> all_languages = names::values(language_table);

// Language -> name; a value outside the enumeration throws aogen::error.
inline const char* to_name(language l) { return names::name_of(language_table, l, "language"); }

// Name -> language; an unknown name throws aogen::error listing the valid names.
inline language language_from_name(std::string_view name) { return names::value_of(language_table, name, "language"); }

struct declaration_options {
    uint32_t set = 0;      // descriptor set (GLSL), bind group (WGSL), register space (HLSL)
    uint32_t binding = 0;  // binding (GLSL, WGSL), register b# (HLSL)
    std::string instance;  // GLSL block instance / WGSL variable; empty: the block name with a lower-case first letter
    bool cpp_prelude = true; // C++: include the helper templates (leave out when emitting several into one header)
};

namespace detail {

// One line of a struct body: the declaration and its offset comment.
struct line {
    std::string text;
    uint32_t offset;
    std::string note;
};

inline std::string format_lines(const std::vector<line>& lines, const std::string& indent = "    ")
{
    size_t width = 0;
    for (const line& l : lines) width = std::max(width, l.text.size());
    std::string out;
    for (const line& l : lines) {
        out += indent + l.text + std::string(width - l.text.size() + 2, ' ') + "// offset " + std::to_string(l.offset);
        if (!l.note.empty()) out += ", " + l.note;
        out += "\n";
    }
    return out;
}

inline std::string array_note(const member_layout& m)
{
    std::string note;
    if (m.is_array()) note = "stride " + std::to_string(m.array_stride);
    if (m.matrix_stride) note += (note.empty() ? "" : ", ") + std::string("matrix stride ") + std::to_string(m.matrix_stride);
    return note;
}

// Calls `visit` on every struct type a layout uses, dependencies first, each name once.
inline void for_each_struct(const std::vector<member_layout>& members, std::set<std::string>& seen,
                            const std::function<void(const member_layout&)>& visit)
{
    for (const member_layout& m : members) {
        if (!m.is_struct()) continue;
        for_each_struct(m.members, seen, visit);
        if (seen.insert(m.type).second) visit(m);
    }
}

inline std::string instance_name(const struct_layout& l, const declaration_options& options)
{
    if (!options.instance.empty()) return options.instance;
    std::string name = l.name;
    name[0] = static_cast<char>(std::tolower(static_cast<unsigned char>(name[0])));
    return name == l.name ? name + "_" : name;
}

inline std::string header_comment(const struct_layout& l)
{
    return "// " + l.name + ": " + to_name(l.rule) + " layout, " + std::to_string(l.size) + " bytes, aligned to " +
           std::to_string(l.align) + "\n";
}

inline void require_rules(const struct_layout& l, language lang, std::initializer_list<rules> accepted)
{
    for (rules r : accepted)
        if (l.rule == r) return;
    std::string valid;
    for (rules r : accepted) valid += (valid.empty() ? "" : ", ") + std::string(to_name(r));
    fail(std::string(to_name(lang)) + " declaration of " + l.name,
         std::string("cannot express ") + to_name(l.rule) + " rules", "valid rules: " + valid);
}

// ----- GLSL ---------------------------------------------------------------------

inline std::string glsl_member(const member_layout& m)
{
    std::string text = m.type + " " + m.name;
    if (m.is_array()) text += m.is_runtime_array() ? "[]" : "[" + std::to_string(*m.count) + "]";
    return text + ";";
}

inline std::string glsl_body(const std::vector<member_layout>& members)
{
    std::vector<line> lines;
    for (const member_layout& m : members) lines.push_back({glsl_member(m), m.offset, array_note(m)});
    return format_lines(lines);
}

inline std::string declare_glsl(const struct_layout& l, const declaration_options& o)
{
    require_rules(l, language::glsl, {rules::std140, rules::std430, rules::scalar});
    std::string out = header_comment(l);
    if (l.rule == rules::scalar) out += "#extension GL_EXT_scalar_block_layout : require\n";
    std::set<std::string> seen;
    for_each_struct(l.members, seen, [&](const member_layout& s) {
        out += "struct " + s.type + " {\n" + glsl_body(s.members) + "};\n";
    });
    const char* storage = l.rule == rules::std140 ? "uniform" : "readonly buffer";
    out += "layout(" + std::string(to_name(l.rule)) + ", set = " + std::to_string(o.set) + ", binding = " +
           std::to_string(o.binding) + ") " + storage + " " + l.name + " {\n" + glsl_body(l.members) + "} " +
           instance_name(l, o) + ";\n";
    return out;
}

// ----- HLSL ---------------------------------------------------------------------

inline std::string hlsl_type(const member_layout& m)
{
    if (m.is_struct()) return m.type;
    const value_type t = *m.value;
    const std::string scalar = scalar_name(t.scalar);
    if (t.is_scalar()) return scalar;
    if (t.is_vector()) return scalar + std::to_string(t.rows);
    // HLSL counts rows first; column_major keeps each GLSL column in one register.
    return "column_major " + scalar + std::to_string(t.rows) + "x" + std::to_string(t.columns);
}

inline std::string hlsl_body(const std::vector<member_layout>& members)
{
    std::vector<line> lines;
    for (const member_layout& m : members) {
        std::string text = hlsl_type(m) + " " + m.name;
        if (m.is_array()) text += "[" + std::to_string(*m.count) + "]";
        lines.push_back({text + ";", m.offset, array_note(m)});
    }
    return format_lines(lines);
}

inline std::string declare_hlsl(const struct_layout& l, const declaration_options& o)
{
    require_rules(l, language::hlsl, {rules::hlsl_cbuffer});
    std::string out = header_comment(l);
    std::set<std::string> seen;
    for_each_struct(l.members, seen, [&](const member_layout& s) {
        out += "struct " + s.type + " {\n" + hlsl_body(s.members) + "};\n";
    });
    out += "cbuffer " + l.name + " : register(b" + std::to_string(o.binding) + ", space" + std::to_string(o.set) +
           ") {\n" + hlsl_body(l.members) + "};\n";
    return out;
}

// ----- MSL ----------------------------------------------------------------------

inline std::string msl_type(const member_layout& m)
{
    if (m.is_struct()) return m.type;
    const value_type t = *m.value;
    const std::string scalar = scalar_name(t.scalar);
    if (t.is_scalar()) return scalar;
    if (t.is_vector()) return (m.packed ? "packed_" : "") + scalar + std::to_string(t.rows);
    return scalar + std::to_string(t.columns) + "x" + std::to_string(t.rows); // Metal: columns x rows
}

inline std::string msl_body(const std::vector<member_layout>& members)
{
    std::vector<line> lines;
    for (const member_layout& m : members) {
        std::string text = msl_type(m) + " " + m.name;
        // Metal has no flexible array member; [1] is the usual spelling, indexed past its end.
        if (m.is_array()) text += "[" + std::to_string(m.is_runtime_array() ? 1u : *m.count) + "]";
        lines.push_back({text + ";", m.offset, m.is_runtime_array() ? "runtime-sized" : array_note(m)});
    }
    return format_lines(lines);
}

inline std::string declare_msl(const struct_layout& l, const declaration_options&)
{
    require_rules(l, language::msl, {rules::msl});
    std::string out = header_comment(l);
    std::set<std::string> seen;
    for_each_struct(l.members, seen, [&](const member_layout& s) {
        out += "struct " + s.type + "\n{\n" + msl_body(s.members) + "};\n";
    });
    out += "struct " + l.name + "\n{\n" + msl_body(l.members) + "};\n";
    return out;
}

// ----- WGSL ---------------------------------------------------------------------

inline std::string wgsl_value_type(value_type t)
{
    const char* scalar = t.scalar == scalar_type::float32 ? "f32" : t.scalar == scalar_type::int32 ? "i32" : "u32";
    if (t.is_scalar()) return scalar;
    if (t.is_vector()) return "vec" + std::to_string(t.rows) + "<" + scalar + ">";
    return "mat" + std::to_string(t.columns) + "x" + std::to_string(t.rows) + "<" + scalar + ">";
}

// The alignment WGSL gives a member without attributes: a struct aligns to its widest
// member (whose own attributes count), a value to its vector alignment.
inline uint32_t wgsl_natural_align(const member_layout& m)
{
    if (!m.is_struct()) return vector_alignment(m.value->rows);
    uint32_t widest = 4;
    for (const member_layout& sub : m.members) widest = std::max(widest, sub.align);
    return widest;
}

inline std::string wgsl_body(const std::vector<member_layout>& members)
{
    std::vector<line> lines;
    for (const member_layout& m : members) {
        std::string text;
        if (m.align != wgsl_natural_align(m)) text += "@align(" + std::to_string(m.align) + ") ";
        if (!m.is_array() && m.size != m.element_size) text += "@size(" + std::to_string(m.size) + ") ";
        const std::string element = m.is_struct() ? m.type : wgsl_value_type(*m.value);
        std::string type = element;
        if (m.is_array()) type = "array<" + element + (m.is_runtime_array() ? "" : ", " + std::to_string(*m.count)) + ">";
        lines.push_back({text + m.name + ": " + type + ",", m.offset, array_note(m)});
    }
    return format_lines(lines);
}

inline std::string declare_wgsl(const struct_layout& l, const declaration_options& o)
{
    require_rules(l, language::wgsl, {rules::wgsl_uniform, rules::wgsl_storage});
    std::string out = header_comment(l);
    std::set<std::string> seen;
    for_each_struct(l.members, seen, [&](const member_layout& s) {
        out += "struct " + s.type + " {\n" + wgsl_body(s.members) + "}\n";
    });
    out += "struct " + l.name + " {\n" + wgsl_body(l.members) + "}\n";
    const char* space = l.rule == rules::wgsl_uniform ? "uniform" : "storage, read";
    out += "@group(" + std::to_string(o.set) + ") @binding(" + std::to_string(o.binding) + ") var<" + space + "> " +
           instance_name(l, o) + ": " + l.name + ";\n";
    return out;
}

// ----- C++ ----------------------------------------------------------------------

// A C++ type expression and its size in bytes.
struct cpp_type {
    std::string text;
    uint32_t size;
};

// `count` elements of `element` every `stride` bytes, `total` bytes in all (HLSL leaves
// the last element unpadded, so total can be less than count × stride).
inline cpp_type cpp_array(const cpp_type& element, uint32_t count, uint32_t stride, uint32_t total)
{
    const std::string n = std::to_string(count), s = std::to_string(stride);
    if (stride == element.size) return {"std::array<" + element.text + ", " + n + ">", total};
    if (total == count * stride) return {"std::array<aogen_padded<" + element.text + ", " + s + ">, " + n + ">", total};
    if (count == 1) return {"std::array<" + element.text + ", 1>", total};
    return {"aogen_padded_array<" + element.text + ", " + s + ", " + n + ">", total};
}

inline cpp_type cpp_value(const member_layout& m)
{
    const value_type t = *m.value;
    const cpp_type scalar{t.scalar == scalar_type::float32 ? "float" : t.scalar == scalar_type::int32 ? "std::int32_t" : "std::uint32_t", 4};
    if (t.is_scalar()) return scalar;
    const cpp_type column{"std::array<" + scalar.text + ", " + std::to_string(t.rows) + ">", 4u * t.rows};
    if (t.is_vector()) return column;
    // element_size is the matrix's own size; its columns are matrix_stride apart.
    return cpp_array(column, t.columns, m.matrix_stride, m.element_size);
}

// One element of the member: a value, a matrix or a struct, padded to element_size
// when the layout makes it larger than its C++ type (a Metal float3 is 16 bytes).
inline cpp_type cpp_element(const member_layout& m)
{
    cpp_type e = m.is_struct() ? cpp_type{m.type, m.element_size} : cpp_value(m);
    if (e.size < m.element_size) e = {"aogen_padded<" + e.text + ", " + std::to_string(m.element_size) + ">", m.element_size};
    return e;
}

inline std::string cpp_struct(const std::string& name, const std::vector<member_layout>& members, uint32_t size)
{
    std::vector<line> lines;
    std::vector<std::string> asserts;
    std::string runtime_note;
    uint32_t cursor = 0;
    int pads = 0;
    auto pad_to = [&](uint32_t offset) {
        if (offset > cursor)
            lines.push_back({"std::uint8_t _pad" + std::to_string(pads++) + "[" + std::to_string(offset - cursor) + "];", cursor, "padding"});
        cursor = offset;
    };
    for (const member_layout& m : members) {
        if (m.is_runtime_array()) {
            runtime_note = "// " + m.name + ": runtime-sized array at offset " + std::to_string(m.offset) +
                           ", stride " + std::to_string(m.array_stride) + ", follows the struct\n";
            continue;
        }
        pad_to(m.offset);
        const cpp_type element = cpp_element(m);
        const cpp_type type = m.is_array() ? cpp_array(element, *m.count, m.array_stride, m.size) : element;
        lines.push_back({type.text + " " + m.name + ";", m.offset, array_note(m)});
        asserts.push_back("static_assert(offsetof(" + name + ", " + m.name + ") == " + std::to_string(m.offset) + ");\n");
        cursor = m.offset + type.size;
    }
    pad_to(size);
    std::string out = "struct " + name + " {\n" + format_lines(lines) + "};\n" + runtime_note;
    for (const std::string& a : asserts) out += a;
    out += "static_assert(sizeof(" + name + ") == " + std::to_string(size) + ");\n";
    return out;
}

// Helpers every generated C++ declaration relies on, defined once per translation unit.
inline const char* cpp_prelude()
{
    return "#include <array>\n"
           "#include <cstddef>\n"
           "#include <cstdint>\n"
           "#ifndef AOGEN_PADDED_DEFINED\n"
           "#define AOGEN_PADDED_DEFINED\n"
           "// One element of a GPU array whose stride is larger than the element.\n"
           "template <class T, std::size_t Stride> struct aogen_padded {\n"
           "    T value;\n"
           "    std::uint8_t padding[Stride - sizeof(T)];\n"
           "};\n"
           "// N elements Stride bytes apart, the last one unpadded (HLSL cbuffer arrays).\n"
           "template <class T, std::size_t Stride, std::size_t N> struct aogen_padded_array {\n"
           "    std::array<aogen_padded<T, Stride>, N - 1> head;\n"
           "    T last;\n"
           "};\n"
           "#endif\n";
}

inline std::string declare_cpp(const struct_layout& l, const declaration_options& o)
{
    std::string out = header_comment(l) + (o.cpp_prelude ? cpp_prelude() : "");
    std::set<std::string> seen;
    for_each_struct(l.members, seen, [&](const member_layout& s) { out += cpp_struct(s.type, s.members, s.element_size); });
    out += cpp_struct(l.name, l.members, l.size);
    return out;
}

} // namespace detail

// The declaration of `l` in `lang`. Throws aogen::error when `lang` cannot express l's rules.
inline std::string declare(const struct_layout& l, language lang, const declaration_options& options = {})
{
    switch (lang) {
    case language::glsl: return detail::declare_glsl(l, options);
    case language::hlsl: return detail::declare_hlsl(l, options);
    case language::msl: return detail::declare_msl(l, options);
    case language::wgsl: return detail::declare_wgsl(l, options);
    case language::cpp: return detail::declare_cpp(l, options);
    }
    names::fail_unlisted(language_table, lang, "declaration language");
}

} // namespace aogen::layout
