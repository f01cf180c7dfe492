// aogen/stages.hpp — the shader stages: what the compiler layer and the AO model both name,
// owned by neither.
//
// WHAT
//   aogen::shader_stage   compute, vertex, fragment (a fragment pass also needs the
//                         fullscreen vertex shader), with names (to_name,
//                         shader_stage_from_name) and file extensions (comp, vert, frag).
//   The compile targets are targets.hpp's.
//
// USAGE
//     #include <aogen/stages.hpp>
//     aogen::file_extension(aogen::shader_stage::compute);            // "comp"
//     aogen::shader_stage_from_name("fragment");                      // shader_stage::fragment
//
// WHY
//   The compiler (compile.hpp, reflect.hpp, wgsl.hpp) turns a stage's GLSL into targets; it
//   needs to know what a stage is, not what an AO variant is. Declared here, below both the
//   compiler and the model (variant.hpp), a stage needs neither, and the compiler layer
//   includes nothing of the AO model (tests/layers/ fails when it does).
#pragma once

#include "names.hpp"

#include <array>
#include <string_view>

namespace aogen {

// The shader stages a variant's passes compile to (a fragment pass also needs the
// fullscreen vertex shader).
enum class shader_stage { compute, vertex, fragment };
inline constexpr std::array<enum_name<shader_stage>, 3> shader_stage_names{{
    {shader_stage::compute, "compute"},
    {shader_stage::vertex, "vertex"},
    {shader_stage::fragment, "fragment"},
}};

inline const char* to_name(shader_stage s) { return names::name_of(shader_stage_names, s, "shader stage"); }
inline shader_stage shader_stage_from_name(std::string_view name, std::string_view subject = "shader stage")
{
    return names::value_of(shader_stage_names, name, subject);
}

// The usual file extension of a stage's GLSL (glslangValidator's): comp, vert, frag.
inline const char* file_extension(shader_stage s)
{
    switch (s) {
    case shader_stage::compute: return "comp";
    case shader_stage::vertex: return "vert";
    case shader_stage::fragment: return "frag";
    }
    names::fail_unlisted(shader_stage_names, s, "shader stage");
}

} // namespace aogen
