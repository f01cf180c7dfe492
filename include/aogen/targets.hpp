// aogen/targets.hpp — the languages compile() makes from a stage's GLSL.
//
// WHAT
//   aogen::compile::target   spv, glsl, essl, hlsl50, hlsl60, msl_macos, msl_ios, wgsl, with
//                            their command-line names ("hlsl" is SM 5.0, "msl" macOS), and
//                            all_targets and spirv_cross_targets; shader_stage (stages.hpp)
//                            under the compiler's namespace.
//
// USAGE
//     #include <aogen/targets.hpp>
//     aogen::compile::target_from_name("msl");   // target::msl_macos
//     aogen::compile::target_list();             // "spv, glsl, essl, hlsl, hlsl60, msl, msl_ios, wgsl"
//
// WHY
//   Its own header, below the compiler, because reflection (reflect.hpp) keys each target's
//   entry point by it and the command lines name it; compile.hpp says what each target is.
#pragma once

#include "names.hpp"
#include "stages.hpp"

#include <array>
#include <string>
#include <string_view>
#include <vector>

namespace aogen::compile {

using aogen::shader_stage;
using aogen::shader_stage_from_name;

// What compile() makes: compile.hpp says what each target is.

enum class target { spv, glsl, essl, hlsl50, hlsl60, msl_macos, msl_ios, wgsl };
inline constexpr std::array<enum_name<target>, 8> target_names{{
    {target::spv, "spv"},
    {target::glsl, "glsl"},
    {target::essl, "essl"},
    {target::hlsl50, "hlsl"},
    {target::hlsl60, "hlsl60"},
    {target::msl_macos, "msl"},
    {target::msl_ios, "msl_ios"},
    {target::wgsl, "wgsl"},
}};
static_assert(names::distinct(target_names));

// Every target, in table order.
inline const std::vector<target> all_targets = [] {
    constexpr auto values = names::values(target_names);
    return std::vector<target>(values.begin(), values.end());
}();

// The targets compile() makes from any Vulkan GLSL, through SPIRV-Cross: all but wgsl, which
// needs SPIR-V in WebGPU's binding model and Node.js (compile.hpp).
inline const std::vector<target> spirv_cross_targets = [] {
    std::vector<target> out;
    for (target t : all_targets)
        if (t != target::wgsl) out.push_back(t);
    return out;
}();

inline const char* to_name(target t) { return names::name_of(target_names, t, "target"); }
inline target target_from_name(std::string_view name, std::string_view subject = "target")
{
    return names::value_of(target_names, name, subject);
}
// "spv, glsl, essl, hlsl, hlsl60, msl, msl_ios, wgsl".
inline std::string target_list() { return names::list(target_names); }

} // namespace aogen::compile
