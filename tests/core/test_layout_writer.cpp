// Tests for aogen/layout_writer.hpp: values land at the layout's offsets, column-major with
// the layout's matrix stride, padding stays zero, the whole buffer is byte-exact, every
// rejected path or value is an aogen::error naming the path, and a runtime-sized last
// member grows the buffer to offset + n * stride.
#include <aogen/layout_writer.hpp>

#include <catch2/catch.hpp>

#include "support.hpp"

#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

// One namespace per test file: the files of one executable share a translation unit
// (tests/CMakeLists.txt: a unity build), and their helpers must not meet.
namespace unity_test_layout_writer {

using Catch::Contains;
using namespace aogen::layout;
using aogen::mat4;
using aogen::vec2;
using aogen::vec3;
using aogen::vec4;

using aogen_test::error_of;

namespace {

// Writes the 4 little-endian bytes of a float, int or uint at `offset` of `bytes`.
template <class T>
void put(std::vector<uint8_t>& bytes, uint32_t offset, T value)
{
    static_assert(sizeof(T) == 4, "4-byte scalars only");
    uint32_t bits;
    std::memcpy(&bits, &value, 4);
    REQUIRE(offset + 4 <= bytes.size());
    for (int i = 0; i < 4; ++i) bytes[offset + i] = static_cast<uint8_t>(bits >> (8 * i));
}

float float_at(const std::vector<uint8_t>& bytes, uint32_t offset)
{
    uint32_t bits = 0;
    for (int i = 0; i < 4; ++i) bits |= uint32_t(bytes[offset + i]) << (8 * i);
    float f;
    std::memcpy(&f, &bits, 4);
    return f;
}

// The writer's test block:
//   struct Light { vec3 color; float intensity; };
//   Params { float radius; vec4 kernel[16]; Light lights[3]; mat4 proj; mat3 normal;
//            int count; uint flags; float weights[4]; }
// std140, worked by hand: radius 0; kernel 16 (stride 16, 256 bytes); lights 272 (Light is
// 16 bytes: color 0, intensity 12; stride 16); proj 320 (columns 16 apart); normal 384 (mat3:
// three vec3 columns 16 apart, 48 bytes); count 432; flags 436; weights 448 (stride 16,
// 64 bytes); size 512.
block_desc params_block()
{
    return {{"Params",
             {{"radius", "float"},
              {"kernel", "vec4", 16},
              {"lights", "Light", 3},
              {"proj", "mat4"},
              {"normal", "mat3"},
              {"count", "int"},
              {"flags", "uint"},
              {"weights", "float", 4}}},
            {{"Light", {{"color", "vec3"}, {"intensity", "float"}}}}};
}

writer params_writer() { return writer(compute(params_block(), rules::std140)); }

} // namespace

TEST_CASE("writer: the hand-worked std140 offsets of the test block", "[writer]")
{
    const struct_layout l = compute(params_block(), rules::std140);
    CHECK(find(l, "radius")->offset == 0);
    CHECK(find(l, "kernel")->offset == 16);
    CHECK(find(l, "lights")->offset == 272);
    CHECK(find(l, "lights")->array_stride == 16);
    CHECK(find(l, "lights.intensity")->offset == 12);
    CHECK(find(l, "proj")->offset == 320);
    CHECK(find(l, "normal")->offset == 384);
    CHECK(find(l, "normal")->matrix_stride == 16);
    CHECK(find(l, "count")->offset == 432);
    CHECK(find(l, "flags")->offset == 436);
    CHECK(find(l, "weights")->offset == 448);
    CHECK(find(l, "weights")->array_stride == 16);
    CHECK(l.size == 512);
}

TEST_CASE("writer: a new buffer is the struct's size and all zero", "[writer]")
{
    const writer w = params_writer();
    CHECK(w.bytes().size() == 512);
    CHECK(w.bytes() == std::vector<uint8_t>(512, 0));
}

TEST_CASE("writer: a float is stored little-endian at its offset and nothing else changes", "[writer]")
{
    writer w = params_writer();
    w.set("radius", 0.5f); // 0x3F000000
    std::vector<uint8_t> expected(512, 0);
    expected[3] = 0x3F;
    CHECK(w.bytes() == expected);
}

TEST_CASE("writer: int and uint members take int32_t and uint32_t values", "[writer]")
{
    writer w = params_writer();
    w.set("count", int32_t(-2));          // 0xFFFFFFFE
    w.set("flags", uint32_t(0xA1B2C3D4u));
    std::vector<uint8_t> expected(512, 0);
    expected[432] = 0xFE, expected[433] = 0xFF, expected[434] = 0xFF, expected[435] = 0xFF;
    expected[436] = 0xD4, expected[437] = 0xC3, expected[438] = 0xB2, expected[439] = 0xA1;
    CHECK(w.bytes() == expected);
}

TEST_CASE("writer: the whole kernel array from std::vector<vec4>", "[writer]")
{
    writer w = params_writer();
    std::vector<vec4> kernel;
    for (int i = 0; i < 16; ++i) kernel.push_back({float(i), float(i) + 0.25f, -float(i), 1.0f / (i + 1)});
    w.set("kernel", kernel);
    std::vector<uint8_t> expected(512, 0);
    for (uint32_t i = 0; i < 16; ++i) {
        put(expected, 16 + 16 * i + 0, kernel[i].x);
        put(expected, 16 + 16 * i + 4, kernel[i].y);
        put(expected, 16 + 16 * i + 8, kernel[i].z);
        put(expected, 16 + 16 * i + 12, kernel[i].w);
    }
    CHECK(w.bytes() == expected);
}

TEST_CASE("writer: one kernel element by index", "[writer]")
{
    writer w = params_writer();
    w.set("kernel[15]", vec4{1, 2, 3, 4});
    std::vector<uint8_t> expected(512, 0);
    put(expected, 16 + 15 * 16 + 0, 1.0f);
    put(expected, 16 + 15 * 16 + 4, 2.0f);
    put(expected, 16 + 15 * 16 + 8, 3.0f);
    put(expected, 16 + 15 * 16 + 12, 4.0f);
    CHECK(w.bytes() == expected);
}

TEST_CASE("writer: lights[2].color and lights[0].intensity inside an array of structs", "[writer]")
{
    writer w = params_writer();
    w.set("lights[2].color", vec3{1, 0.5f, 0.25f});
    w.set("lights[0].intensity", 7.0f);
    std::vector<uint8_t> expected(512, 0);
    put(expected, 272 + 2 * 16 + 0, 1.0f);
    put(expected, 272 + 2 * 16 + 4, 0.5f);
    put(expected, 272 + 2 * 16 + 8, 0.25f);
    put(expected, 272 + 0 * 16 + 12, 7.0f);
    CHECK(w.bytes() == expected);
}

TEST_CASE("writer: mat4 is written column-major, column c at offset + 16c", "[writer]")
{
    writer w = params_writer();
    mat4 m;
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r) m[c][r] = float(10 * c + r);
    w.set("proj", m);
    std::vector<uint8_t> expected(512, 0);
    for (uint32_t c = 0; c < 4; ++c)
        for (uint32_t r = 0; r < 4; ++r) put(expected, 320 + 16 * c + 4 * r, float(10 * c + r));
    CHECK(w.bytes() == expected);
}

TEST_CASE("writer: std140 mat3 puts column c at c*16 and leaves each column's fourth lane zero", "[writer]")
{
    writer w = params_writer();
    const float m[9] = {1, 2, 3, 4, 5, 6, 7, 8, 9}; // columns (1,2,3), (4,5,6), (7,8,9)
    w.set_floats("normal", m, 9);
    std::vector<uint8_t> expected(512, 0);
    for (uint32_t c = 0; c < 3; ++c)
        for (uint32_t r = 0; r < 3; ++r) put(expected, 384 + 16 * c + 4 * r, m[3 * c + r]);
    CHECK(w.bytes() == expected);
    for (uint32_t c = 0; c < 3; ++c) CHECK(float_at(w.bytes(), 384 + 16 * c + 12) == 0.0f);
}

TEST_CASE("writer: a std140 float array from std::vector<float> uses stride 16", "[writer]")
{
    writer w = params_writer();
    w.set("weights", std::vector<float>{0.5f, 0.25f, 0.125f, 0.0625f});
    w.set("weights[1]", 2.0f); // then one element again
    std::vector<uint8_t> expected(512, 0);
    put(expected, 448, 0.5f);
    put(expected, 464, 2.0f);
    put(expected, 480, 0.125f);
    put(expected, 496, 0.0625f);
    CHECK(w.bytes() == expected);
}

TEST_CASE("writer: the same values give the same bytes, a later write replaces an earlier one", "[writer]")
{
    writer a = params_writer(), b = params_writer();
    a.set("radius", 1.0f);
    a.set("radius", 0.5f);
    b.set("radius", 0.5f);
    CHECK(a.bytes() == b.bytes());
}

TEST_CASE("writer: matrices follow each rule set's matrix stride", "[writer]")
{
    // mat3 has 16-byte columns under std430, wgsl-storage and msl, 12-byte columns under scalar,
    // and one register per column under hlsl-cbuffer (44 bytes in a 48-byte cbuffer).
    const block_desc block{{"M", {{"m", "mat3"}}}, {}};
    const float v[9] = {1, 2, 3, 4, 5, 6, 7, 8, 9};
    struct expect {
        rules rule;
        uint32_t stride, size;
    };
    for (const expect& e : {expect{rules::std430, 16, 48}, expect{rules::scalar, 12, 36},
                            expect{rules::hlsl_cbuffer, 16, 48}, expect{rules::wgsl_storage, 16, 48},
                            expect{rules::msl, 16, 48}}) {
        INFO(to_name(e.rule));
        writer w(compute(block, e.rule));
        w.set_floats("m", v, 9);
        std::vector<uint8_t> expected(e.size, 0);
        for (uint32_t c = 0; c < 3; ++c)
            for (uint32_t r = 0; r < 3; ++r) put(expected, e.stride * c + 4 * r, v[3 * c + r]);
        CHECK(w.bytes() == expected);
    }
}

TEST_CASE("writer: hlsl-cbuffer arrays leave the last element unpadded", "[writer]")
{
    // float a[3] at 0, stride 16, 36 bytes; b packs at 36; the cbuffer is 48 bytes.
    const struct_layout l = compute({{"C", {{"a", "float", 3}, {"b", "float"}}}, {}}, rules::hlsl_cbuffer);
    writer w(l);
    w.set("a", std::vector<float>{1, 2, 3});
    w.set("b", 4.0f);
    std::vector<uint8_t> expected(48, 0);
    put(expected, 0, 1.0f);
    put(expected, 16, 2.0f);
    put(expected, 32, 3.0f);
    put(expected, 36, 4.0f);
    CHECK(w.bytes() == expected);
}

TEST_CASE("writer: an msl packed_float3 is followed directly by its scalar", "[writer]")
{
    const struct_layout l = compute({{"M", {{"c", "vec3"}, {"d", "float"}}}, {}}, rules::msl);
    writer w(l);
    w.set("c", vec3{1, 2, 3});
    w.set("d", 4.0f);
    std::vector<uint8_t> expected(16, 0);
    put(expected, 0, 1.0f);
    put(expected, 4, 2.0f);
    put(expected, 8, 3.0f);
    put(expected, 12, 4.0f);
    CHECK(w.bytes() == expected);
}

TEST_CASE("writer: wgsl-uniform struct members land after their @align(16)", "[writer]")
{
    // S { x: f32 } takes 16 bytes at 16 (see test_layout_wgsl.cpp); y at 32; size 48.
    const struct_layout l =
        compute({{"U", {{"a", "float"}, {"s", "S"}, {"y", "float"}}}, {{"S", {{"x", "float"}}}}}, rules::wgsl_uniform);
    writer w(l);
    w.set("s.x", 2.0f);
    w.set("y", 3.0f);
    std::vector<uint8_t> expected(48, 0);
    put(expected, 16, 2.0f);
    put(expected, 32, 3.0f);
    CHECK(w.bytes() == expected);
}

// ---------------------------------------------------------------------------------
// Runtime-sized last member
// ---------------------------------------------------------------------------------

TEST_CASE("writer: a runtime-sized last member grows the buffer to offset + n * stride", "[writer]")
{
    // std430 { uint count; vec4 data[]; }: data at 16, stride 16; the struct alone is 16 bytes.
    const struct_layout l = compute({{"B", {{"count", "uint"}, {"data", "vec4", 0u}}}, {}}, rules::std430);
    REQUIRE(find(l, "data")->offset == 16);
    REQUIRE(find(l, "data")->array_stride == 16);
    CHECK(writer(l).bytes().size() == 16);
    CHECK(writer(l, 1).bytes().size() == 32);

    writer w(l, 3);
    CHECK(w.bytes().size() == 16 + 3 * 16);
    w.set("count", uint32_t(3));
    w.set("data", std::vector<vec4>{{1, 2, 3, 4}, {5, 6, 7, 8}, {9, 10, 11, 12}});
    std::vector<uint8_t> expected(64, 0);
    put(expected, 0, uint32_t(3));
    for (uint32_t i = 0; i < 12; ++i) put(expected, 16 + 4 * i, float(i + 1));
    CHECK(w.bytes() == expected);

    w.set("data[2]", vec4{0, 0, 0, 1});
    CHECK(float_at(w.bytes(), 16 + 2 * 16 + 12) == 1.0f);
    CHECK(float_at(w.bytes(), 16 + 2 * 16 + 0) == 0.0f);

    CHECK_THAT(error_of([&] { w.set("data[3]", vec4{}); }),
               Contains("data[3]") && Contains("index 3 is out of range") && Contains("0..3"));
    CHECK_THAT(error_of([&] { w.set("data", std::vector<vec4>(4)); }),
               Contains("data") && Contains("given 16 values") && Contains("valid: 12 values"));
}

TEST_CASE("writer: a runtime-sized array of vec3 under wgsl-storage has stride 16", "[writer]")
{
    const struct_layout l = compute({{"D", {{"n", "uint"}, {"dirs", "vec3", 0u}}}, {}}, rules::wgsl_storage);
    writer w(l, 2);
    CHECK(w.bytes().size() == 16 + 2 * 16);
    w.set("dirs[1]", vec3{1, 2, 3});
    std::vector<uint8_t> expected(48, 0);
    put(expected, 32, 1.0f);
    put(expected, 36, 2.0f);
    put(expected, 40, 3.0f);
    CHECK(w.bytes() == expected);
}

// Regression: writer(layout, n) once computed offset + stride * n in uint32_t. With
// std430 { uint count; vec4 data[]; } (data at 16, stride 16) and n = 1 << 28 the buffer should
// be 16 + 2^32 bytes; it wraps and the writer allocates 16 bytes while accepting indices up to
// n - 1, so w.set("data[1]", vec4{}) writes past the end of the vector. Expected: an
// aogen::error for an n whose buffer does not fit in 32 bits. (The test only constructs the
// writer; it never writes through it.)
TEST_CASE("writer: a runtime element count whose buffer exceeds 32 bits is rejected", "[writer][errors][limits]")
{
    const struct_layout l = compute({{"B", {{"count", "uint"}, {"data", "vec4", 0u}}}, {}}, rules::std430);
    CHECK_THROWS_AS(writer(l, 1u << 28), aogen::error);
}

TEST_CASE("writer: no runtime elements means no index is valid", "[writer]")
{
    const struct_layout l = compute({{"B", {{"count", "uint"}, {"data", "float", 0u}}}, {}}, rules::std430);
    writer w(l);
    CHECK_THAT(error_of([&] { w.set("data[0]", 1.0f); }), Contains("data[0]") && Contains("out of range"));
}

// ---------------------------------------------------------------------------------
// Errors: each an aogen::error naming the path
// ---------------------------------------------------------------------------------

TEST_CASE("writer: an unknown member names the path and lists the valid members", "[writer][errors]")
{
    writer w = params_writer();
    CHECK_THAT(error_of([&] { w.set("radiuss", 1.0f); }),
               Contains("radiuss: no member named 'radiuss'") && Contains("valid: radius, kernel, lights"));
    CHECK_THAT(error_of([&] { w.set("lights[1].colour", vec3{}); }),
               Contains("lights[1].colour: no member named 'colour'") && Contains("valid: color, intensity"));
    CHECK_THAT(error_of([&] { w.set("", 1.0f); }), Contains("no member named ''"));
}

TEST_CASE("writer: an index past the end names the path and the valid range", "[writer][errors]")
{
    writer w = params_writer();
    CHECK_THAT(error_of([&] { w.set("kernel[16]", vec4{}); }),
               Contains("kernel[16]") && Contains("index 16 is out of range") && Contains("0..16"));
    CHECK_THAT(error_of([&] { w.set("lights[3].intensity", 1.0f); }),
               Contains("lights[3].intensity") && Contains("index 3 is out of range"));
}

TEST_CASE("writer: a malformed index names the path", "[writer][errors]")
{
    writer w = params_writer();
    for (const char* path : {"kernel[x]", "kernel[-1]", "kernel[]", "kernel[1.5]"}) {
        INFO(path);
        CHECK_THAT(error_of([&] { w.set(path, vec4{}); }), Contains(path) && Contains("is not an array index"));
    }
    // An unclosed bracket is rejected too (whatever the wording), naming the path.
    CHECK_THAT(error_of([&] { w.set("kernel[1", vec4{}); }), Contains("kernel[1"));
}

TEST_CASE("writer: indexing a member that is not an array names the path", "[writer][errors]")
{
    writer w = params_writer();
    CHECK_THAT(error_of([&] { w.set("radius[0]", 1.0f); }),
               Contains("radius[0]") && Contains("'radius' is not an array"));
}

TEST_CASE("writer: the wrong scalar kind names the path, the type and what was given", "[writer][errors]")
{
    writer w = params_writer();
    CHECK_THAT(error_of([&] { w.set("count", 1.0f); }),
               Contains("count: is int, given float values") && Contains("valid: int values"));
    CHECK_THAT(error_of([&] { w.set("flags", int32_t(1)); }),
               Contains("flags: is uint, given int values") && Contains("valid: uint values"));
    CHECK_THAT(error_of([&] { w.set("radius", uint32_t(1)); }),
               Contains("radius: is float, given uint values") && Contains("valid: float values"));
    CHECK(w.bytes() == std::vector<uint8_t>(512, 0)); // nothing written
}

TEST_CASE("writer: the wrong component count names the path and both counts", "[writer][errors]")
{
    writer w = params_writer();
    CHECK_THAT(error_of([&] { w.set("radius", vec2{}); }),
               Contains("radius: is float, given 2 values") && Contains("valid: 1 values"));
    CHECK_THAT(error_of([&] { w.set("lights[0].color", vec4{}); }),
               Contains("lights[0].color: is vec3, given 4 values") && Contains("valid: 3 values"));
    CHECK_THAT(error_of([&] { w.set("normal", mat4{}); }),
               Contains("normal: is mat3, given 16 values") && Contains("valid: 9 values"));
    CHECK_THAT(error_of([&] { w.set("kernel", std::vector<vec4>(15)); }),
               Contains("kernel: is vec4[16], given 60 values") && Contains("valid: 64 values"));
    CHECK_THAT(error_of([&] { w.set("kernel[0]", std::vector<vec4>(2)); }),
               Contains("kernel[0]: is vec4, given 8 values") && Contains("valid: 4 values"));
    CHECK(w.bytes() == std::vector<uint8_t>(512, 0));
}

TEST_CASE("writer: setting a struct is rejected naming the path", "[writer][errors]")
{
    writer w = params_writer();
    CHECK_THAT(error_of([&] { w.set("lights[0]", 1.0f); }),
               Contains("lights[0]: is a struct Light") && Contains("set its members one by one"));
    CHECK_THAT(error_of([&] { w.set("lights", 1.0f); }), Contains("lights: is a struct Light"));
}

TEST_CASE("writer: descending into a non-struct, or into an array without an index, names the path", "[writer][errors]")
{
    writer w = params_writer();
    CHECK_THAT(error_of([&] { w.set("radius.x", 1.0f); }),
               Contains("radius.x") && Contains("cannot descend into 'radius'"));
    CHECK_THAT(error_of([&] { w.set("kernel[0].x", 1.0f); }),
               Contains("kernel[0].x") && Contains("cannot descend into 'kernel'"));
    CHECK_THAT(error_of([&] { w.set("lights.color", vec3{}); }),
               Contains("lights.color") && Contains("cannot descend into 'lights'"));
    CHECK_THAT(error_of([&] { w.set("lights[0]color", vec3{}); }),
               Contains("lights[0]color") && Contains("cannot descend into 'lights'"));
}

} // namespace unity_test_layout_writer
