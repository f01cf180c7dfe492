// Oracle: glslang (the Khronos reference GLSL front end) and SPIRV-Cross's reflection.
//
// For random structs under std140, std430 and scalar, aogen::layout::compute gives the
// layout and declare(..., language::glsl) the block; glslang compiles that block inside a
// compute shader that reads it (Vulkan 1.0, SPIR-V 1.0) and decorates every member with
// the Offset, ArrayStride and MatrixStride its own implementation of the GLSL/Vulkan
// layout rules computes; spirv-val then checks those decorations against the Vulkan
// block-layout rules once more, independently of glslang. SPIRV-Cross reads the
// decorations back and every member's offset, array stride, matrix stride and size, and
// the struct size, must equal aogen's, recursively through nested structs.
//
// Trustworthy because glslang's layout code is what every Vulkan GLSL shader in the wild
// is compiled with and is checked by the conformance tests, and spirv-val is a second,
// separate implementation of the same rules; neither shares code with aogen.
//
// One difference in definitions, not in layout: SPIRV-Cross's get_declared_struct_size
// (and get_declared_struct_member_size for a struct member) is the end of the last
// member, without the tail padding a struct's alignment adds; aogen's sizes include that
// padding. So the sizes compared are aogen's unpadded end, and aogen's size rounded
// against SPIRV-Cross's. The padded size itself is checked where it matters, through the
// ArrayStride of arrays of structs and the Offset of the member after a nested struct.
// SPIRV-Cross reports a runtime-sized array's member size as 0 (stride × 0), as aogen does.

#include "glsl_compile.hpp"
#include "random_structs.hpp"
#include "spirv_layout_compare.hpp"

#include <aogen/declare.hpp>
#include <aogen/layout.hpp>

#include <catch2/catch.hpp>

#include <map>
#include <set>

// One namespace per test file: the files of one executable share a translation unit
// (tests/CMakeLists.txt: a unity build), and their helpers must not meet.
namespace unity_test_layout_glsl_oracle {

using namespace aogen::layout;

namespace {

constexpr uint32_t structs_per_rule = 220;

struct check_result {
    bool compiled = false;
    std::string report; // empty when every member agrees
};

// Lays out, declares, compiles and compares one block; the report names the seed, the
// GLSL and each disagreeing member path.
check_result check_glsl_block(const block_desc& block, rules r, const std::string& label)
{
    check_result out;
    const struct_layout l = compute(block, r);
    declaration_options options;
    options.instance = "blk";
    const std::string glsl = declare(l, language::glsl, options);
    const std::string shader = aogen_test::glsl_shader_using(glsl, l, "blk");
    const aogen_test::spirv_result spirv = aogen_test::compile_compute(shader);
    if (!spirv.ok) {
        out.report = label + ": glslang rejected the declaration\n" + spirv.log + "\n" + shader;
        return out;
    }
    out.compiled = true;
    const std::string invalid = aogen_test::validate_spirv(spirv.words, r == rules::scalar);
    if (!invalid.empty()) {
        out.report = label + ": spirv-val rejected glslang's module\n" + invalid + "\n" + glsl;
        return out;
    }
    spirv_cross::Compiler reflect(spirv.words);
    const spirv_cross::SPIRType* type = aogen_test::find_block_type(reflect, l.name);
    if (!type) {
        out.report = label + ": block " + l.name + " not found in the SPIR-V\n" + glsl;
        return out;
    }
    const std::vector<std::string> errors = aogen_test::compare_block(reflect, *type, l);
    if (!errors.empty()) out.report = label + " (" + to_name(r) + "), declaration:\n" + glsl + aogen_test::join_lines(errors);
    return out;
}

void run_random(rules r)
{
    aogen_test::generator_options options;
    options.runtime_array = allows_runtime_array(r);
    int failures = 0, compiled = 0;
    for (uint32_t seed = 1; seed <= structs_per_rule; ++seed) {
        const block_desc block = aogen_test::random_block(seed, options);
        const check_result result = check_glsl_block(block, r, "seed " + std::to_string(seed) + " " + aogen_test::describe(block));
        compiled += result.compiled;
        if (result.report.empty()) continue;
        if (++failures <= 5) FAIL_CHECK(result.report);
    }
    INFO(to_name(r) << ": " << failures << " of " << structs_per_rule << " random structs disagree with glslang");
    CHECK(failures == 0);
    CHECK(compiled == static_cast<int>(structs_per_rule));
}

} // namespace

TEST_CASE("glslang oracle: std140 layouts of random structs", "[layout][oracle][glslang]")
{
    run_random(rules::std140);
}

TEST_CASE("glslang oracle: std430 layouts of random structs", "[layout][oracle][glslang]")
{
    run_random(rules::std430);
}

TEST_CASE("glslang oracle: scalar layouts of random structs", "[layout][oracle][glslang]")
{
    run_random(rules::scalar);
}

TEST_CASE("glslang oracle: the classic cases, by hand", "[layout][oracle][glslang]")
{
    // A few blocks whose layouts are well known, so a generator bug cannot hide them.
    const block_desc cases[] = {
        {{"Blk", {{"a", "vec3"}, {"b", "float"}, {"c", "vec3"}, {"d", "vec2"}, {"e", "float", 4}}}, {}},
        {{"Blk", {{"a", "float"}, {"s", "S"}, {"b", "float"}, {"t", "S", 3}, {"c", "float"}}},
         {{"S", {{"v", "vec3"}, {"f", "float"}, {"x", "float"}}}}},
        {{"Blk", {{"m", "mat2x3"}, {"f", "float"}, {"n", "mat3x2", 2}, {"g", "uint"}, {"k", "mat4x3"}, {"h", "ivec3"}}}, {}},
    };
    for (rules r : {rules::std140, rules::std430, rules::scalar})
        for (const block_desc& block : cases) {
            const check_result result = check_glsl_block(block, r, aogen_test::describe(block));
            CHECK(result.compiled);
            if (!result.report.empty()) FAIL_CHECK(result.report);
        }
}

TEST_CASE("random struct generator covers what the oracles need", "[layout][oracle]")
{
    // The oracles above are only as good as the structs they see: every value type, arrays
    // of 1..5, arrays of structs, two nesting levels, runtime arrays, vec3-then-scalar.
    aogen_test::generator_options options;
    options.runtime_array = true;
    std::set<std::string> types;
    std::set<uint32_t> counts;
    int vec3_then_scalar = 0, struct_arrays = 0, two_levels = 0, runtime = 0;
    for (uint32_t seed = 1; seed <= structs_per_rule; ++seed) {
        const block_desc block = aogen_test::random_block(seed, options);
        std::map<std::string, const struct_desc*> by_name;
        for (const struct_desc& s : block.structs) by_name[s.name] = &s;
        std::vector<const struct_desc*> all{&block.root};
        for (const struct_desc& s : block.structs) all.push_back(&s);
        for (const struct_desc* s : all)
            for (size_t i = 0; i < s->members.size(); ++i) {
                const member_desc& m = s->members[i];
                types.insert(m.type);
                if (m.count) counts.insert(*m.count);
                if (m.count == 0u) ++runtime;
                if (by_name.count(m.type) && m.count) ++struct_arrays;
                if (s == &block.root && by_name.count(m.type))
                    for (const member_desc& inner : by_name[m.type]->members)
                        if (by_name.count(inner.type)) ++two_levels;
                if (i + 1 < s->members.size() && (m.type == "vec3" || m.type == "ivec3" || m.type == "uvec3") && !m.count) {
                    const std::string& next = s->members[i + 1].type;
                    if (next == "float" || next == "int" || next == "uint") ++vec3_then_scalar;
                }
            }
    }
    for (value_type t : all_value_types()) {
        INFO(glsl_name(t));
        CHECK(types.count(glsl_name(t)) == 1);
    }
    CHECK(counts == std::set<uint32_t>{0, 1, 2, 3, 4, 5});
    CHECK(vec3_then_scalar >= static_cast<int>(structs_per_rule / 2));
    CHECK(struct_arrays >= 50);
    CHECK(two_levels >= 30);
    CHECK(runtime >= 30);
}

} // namespace unity_test_layout_glsl_oracle
