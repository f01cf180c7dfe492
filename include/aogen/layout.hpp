// aogen/layout.hpp — where every member of a GPU buffer lives, under each rule set.
//
// A shader reads a uniform or storage buffer through a struct declaration; the host
// must write the bytes exactly where that declaration puts each member. Each shading
// language has its own rules for this, and they disagree (a vec3 followed by a float
// is 16 bytes in std140 but 12 + 4 in HLSL; a float[4] is 64 bytes in std140 and 16 in
// std430). This header computes, from one description of a struct, the offset, size,
// alignment, array stride and matrix stride of every member under:
//
//   std140        GLSL uniform blocks (Vulkan, OpenGL)
//   std430        GLSL storage blocks
//   scalar        VK_EXT_scalar_block_layout: everything aligned to its scalar
//   wgsl-storage  WGSL's host-shareable layout (storage address space)
//   wgsl-uniform  WGSL's layout plus the portable uniform-address-space constraints
//   hlsl-cbuffer  HLSL constant buffers as DXC and FXC pack them (16-byte registers)
//   msl           Metal structs as SPIRV-Cross emits them (packed_float3 before a scalar)
//
// Usage:
//
//     using namespace aogen::layout;
//     block_desc block{{"Params", {{"radius", "float"},
//                                  {"kernel", "vec4", 16},
//                                  {"light", "Light"}}},
//                      {{"Light", {{"color", "vec3"}, {"intensity", "float"}}}}};
//     struct_layout l = compute(block, rules::std140);
//     l.size;                      // 288
//     find(l, "light.intensity");  // member_layout*, offset relative to its struct
//
// Types use GLSL spellings: float int uint, vecN ivecN uvecN (N = 2..4), matC and matCxR
// (C columns of R rows, float only), or the name of a struct in `block.structs`. A member
// with `count` is an array; count 0 is a runtime-sized array, allowed only as the last
// member of the top-level struct under std430, scalar, wgsl-storage and msl.
//
// Declarations that reproduce a layout are in declare.hpp; filling a buffer through a
// layout by member path is in layout_writer.hpp. Anything a rule set cannot express is
// an aogen::error naming the member and the rule.
//
// Sources for the rules: the GLSL 4.60 and Vulkan specifications (std140, std430, the
// scalar block layout), the WGSL specification's "Memory Layout" section, LLVM's HLSL
// proposal 0034 (cbuffer packing, with worked examples), the Metal Shading Language
// specification's size/alignment table and SPIRV-Cross's MSL struct packing.
#pragma once

#include "error.hpp"
#include "names.hpp"

#include <algorithm>
#include <atomic>
#include <array>
#include <cctype>
#include <cstdint>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <string_view>
#include <vector>

namespace aogen::layout {

// ---------------------------------------------------------------------------------
// Rule sets
// ---------------------------------------------------------------------------------

enum class rules { std140, std430, scalar, wgsl_storage, wgsl_uniform, hlsl_cbuffer, msl };

// The rule sets' names, as the command line and JSON spell them (see names.hpp; the
// readers also take '_' for '-': "wgsl_storage").
inline constexpr std::array<enum_name<rules>, 7> rules_table{{
    {rules::std140, "std140"},
    {rules::std430, "std430"},
    {rules::scalar, "scalar"},
    {rules::wgsl_storage, "wgsl-storage"},
    {rules::wgsl_uniform, "wgsl-uniform"},
    {rules::hlsl_cbuffer, "hlsl-cbuffer"},
    {rules::msl, "msl"},
}};
static_assert(names::distinct(rules_table));

// Every rule set, in table order.
inline constexpr std::array<rules, rules_table.size()> all_rules = names::values(rules_table);

// Rule set -> name; a value outside the enumeration throws aogen::error.
inline const char* to_name(rules r) { return names::name_of(rules_table, r, "layout rules"); }

// "std140, std430, scalar, wgsl-storage, wgsl-uniform, hlsl-cbuffer, msl".
inline std::string rules_names() { return names::list(rules_table); }

// Name -> rule set; an unknown name throws aogen::error listing the valid names.
inline rules rules_from_name(std::string_view name) { return names::value_of(rules_table, name, "layout rules"); }

// Uniform blocks cannot hold a runtime-sized array; storage blocks can.
inline bool allows_runtime_array(rules r)
{
    return r == rules::std430 || r == rules::scalar || r == rules::wgsl_storage || r == rules::msl;
}

// ---------------------------------------------------------------------------------
// Description: what the user declares
// ---------------------------------------------------------------------------------

struct member_desc {
    std::string name;
    std::string type;              // GLSL spelling, or a struct name
    std::optional<uint32_t> count = {}; // absent: not an array; 0: runtime-sized
};

struct struct_desc {
    std::string name;
    std::vector<member_desc> members;
};

struct block_desc {
    struct_desc root;                // the block itself
    std::vector<struct_desc> structs; // struct types its members may name
};

// The largest array count accepted, and the largest block (1 GiB): every size and
// offset then fits in 32 bits with room to spare, and no real buffer is larger.
inline constexpr uint32_t max_array_count = 1u << 20;
inline constexpr uint32_t max_block_bytes = 1u << 30;

// ---------------------------------------------------------------------------------
// Value types: scalars, vectors and matrices
// ---------------------------------------------------------------------------------

enum class scalar_type { float32, int32, uint32 };

// A scalar is 1 column of 1 row, a vecN is 1 column of N rows, a matCxR C columns of R.
struct value_type {
    scalar_type scalar = scalar_type::float32;
    int columns = 1;
    int rows = 1;

    bool is_scalar() const { return columns == 1 && rows == 1; }
    bool is_vector() const { return columns == 1 && rows > 1; }
    bool is_matrix() const { return columns > 1; }
    int components() const { return columns * rows; }
};

inline bool operator==(value_type a, value_type b)
{
    return a.scalar == b.scalar && a.columns == b.columns && a.rows == b.rows;
}

inline const char* scalar_name(scalar_type s)
{
    switch (s) {
    case scalar_type::float32: return "float";
    case scalar_type::int32: return "int";
    case scalar_type::uint32: return "uint";
    }
    return "?";
}

// The GLSL spelling of a value type: float, ivec3, mat4, mat2x3.
inline std::string glsl_name(value_type t)
{
    if (t.is_scalar()) return scalar_name(t.scalar);
    if (t.is_vector()) {
        const char* prefix = t.scalar == scalar_type::float32 ? "" : t.scalar == scalar_type::int32 ? "i" : "u";
        return prefix + std::string("vec") + std::to_string(t.rows);
    }
    if (t.columns == t.rows) return "mat" + std::to_string(t.columns);
    return "mat" + std::to_string(t.columns) + "x" + std::to_string(t.rows);
}

inline std::vector<value_type> all_value_types()
{
    std::vector<value_type> types;
    for (scalar_type s : {scalar_type::float32, scalar_type::int32, scalar_type::uint32})
        for (int n = 1; n <= 4; ++n) types.push_back({s, 1, n});
    for (int c = 2; c <= 4; ++c)
        for (int r = 2; r <= 4; ++r) types.push_back({scalar_type::float32, c, r});
    return types;
}

// Parses a GLSL type name; nothing when it is not a built-in value type.
inline std::optional<value_type> parse_value_type(std::string_view name)
{
    for (value_type t : all_value_types())
        if (name == glsl_name(t)) return t;
    for (int c = 2; c <= 4; ++c) // matNxN may also be spelled matN
        if (name == "mat" + std::to_string(c) + "x" + std::to_string(c)) return value_type{scalar_type::float32, c, c};
    return std::nullopt;
}

// ---------------------------------------------------------------------------------
// Result: where everything lives
// ---------------------------------------------------------------------------------

struct member_layout {
    std::string name;
    std::string type;              // as described (GLSL spelling or struct name)
    std::optional<uint32_t> count; // as described
    std::optional<value_type> value; // set for scalar, vector and matrix members
    uint32_t offset = 0;        // bytes from the start of the enclosing struct
    uint32_t size = 0;          // bytes the member occupies; 0 for a runtime-sized array
    uint32_t align = 0;         // the alignment its offset honours
    uint32_t element_size = 0;  // one element of an array; equals size otherwise
    uint32_t array_stride = 0;  // bytes between array elements; 0 when not an array
    uint32_t matrix_stride = 0; // bytes between matrix columns; 0 when not a matrix
    bool packed = false;        // msl: a 3-vector stored as packed_float3 (12 bytes)
    std::vector<member_layout> members; // a struct type's members, offsets from its start

    bool is_array() const { return count.has_value(); }
    bool is_runtime_array() const { return count == 0u; }
    bool is_struct() const { return !value.has_value(); }
};

struct struct_layout {
    rules rule = rules::std140;
    std::string name;
    uint32_t size = 0;  // bytes of the struct (a runtime-sized array counts as 0 elements)
    uint32_t align = 0;
    std::vector<member_layout> members;
};

// ---------------------------------------------------------------------------------
// The rules themselves
// ---------------------------------------------------------------------------------

namespace detail {

inline uint32_t round_up(uint32_t value, uint32_t multiple) { return (value + multiple - 1) / multiple * multiple; }

// Size and alignment of something that can be placed: a value, an array or a struct.
struct extent {
    uint32_t size = 0;
    uint32_t align = 0;
    uint32_t matrix_stride = 0;
};

// The base alignment of a vector of n 4-byte components in std140, std430, WGSL and
// Metal: a vec3 aligns like a vec4.
inline uint32_t vector_alignment(int n) { return n == 1 ? 4 : n == 2 ? 8 : 16; }

inline extent vector_extent(rules r, int n, bool packed)
{
    const uint32_t bytes = 4u * n;
    switch (r) {
    case rules::scalar: return {bytes, 4};
    case rules::hlsl_cbuffer: return {bytes, 4}; // placed by the register rule instead
    case rules::msl:
        if (n == 3 && packed) return {12, 4};    // packed_float3
        return {n == 3 ? 16u : bytes, vector_alignment(n)}; // float3 is 16 bytes in Metal
    default: return {bytes, vector_alignment(n)};
    }
}

// A matrix is an array of its columns; the rule sets differ in the column stride.
inline extent matrix_extent(rules r, int columns, int rows)
{
    uint32_t stride = 0, align = 0, size = 0;
    switch (r) {
    case rules::std140:
        stride = 16, align = 16, size = columns * stride;
        break;
    case rules::scalar:
        stride = 4u * rows, align = 4, size = columns * stride;
        break;
    case rules::hlsl_cbuffer: // one register per column, the last one not padded
        stride = 16, align = 16, size = (columns - 1) * 16 + 4u * rows;
        break;
    default: // std430, WGSL, Metal: columns aligned as vectors
        align = vector_alignment(rows), stride = round_up(4u * rows, align), size = columns * stride;
        break;
    }
    return {size, align, stride};
}

inline extent value_extent(rules r, value_type t, bool packed)
{
    if (t.is_matrix()) return matrix_extent(r, t.columns, t.rows);
    return vector_extent(r, t.rows, packed);
}

// Stride and alignment of an array of `element`.
inline extent array_element_step(rules r, extent element)
{
    switch (r) {
    case rules::std140: {
        const uint32_t align = round_up(element.align, 16);
        return {round_up(element.size, align), align};
    }
    case rules::scalar: return {element.size, element.align};
    case rules::hlsl_cbuffer: return {round_up(element.size, 16), 16};
    case rules::wgsl_uniform: // @align(16) on the array member
        return {round_up(element.size, element.align), round_up(element.align, 16)};
    default: return {round_up(element.size, element.align), element.align};
    }
}

// Total bytes of `count` elements. HLSL does not pad the last element.
inline uint32_t array_size(rules r, uint32_t count, uint32_t stride, uint32_t element_size)
{
    if (count == 0) return 0;
    if (r == rules::hlsl_cbuffer) return stride * (count - 1) + element_size;
    return stride * count;
}

// Alignment of a struct whose widest member aligns to `widest`.
inline uint32_t struct_alignment(rules r, uint32_t widest)
{
    switch (r) {
    case rules::std140: return round_up(widest, 16);
    case rules::hlsl_cbuffer: return 16;
    default: return widest;
    }
}

// Size of a struct whose last member ends at `end`. HLSL leaves it unpadded, so a
// scalar may follow a struct in the same register.
inline uint32_t struct_size(rules r, uint32_t end, uint32_t align)
{
    if (r == rules::hlsl_cbuffer) return end;
    return round_up(end, align);
}

// Where a member starts, given where the previous one ended.
inline uint32_t place(rules r, uint32_t cursor, const member_layout& m)
{
    if (r == rules::hlsl_cbuffer) {
        if (m.is_array() || m.is_struct() || m.value->is_matrix()) return round_up(cursor, 16);
        const uint32_t offset = round_up(cursor, 4); // a vector never straddles a register
        return (offset % 16) + m.size > 16 ? round_up(offset, 16) : offset;
    }
    return round_up(cursor, m.align);
}

[[noreturn]] inline void fail_member(rules r, const std::string& path, const std::string& problem)
{
    fail(path, problem, std::string("rules: ") + to_name(r));
}

inline bool is_identifier(std::string_view s)
{
    if (s.empty() || !(std::isalpha(static_cast<unsigned char>(s[0])) || s[0] == '_')) return false;
    return std::all_of(s.begin(), s.end(), [](char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; });
}

// Words a declaration in some target language could not use as a name: keywords and
// type names of GLSL, HLSL, MSL, WGSL and C++ that a struct member might plausibly be
// called. (Built-in GLSL type names are caught separately, by parse_value_type.)
inline bool is_reserved_word(std::string_view s)
{
    static const char* const words[] = {
        "alignas", "alignof", "auto", "bool", "break", "buffer", "case", "cbuffer", "char", "class",
        "const", "constant", "continue", "default", "delete", "device", "discard", "do", "double", "else", "enum",
        "extern", "f16", "f32", "false", "fn", "for", "half", "i32", "if", "in", "inout", "layout", "let", "long",
        "namespace", "new", "out", "override", "packoffset", "private", "public", "register", "return", "sampler",
        "short", "signed", "sizeof", "static", "struct", "switch", "template", "texture", "this", "thread", "true",
        "typedef", "typename", "u32", "uniform", "union", "unsigned", "var", "void", "volatile", "while"};
    if (s.rfind("gl_", 0) == 0) return true; // GLSL reserves the prefix
    return std::any_of(std::begin(words), std::end(words), [&](const char* w) { return s == w; }) ||
           parse_value_type(s).has_value();
}

// The longest name a declaration may use: glslang and the other shader compilers take
// identifiers of up to 1024 characters.
inline constexpr size_t max_identifier_length = 1024;

// What is wrong with `name` as a declaration's name, as "problem (valid: ...)"; "" if nothing.
inline std::string name_problem(const std::string& name)
{
    if (name.size() > max_identifier_length)
        return "is a name of " + std::to_string(name.size()) + " characters (valid: at most " + std::to_string(max_identifier_length) +
               ", what shader compilers accept)";
    if (!is_identifier(name)) return quote(name) + " is not an identifier (valid: letters, digits and _, not starting with a digit)";
    if (is_reserved_word(name)) return quote(name) + " is a keyword or type name of a target language (valid: any other identifier)";
    return "";
}

inline void require_name(const std::string& subject, const std::string& name)
{
    const std::string problem = name_problem(name);
    if (!problem.empty()) throw error(subject + ": " + problem);
}

// Computes struct layouts recursively; each named struct is laid out once per rule set.
class engine {
public:
    engine(const block_desc& block, rules r) : block_(block), rule_(r)
    {
        for (const struct_desc& s : block.structs) {
            require_name("struct name", s.name);
            if (!structs_.emplace(s.name, &s).second) fail("struct " + s.name, "is defined twice", "valid: one definition per struct name");
        }
    }

    struct_layout run()
    {
        struct_layout result;
        result.rule = rule_;
        result.name = block_.root.name;
        require_name("block name", result.name);
        if (structs_.count(result.name)) fail("block name", quote(result.name) + " is also the name of a struct", "valid: a name no struct in block.structs uses");
        lay_out(block_.root, block_.root.name, /*top_level=*/true, result.members, result.size, result.align);
        if (rule_ == rules::hlsl_cbuffer) result.size = round_up(result.size, 16); // a cbuffer is whole registers
        // Structs no member uses are checked too: an unknown type in one is a mistake
        // that would surface the day a member uses it.
        for (const struct_desc& s : block_.structs) {
            std::vector<member_layout> unused;
            describe_struct(s.name, "struct " + s.name, unused);
        }
        return result;
    }

private:
    const block_desc& block_;
    rules rule_;
    std::map<std::string, const struct_desc*> structs_;
    std::vector<std::string> open_; // structs being laid out, to catch recursion

    void lay_out(const struct_desc& s, const std::string& path, bool top_level,
                 std::vector<member_layout>& members, uint32_t& size, uint32_t& align)
    {
        if (s.members.empty()) fail(path, "has no members", "valid: at least one member");
        std::set<std::string> names;
        for (size_t i = 0; i < s.members.size(); ++i) {
            const member_desc& d = s.members[i];
            const std::string member_path = path + "." + printable(d.name, 64);
            require_name(member_path, d.name);
            if (!names.insert(d.name).second) fail(member_path, "is declared twice", "valid: unique member names");
            if (d.count == 0u) check_runtime_array(member_path, top_level, i + 1 == s.members.size());
            if (d.count && *d.count > max_array_count)
                fail(member_path, "array count " + std::to_string(*d.count) + " is too large", "valid: 0 (runtime-sized) or 1.." + std::to_string(max_array_count));
            members.push_back(describe(d, member_path));
        }
        if (rule_ == rules::msl) pack_msl_vectors(members);

        uint32_t cursor = 0, widest = 4;
        for (member_layout& m : members) {
            m.offset = place(rule_, cursor, m);
            if (uint64_t{m.offset} + m.size > max_block_bytes)
                fail(path + "." + m.name, "ends at byte " + std::to_string(uint64_t{m.offset} + m.size) + ", past the largest block",
                     "valid: blocks up to " + std::to_string(max_block_bytes) + " bytes");
            cursor = m.offset + m.size;
            widest = std::max(widest, m.align);
        }
        align = struct_alignment(rule_, widest);
        size = struct_size(rule_, cursor, align);
    }

    void check_runtime_array(const std::string& path, bool top_level, bool last)
    {
        if (!allows_runtime_array(rule_))
            fail_member(rule_, path, "a runtime-sized array cannot be in a uniform block; use std430, scalar, wgsl-storage or msl");
        if (!top_level || !last)
            fail_member(rule_, path, "a runtime-sized array must be the last member of the top-level block");
    }

    // Made of scalars alone, through any nesting: what std430 aligns to 4 bytes.
    static bool only_scalars(const member_layout& m)
    {
        if (m.is_struct()) return std::all_of(m.members.begin(), m.members.end(), only_scalars);
        return m.value->is_scalar();
    }

    // Metal stores a float3 in 16 bytes; SPIRV-Cross emits packed_float3 (12 bytes,
    // 4-aligned) when the next member is made of scalars (a scalar, a scalar array, a
    // struct of scalars), which std430 places in the vector's fourth lane. A struct that
    // Metal aligns to 4 only because it holds a packed vector itself does not count:
    // std430 still aligns it to 16.
    void pack_msl_vectors(std::vector<member_layout>& members)
    {
        for (size_t i = 0; i + 1 < members.size(); ++i) {
            member_layout& m = members[i];
            if (m.is_array() || m.is_struct() || !m.value->is_vector() || m.value->rows != 3) continue;
            if (!only_scalars(members[i + 1])) continue;
            m.packed = true;
            m.size = m.element_size = 12;
            m.align = 4;
        }
    }

    member_layout describe(const member_desc& d, const std::string& path)
    {
        member_layout m;
        m.name = d.name;
        m.type = d.type;
        m.count = d.count;
        extent element;
        if (std::optional<value_type> value = parse_value_type(d.type)) {
            m.value = value;
            element = value_extent(rule_, *value, false);
            m.matrix_stride = element.matrix_stride;
        } else {
            element = describe_struct(d.type, path, m.members);
        }
        m.element_size = element.size;
        m.size = element.size;
        m.align = element.align;
        if (rule_ == rules::wgsl_uniform && m.is_struct()) {
            // The uniform address space wants struct members 16-aligned and at least
            // roundUp(16, SizeOf(S)) bytes before the next member (@align(16) @size(...)).
            m.align = round_up(m.align, 16);
            m.size = round_up(m.size, 16);
        }
        if (d.count) {
            const extent step = array_element_step(rule_, element);
            if (rule_ == rules::wgsl_uniform && step.size % 16 != 0)
                fail_member(rule_, path, "array stride " + std::to_string(step.size) +
                                             " is not a multiple of 16 in the uniform address space; use a vec4 (or a 16-byte struct) element");
            if (uint64_t{*d.count} * step.size > max_block_bytes)
                fail(path, std::to_string(*d.count) + " elements of " + std::to_string(step.size) + " bytes exceed the largest block",
                     "valid: blocks up to " + std::to_string(max_block_bytes) + " bytes");
            m.array_stride = step.size;
            m.align = step.align;
            m.size = array_size(rule_, *d.count, step.size, element.size);
        }
        return m;
    }

    extent describe_struct(const std::string& type, const std::string& path, std::vector<member_layout>& members)
    {
        auto found = structs_.find(type);
        if (found == structs_.end()) {
            std::string valid = "valid: float, int, uint, vec2..4, ivec2..4, uvec2..4, mat2..4, matCxR";
            for (const auto& entry : structs_) valid += ", " + entry.first;
            fail(path, "unknown type " + quote(type), valid);
        }
        if (std::find(open_.begin(), open_.end(), type) != open_.end())
            fail(path, "struct " + type + " contains itself", "valid: structs nest without cycles");
        open_.push_back(type);
        extent e;
        lay_out(*found->second, path, /*top_level=*/false, members, e.size, e.align);
        open_.pop_back();
        return e;
    }
};

} // namespace detail

namespace detail {

// How many layouts compute() has made in this process. Not a feature: it lets a test pin that
// a plan (codegen/plan.hpp) lays each uniform block out once, and that binding a planned chain
// lays out nothing again.
inline std::atomic<unsigned long>& computations()
{
    static std::atomic<unsigned long> count{0};
    return count;
}

} // namespace detail

// Lays out `block` under `r`. Throws aogen::error naming the member when the rule set
// cannot express it.
inline struct_layout compute(const block_desc& block, rules r)
{
    ++detail::computations();
    return detail::engine(block, r).run();
}

// The member at `path` ("light", "light.intensity"; array indices are not part of a
// layout path — see layout_writer.hpp for "lights[2].color"). Nothing if absent.
inline const member_layout* find(const std::vector<member_layout>& members, std::string_view path)
{
    const size_t dot = path.find('.');
    const std::string_view head = path.substr(0, dot);
    for (const member_layout& m : members) {
        if (m.name != head) continue;
        if (dot == std::string_view::npos) return &m;
        return find(m.members, path.substr(dot + 1));
    }
    return nullptr;
}

inline const member_layout* find(const struct_layout& layout, std::string_view path)
{
    return find(layout.members, path);
}

} // namespace aogen::layout
