// The math the templates write out so that every target computes the same operations
// (common/core.glsl): no pass leaves acos, atan or a float mix() to the driver. Mesa's GL
// and Vulkan front ends build acos and atan from different polynomials and round mix()
// differently (a GTAO pixel 1/255 apart, an SSAO vote, a VBAO sector: docs/webgpu.md § GL runner),
// so a pass that calls them is bit-identical on one driver pair and not on another — a
// property the GL comparison sees only when a pixel happens to sit at a rounding boundary.
// Here it is stated directly, on every pass's SPIR-V: no GLSL.std.450 Acos, Atan, Atan2 or
// FMix instruction. Templates read through template_under_test (mutants/mutants.hpp).
#include "mutants/mutants.hpp"

#include <aogen/codegen.hpp>
#include <aogen/compile.hpp>
#include <aogen/names.hpp>

#include <catch2/catch.hpp>

#include <cstring>
#include <map>
#include <string>
#include <vector>

// One namespace per test file: the files of one executable share a translation unit
// (tests/CMakeLists.txt: a unity build), and their helpers must not meet.
namespace unity_test_portable_math {

using namespace aogen;

namespace {

// GLSL.std.450's instruction numbers (the extended instruction set's specification).
const std::map<uint32_t, const char*> driver_dependent{{17, "Acos"}, {18, "Atan"}, {25, "Atan2"}, {46, "FMix"}};

// The GLSL.std.450 instructions of `spirv` that are in driver_dependent, by name.
std::vector<std::string> driver_dependent_calls(const std::vector<uint32_t>& spirv)
{
    constexpr uint32_t op_ext_inst_import = 11, op_ext_inst = 12;
    std::vector<std::string> found;
    uint32_t glsl_std = 0; // the id of the imported GLSL.std.450 set
    for (size_t i = 5; i < spirv.size();) {
        const uint32_t count = spirv[i] >> 16, opcode = spirv[i] & 0xffff;
        REQUIRE(count > 0);
        if (opcode == op_ext_inst_import && std::strcmp(reinterpret_cast<const char*>(&spirv[i + 2]), "GLSL.std.450") == 0)
            glsl_std = spirv[i + 1];
        if (opcode == op_ext_inst && spirv[i + 3] == glsl_std) {
            const auto named = driver_dependent.find(spirv[i + 4]);
            if (named != driver_dependent.end()) found.push_back(named->second);
        }
        i += count;
    }
    return found;
}

} // namespace

TEST_CASE("portable math: no pass of any technique calls the driver's acos, atan or float mix", "[glslang]")
{
    size_t shaders = 0;
    for (const char* name : {"ssao-s16-half-bilateral-gbufworld-std-persp-cs", "ssao-s64-full-noblur-recon-std-persp-cs-pc-rc004",
                             "gtao-2x3-half-denoise-gbufview-std-persp-cs", "gtao-2x3-half-bilateral-recon-std-persp-fs",
                             "gtao-2x3-half-bilateral-gbufworld-std-persp-cs-fp16", "vbao-2x3-half-box-gbufworld-std-persp-cs",
                             "vbao-2x2-full-noblur-recon-std-persp-fs", "ssao-s16-half-bilateral-gbufworld-std-persp-fs-rawdepth-nearest"}) {
        const variant v = variant_from_name(name);
        for (const codegen::shader_source& s : codegen::generate(codegen::make_plan(v, aogen_test::under_test()))) {
            INFO(s.name);
            CHECK(driver_dependent_calls(compile::glsl_to_spirv(s.glsl, s.stage, s.name)).empty());
            ++shaders;
        }
    }
    CHECK(shaders >= 20);
}

TEST_CASE("portable math: the scan finds acos, atan and mix where a shader calls them", "[glslang]")
{
    const std::string body = "#version 450\nlayout(local_size_x = 1) in;\nlayout(set = 0, binding = 0) buffer B { float x[]; };\n"
                             "void main() { x[0] = acos(x[1]) + atan(x[2], x[3]) + atan(x[4]) + mix(x[5], x[6], x[7]); }\n";
    std::vector<std::string> calls = driver_dependent_calls(compile::glsl_to_spirv(body, shader_stage::compute, "planted"));
    std::sort(calls.begin(), calls.end());
    CHECK(calls == std::vector<std::string>{"Acos", "Atan", "Atan2", "FMix"});
}

} // namespace unity_test_portable_math
