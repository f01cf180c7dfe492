// tests/compiler/msl_structs.hpp — test helper: reads the struct definitions out of Metal
// source, as SPIRV-Cross (CompilerMSL) and aogen's declare(..., language::msl) write them.
//
// Only the shapes those two emit are understood, and anything else is reported rather
// than guessed at:
//     struct Name            (the brace on the next line, or on the same one)
//     {
//         float3 a;          // value types: float int uint, floatN intN uintN,
//         packed_float3 b;   //   packed_floatN packed_intN packed_uintN, floatCxR
//         Other c[4];        // a struct type, an array of N
//         spvUnsafeArray<float, 4> d;
//         alignas(16) float e;
//         char _m3_pad[12];  // SPIRV-Cross's padding: N bytes
//     };
// Comments after a member are ignored. A struct with anything else in it (a method, a
// template) is recorded as unparsed, with the offending line.
#pragma once

#include <aogen/layout.hpp>

#include <algorithm>
#include <cctype>
#include <cstdint>
#include <map>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

namespace aogen_test {

struct metal_member {
    std::string type;               // as written, without alignas: "packed_float3", "S", "char"
    std::string name;
    std::optional<uint32_t> count;  // [N] or spvUnsafeArray<T, N>
    std::optional<uint32_t> alignas_bytes;
    bool is_padding() const { return type == "char" && name.rfind("_m", 0) == 0 && name.find("pad") != std::string::npos; }
};

struct metal_struct {
    std::string name;
    std::vector<metal_member> members;
    std::string unparsed; // the first line that is not a plain member; empty when all were
};

namespace detail {

inline std::string trim(const std::string& s)
{
    size_t b = 0, e = s.size();
    while (b < e && std::isspace(static_cast<unsigned char>(s[b]))) ++b;
    while (e > b && std::isspace(static_cast<unsigned char>(s[e - 1]))) --e;
    return s.substr(b, e - b);
}

inline bool all_digits(const std::string& s)
{
    return !s.empty() && std::all_of(s.begin(), s.end(), [](char c) { return std::isdigit(static_cast<unsigned char>(c)); });
}

inline bool is_identifier(const std::string& s)
{
    if (s.empty() || std::isdigit(static_cast<unsigned char>(s[0]))) return false;
    return std::all_of(s.begin(), s.end(), [](char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; });
}

// One member line without its comment; nothing when it is not a plain member.
inline std::optional<metal_member> parse_member(std::string text)
{
    text = trim(text);
    if (text.empty() || text.back() != ';') return std::nullopt;
    text = trim(text.substr(0, text.size() - 1));
    metal_member m;
    if (text.rfind("alignas(", 0) == 0) {
        const size_t close = text.find(')');
        if (close == std::string::npos || !all_digits(text.substr(8, close - 8))) return std::nullopt;
        m.alignas_bytes = static_cast<uint32_t>(std::stoul(text.substr(8, close - 8)));
        text = trim(text.substr(close + 1));
    }
    if (text.rfind("spvUnsafeArray<", 0) == 0) {
        const size_t comma = text.find(','), close = text.find('>');
        if (comma == std::string::npos || close == std::string::npos || comma > close) return std::nullopt;
        const std::string count = trim(text.substr(comma + 1, close - comma - 1));
        if (!all_digits(count)) return std::nullopt;
        m.type = trim(text.substr(15, comma - 15));
        m.count = static_cast<uint32_t>(std::stoul(count));
        m.name = trim(text.substr(close + 1));
    } else {
        const size_t space = text.rfind(' ');
        if (space == std::string::npos) return std::nullopt;
        m.type = trim(text.substr(0, space));
        m.name = text.substr(space + 1);
        const size_t bracket = m.name.find('[');
        if (bracket != std::string::npos) {
            if (m.name.back() != ']') return std::nullopt;
            const std::string count = m.name.substr(bracket + 1, m.name.size() - bracket - 2);
            if (!all_digits(count)) return std::nullopt;
            m.count = static_cast<uint32_t>(std::stoul(count));
            m.name = m.name.substr(0, bracket);
        }
    }
    if (!is_identifier(m.type) || !is_identifier(m.name)) return std::nullopt;
    return m;
}

} // namespace detail

// Every `struct Name { ... };` at the start of a line in `source`, by name.
inline std::map<std::string, metal_struct> parse_metal_structs(const std::string& source)
{
    std::map<std::string, metal_struct> out;
    std::istringstream in(source);
    std::string line;
    metal_struct* open = nullptr;
    bool want_brace = false;
    while (std::getline(in, line)) {
        const size_t comment = line.find("//");
        if (comment != std::string::npos) line = line.substr(0, comment);
        const std::string t = detail::trim(line);
        if (!open) {
            if (t.rfind("struct ", 0) != 0) continue;
            std::string name = detail::trim(t.substr(7));
            want_brace = true;
            if (!name.empty() && name.back() == '{') name = detail::trim(name.substr(0, name.size() - 1)), want_brace = false;
            if (!detail::is_identifier(name)) continue; // a declaration such as `struct X;` or a template
            open = &out[name];
            open->name = name;
            open->members.clear();
            open->unparsed.clear();
            continue;
        }
        if (want_brace) {
            if (t == "{") want_brace = false;
            else { open->unparsed = "expected '{', got: " + t; open = nullptr; }
            continue;
        }
        if (t == "};") { open = nullptr; continue; }
        if (t.empty()) continue;
        if (std::optional<metal_member> m = detail::parse_member(t)) open->members.push_back(*m);
        else if (open->unparsed.empty()) open->unparsed = t;
    }
    return out;
}

// A Metal value type in GLSL spelling, and whether it is a packed_ vector. Nothing for
// a struct name or anything else.
struct metal_value {
    std::string glsl;
    bool packed = false;
};

inline std::optional<metal_value> metal_value_type(std::string type)
{
    metal_value v;
    if (type.rfind("packed_", 0) == 0) v.packed = true, type = type.substr(7);
    for (aogen::layout::value_type t : aogen::layout::all_value_types()) {
        const std::string scalar = aogen::layout::scalar_name(t.scalar);
        std::string metal;
        if (t.is_scalar()) metal = scalar;
        else if (t.is_vector()) metal = scalar + std::to_string(t.rows);
        else metal = scalar + std::to_string(t.columns) + "x" + std::to_string(t.rows); // Metal: columns x rows
        if (metal == type) {
            if (v.packed && !t.is_vector()) return std::nullopt;
            v.glsl = aogen::layout::glsl_name(t);
            return v;
        }
    }
    return std::nullopt;
}

} // namespace aogen_test
