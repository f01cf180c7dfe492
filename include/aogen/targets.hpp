// aogen/targets.hpp — the languages compile() makes from a stage's GLSL: one row each.
//
// WHAT
//   aogen::compile::target   spv, glsl, essl, hlsl, hlsl60, msl_macos, msl_ios, wgsl, with
//                            their command-line names ("hlsl" is SM 5.0, "msl" macOS)
//   target_table             one row per target, every fact about it in one place: its name,
//                            the extension `aogen generate` gives its files, whether
//                            SPIRV-Cross makes it, whether `aogen generate` makes it by
//                            default, what it needs of the GLSL it is made from (four-channel
//                            8-bit outputs, WebGPU's separate samplers) and how aogen's own
//                            tests check it (executed, round-tripped or validated)
//   all_targets, spirv_cross_targets, info(t); shader_stage (stages.hpp) under the
//                            compiler's namespace.
//
// USAGE
//     #include <aogen/targets.hpp>
//     aogen::compile::target_from_name("msl");   // target::msl_macos
//     aogen::compile::info(target::hlsl).extension;   // "sm50.hlsl"
//     aogen::compile::target_list();             // "spv, glsl, essl, hlsl, hlsl60, msl, msl_ios, wgsl"
//
// ERRORS
//   A row left out, out of order or without a name does not compile (the static_assert).
//
// WHY
//   Its own header, below the compiler, because reflection (reflect.hpp) keys each target's
//   entry point by it and the command lines name it; compile.hpp says how each target is made.
//   A new target is its enum value and its row here, and its case in compile.hpp's
//   cross_compile (or its own route, as WGSL's).
#pragma once

#include "names.hpp"
#include "stages.hpp"

#include <array>
#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace aogen::compile {

using aogen::shader_stage;
using aogen::shader_stage_from_name;

// What compile() makes: compile.hpp says what each target is.

enum class target { spv, glsl, essl, hlsl, hlsl60, msl_macos, msl_ios, wgsl };
inline constexpr std::array<enum_name<target>, 8> target_names{{
    {target::spv, "spv"},
    {target::glsl, "glsl"},
    {target::essl, "essl"},
    {target::hlsl, "hlsl"},
    {target::hlsl60, "hlsl60"},
    {target::msl_macos, "msl"},
    {target::msl_ios, "msl_ios"},
    {target::wgsl, "wgsl"},
}};
static_assert(names::distinct(target_names));

// How aogen's own tests check a target's text (docs/webgpu.md § GL runner):
//   executed       run and compared per pixel with the SPIR-V (spv itself: the Vulkan
//                  harness; glsl, essl: aogen::gl on OpenGL 4.5 / ES 3.2; wgsl: Dawn, and
//                  round-tripped through naga too)
//   round_tripped  compiled back to SPIR-V by glslang's HLSL front end and run on the Vulkan
//                  harness (hlsl, hlsl60): the HLSL's meaning as glslang reads it, not DXC's
//   validated      compiled and reflected, never run: MSL (no Metal compiler on Linux)
enum class verification { executed, round_tripped, validated };
inline constexpr std::array<enum_name<verification>, 3> verification_names{{
    {verification::executed, "executed"},
    {verification::round_tripped, "round_tripped"},
    {verification::validated, "validated"},
}};

// Everything about one target.
struct target_info {
    target value;
    const char* extension;      // of `aogen generate`'s files, after "<pass>.<stage>."
    bool spirv_cross;           // made from SPIR-V by SPIRV-Cross (wgsl: by naga, compile.hpp)
    bool generated_by_default;  // in `aogen generate`'s default --targets (wgsl needs Node.js)
    bool four_channel_output;   // no one-channel 8-bit storage image: the AO is written as rgba8
    bool separate_samplers;     // WebGPU's binding model (bindings.hpp): made from its own GLSL
    verification checked;       // how the tests check it
    verification checked_fp16;  // ... an fp16 variant's text: glslang reads min16float as float
                                // and has no min16float3x3, so an HLSL round trip would not
                                // run its arithmetic
};

inline constexpr std::array<target_info, target_names.size()> target_table{{
    {target::spv, "spv", false, true, false, false, verification::executed, verification::executed},
    {target::glsl, "glsl", true, true, false, false, verification::executed, verification::executed},
    {target::essl, "essl", true, true, true, false, verification::executed, verification::executed},
    {target::hlsl, "sm50.hlsl", true, true, false, false, verification::round_tripped, verification::validated},
    {target::hlsl60, "sm60.hlsl", true, true, false, false, verification::round_tripped, verification::validated},
    {target::msl_macos, "macos.metal", true, true, false, false, verification::validated, verification::validated},
    {target::msl_ios, "ios.metal", true, true, false, false, verification::validated, verification::validated},
    {target::wgsl, "wgsl", false, false, true, true, verification::executed, verification::executed},
}};

namespace detail {
constexpr bool target_table_complete()
{
    for (std::size_t i = 0; i < target_table.size(); ++i)
        if (target_table[i].value != target_names[i].value || !target_table[i].extension || !*target_table[i].extension) return false;
    return true;
}
} // namespace detail
static_assert(detail::target_table_complete(), "target_table: one row per target of target_names, in its order, each with its extension");

// The row of target `t`.
inline const target_info& info(target t)
{
    names::require_listed(target_names, t, "target");
    return target_table[static_cast<std::size_t>(t)];
}

// Every target, in table order.
inline const std::vector<target> all_targets = [] {
    constexpr auto values = names::values(target_names);
    return std::vector<target>(values.begin(), values.end());
}();

// The targets compile() makes from any Vulkan GLSL, through SPIRV-Cross: all but spv itself
// and wgsl, which needs SPIR-V in WebGPU's binding model and Node.js (compile.hpp); spv first.
inline const std::vector<target> spirv_cross_targets = [] {
    std::vector<target> out;
    for (const target_info& t : target_table)
        if (t.value == target::spv || t.spirv_cross) out.push_back(t.value);
    return out;
}();

// `aogen generate`'s default --targets: "spv,glsl,essl,hlsl,hlsl60,msl,msl_ios".
inline std::string default_generate_targets()
{
    std::string out;
    for (const target_info& t : target_table)
        if (t.generated_by_default) out += (out.empty() ? "" : ",") + std::string(names::name_of(target_names, t.value, "target"));
    return out;
}

inline const char* to_name(verification v) { return names::name_of(verification_names, v, "verification"); }

inline const char* to_name(target t) { return names::name_of(target_names, t, "target"); }
inline target target_from_name(std::string_view name, std::string_view subject = "target")
{
    return names::value_of(target_names, name, subject);
}
// "spv, glsl, essl, hlsl, hlsl60, msl, msl_ios, wgsl".
inline std::string target_list() { return names::list(target_names); }

} // namespace aogen::compile
