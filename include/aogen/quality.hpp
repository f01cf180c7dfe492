// aogen/quality.hpp — named quality presets for GTAO and VBAO: Low, Medium, High, Ultra.
//
// WHAT
//   Engines that ported Intel's XeGTAO expose its four quality levels by name; these are the
//   same slice × step counts (XeGTAO's XeGTAO_QualityLevel: slices, steps per side):
//       low     1 × 2
//       medium  2 × 2
//       high    3 × 3
//       ultra   9 × 3
//   A preset sets only a GTAO or VBAO variant's slice and step counts (VBAO marches the same
//   slices and steps, so the same counts cost it about what they cost GTAO); every other axis (resolution,
//   blur, normals, ...) stays the caller's. `aogen list` prints them, and `aogen generate`'s
//   manifest names the preset a variant's counts match ("quality").
//
// USAGE
//     aogen::variant v;
//     v.tech = aogen::technique::gtao;
//     aogen::apply_quality(v, aogen::quality_preset_from_name("high"));   // 3 × 3
//     aogen::quality_name_of(v);                                          // "high"
//     aogen::quality_name_of(aogen::variant{});                            // "" (SSAO: none)
#pragma once

#include "variant.hpp"

#include <array>
#include <string>
#include <string_view>

namespace aogen {

struct quality_preset {
    const char* name;
    int slices, steps; // GTAO slices per pixel, steps per side of each slice
};

inline constexpr std::array<quality_preset, 4> quality_presets{{
    {"low", 1, 2},
    {"medium", 2, 2},
    {"high", 3, 3},
    {"ultra", 9, 3},
}};

// The preset called `name`; an aogen::error naming `subject` and the valid names otherwise.
inline quality_preset quality_preset_from_name(std::string_view name, std::string_view subject = "quality")
{
    std::string valid;
    for (const quality_preset& p : quality_presets) {
        if (name == p.name) return p;
        valid += (valid.empty() ? "" : ", ") + std::string(p.name);
    }
    fail(std::string(subject), quote(std::string(name)) + " is not a quality preset", "valid: " + valid);
}

// `v` with the preset's slice and step counts (a GTAO or VBAO variant's; an aogen::error
// otherwise: SSAO has no slices).
inline void apply_quality(variant& v, const quality_preset& p)
{
    if (!has_slices(v.tech))
        fail("quality", quote(std::string(p.name)) + " sets slices and steps, and the variant is " + names::name_of(technique_names, v.tech, "technique"),
             "valid: technique gtao or vbao");
    v.slices = p.slices, v.steps = p.steps;
}

// The preset whose counts `v` has, or "" (SSAO, or counts no preset has).
inline std::string quality_name_of(const variant& v)
{
    if (!has_slices(v.tech)) return "";
    for (const quality_preset& p : quality_presets)
        if (v.slices == p.slices && v.steps == p.steps) return p.name;
    return "";
}

} // namespace aogen
