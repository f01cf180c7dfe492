// generator/format.hpp — kernels and noise tiles as JSON, C++, GLSL, WGSL or raw bytes.
//
// Floats are written with the fewest digits that read back to the same float
// (std::to_chars), plus what each language needs to see a float literal ("1.0f" in
// C++, "1.0" in GLSL and WGSL), so a generated constant is bit-identical to the data.
#pragma once

#include <aogen/error.hpp>
#include <aogen/math.hpp>
#include <aogen/noise.hpp>

#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

namespace aogen::cli {

enum class text_language { json, cpp, glsl, wgsl };

inline std::string float_literal(float value, text_language lang)
{
    std::string text = format_number(value);
    if (text.find_first_of(".en") == std::string::npos) text += ".0";
    if (lang == text_language::cpp) text += "f";
    return text;
}

// A float as the JSON number with the fewest digits that reads back to it (0.025, not
// 0.02500000037252903, which is what the float's exact double value prints as).
inline double json_float(float value) { return std::stod(format_number(value)); }

inline std::string vec4_literal(const vec4& v, text_language lang, int components = 4)
{
    const float values[4] = {v.x, v.y, v.z, v.w};
    std::string out;
    for (int i = 0; i < components; ++i) out += (i ? ", " : "") + float_literal(values[i], lang);
    switch (lang) {
    case text_language::json: return "[" + out + "]";
    case text_language::cpp: return "{" + out + "}";
    case text_language::glsl: return "vec" + std::to_string(components) + "(" + out + ")";
    case text_language::wgsl: return "vec" + std::to_string(components) + "<f32>(" + out + ")";
    }
    return out;
}

// The vec4s laid end to end, little-endian RGBA32F.
inline std::string vec4_bytes(const std::vector<vec4>& values)
{
    std::string bytes;
    for (const vec4& v : values)
        for (float f : {v.x, v.y, v.z, v.w}) {
            uint32_t bits;
            std::memcpy(&bits, &f, 4);
            for (int i = 0; i < 4; ++i) bytes.push_back(static_cast<char>(bits >> (8 * i)));
        }
    return bytes;
}

// A constant array of vec4s named `name`, in `lang`.
inline std::string vec4_array(const std::string& name, const std::vector<vec4>& values, text_language lang)
{
    const std::string n = std::to_string(values.size());
    std::string items;
    for (size_t i = 0; i < values.size(); ++i) items += (i ? ",\n    " : "    ") + vec4_literal(values[i], lang);
    switch (lang) {
    case text_language::json: return "[\n" + items + "\n]\n";
    case text_language::cpp: return "static const float " + name + "[" + n + "][4] = {\n" + items + "\n};\n";
    case text_language::glsl: return "const vec4 " + name + "[" + n + "] = vec4[" + n + "](\n" + items + ");\n";
    case text_language::wgsl: return "const " + name + " = array<vec4<f32>, " + n + ">(\n" + items + ");\n";
    }
    return items;
}

inline std::string byte_list(const std::vector<uint8_t>& bytes)
{
    std::string out;
    for (size_t i = 0; i < bytes.size(); ++i) {
        if (i % 16 == 0) out += i ? ",\n    " : "    ";
        else out += ", ";
        out += std::to_string(bytes[i]);
    }
    return out;
}

} // namespace aogen::cli
