// Hand-worked layout cases for hlsl-cbuffer (no DXC or FXC on this machine).
//
// Sources, cited per case:
//   [MS]      Microsoft, "Packing Rules for Constant Variables" (learn.microsoft.com,
//             direct3dhlsl/dx-graphics-hlsl-packing-rules; MicrosoftDocs/win32
//             desktop-src/direct3dhlsl/dx-graphics-hlsl-packing-rules.md): its eleven `cbuffer IE`
//             examples with their sizes in 16-byte elements.
//   [MS-legacy] the same rules restated as "Legacy Constant Buffer Basics" (Microsoft's
//             Global Blocks / Constant Buffer Packing page and the DirectXShaderCompiler wiki page
//             "Buffer Packing"): rows of 16 bytes; scalars and vectors packed into the last row if
//             they fit; matrices with more than one row (in row_major-equivalent storage) aligned
//             to a row, each column of a column_major matrix in its own row; arrays and structs
//             row-aligned, and "if the aggregate ends in an element that does not completely
//             fill a row, the remaining space on the last row may be used by the next value".
//   [0034]    LLVM wg-hlsl proposal 0034 "Explicit Padding in Structs and CBuffer Arrays":
//             cbuffer cb1 (struct S { int v; }: i 0, s 16, j 20) and cb2
//             (float a1[3]: offset 0, size 4 (+12) * 3, the last element unpadded).
//   [0016]    LLVM wg-hlsl proposal 0016 "Constant buffers": cbuffer Constants { int i; S s; }
//             with layout size 20 and cbuffer OtherConstants { float4 v; int array[10]; } with
//             layout size 164.
//   [0003]    LLVM wg-hlsl proposal 0003 "packoffset": "without the packoffset, Element2 will be
//             in c1.x" (and Microsoft's packoffset page: Element1 c0, Element2 c1, Element3 c1.y).
//   [DXC-fxc] DirectXShaderCompiler tests that record FXC's reflection offsets:
//             tools/clang/test/CodeGenSPIRV/vk.layout.cbuffer.fxc.hlsl (struct S and
//             cbuffer MyCBuffer) and vk.layout.cbuffer.fxc.matrix.array.hlsl (float3x2 foo[7]).
//
// Translating HLSL types into our GLSL-typed description: floatN/intN/uintN = vecN/ivecN/uvecN.
// HLSL floatRxC has R rows and C columns; column_major (the default) stores each column in its
// own register, so it is GLSL matCxR (C columns of R rows): float3x2 = mat2x3,
// float2x3 = mat3x2, float4x4 = mat4. `row_major floatRxC` stores each row in a register,
// which is the storage of column_major floatCxR, i.e. GLSL matRxC: row_major float2x3 = mat2x3,
// row_major float3x2 = mat3x2. Doubles and 16-bit types have no counterpart here; cases that
// contain them are cut down to runs of 32-bit members and their offsets made relative to the
// run's first member (stated per case).
#include <aogen/declare.hpp>
#include <aogen/layout.hpp>

#include <catch2/catch.hpp>

#include "support.hpp"

#include <string>

// One namespace per test file: the files of one executable share a translation unit
// (tests/CMakeLists.txt: a unity build), and their helpers must not meet.
namespace unity_test_layout_hlsl {

using Catch::Contains;
using namespace aogen::layout;

using aogen_test::error_of;
using aogen_test::at;

namespace {

void check(const struct_layout& l, const char* path, uint32_t offset, uint32_t size)
{
    const member_layout& m = at(l, path);
    INFO("member " << path);
    CHECK(m.offset == offset);
    CHECK(m.size == size);
}

struct_layout cbuffer(const block_desc& block) { return compute(block, rules::hlsl_cbuffer); }

// The MS examples name the struct members SVal1, SVal2.
struct_desc s_vec4_float() { return {"S41", {{"SVal1", "vec4"}, {"SVal2", "float"}}}; }
struct_desc s_float_vec4() { return {"S14", {{"SVal1", "float"}, {"SVal2", "vec4"}}}; }

} // namespace

// ---------------------------------------------------------------------------------
// [MS] Microsoft's eleven examples
// ---------------------------------------------------------------------------------

TEST_CASE("hlsl-cbuffer [MS 1]: float4, float2, float2 is 2 x 16 bytes", "[layout][hlsl]")
{
    // float4 Val1; float2 Val2; // starts a new vector; float2 Val3;  -- 2 x 16byte elements
    const struct_layout l = cbuffer({{"IE", {{"Val1", "vec4"}, {"Val2", "vec2"}, {"Val3", "vec2"}}}, {}});
    check(l, "Val1", 0, 16);
    check(l, "Val2", 16, 8);
    check(l, "Val3", 24, 8);
    CHECK(l.size == 32);
}

TEST_CASE("hlsl-cbuffer [MS 2]: float2, float4, float2 is 3 x 16 bytes", "[layout][hlsl]")
{
    // float2 Val1; float4 Val2; // starts a new vector; float2 Val3; // starts a new vector
    const struct_layout l = cbuffer({{"IE", {{"Val1", "vec2"}, {"Val2", "vec4"}, {"Val3", "vec2"}}}, {}});
    check(l, "Val1", 0, 8);
    check(l, "Val2", 16, 16);
    check(l, "Val3", 32, 8);
    CHECK(l.size == 48);
}

TEST_CASE("hlsl-cbuffer [MS 3]: float1, float1, float2 is 1 x 16 bytes", "[layout][hlsl]")
{
    const struct_layout l = cbuffer({{"IE", {{"Val1", "float"}, {"Val2", "float"}, {"Val3", "vec2"}}}, {}});
    check(l, "Val1", 0, 4);
    check(l, "Val2", 4, 4);
    check(l, "Val3", 8, 8);
    CHECK(l.size == 16);
}

TEST_CASE("hlsl-cbuffer [MS 4]: float1, float2, float1 is 1 x 16 bytes (float2 at c0.y)", "[layout][hlsl]")
{
    // A float2 needs only 4-byte alignment: it fits at 4..12 without straddling.
    const struct_layout l = cbuffer({{"IE", {{"Val1", "float"}, {"Val2", "vec2"}, {"Val3", "float"}}}, {}});
    check(l, "Val1", 0, 4);
    check(l, "Val2", 4, 8);
    check(l, "Val3", 12, 4);
    CHECK(l.size == 16);
}

TEST_CASE("hlsl-cbuffer [MS 5]: three float1 then float2 is 2 x 16 bytes", "[layout][hlsl]")
{
    // float1 Val1; float1 Val1; float1 Val1; float2 Val2; // starts a new vector
    // (the example repeats the name Val1; ours must be unique)
    const struct_layout l =
        cbuffer({{"IE", {{"Val1a", "float"}, {"Val1b", "float"}, {"Val1c", "float"}, {"Val2", "vec2"}}}, {}});
    check(l, "Val1c", 8, 4);
    check(l, "Val2", 16, 8); // 12..20 would straddle
    CHECK(l.size == 32);
}

TEST_CASE("hlsl-cbuffer [MS 6]: float3, float1 is 1 x 16 bytes", "[layout][hlsl]")
{
    const struct_layout l = cbuffer({{"IE", {{"Val1", "vec3"}, {"Val2", "float"}}}, {}});
    check(l, "Val1", 0, 12);
    check(l, "Val2", 12, 4);
    CHECK(l.size == 16);
}

TEST_CASE("hlsl-cbuffer [MS 7]: float1, float3 is 1 x 16 bytes (float3 at c0.y)", "[layout][hlsl]")
{
    const struct_layout l = cbuffer({{"IE", {{"Val1", "float"}, {"Val2", "vec3"}}}, {}});
    check(l, "Val1", 0, 4);
    check(l, "Val2", 4, 12);
    CHECK(l.size == 16);
}

TEST_CASE("hlsl-cbuffer [MS 8]: float1, float1, float3 is 2 x 16 bytes", "[layout][hlsl]")
{
    // float1 Val1; float1 Val1; float3 Val2; // starts a new vector
    const struct_layout l = cbuffer({{"IE", {{"Val1a", "float"}, {"Val1b", "float"}, {"Val2", "vec3"}}}, {}});
    check(l, "Val2", 16, 12);
    CHECK(l.size == 32);
}

TEST_CASE("hlsl-cbuffer [MS 9]: float1 then struct { float4, float1 } is 3 x 16 bytes", "[layout][hlsl]")
{
    // float1 Val1; struct { float4 SVal1; // starts a new vector
    //                        float1 SVal2; // starts a new vector } Val2;
    const struct_layout l = cbuffer({{"IE", {{"Val1", "float"}, {"Val2", "S41"}}}, {s_vec4_float()}});
    check(l, "Val1", 0, 4);
    check(l, "Val2", 16, 20); // a struct starts a register; its size is not padded
    CHECK(at(l, "Val2.SVal1").offset == 0);
    CHECK(at(l, "Val2.SVal2").offset == 16);
    CHECK(l.size == 48);
}

TEST_CASE("hlsl-cbuffer [MS 10]: float1 then struct { float1, float4 } is 3 x 16 bytes", "[layout][hlsl]")
{
    // float1 Val1; struct { float1 SVal1; // starts a new vector
    //                        float4 SVal2; // starts a new vector } Val2;
    const struct_layout l = cbuffer({{"IE", {{"Val1", "float"}, {"Val2", "S14"}}}, {s_float_vec4()}});
    check(l, "Val2", 16, 32);
    CHECK(at(l, "Val2.SVal1").offset == 0);
    CHECK(at(l, "Val2.SVal2").offset == 16); // 4..20 would straddle
    CHECK(l.size == 48);
}

TEST_CASE("hlsl-cbuffer [MS 11]: struct { float4, float1 } then float1 shares the struct's last register", "[layout][hlsl]")
{
    // struct { float4 SVal1; float1 SVal2; } Val1; float1 Val2;
    // [MS] labels this "3 x 16byte elements" (and an older revision comments Val2 "starts a new
    // vector"), but that contradicts [MS-legacy] rule 4 ("the remaining space on the last row
    // may be used by the next value") and [0034]'s cb1, where `int j` follows `S s` at 20 in
    // the struct's register. FXC and DXC place Val2 at c1.y (offset 20): 2 x 16 bytes. We follow
    // the compilers and [0034]; the [MS] figure for this one example is not used.
    const struct_layout l = cbuffer({{"IE", {{"Val1", "S41"}, {"Val2", "float"}}}, {s_vec4_float()}});
    check(l, "Val1", 0, 20);
    check(l, "Val2", 20, 4);
    CHECK(l.size == 32);
}

// ---------------------------------------------------------------------------------
// [0003] [0034] [0016]: LLVM's HLSL proposals
// ---------------------------------------------------------------------------------

TEST_CASE("hlsl-cbuffer [0003]: float4, float1, float1 go to c0, c1.x, c1.y", "[layout][hlsl]")
{
    // cbuffer MyBuffer { float4 Element1 : packoffset(c0); float1 Element2 : packoffset(c1);
    // float1 Element3 : packoffset(c1.y); } -- the packoffsets spell out the automatic packing.
    const struct_layout l =
        cbuffer({{"MyBuffer", {{"Element1", "vec4"}, {"Element2", "float"}, {"Element3", "float"}}}, {}});
    check(l, "Element1", 0, 16);
    check(l, "Element2", 16, 4);
    check(l, "Element3", 20, 4);
    CHECK(l.size == 32);
}

TEST_CASE("hlsl-cbuffer [0034 cb1]: int i, S s, int j gives 0, 16, 20", "[layout][hlsl]")
{
    // struct S { int v; }; cbuffer cb1 { int i; // offset 0, size 4 (+12)
    //                                    S s;   // offset 16, size 4
    //                                    int j; // offset 20, size 4 }
    const struct_layout l = cbuffer({{"cb1", {{"i", "int"}, {"s", "S"}, {"j", "int"}}}, {{"S", {{"v", "int"}}}}});
    check(l, "i", 0, 4);
    check(l, "s", 16, 4);
    check(l, "j", 20, 4);
    CHECK(l.size == 32); // whole registers
}

TEST_CASE("hlsl-cbuffer [0034 cb2]: float a1[3] is 36 bytes, stride 16, last element unpadded", "[layout][hlsl]")
{
    // cbuffer cb2 { float a1[3]; // offset 0, size 4 (+12) * 3 ... uint4 a3[2]; // size 16 * 2 }
    // LLVM type <{ [2 x <{ float, pad 12 }>], float }> = 36 bytes. The example's double3 a2[2]
    // and float16_t a4 are left out, so a3 (an array: starts a register) follows a1 at 48
    // instead of the example's 112; its size 16 * 2 is the example's.
    const struct_layout l = cbuffer({{"cb2", {{"a1", "float", 3}, {"a3", "uvec4", 2}}}, {}});
    const member_layout& a1 = at(l, "a1");
    CHECK(a1.offset == 0);
    CHECK(a1.array_stride == 16);
    CHECK(a1.element_size == 4);
    CHECK(a1.size == 36);
    const member_layout& a3 = at(l, "a3");
    CHECK(a3.offset == 48);
    CHECK(a3.array_stride == 16);
    CHECK(a3.size == 32);
    CHECK(l.size == 80);
}

TEST_CASE("hlsl-cbuffer [0016]: Constants { int i, S s, } has layout size 20", "[layout][hlsl]")
{
    // struct S { float f; }; cbuffer Constants { int i; S s; };
    // target("dx.Layout", %__cblayout_Constants, 20, 0, 16): i at 0, s at 16, 20 bytes of
    // layout; the buffer itself is whole registers, 32 bytes.
    const struct_layout l =
        cbuffer({{"Constants", {{"i", "int"}, {"s", "S"}}}, {{"S", {{"f", "float"}}}}});
    check(l, "i", 0, 4);
    check(l, "s", 16, 4);
    CHECK(at(l, "s").offset + at(l, "s").size == 20);
    CHECK(l.size == 32);
}

TEST_CASE("hlsl-cbuffer [0016]: OtherConstants { float4 v, int array[10], } has layout size 164", "[layout][hlsl]")
{
    // target("dx.Layout", %__cblayout_OtherConstants, 164, 0, 16): v at 0, array at 16 with
    // 9 padded elements and an unpadded last one: 9 * 16 + 4 = 148; 16 + 148 = 164.
    const struct_layout l = cbuffer({{"OtherConstants", {{"v", "vec4"}, {"array", "int", 10}}}, {}});
    check(l, "v", 0, 16);
    const member_layout& a = at(l, "array");
    CHECK(a.offset == 16);
    CHECK(a.array_stride == 16);
    CHECK(a.size == 148);
    CHECK(a.offset + a.size == 164);
    CHECK(l.size == 176);
}

// ---------------------------------------------------------------------------------
// [DXC-fxc]: FXC's reflection offsets recorded in DXC's tests
// ---------------------------------------------------------------------------------

TEST_CASE("hlsl-cbuffer [DXC-fxc struct S]: the four 2x3 / 3x2 matrices and the array after them", "[layout][hlsl]")
{
    // struct S: float2x3 matrix1 112; row_major float2x3 matrix2 160; float3x2 matrix3 192;
    // row_major float3x2 matrix4 224; float scalarArray1[1] 272 (offsets relative to matrix1:
    // 0, 48, 80, 112, 160). MatrixStride 16 for all four.
    // float2x3 = mat3x2 (3 registers, last 8 bytes: 40); row_major float2x3 = mat2x3 (28);
    // float3x2 = mat2x3 (28); row_major float3x2 = mat3x2 (40).
    const struct_layout l = cbuffer({{"S",
                                      {{"matrix1", "mat3x2"},
                                       {"matrix2", "mat2x3"},
                                       {"matrix3", "mat2x3"},
                                       {"matrix4", "mat3x2"},
                                       {"scalarArray1", "float", 1}}},
                                     {}});
    check(l, "matrix1", 0, 40);
    check(l, "matrix2", 48, 28);
    check(l, "matrix3", 80, 28);
    check(l, "matrix4", 112, 40);
    check(l, "scalarArray1", 160, 4);
    for (const char* m : {"matrix1", "matrix2", "matrix3", "matrix4"}) CHECK(at(l, m).matrix_stride == 16);
}

TEST_CASE("hlsl-cbuffer [DXC-fxc MyCBuffer 2000..2096]: one-element arrays, float3 and float2x3[1]", "[layout][hlsl]")
{
    // float CB_scalarArray1[1] 2000 (size 4); float3 CB_vectorArray1[1] 2016 (12);
    // float3 CB_vector1 2032 (12); float2x3 CB_matrixArray1[1] 2048 (40); float3 CB_vector2 2096.
    // Relative to 2000: 0, 16, 32, 48, 96. The float3 after the 12-byte array cannot fit in
    // 28..40 (straddles 32), and the one after the matrix array cannot fit in 88..100.
    const struct_layout l = cbuffer({{"MyCBuffer",
                                      {{"CB_scalarArray1", "float", 1},
                                       {"CB_vectorArray1", "vec3", 1},
                                       {"CB_vector1", "vec3"},
                                       {"CB_matrixArray1", "mat3x2", 1},
                                       {"CB_vector2", "vec3"}}},
                                     {}});
    check(l, "CB_scalarArray1", 0, 4);
    check(l, "CB_vectorArray1", 16, 12);
    check(l, "CB_vector1", 32, 12);
    check(l, "CB_matrixArray1", 48, 40);
    check(l, "CB_vector2", 96, 12);
}

TEST_CASE("hlsl-cbuffer [DXC-fxc MyCBuffer 2224..2432]: matrices and arrays of matrices", "[layout][hlsl]")
{
    // row_major float2x3 CB_matrix2 2224 (28); row_major float2x3 CB_matrixArray2[2] 2256 (60);
    // float3x2 CB_matrix3 2320 (28); row_major float3x2 CB_matrix4 2352 (40);
    // float3 CB_vectorArray2[2] 2400 (28); float3x2 CB_matrixArray3[3] 2432 (92).
    // Relative to 2224: 0, 32, 96, 128, 176, 208.
    const struct_layout l = cbuffer({{"MyCBuffer",
                                      {{"CB_matrix2", "mat2x3"},
                                       {"CB_matrixArray2", "mat2x3", 2},
                                       {"CB_matrix3", "mat2x3"},
                                       {"CB_matrix4", "mat3x2"},
                                       {"CB_vectorArray2", "vec3", 2},
                                       {"CB_matrixArray3", "mat2x3", 3}}},
                                     {}});
    check(l, "CB_matrix2", 0, 28);
    check(l, "CB_matrixArray2", 32, 60);
    CHECK(at(l, "CB_matrixArray2").array_stride == 32);
    check(l, "CB_matrix3", 96, 28);
    check(l, "CB_matrix4", 128, 40);
    check(l, "CB_vectorArray2", 176, 28);
    CHECK(at(l, "CB_vectorArray2").array_stride == 16);
    check(l, "CB_matrixArray3", 208, 92);
    CHECK(at(l, "CB_matrixArray3").array_stride == 32);
}

TEST_CASE("hlsl-cbuffer [DXC-fxc MyCBuffer 2976..3028]: a float3 packs after an array's last element", "[layout][hlsl]")
{
    // float3 CB_vector5 2976; int CB_scalarArray3[3] 2992 (size 36); float3 CB_vector6 3028.
    // Relative to 2976: 0, 16, 52 -- the float3 uses the .yzw of the array's last register.
    const struct_layout l = cbuffer(
        {{"MyCBuffer", {{"CB_vector5", "vec3"}, {"CB_scalarArray3", "int", 3}, {"CB_vector6", "vec3"}}}, {}});
    check(l, "CB_vector5", 0, 12);
    check(l, "CB_scalarArray3", 16, 36);
    check(l, "CB_vector6", 52, 12);
    CHECK(l.size == 64);
}

TEST_CASE("hlsl-cbuffer [DXC-fxc matrix.array]: float3x2 foo[7] is 220 bytes at 16", "[layout][hlsl]")
{
    // cbuffer buffer0 { float dummy0; // Offset 0 Size 4
    //                   float3x2 foo[7]; // Offset 16 Size 220 } with ArrayStride 32.
    // float3x2 = mat2x3: 16 + 12 = 28 bytes, stride 32, 6 * 32 + 28 = 220.
    const struct_layout l = cbuffer({{"buffer0", {{"dummy0", "float"}, {"foo", "mat2x3", 7}}}, {}});
    check(l, "dummy0", 0, 4);
    const member_layout& foo = at(l, "foo");
    CHECK(foo.offset == 16);
    CHECK(foo.size == 220);
    CHECK(foo.array_stride == 32);
    CHECK(foo.element_size == 28);
    CHECK(foo.matrix_stride == 16);
}

// ---------------------------------------------------------------------------------
// The rules, case by case ([MS-legacy] unless stated)
// ---------------------------------------------------------------------------------

TEST_CASE("hlsl-cbuffer: every matCxR is C registers, the last one unpadded: (C-1)*16 + 4R", "[layout][hlsl]")
{
    // [MS-legacy] rule 3: each column of a column_major matrix is aligned to a 16-byte row.
    // Checked against [DXC-fxc]: float2x3 (mat3x2) 40, float3x2 (mat2x3) 28.
    struct row {
        const char* type;
        uint32_t size;
    };
    const row table[] = {{"mat2", 24},   {"mat3x2", 40}, {"mat4x2", 56}, {"mat2x3", 28}, {"mat3", 44},
                         {"mat4x3", 60}, {"mat2x4", 32}, {"mat3x4", 48}, {"mat4", 64}};
    for (const row& r : table) {
        DYNAMIC_SECTION(r.type)
        {
            const struct_layout l = cbuffer({{"C", {{"a", "float"}, {"m", r.type}}}, {}});
            const member_layout& m = at(l, "m");
            CHECK(m.offset == 16); // a matrix starts a register
            CHECK(m.size == r.size);
            CHECK(m.matrix_stride == 16);
            CHECK(l.size == 16 + (r.size + 15) / 16 * 16);
        }
    }
}

TEST_CASE("hlsl-cbuffer: a float after float3x3 packs into the last column's register", "[layout][hlsl]")
{
    // mat3 = float3x3: columns at 16, 32, 48 (12 bytes each); ends at 60, so b fits at 60.
    // Same pattern as [DXC-fxc] float1x2 foo (16, size 20) followed by `float end` at 36.
    const struct_layout l = cbuffer({{"C", {{"a", "float"}, {"m", "mat3"}, {"b", "float"}}}, {}});
    check(l, "m", 16, 44);
    check(l, "b", 60, 4);
    CHECK(l.size == 64);
}

TEST_CASE("hlsl-cbuffer: float4x4 takes four whole registers", "[layout][hlsl]")
{
    const struct_layout l = cbuffer({{"C", {{"a", "float"}, {"m", "mat4"}, {"b", "float"}}}, {}});
    check(l, "m", 16, 64);
    check(l, "b", 80, 4);
    CHECK(l.size == 96);
}

TEST_CASE("hlsl-cbuffer: vectors never straddle a register", "[layout][hlsl]")
{
    // float a 0; float2 b fits 4..12; float2 c would straddle 12..20, so it starts c1 (16);
    // float3 d would straddle 24..36, so c2 (32); float4 e needs a whole register: 48.
    const struct_layout l = cbuffer(
        {{"C", {{"a", "float"}, {"b", "vec2"}, {"c", "vec2"}, {"d", "vec3"}, {"e", "vec4"}}}, {}});
    check(l, "b", 4, 8);
    check(l, "c", 16, 8);
    check(l, "d", 32, 12);
    check(l, "e", 48, 16);
    CHECK(l.size == 64);
}

TEST_CASE("hlsl-cbuffer: int and uint vectors pack like float vectors", "[layout][hlsl]")
{
    // [MS] "given: a float1 occupies 4 bytes"; 32-bit ints are packed the same way
    // ([0034] cb1 uses int).
    const struct_layout l = cbuffer({{"C", {{"a", "uint"}, {"b", "ivec3"}, {"c", "int"}, {"d", "uvec2"}}}, {}});
    check(l, "b", 4, 12);
    check(l, "c", 16, 4);
    check(l, "d", 20, 8);
    CHECK(l.size == 32);
}

TEST_CASE("hlsl-cbuffer: an array of 20-byte structs: stride 32, last element unpadded", "[layout][hlsl]")
{
    // [0034] array elements padded to 16-byte boundaries "but crucially they do not have padding
    // after the last member"; [MS-legacy] rule 4 lets the next value use the last row.
    // P { float4 a; float b; } is 20 bytes; P p[2] = 32 + 20 = 52 bytes at 16; c at 68.
    const struct_layout l = cbuffer({{"C", {{"x", "float"}, {"p", "P", 2}, {"c", "float"}}},
                                     {{"P", {{"a", "vec4"}, {"b", "float"}}}}});
    const member_layout& p = at(l, "p");
    CHECK(p.offset == 16);
    CHECK(p.element_size == 20);
    CHECK(p.array_stride == 32);
    CHECK(p.size == 52);
    check(l, "c", 68, 4);
    CHECK(l.size == 80);
}

TEST_CASE("hlsl-cbuffer: an array of 16-byte structs has stride 16", "[layout][hlsl]")
{
    const struct_layout l = cbuffer({{"C", {{"lights", "Light", 3}, {"count", "int"}}},
                                     {{"Light", {{"color", "vec3"}, {"intensity", "float"}}}}});
    const member_layout& lights = at(l, "lights");
    CHECK(lights.array_stride == 16);
    CHECK(lights.size == 48);
    CHECK(at(l, "lights.intensity").offset == 12);
    check(l, "count", 48, 4);
}

TEST_CASE("hlsl-cbuffer: nested struct sizes are not rounded up, the cbuffer is", "[layout][hlsl]")
{
    // [MS-legacy] rules 4-5: Inner { float4 a; float b; } is 20 bytes; Outer { Inner i; float x; }
    // puts x at 20 and is 24 bytes; in the cbuffer, y follows o at 24. Only the cbuffer itself
    // is whole registers (32).
    const struct_layout l = cbuffer({{"C", {{"o", "Outer"}, {"y", "float"}}},
                                     {{"Inner", {{"a", "vec4"}, {"b", "float"}}},
                                      {"Outer", {{"i", "Inner"}, {"x", "float"}}}}});
    CHECK(at(l, "o.i").size == 20);
    CHECK(at(l, "o.x").offset == 20);
    check(l, "o", 0, 24);
    check(l, "y", 24, 4);
    CHECK(l.size == 32);
    CHECK(l.align == 16);
}

TEST_CASE("hlsl-cbuffer: a float3 may follow a struct inside its last register", "[layout][hlsl]")
{
    // [MS-legacy] rule 4: P { float4 a; float b; } ends at 20; a float3 fits 20..32.
    const struct_layout l =
        cbuffer({{"C", {{"p", "P"}, {"v", "vec3"}}}, {{"P", {{"a", "vec4"}, {"b", "float"}}}}});
    check(l, "v", 20, 12);
    CHECK(l.size == 32);
}

TEST_CASE("hlsl-cbuffer: a struct after a scalar starts a new register", "[layout][hlsl]")
{
    // [MS] "Each structure forces ... the next four-component vector" for the struct's start
    // (examples 9 and 10); the struct's own alignment is 16.
    const struct_layout l = cbuffer({{"C", {{"a", "float"}, {"s", "S"}}}, {{"S", {{"x", "float"}}}}});
    check(l, "s", 16, 4);
    CHECK(at(l, "s").align == 16);
    CHECK(l.size == 32);
}

TEST_CASE("hlsl-cbuffer: an array after a scalar starts a new register", "[layout][hlsl]")
{
    // [MS] "every element in an array is stored in a four-component vector"; [0034] arrays
    // start on 16-byte boundaries.
    const struct_layout l = cbuffer({{"C", {{"a", "float"}, {"w", "vec2", 2}, {"b", "float"}}}, {}});
    const member_layout& w = at(l, "w");
    CHECK(w.offset == 16);
    CHECK(w.array_stride == 16);
    CHECK(w.size == 24);
    check(l, "b", 40, 4);
    CHECK(l.size == 48);
}

TEST_CASE("hlsl-cbuffer: the cbuffer size is whole registers", "[layout][hlsl]")
{
    CHECK(cbuffer({{"C", {{"a", "float"}}}, {}}).size == 16);
    CHECK(cbuffer({{"C", {{"a", "vec4"}}}, {}}).size == 16);
    CHECK(cbuffer({{"C", {{"a", "vec4"}, {"b", "float"}}}, {}}).size == 32);
}

TEST_CASE("hlsl-cbuffer: runtime-sized arrays are rejected", "[layout][hlsl]")
{
    const block_desc block{{"C", {{"count", "uint"}, {"data", "vec4", 0u}}}, {}};
    CHECK_THAT(error_of([&] { cbuffer(block); }),
               Contains("C.data") && Contains("runtime-sized") && Contains("rules: hlsl-cbuffer"));
}

TEST_CASE("hlsl-cbuffer: the declaration spells GLSL matCxR as column_major floatRxC", "[layout][hlsl][declare]")
{
    const struct_layout l = cbuffer({{"C",
                                      {{"a", "mat2x3"}, {"b", "mat3x2"}, {"c", "mat4"}, {"d", "mat3x4"},
                                       {"e", "mat2x3", 7}, {"f", "ivec3"}}},
                                     {}});
    const std::string text = declare(l, language::hlsl, {0, 2, ""});
    CHECK_THAT(text, Contains("column_major float3x2 a;") && Contains("column_major float2x3 b;") &&
                         Contains("column_major float4x4 c;") && Contains("column_major float4x3 d;") &&
                         Contains("column_major float3x2 e[7];") && Contains("int3 f;") &&
                         Contains("cbuffer C : register(b2, space0) {"));
}

} // namespace unity_test_layout_hlsl
