// Tests for aogen/declare.hpp (the declaration of a laid-out struct in GLSL, HLSL, MSL, WGSL
// and C++) and for the errors aogen/layout.hpp raises on a description it cannot lay out:
// invalid and reserved names, unknown types, duplicates, recursion, empty structs, counts
// too large and misplaced runtime-sized arrays. Every error is an aogen::error whose message
// names the member path (or the name at fault) and the rule broken.
#include <aogen/declare.hpp>
#include <aogen/layout.hpp>

#include <catch2/catch.hpp>

#include "support.hpp"

#include <string>
#include <vector>

// One namespace per test file: the files of one executable share a translation unit
// (tests/CMakeLists.txt: a unity build), and their helpers must not meet.
namespace unity_test_declare {

using Catch::Contains;
using Catch::StartsWith;
using namespace aogen::layout;

using aogen_test::error_of;

namespace {

size_t count_of(const std::string& text, const std::string& what)
{
    size_t n = 0;
    for (size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
    return n;
}

// Seed 004's SSAO uniform block.
block_desc ssao_uniform()
{
    return {{"SsaoUniform",
             {{"inv_proj", "mat4"}, {"proj", "mat4"}, {"radius", "float"}, {"bias", "float"}, {"_pad", "vec2"}}},
            {}};
}

std::string layout_error(const block_desc& block, rules r = rules::std430)
{
    return error_of([&] { compute(block, r); });
}

} // namespace

// ---------------------------------------------------------------------------------
// WGSL
// ---------------------------------------------------------------------------------

TEST_CASE("declare wgsl: seed 004 SsaoUniform under wgsl-uniform, golden text", "[declare][wgsl]")
{
    // 144 bytes; offsets 0, 64, 128, 132, 136 are WGSL's natural placement, so the struct
    // needs no @align or @size: exactly these five members.
    const struct_layout l = compute(ssao_uniform(), rules::wgsl_uniform);
    REQUIRE(l.size == 144);
    const std::string expected =
        "// SsaoUniform: wgsl-uniform layout, 144 bytes, aligned to 16\n"
        "struct SsaoUniform {\n"
        "    inv_proj: mat4x4<f32>,  // offset 0, matrix stride 16\n"
        "    proj: mat4x4<f32>,      // offset 64, matrix stride 16\n"
        "    radius: f32,            // offset 128\n"
        "    bias: f32,              // offset 132\n"
        "    _pad: vec2<f32>,        // offset 136\n"
        "}\n"
        "@group(0) @binding(0) var<uniform> ssaoUniform: SsaoUniform;\n";
    CHECK(declare(l, language::wgsl) == expected);
}

TEST_CASE("declare wgsl: group, binding and instance name come from the options", "[declare][wgsl]")
{
    const struct_layout l = compute(ssao_uniform(), rules::wgsl_uniform);
    const std::string text = declare(l, language::wgsl, {2, 5, "ssao"});
    CHECK_THAT(text, Contains("@group(2) @binding(5) var<uniform> ssao: SsaoUniform;\n"));
}

TEST_CASE("declare wgsl: @align(16) and @size only on the members that need them", "[declare][wgsl]")
{
    // Light { color: vec3, intensity: f32 } is 16 bytes, 16-aligned: nothing to add.
    // Pair { a: f32, b: f32 } is 8 bytes, 4-aligned: @align(16) @size(16) in the uniform space.
    // array<Pair, 2> has stride 8 -> rejected, so use array<Light, 2>: nothing to add.
    // array<mat2x2, 2>: stride 16, natural alignment 8 -> @align(16).
    const block_desc block{{"Frame",
                            {{"time", "float"}, {"pair", "Pair"}, {"light", "Light"}, {"lights", "Light", 2},
                             {"rot", "mat2", 2}, {"exposure", "float"}}},
                           {{"Pair", {{"a", "float"}, {"b", "float"}}},
                            {"Light", {{"color", "vec3"}, {"intensity", "float"}}}}};
    const struct_layout l = compute(block, rules::wgsl_uniform);
    const std::string text = declare(l, language::wgsl);
    CHECK_THAT(text, Contains("    @align(16) @size(16) pair: Pair,  ") && Contains("    light: Light,  ") &&
                         Contains("    lights: array<Light, 2>,  ") &&
                         Contains("    @align(16) rot: array<mat2x2<f32>, 2>,  ") &&
                         Contains("    exposure: f32,  ") && Contains("    time: f32,  "));
    CHECK(count_of(text, "@align(") == 2);
    CHECK(count_of(text, "@size(") == 1);
    // The same block under wgsl-storage needs no attribute at all.
    const std::string storage = declare(compute(block, rules::wgsl_storage), language::wgsl);
    CHECK(count_of(storage, "@align(") == 0);
    CHECK(count_of(storage, "@size(") == 0);
    CHECK_THAT(storage, Contains("var<storage, read> frame: Frame;"));
}

TEST_CASE("declare wgsl: struct types come first, dependencies before users, each once", "[declare][wgsl]")
{
    const block_desc block{{"Scene", {{"a", "Outer"}, {"b", "Inner"}, {"c", "Outer", 2}}},
                           {{"Outer", {{"i", "Inner"}, {"j", "Inner"}}}, {"Inner", {{"v", "vec4"}}}}};
    const std::string text = declare(compute(block, rules::wgsl_storage), language::wgsl);
    CHECK(count_of(text, "struct Inner {") == 1);
    CHECK(count_of(text, "struct Outer {") == 1);
    CHECK(text.find("struct Inner {") < text.find("struct Outer {"));
    CHECK(text.find("struct Outer {") < text.find("struct Scene {"));
}

TEST_CASE("declare wgsl: a runtime-sized last member is array<T>", "[declare][wgsl]")
{
    const block_desc block{{"Points", {{"count", "uint"}, {"points", "vec4", 0u}}}, {}};
    const std::string text = declare(compute(block, rules::wgsl_storage), language::wgsl);
    CHECK_THAT(text, Contains("points: array<vec4<f32>>,") && Contains("count: u32,") &&
                         Contains("var<storage, read> points: Points;"));
}

// ---------------------------------------------------------------------------------
// HLSL, MSL, GLSL, C++
// ---------------------------------------------------------------------------------

TEST_CASE("declare hlsl: matrices are column_major floatRxC, one register per GLSL column", "[declare][hlsl]")
{
    const block_desc block{{"Camera",
                            {{"view", "mat4"}, {"normal", "mat3"}, {"uv", "mat2x3"}, {"w", "mat4x2"},
                             {"jitter", "vec2"}, {"frame", "uint"}}},
                           {}};
    const std::string text = declare(compute(block, rules::hlsl_cbuffer), language::hlsl, {1, 3, ""});
    CHECK_THAT(text, Contains("column_major float4x4 view;") && Contains("column_major float3x3 normal;") &&
                         Contains("column_major float3x2 uv;") && Contains("column_major float2x4 w;") &&
                         Contains("float2 jitter;") && Contains("uint frame;") &&
                         Contains("cbuffer Camera : register(b3, space1) {"));
    CHECK(count_of(text, "column_major") == 4);
    CHECK(count_of(text, "row_major") == 0);
}

TEST_CASE("declare hlsl: member lines carry offsets, array strides and matrix strides", "[declare][hlsl]")
{
    const block_desc block{{"C", {{"a", "float"}, {"w", "float", 3}, {"m", "mat3"}}}, {}};
    const std::string text = declare(compute(block, rules::hlsl_cbuffer), language::hlsl);
    CHECK_THAT(text, Contains("float w[3];") && Contains("// offset 16, stride 16") &&
                         Contains("column_major float3x3 m;") && Contains("// offset 64, matrix stride 16") &&
                         StartsWith("// C: hlsl-cbuffer layout, 112 bytes, aligned to 16\n"));
}

TEST_CASE("declare msl: packed_float3 exactly where a 3-vector is followed by a scalar", "[declare][msl]")
{
    // a (then float), e (then int) and k (ivec3 then uint) are packed; c (then vec3), d (then
    // vec3), g (then vec4), i (then vec2), arr (an array) and last (no follower) are not.
    const block_desc block{{"M",
                            {{"a", "vec3"}, {"b", "float"}, {"c", "vec3"}, {"d", "vec3"}, {"e", "vec3"},
                             {"f", "int"}, {"g", "vec3"}, {"h", "vec4"}, {"i", "vec3"}, {"j", "vec2"},
                             {"k", "ivec3"}, {"l", "uint"}, {"arr", "vec3", 2}, {"x", "float"},
                             {"last", "vec3"}}},
                           {}};
    const struct_layout l = compute(block, rules::msl);
    const std::string text = declare(l, language::msl);
    CHECK(count_of(text, "packed_") == 3);
    CHECK_THAT(text, Contains("packed_float3 a;") && Contains("packed_float3 e;") && Contains("packed_int3 k;") &&
                         Contains("    float3 c;") && Contains("    float3 d;") && Contains("    float3 g;") &&
                         Contains("    float3 i;") && Contains("    float3 arr[2];") &&
                         Contains("    float3 last;"));
    // The packed vector is 12 bytes and its scalar takes the fourth lane.
    CHECK(find(l, "a")->size == 12);
    CHECK(find(l, "b")->offset == 12);
    CHECK(find(l, "c")->offset == 16);
    CHECK(find(l, "c")->size == 16);
    CHECK(find(l, "e")->offset == 48);
    CHECK(find(l, "f")->offset == 60);
    CHECK(find(l, "k")->offset == 120);
    CHECK(find(l, "l")->offset == 132);
}

TEST_CASE("declare msl: matrices are floatCxR, as in GLSL", "[declare][msl]")
{
    const block_desc block{{"M", {{"a", "mat2x3"}, {"b", "mat4"}}}, {}};
    const std::string text = declare(compute(block, rules::msl), language::msl);
    CHECK_THAT(text, Contains("float2x3 a;") && Contains("float4x4 b;") && Contains("struct M\n{\n"));
}

TEST_CASE("declare glsl: std140 uniform block, std430 and scalar readonly buffers", "[declare][glsl]")
{
    const block_desc block{{"Params", {{"radius", "float"}, {"kernel", "vec4", 16}}}, {}};
    const std::string u = declare(compute(block, rules::std140), language::glsl, {0, 1, ""});
    CHECK_THAT(u, Contains("layout(std140, set = 0, binding = 1) uniform Params {") && Contains("} params;") &&
                      Contains("vec4 kernel[16];"));
    const std::string b = declare(compute(block, rules::std430), language::glsl, {1, 2, "p"});
    CHECK_THAT(b, Contains("layout(std430, set = 1, binding = 2) readonly buffer Params {") && Contains("} p;"));
    const std::string s = declare(compute(block, rules::scalar), language::glsl);
    CHECK_THAT(s, Contains("#extension GL_EXT_scalar_block_layout : require") &&
                      Contains("layout(scalar, set = 0, binding = 0) readonly buffer Params {"));
}

TEST_CASE("declare cpp: padding members and a static_assert per offset and on the size", "[declare][cpp]")
{
    const block_desc block{{"Params", {{"radius", "float"}, {"dir", "vec3"}, {"w", "float", 2}}}, {}};
    const std::string text = declare(compute(block, rules::std140), language::cpp);
    CHECK_THAT(text, Contains("std::uint8_t _pad0[12];") && Contains("static_assert(offsetof(Params, dir) == 16);") &&
                         Contains("static_assert(offsetof(Params, w) == 32);") &&
                         Contains("std::array<aogen_padded<float, 16>, 2> w;") &&
                         Contains("static_assert(sizeof(Params) == 64);"));
}

// ---------------------------------------------------------------------------------
// A language that cannot express the rule set
// ---------------------------------------------------------------------------------

TEST_CASE("declare: a language that cannot express the rules throws naming both", "[declare][errors]")
{
    const block_desc block{{"P", {{"a", "float"}, {"b", "vec4"}}}, {}};
    auto accepts = [](language lang, rules r) {
        switch (lang) {
        case language::glsl: return r == rules::std140 || r == rules::std430 || r == rules::scalar;
        case language::hlsl: return r == rules::hlsl_cbuffer;
        case language::msl: return r == rules::msl;
        case language::wgsl: return r == rules::wgsl_uniform || r == rules::wgsl_storage;
        case language::cpp: return true;
        }
        return false;
    };
    for (rules r : all_rules) {
        const struct_layout l = compute(block, r);
        for (language lang : all_languages) {
            INFO(to_name(lang) << " for " << to_name(r));
            if (accepts(lang, r)) {
                CHECK_NOTHROW(declare(l, lang));
            } else {
                CHECK_THAT(error_of([&] { declare(l, lang); }),
                           StartsWith(std::string(to_name(lang)) + " declaration of P: cannot express " + to_name(r) +
                                      " rules") &&
                               Contains("valid rules: "));
            }
        }
    }
}

TEST_CASE("declare: glsl for hlsl-cbuffer and wgsl for std140, spelled out", "[declare][errors]")
{
    const block_desc block{{"P", {{"a", "float"}}}, {}};
    CHECK(error_of([&] { declare(compute(block, rules::hlsl_cbuffer), language::glsl); }) ==
          "glsl declaration of P: cannot express hlsl-cbuffer rules (valid rules: std140, std430, scalar)");
    CHECK(error_of([&] { declare(compute(block, rules::std140), language::wgsl); }) ==
          "wgsl declaration of P: cannot express std140 rules (valid rules: wgsl-uniform, wgsl-storage)");
}

TEST_CASE("declare: rule and language names round-trip, unknown names list the valid ones", "[declare][errors]")
{
    for (rules r : all_rules) CHECK(rules_from_name(to_name(r)) == r);
    for (language l : all_languages) CHECK(language_from_name(to_name(l)) == l);
    CHECK(error_of([] { rules_from_name("std150"); }) ==
          "layout rules: 'std150' is not a known name (valid: std140, std430, scalar, wgsl-storage, wgsl-uniform, "
          "hlsl-cbuffer, msl)");
    CHECK(error_of([] { language_from_name("spirv"); }) ==
          "language: 'spirv' is not a known name (valid: glsl, hlsl, msl, wgsl, cpp)");
    // '-' and '_' are the same character in names; to_name keeps the table's spelling.
    CHECK(rules_from_name("wgsl_storage") == rules::wgsl_storage);
    CHECK(rules_from_name("hlsl-cbuffer") == rules::hlsl_cbuffer);
    CHECK(std::string(to_name(rules::wgsl_uniform)) == "wgsl-uniform");
    CHECK(rules_names() == "std140, std430, scalar, wgsl-storage, wgsl-uniform, hlsl-cbuffer, msl");
    CHECK(all_rules.size() == 7);
    CHECK(all_languages.size() == 5);
    CHECK(error_of([] { to_name(static_cast<rules>(7)); }) ==
          "layout rules: 7 is not a valid value (valid: std140, std430, scalar, wgsl-storage, wgsl-uniform, "
          "hlsl-cbuffer, msl)");
    CHECK(error_of([] { to_name(static_cast<language>(5)); }) ==
          "language: 5 is not a valid value (valid: glsl, hlsl, msl, wgsl, cpp)");
}

// ---------------------------------------------------------------------------------
// layout.hpp: names
// ---------------------------------------------------------------------------------

TEST_CASE("layout: member names must be identifiers", "[layout][errors]")
{
    for (const char* bad : {"", "2x", "a-b", "a b", "a.b", "a[0]"}) {
        INFO("'" << bad << "'");
        const std::string message = layout_error({{"P", {{"ok", "float"}, {bad, "float"}}}, {}});
        CHECK_THAT(message, StartsWith("P." + std::string(bad) + ": '" + bad + "' is not an identifier") &&
                                Contains("valid: letters, digits and _, not starting with a digit"));
    }
    CHECK_NOTHROW(compute({{"P", {{"_pad", "float"}, {"a1_b2", "float"}}}, {}}, rules::std140));
}

TEST_CASE("layout: the block name and struct names must be identifiers", "[layout][errors]")
{
    CHECK_THAT(layout_error({{"1P", {{"a", "float"}}}, {}}),
               StartsWith("block name: '1P' is not an identifier"));
    CHECK_THAT(layout_error({{"P", {{"a", "my-struct"}}}, {{"my-struct", {{"x", "float"}}}}}),
               StartsWith("struct name: 'my-struct' is not an identifier"));
}

TEST_CASE("layout: a struct may not take a built-in type's name", "[layout][errors]")
{
    for (const char* reserved : {"float", "int", "uint", "vec3", "ivec2", "uvec4", "mat4", "mat2x3", "mat3x3"}) {
        INFO(reserved);
        CHECK_THAT(layout_error({{"P", {{"a", "float"}}}, {{reserved, {{"x", "float"}}}}}),
                   StartsWith(std::string("struct name: '") + reserved + "' is a keyword or type name") &&
                       Contains("valid: any other identifier"));
    }
}

TEST_CASE("layout: a struct may be defined only once", "[layout][errors]")
{
    CHECK_THAT(layout_error({{"P", {{"l", "L"}}}, {{"L", {{"x", "float"}}}, {"L", {{"y", "vec4"}}}}}),
               StartsWith("struct L: is defined twice") && Contains("one definition per struct name"));
}

TEST_CASE("layout: the block may not share its name with one of its struct types", "[layout][errors]")
{
    // Found while writing these tests: `Light { main: Light }` with a struct Light made WGSL,
    // MSL and C++ declarations with two `struct Light` definitions. Fixed in layout.hpp by
    // rejecting the name.
    const block_desc block{{"Light", {{"main", "Light"}, {"k", "float"}}}, {{"Light", {{"color", "vec3"}}}}};
    for (rules r : all_rules) {
        INFO(to_name(r));
        CHECK(layout_error(block, r) ==
              "block name: 'Light' is also the name of a struct (valid: a name no struct in block.structs uses)");
    }
}

// Regression: layout.hpp once accepted keywords of the target languages as member
// names, so declare() emitted declarations that no shader compiler accepts -- e.g. a member
// named `struct` gives GLSL `float struct;`, HLSL `float struct;`, MSL `float struct;`, WGSL
// `struct: f32,` and C++ `float struct;`. Now: an aogen::error naming the member path.
TEST_CASE("layout: keywords of the target languages are rejected as member names", "[layout][errors][limits]")
{
    for (const char* keyword : {"struct", "float"}) {
        INFO(keyword);
        CHECK_THAT(layout_error({{"P", {{keyword, "float"}}}, {}}), StartsWith(std::string("P.") + keyword + ": "));
    }
}

// ---------------------------------------------------------------------------------
// layout.hpp: types, duplicates, recursion, empty structs, counts
// ---------------------------------------------------------------------------------

TEST_CASE("layout: an unknown type names the member and lists the valid types", "[layout][errors]")
{
    const std::string message =
        layout_error({{"P", {{"a", "float"}, {"dir", "vec5"}}}, {{"Light", {{"x", "float"}}}, {"Ray", {{"o", "vec3"}}}}});
    CHECK(message == "P.dir: unknown type 'vec5' (valid: float, int, uint, vec2..4, ivec2..4, uvec2..4, mat2..4, "
                     "matCxR, Light, Ray)");
    // Types are spelled as in GLSL: WGSL and HLSL spellings are unknown.
    for (const char* other : {"f32", "float3", "vec3<f32>", "double", "bool", "mat5", "mat4x5", "Vec3"}) {
        INFO(other);
        CHECK_THAT(layout_error({{"P", {{"a", other}}}, {}}),
                   StartsWith(std::string("P.a: unknown type '") + other + "'") && Contains("valid: float"));
    }
}

TEST_CASE("layout: an unknown type inside a struct names the full member path", "[layout][errors]")
{
    CHECK_THAT(layout_error({{"P", {{"light", "Light"}}}, {{"Light", {{"color", "colour3"}}}}}),
               StartsWith("P.light.color: unknown type 'colour3'"));
}

TEST_CASE("layout: a member declared twice is rejected with its path", "[layout][errors]")
{
    CHECK(layout_error({{"P", {{"a", "float"}, {"b", "vec2"}, {"a", "vec4"}}}, {}}) ==
          "P.a: is declared twice (valid: unique member names)");
    CHECK(layout_error({{"P", {{"l", "L"}}}, {{"L", {{"x", "float"}, {"x", "float"}}}}}) ==
          "P.l.x: is declared twice (valid: unique member names)");
}

TEST_CASE("layout: a struct that contains itself is rejected", "[layout][errors]")
{
    CHECK(layout_error({{"P", {{"n", "Node"}}}, {{"Node", {{"v", "float"}, {"next", "Node"}}}}}) ==
          "P.n.next: struct Node contains itself (valid: structs nest without cycles)");
    // Through another struct, and through an array.
    CHECK_THAT(layout_error({{"P", {{"a", "A"}}}, {{"A", {{"b", "B"}}}, {"B", {{"a", "A", 2}}}}}),
               StartsWith("P.a.b.a: struct A contains itself"));
    // The same struct twice side by side is not recursion.
    CHECK_NOTHROW(compute({{"P", {{"x", "V"}, {"y", "V"}}}, {{"V", {{"v", "vec4"}}}}}, rules::std140));
}

TEST_CASE("layout: empty structs are rejected", "[layout][errors]")
{
    CHECK(layout_error({{"P", {}}, {}}) == "P: has no members (valid: at least one member)");
    CHECK(layout_error({{"P", {{"a", "float"}, {"e", "Empty"}}}, {{"Empty", {}}}}) ==
          "P.e: has no members (valid: at least one member)");
}

TEST_CASE("layout: array counts above the maximum are rejected", "[layout][errors]")
{
    const uint32_t too_many = max_array_count + 1;
    CHECK(layout_error({{"P", {{"a", "float", too_many}}}, {}}) ==
          "P.a: array count 1048577 is too large (valid: 0 (runtime-sized) or 1..1048576)");
    const struct_layout l = compute({{"P", {{"a", "float", max_array_count}}}, {}}, rules::scalar);
    CHECK(l.size == 4u * max_array_count);
}

// Regression: sizes are uint32_t and once wrapped silently. max_array_count (2^20) bounds
// one array, but an array of structs that themselves hold large arrays multiplies past 2^32:
// S { vec4 a[1 << 20]; } is 16 MiB, so S s[256] is 2^32 bytes, and compute() returns
// P.size == 0 under every rule set. Now: an aogen::error naming P.s and the 1 GiB limit.
TEST_CASE("layout: a block of 4 GiB or more is rejected instead of wrapping its size to 0", "[layout][errors][limits]")
{
    const block_desc block{{"P", {{"s", "S", 256}}}, {{"S", {{"a", "vec4", max_array_count}}}}};
    for (rules r : all_rules) {
        INFO(to_name(r));
        CHECK_THAT(layout_error(block, r), StartsWith("P.s: "));
    }
}

TEST_CASE("layout: a runtime-sized array must be the last member of the top-level block", "[layout][errors]")
{
    CHECK(layout_error({{"P", {{"data", "vec4", 0u}, {"count", "uint"}}}, {}}, rules::std430) ==
          "P.data: a runtime-sized array must be the last member of the top-level block (rules: std430)");
    CHECK(layout_error({{"P", {{"count", "uint"}, {"inner", "I"}}}, {{"I", {{"x", "float"}, {"data", "float", 0u}}}}},
                       rules::scalar) ==
          "P.inner.data: a runtime-sized array must be the last member of the top-level block (rules: scalar)");
    for (rules r : {rules::std430, rules::scalar, rules::wgsl_storage, rules::msl}) {
        INFO(to_name(r));
        CHECK_NOTHROW(compute({{"P", {{"count", "uint"}, {"data", "vec4", 0u}}}, {}}, r));
    }
}

TEST_CASE("layout: a runtime-sized array in a uniform rule set names the member and the rules", "[layout][errors]")
{
    for (rules r : {rules::std140, rules::wgsl_uniform, rules::hlsl_cbuffer}) {
        INFO(to_name(r));
        CHECK(layout_error({{"P", {{"count", "uint"}, {"data", "vec4", 0u}}}, {}}, r) ==
              "P.data: a runtime-sized array cannot be in a uniform block; use std430, scalar, wgsl-storage or msl "
              "(rules: " +
                  std::string(to_name(r)) + ")");
    }
}

} // namespace unity_test_declare
