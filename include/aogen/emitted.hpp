// aogen/emitted.hpp — a variant's shaders as one target's texts, as `aogen generate` writes them.
//
//     std::vector<std::string> glsl = aogen::emitted_texts(v, aogen::compile::target::glsl);
//
// One text per shader codegen::generate(v, o) returns, in its order (per pass: a compute
// shader, or a vertex and a fragment shader), each compiled by compile.hpp to `target`. What
// aogen::gl::run and the HLSL round trip take.
#pragma once

#include "codegen.hpp"
#include "compile.hpp"

#include <string>
#include <vector>

namespace aogen {

inline std::vector<std::string> emitted_texts(const variant& v, compile::target target, const codegen::options& o = {})
{
    std::vector<std::string> out;
    for (const codegen::shader_source& s : codegen::generate(v, o)) out.push_back(compile::compile(s.glsl, s.stage, s.name, {target}).text.at(target));
    return out;
}

} // namespace aogen
