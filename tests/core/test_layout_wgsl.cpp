// Hand-worked layout cases for the two WGSL rule sets (no WGSL compiler on this machine).
//
// Every number below comes from the WGSL specification (W3C editor's draft, gpuweb/gpuweb
// wgsl/index.bs), section "Memory Layout" (#memory-layouts):
//   [align-size]  "Alignment and Size" (#alignment-and-size): the AlignOf/SizeOf table
//                 (i32/u32/f32 4/4, vec2 8/8, vec3 16/12, vec4 16/16, every matCxR<f32>,
//                 struct = max member alignment and roundUp(AlignOf(S), justPastLastMember),
//                 array<E,N> = AlignOf(E) and N x roundUp(AlignOf(E), SizeOf(E)));
//   [member]      "Structure Member Layout" (#structure-member-layout) and its two examples
//                 "Layout of structures using implicit member sizes and alignments" and
//                 "... with explicit member sizes and alignments" (structs A and B);
//   [arrays]      "Array Layout Examples" (#array-layout-examples): small_stride, bigger_stride,
//                 weights: array<f32>, directions: array<vec3<f32>>;
//   [internal]    "Internal Layout of Values" (#internal-value-layout): column i of a matrix at
//                 i x AlignOf(vecR), element i of an array at i x StrideOf(A);
//   [uniform]     "Address Space Layout Constraints" (#address-space-layout-constraints):
//                 RequiredAlignOf(array or struct, uniform) = roundUp(16, AlignOf(...)), array
//                 stride a multiple of 16 in uniform, bytes after a struct-typed member at
//                 least roundUp(16, SizeOf(S)), runtime-sized arrays disallowed in uniform, and
//                 its two examples "Satisfying offset requirements for uniform address space"
//                 (S, Invalid, Valid) and "Satisfying stride requirements ..." (small_stride,
//                 wrapped_f32, big_stride);
//   [intro]       the introduction's example (PointLight, LightStorage with array<PointLight>).
// Our descriptions use GLSL spellings: float=f32, int=i32, uint=u32, vecN=vecN<f32>,
// matCxR=matCxR<f32> (C columns of R rows in both languages).
#include <aogen/declare.hpp>
#include <aogen/layout.hpp>

#include <catch2/catch.hpp>

#include "support.hpp"

#include <string>
#include <vector>

// One namespace per test file: the files of one executable share a translation unit
// (tests/CMakeLists.txt: a unity build), and their helpers must not meet.
namespace unity_test_layout_wgsl {

using Catch::Contains;
using namespace aogen::layout;

using aogen_test::error_of;
using aogen_test::at;

namespace {

void check(const struct_layout& l, const char* path, uint32_t offset, uint32_t size, uint32_t align)
{
    const member_layout& m = at(l, path);
    INFO("member " << path);
    CHECK(m.offset == offset);
    CHECK(m.size == size);
    CHECK(m.align == align);
}

// The spec's struct A of the implicit-layout example.
struct_desc spec_struct_a()
{
    return {"A", {{"u", "float"}, {"v", "float"}, {"w", "vec2"}, {"x", "float"}}};
}

// The spec's struct B (both examples use the same members; only A differs).
struct_desc spec_struct_b()
{
    return {"B",
            {{"a", "vec2"},
             {"b", "vec3"},
             {"c", "float"},
             {"d", "float"},
             {"e", "A"},
             {"f", "vec3"},
             {"g", "A", 3},
             {"h", "int"}}};
}

size_t count_of(const std::string& text, const std::string& what)
{
    size_t n = 0;
    for (size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
    return n;
}

} // namespace

// ---------------------------------------------------------------------------------
// wgsl-storage: the plain WGSL layout
// ---------------------------------------------------------------------------------

TEST_CASE("wgsl-storage: i32, u32 and f32 are 4-aligned and 4 bytes", "[layout][wgsl]")
{
    // [align-size] table row "i32, u32, or f32: 4, 4". Also the spec's memory-model example
    // struct S { a: f32, b: u32, c: f32 } (#memory-operation): 0, 4, 8, size 12.
    const block_desc block{{"S", {{"a", "float"}, {"b", "uint"}, {"c", "float"}, {"d", "int"}}}, {}};
    const struct_layout l = compute(block, rules::wgsl_storage);
    check(l, "a", 0, 4, 4);
    check(l, "b", 4, 4, 4);
    check(l, "c", 8, 4, 4);
    check(l, "d", 12, 4, 4);
    CHECK(l.size == 16);
    CHECK(l.align == 4);
}

TEST_CASE("wgsl-storage: vec2 is 8-aligned and 8 bytes", "[layout][wgsl]")
{
    // [align-size] "vec2<T>: 8, 8". f32 at 0, then vec2 rounds 4 up to 8; struct size
    // roundUp(8, 16) = 16.
    const block_desc block{{"S", {{"a", "float"}, {"b", "vec2"}}}, {}};
    const struct_layout l = compute(block, rules::wgsl_storage);
    check(l, "b", 8, 8, 8);
    CHECK(l.size == 16);
    CHECK(l.align == 8);
}

TEST_CASE("wgsl-storage: vec3 is 16-aligned and 12 bytes, a scalar fills its fourth lane", "[layout][wgsl]")
{
    // [align-size] "vec3<T>: 16, 12". The spec's struct B shows it: b: vec3 at 16, c: f32 at 28.
    const block_desc block{{"S", {{"a", "float"}, {"b", "vec3"}, {"c", "float"}}}, {}};
    const struct_layout l = compute(block, rules::wgsl_storage);
    check(l, "b", 16, 12, 16);
    check(l, "c", 28, 4, 4);
    CHECK(l.size == 32);
    CHECK(l.align == 16);
}

TEST_CASE("wgsl-storage: vec4 is 16-aligned and 16 bytes", "[layout][wgsl]")
{
    // [align-size] "vec4<T>: 16, 16".
    const block_desc block{{"S", {{"a", "float"}, {"b", "vec4"}, {"c", "float"}}}, {}};
    const struct_layout l = compute(block, rules::wgsl_storage);
    check(l, "b", 16, 16, 16);
    check(l, "c", 32, 4, 4);
    CHECK(l.size == 48);
}

TEST_CASE("wgsl-storage: integer vectors lay out like f32 vectors", "[layout][wgsl]")
{
    // [align-size] the vecN rows hold for T = i32, u32 or f32 alike.
    const block_desc block{{"S", {{"a", "uint"}, {"b", "ivec2"}, {"c", "uvec3"}, {"d", "ivec4"}}}, {}};
    const struct_layout l = compute(block, rules::wgsl_storage);
    check(l, "b", 8, 8, 8);
    check(l, "c", 16, 12, 16);
    check(l, "d", 32, 16, 16);
    CHECK(l.size == 48);
}

TEST_CASE("wgsl-storage: every matCxR<f32> has the table's alignment, size and column stride", "[layout][wgsl]")
{
    // [align-size] matrix rows for f32: AlignOf(vecR) and SizeOf(array<vecR, C>);
    // [internal] column i at i x AlignOf(vecR), so the matrix stride is AlignOf(vecR).
    struct row {
        const char* type;
        uint32_t align, size, column_stride;
    };
    const row table[] = {
        {"mat2x2", 8, 16, 8},  {"mat3x2", 8, 24, 8},   {"mat4x2", 8, 32, 8},
        {"mat2x3", 16, 32, 16}, {"mat3x3", 16, 48, 16}, {"mat4x3", 16, 64, 16},
        {"mat2x4", 16, 32, 16}, {"mat3x4", 16, 48, 16}, {"mat4x4", 16, 64, 16},
    };
    for (const row& r : table) {
        DYNAMIC_SECTION(r.type)
        {
            // A leading f32 shows the alignment: the matrix lands on roundUp(align, 4).
            const block_desc block{{"S", {{"f", "float"}, {"m", r.type}}}, {}};
            const struct_layout l = compute(block, rules::wgsl_storage);
            const member_layout& m = at(l, "m");
            CHECK(m.offset == r.align);
            CHECK(m.size == r.size);
            CHECK(m.align == r.align);
            CHECK(m.matrix_stride == r.column_stride);
            CHECK(l.size == r.align + r.size); // already a multiple of the struct alignment
        }
    }
}

TEST_CASE("wgsl-storage: the spec's struct A (implicit layout) is 8-aligned and 24 bytes", "[layout][wgsl]")
{
    // [member] implicit example: u offset(0), v offset(4), w offset(8) align(8), x offset(16),
    // implicit struct size padding at 20, A: align(8) size(24).
    const block_desc block{spec_struct_a(), {}};
    const struct_layout l = compute(block, rules::wgsl_storage);
    check(l, "u", 0, 4, 4);
    check(l, "v", 4, 4, 4);
    check(l, "w", 8, 8, 8);
    check(l, "x", 16, 4, 4);
    CHECK(l.align == 8);
    CHECK(l.size == 24);
}

TEST_CASE("wgsl-storage: the spec's struct B (implicit layout) has the listed offsets", "[layout][wgsl]")
{
    // [member] implicit example, struct B: align(16) size(160);
    // a 0 (8), b 16 (12), c 28, d 32, e: A 40 (align 8, size 24), f 64 (12),
    // g: array<A, 3> 80 (element stride 24, size 72), h 152, struct padding at 156.
    const block_desc block{spec_struct_b(), {spec_struct_a()}};
    const struct_layout l = compute(block, rules::wgsl_storage);
    check(l, "a", 0, 8, 8);
    check(l, "b", 16, 12, 16);
    check(l, "c", 28, 4, 4);
    check(l, "d", 32, 4, 4);
    check(l, "e", 40, 24, 8);
    check(l, "f", 64, 12, 16);
    check(l, "g", 80, 72, 8);
    CHECK(at(l, "g").array_stride == 24);
    check(l, "h", 152, 4, 4);
    CHECK(l.align == 16);
    CHECK(l.size == 160);
    // The nested struct's members keep A's own offsets.
    CHECK(at(l, "e.w").offset == 8);
    CHECK(at(l, "g.x").offset == 16);
}

TEST_CASE("wgsl-storage: array<f32, 8> has stride 4 and size 32", "[layout][wgsl]")
{
    // [arrays] small_stride: alignment 4, element stride roundUp(4,4) = 4, size 4 * 8 = 32.
    const block_desc block{{"S", {{"small_stride", "float", 8}}}, {}};
    const struct_layout l = compute(block, rules::wgsl_storage);
    const member_layout& m = at(l, "small_stride");
    CHECK(m.align == 4);
    CHECK(m.array_stride == 4);
    CHECK(m.size == 32);
    CHECK(m.element_size == 4);
    CHECK(l.size == 32);
}

TEST_CASE("wgsl-storage: array<vec3<f32>, 8> has stride 16 and size 128", "[layout][wgsl]")
{
    // [arrays] bigger_stride: alignment 16, stride roundUp(16, 12) = 16, size 16 * 8 = 128.
    const block_desc block{{"S", {{"bigger_stride", "vec3", 8}}}, {}};
    const struct_layout l = compute(block, rules::wgsl_storage);
    const member_layout& m = at(l, "bigger_stride");
    CHECK(m.align == 16);
    CHECK(m.array_stride == 16);
    CHECK(m.size == 128);
    CHECK(m.element_size == 12);
}

TEST_CASE("wgsl-storage: runtime-sized array<f32> has stride 4", "[layout][wgsl]")
{
    // [arrays] weights: array<f32>: alignment 4, element stride 4 (N_runtime = floor(B / 4)).
    // Our root is always a struct, so the array is its only member, at offset 0.
    const block_desc block{{"Weights", {{"weights", "float", 0u}}}, {}};
    const struct_layout l = compute(block, rules::wgsl_storage);
    const member_layout& m = at(l, "weights");
    CHECK(m.is_runtime_array());
    CHECK(m.offset == 0);
    CHECK(m.align == 4);
    CHECK(m.array_stride == 4);
    CHECK(m.size == 0); // counts as zero elements
}

TEST_CASE("wgsl-storage: runtime-sized array<vec3<f32>> has stride 16", "[layout][wgsl]")
{
    // [arrays] directions: array<vec3<f32>>: alignment 16, stride roundUp(16, 12) = 16.
    const block_desc block{{"Directions", {{"directions", "vec3", 0u}}}, {}};
    const struct_layout l = compute(block, rules::wgsl_storage);
    const member_layout& m = at(l, "directions");
    CHECK(m.align == 16);
    CHECK(m.array_stride == 16);
}

TEST_CASE("wgsl-storage: the introduction's LightStorage with array<PointLight>", "[layout][wgsl]")
{
    // [intro] struct PointLight { position: vec3f, color: vec3f }
    //         struct LightStorage { pointCount: u32, point: array<PointLight> }
    // Worked from [align-size]: PointLight aligns to 16; color at 16; size roundUp(16, 28) = 32.
    // point aligns to 16, so it starts at 16 with stride roundUp(16, 32) = 32.
    const block_desc block{{"LightStorage", {{"pointCount", "uint"}, {"point", "PointLight", 0u}}},
                           {{"PointLight", {{"position", "vec3"}, {"color", "vec3"}}}}};
    const struct_layout l = compute(block, rules::wgsl_storage);
    const member_layout& point = at(l, "point");
    CHECK(point.offset == 16);
    CHECK(point.align == 16);
    CHECK(point.array_stride == 32);
    CHECK(point.element_size == 32);
    CHECK(at(l, "point.color").offset == 16);
    CHECK(l.size == 16);
    CHECK(l.align == 16);
}

TEST_CASE("wgsl-storage: a struct aligns to its widest member, mat3x2 included", "[layout][wgsl]")
{
    // [align-size] struct AlignOf = max AlignOfMember; mat3x2 aligns like vec2 (8), 24 bytes.
    const block_desc block{{"S", {{"a", "float"}, {"m", "mat3x2"}, {"b", "float"}}}, {}};
    const struct_layout l = compute(block, rules::wgsl_storage);
    check(l, "m", 8, 24, 8);
    check(l, "b", 32, 4, 4);
    CHECK(l.align == 8);
    CHECK(l.size == 40); // roundUp(8, 36)
}

TEST_CASE("wgsl-storage: a struct-typed member packs right after the struct, no 16-byte rule", "[layout][wgsl]")
{
    // [member] in storage a member after e: A simply follows at OffsetOfMember + SizeOf(A);
    // the uniform-only roundUp(16, SizeOf(S)) rule does not apply. S { x: f32 } is 4 bytes.
    const block_desc block{{"Invalid", {{"a", "S"}, {"b", "float"}}}, {{"S", {{"x", "float"}}}}};
    const struct_layout l = compute(block, rules::wgsl_storage);
    check(l, "a", 0, 4, 4);
    check(l, "b", 4, 4, 4);
    CHECK(l.size == 8);
}

TEST_CASE("wgsl-storage: a runtime-sized array must be the last member", "[layout][wgsl]")
{
    // [align-size]/the spec's type rules: a runtime-sized array may only be the last member
    // of the buffer's structure.
    const block_desc block{{"S", {{"data", "vec4", 0u}, {"count", "uint"}}}, {}};
    const std::string message = error_of([&] { compute(block, rules::wgsl_storage); });
    CHECK_THAT(message, Contains("S.data") && Contains("last member") && Contains("wgsl-storage"));
}

TEST_CASE("wgsl-storage: a runtime-sized array cannot be inside a nested struct", "[layout][wgsl]")
{
    const block_desc block{{"S", {{"count", "uint"}, {"inner", "Inner"}}},
                           {{"Inner", {{"x", "float"}, {"data", "float", 0u}}}}};
    const std::string message = error_of([&] { compute(block, rules::wgsl_storage); });
    CHECK_THAT(message, Contains("S.inner.data") && Contains("top-level") && Contains("wgsl-storage"));
}

TEST_CASE("wgsl-storage: the declaration needs no attributes", "[layout][wgsl][declare]")
{
    // WGSL's natural layout is the storage layout, so nothing needs @align or @size.
    const block_desc block{spec_struct_b(), {spec_struct_a()}};
    const std::string text = declare(compute(block, rules::wgsl_storage), language::wgsl);
    CHECK(count_of(text, "@align") == 0);
    CHECK(count_of(text, "@size") == 0);
    CHECK_THAT(text, Contains("g: array<A, 3>,") && Contains("var<storage, read> b: B;"));
}

// ---------------------------------------------------------------------------------
// wgsl-uniform: plus the portable uniform-address-space constraints
// ---------------------------------------------------------------------------------

TEST_CASE("wgsl-uniform: the spec's Invalid/Valid pair puts b 16 bytes after a: S", "[layout][wgsl]")
{
    // [uniform] "Satisfying offset requirements": struct S { x: f32 };
    // Invalid { a: S, b: f32 } puts b 4 bytes after a, "but must be at least 16";
    // Valid { a: S, @align(16) b: f32 }: b at 16, Valid's alignment 16, so its size is
    // roundUp(16, 20) = 32. We reach the same offsets with @align(16) @size(16) on a.
    const block_desc block{{"Valid", {{"a", "S"}, {"b", "float"}}}, {{"S", {{"x", "float"}}}}};
    const struct_layout l = compute(block, rules::wgsl_uniform);
    const member_layout& a = at(l, "a");
    CHECK(a.offset == 0);
    CHECK(a.size == 16);        // roundUp(16, SizeOf(S)) = roundUp(16, 4)
    CHECK(a.element_size == 4); // SizeOf(S) itself
    CHECK(a.align == 16);       // RequiredAlignOf(S, uniform) = roundUp(16, 4)
    check(l, "b", 16, 4, 4);
    CHECK(l.size == 32);
    CHECK(l.align == 16);
}

TEST_CASE("wgsl-uniform: the spec's small_stride array<f32, 8> is rejected", "[layout][wgsl]")
{
    // [uniform] "Satisfying stride requirements": small_stride { a: array<f32,8> } // stride 4
    // "Invalid, stride must be a multiple of 16".
    const block_desc block{{"small_stride", {{"a", "float", 8}}}, {}};
    const std::string message = error_of([&] { compute(block, rules::wgsl_uniform); });
    CHECK_THAT(message, Contains("small_stride.a") && Contains("array stride 4") && Contains("multiple of 16") &&
                            Contains("wgsl-uniform"));
}

TEST_CASE("wgsl-uniform: the spec's big_stride array of 16-byte wrapped_f32 is accepted", "[layout][wgsl]")
{
    // [uniform] struct wrapped_f32 { @size(16) elem: f32 }; big_stride { a: array<wrapped_f32,8> }
    // "stride 16 ... Valid". We cannot write @size on a value, so wrapped_f32 spells its 16
    // bytes as elem plus three f32 of padding: the same size (16) and alignment (4).
    const block_desc block{{"big_stride", {{"a", "wrapped_f32", 8}}},
                           {{"wrapped_f32", {{"elem", "float"}, {"p1", "float"}, {"p2", "float"}, {"p3", "float"}}}}};
    const struct_layout l = compute(block, rules::wgsl_uniform);
    const member_layout& a = at(l, "a");
    CHECK(a.offset == 0);
    CHECK(a.array_stride == 16);
    CHECK(a.size == 128);
    CHECK(a.align == 16); // RequiredAlignOf(array, uniform) = roundUp(16, AlignOf = 4)
    CHECK(l.size == 128);
}

TEST_CASE("wgsl-uniform: array<f32, 4> and array<i32, 4> are rejected naming member and rule", "[layout][wgsl]")
{
    // [uniform] "Array elements are aligned to 16 byte boundaries": stride 4 is not 16 x k.
    for (const char* type : {"float", "int", "uint"}) {
        INFO(type);
        const block_desc block{{"Params", {{"radius", "float"}, {"weights", type, 4}}}, {}};
        const std::string message = error_of([&] { compute(block, rules::wgsl_uniform); });
        CHECK_THAT(message, Contains("Params.weights") && Contains("array stride 4") && Contains("rules: wgsl-uniform"));
        CHECK_NOTHROW(compute(block, rules::wgsl_storage)); // fine outside the uniform space
    }
}

TEST_CASE("wgsl-uniform: array<vec2<f32>, 4> (stride 8) is rejected", "[layout][wgsl]")
{
    // [uniform] stride roundUp(8, 8) = 8 is not a multiple of 16.
    const block_desc block{{"P", {{"offsets", "vec2", 4}}}, {}};
    CHECK_THAT(error_of([&] { compute(block, rules::wgsl_uniform); }),
               Contains("P.offsets") && Contains("array stride 8") && Contains("wgsl-uniform"));
}

TEST_CASE("wgsl-uniform: array<vec4<f32>, 16> is accepted unchanged", "[layout][wgsl]")
{
    // [uniform] stride 16 = 16 x 1; roundUp(16, AlignOf(vec4) = 16) = 16, so no extra alignment.
    const block_desc block{{"P", {{"radius", "float"}, {"kernel", "vec4", 16}}}, {}};
    const struct_layout l = compute(block, rules::wgsl_uniform);
    const member_layout& k = at(l, "kernel");
    CHECK(k.offset == 16);
    CHECK(k.array_stride == 16);
    CHECK(k.size == 256);
    CHECK(k.align == 16);
    CHECK(l.size == 272);
}

TEST_CASE("wgsl-uniform: array<vec3<f32>, 2> is accepted with stride 16", "[layout][wgsl]")
{
    // [arrays] stride roundUp(16, 12) = 16, a multiple of 16.
    const block_desc block{{"P", {{"a", "float"}, {"dirs", "vec3", 2}, {"b", "float"}}}, {}};
    const struct_layout l = compute(block, rules::wgsl_uniform);
    const member_layout& d = at(l, "dirs");
    CHECK(d.offset == 16);
    CHECK(d.array_stride == 16);
    CHECK(d.size == 32);
    check(l, "b", 48, 4, 4);
}

TEST_CASE("wgsl-uniform: array<mat2x2<f32>, 2> has stride 16 and aligns to 16", "[layout][wgsl]")
{
    // [align-size] mat2x2: align 8, size 16 -> stride 16 (accepted);
    // [uniform] RequiredAlignOf(array, uniform) = roundUp(16, 8) = 16, so after an f32 the
    // array starts at 16, not 8 (storage: 8).
    const block_desc block{{"P", {{"a", "float"}, {"m", "mat2", 2}}}, {}};
    const struct_layout u = compute(block, rules::wgsl_uniform);
    CHECK(at(u, "m").offset == 16);
    CHECK(at(u, "m").align == 16);
    CHECK(at(u, "m").array_stride == 16);
    CHECK(at(u, "m").matrix_stride == 8);
    CHECK(u.size == 48);
    const struct_layout s = compute(block, rules::wgsl_storage);
    CHECK(at(s, "m").offset == 8);
    CHECK(s.size == 40);
}

TEST_CASE("wgsl-uniform: array<mat3x2<f32>, 2> (stride 24) is rejected, array<mat4x2<f32>, 2> accepted", "[layout][wgsl]")
{
    // [align-size] mat3x2: align 8, size 24 -> stride 24, not 16 x k; mat4x2: size 32 -> stride 32.
    const block_desc bad{{"P", {{"m", "mat3x2", 2}}}, {}};
    CHECK_THAT(error_of([&] { compute(bad, rules::wgsl_uniform); }),
               Contains("P.m") && Contains("array stride 24") && Contains("wgsl-uniform"));
    const block_desc good{{"P", {{"a", "float"}, {"m", "mat4x2", 2}}}, {}};
    const struct_layout l = compute(good, rules::wgsl_uniform);
    CHECK(at(l, "m").offset == 16);
    CHECK(at(l, "m").array_stride == 32);
    CHECK(at(l, "m").size == 64);
}

TEST_CASE("wgsl-uniform: the spec's implicit struct B is rejected for g: array<A, 3>", "[layout][wgsl]")
{
    // [member] A is 24 bytes, so g's element stride is 24 -- fine in storage (see above), but
    // [uniform] requires a multiple of 16.
    const block_desc block{spec_struct_b(), {spec_struct_a()}};
    CHECK_THAT(error_of([&] { compute(block, rules::wgsl_uniform); }),
               Contains("B.g") && Contains("array stride 24") && Contains("rules: wgsl-uniform"));
}

TEST_CASE("wgsl-uniform: the spec's explicit-layout struct B (var<uniform>) has the listed offsets", "[layout][wgsl]")
{
    // [member] explicit example, declared `var<uniform> uniform_buffer: B`:
    //   A { u 0, v 4, w 8, @size(16) x 16 }: align(8) size(32)
    //   B: a 0, b 16, c 28, d 32, @align(16) e: A 48 (size 32), f 80, g: array<A, 3> 96
    //   (element stride 32, size 96), h 192, implicit struct size padding 12 -> size(208).
    // @size(16) on x is spelled as x plus three f32 of padding (same size 32, alignment 8).
    const struct_desc a{"A", {{"u", "float"}, {"v", "float"}, {"w", "vec2"}, {"x", "float"},
                              {"x_pad1", "float"}, {"x_pad2", "float"}, {"x_pad3", "float"}}};
    const block_desc block{spec_struct_b(), {a}};
    const struct_layout l = compute(block, rules::wgsl_uniform);
    check(l, "a", 0, 8, 8);
    check(l, "b", 16, 12, 16);
    check(l, "c", 28, 4, 4);
    check(l, "d", 32, 4, 4);
    check(l, "e", 48, 32, 16); // the example's @align(16); SizeOf(A) = 32 needs no @size
    CHECK(at(l, "e").element_size == 32);
    check(l, "f", 80, 12, 16);
    CHECK(at(l, "g").offset == 96);
    CHECK(at(l, "g").array_stride == 32);
    CHECK(at(l, "g").size == 96);
    check(l, "h", 192, 4, 4);
    CHECK(l.align == 16);
    CHECK(l.size == 208);
}

TEST_CASE("wgsl-uniform: a 4-byte struct member gets @align(16) @size(16)", "[layout][wgsl]")
{
    // [uniform] RequiredAlignOf(S, uniform) = roundUp(16, 4) = 16 and the next member starts
    // at least roundUp(16, SizeOf(S) = 4) = 16 bytes after it.
    const block_desc block{{"U", {{"x", "float"}, {"s", "S"}, {"y", "float"}}}, {{"S", {{"v", "float"}}}}};
    const struct_layout l = compute(block, rules::wgsl_uniform);
    check(l, "s", 16, 16, 16);
    check(l, "y", 32, 4, 4);
    CHECK(l.size == 48);
    const struct_layout s = compute(block, rules::wgsl_storage);
    check(s, "s", 4, 4, 4);
    check(s, "y", 8, 4, 4);
}

TEST_CASE("wgsl-uniform: the spec's 24-byte struct A as a member takes 32 bytes", "[layout][wgsl]")
{
    // [member] SizeOf(A) = 24, AlignOf(A) = 8; [uniform] the member is 16-aligned and the next
    // one starts roundUp(16, 24) = 32 bytes later (storage: 24).
    const block_desc block{{"U", {{"a", "A"}, {"b", "float"}}}, {spec_struct_a()}};
    const struct_layout l = compute(block, rules::wgsl_uniform);
    const member_layout& a = at(l, "a");
    CHECK(a.offset == 0);
    CHECK(a.align == 16);
    CHECK(a.size == 32);
    CHECK(a.element_size == 24);
    check(l, "b", 32, 4, 4);
    CHECK(l.size == 48);
    CHECK(at(compute(block, rules::wgsl_storage), "b").offset == 24);
}

TEST_CASE("wgsl-uniform: a struct already 16-aligned and 16 x k bytes is unchanged", "[layout][wgsl]")
{
    // [uniform] roundUp(16, 16) = 16 and roundUp(16, 32) = 32: nothing to add.
    const block_desc block{{"U", {{"a", "float"}, {"s", "S"}, {"b", "float"}}},
                           {{"S", {{"p", "vec3"}, {"q", "vec4"}}}}};
    const struct_layout l = compute(block, rules::wgsl_uniform);
    check(l, "s", 16, 32, 16);
    CHECK(at(l, "s").element_size == 32);
    check(l, "b", 48, 4, 4);
}

TEST_CASE("wgsl-uniform: nested structs obey the constraints at every level", "[layout][wgsl]")
{
    // [uniform] "All structure and array types directly or indirectly referenced by a variable
    // must obey the constraints". Inner { x: f32 } (4 bytes); in Mid, i takes 16 bytes so y is
    // at 16, Mid's alignment becomes 16 and its size roundUp(16, 20) = 32; in Outer, m is 32
    // bytes and z follows at 32.
    const block_desc block{{"Outer", {{"m", "Mid"}, {"z", "float"}}},
                           {{"Inner", {{"x", "float"}}}, {"Mid", {{"i", "Inner"}, {"y", "float"}}}}};
    const struct_layout l = compute(block, rules::wgsl_uniform);
    CHECK(at(l, "m.i").size == 16);
    CHECK(at(l, "m.y").offset == 16);
    CHECK(at(l, "m").element_size == 32);
    CHECK(at(l, "m").size == 32);
    check(l, "z", 32, 4, 4);
    CHECK(l.size == 48);
}

TEST_CASE("wgsl-uniform: a struct array inside a nested struct is checked too", "[layout][wgsl]")
{
    const block_desc block{{"U", {{"a", "float"}, {"inner", "Inner"}}}, {{"Inner", {{"w", "float", 4}}}}};
    CHECK_THAT(error_of([&] { compute(block, rules::wgsl_uniform); }),
               Contains("U.inner.w") && Contains("multiple of 16") && Contains("wgsl-uniform"));
}

TEST_CASE("wgsl-uniform: values keep their WGSL placement (vec3 then f32, matrices)", "[layout][wgsl]")
{
    // [uniform] RequiredAlignOf of scalars, vectors and matrices is just AlignOf, so a vec3
    // followed by an f32 still shares 16 bytes and mat3x3 keeps its 16-byte columns.
    const block_desc block{{"U", {{"v", "vec3"}, {"f", "float"}, {"m", "mat3"}, {"g", "float"}}}, {}};
    const struct_layout l = compute(block, rules::wgsl_uniform);
    check(l, "v", 0, 12, 16);
    check(l, "f", 12, 4, 4);
    check(l, "m", 16, 48, 16);
    CHECK(at(l, "m").matrix_stride == 16);
    check(l, "g", 64, 4, 4);
    CHECK(l.size == 80);
}

TEST_CASE("wgsl-uniform: the seed 004 SsaoUniform block is 144 bytes", "[layout][wgsl]")
{
    // { inv_proj: mat4x4<f32>, proj: mat4x4<f32>, radius: f32, bias: f32, _pad: vec2<f32> }:
    // [align-size] mat4x4 16/64 -> 0 and 64; f32 at 128 and 132; vec2 at 136; size 144.
    const block_desc block{{"SsaoUniform",
                            {{"inv_proj", "mat4"}, {"proj", "mat4"}, {"radius", "float"}, {"bias", "float"},
                             {"_pad", "vec2"}}},
                           {}};
    const struct_layout l = compute(block, rules::wgsl_uniform);
    check(l, "inv_proj", 0, 64, 16);
    check(l, "proj", 64, 64, 16);
    check(l, "radius", 128, 4, 4);
    check(l, "bias", 132, 4, 4);
    check(l, "_pad", 136, 8, 8);
    CHECK(l.size == 144);
    CHECK(l.align == 16);
}

TEST_CASE("wgsl-uniform: runtime-sized arrays are rejected", "[layout][wgsl]")
{
    // [uniform] "array<T>: Disallowed if C is uniform".
    const block_desc block{{"Lights", {{"count", "uint"}, {"lights", "vec4", 0u}}}, {}};
    const std::string message = error_of([&] { compute(block, rules::wgsl_uniform); });
    CHECK_THAT(message, Contains("Lights.lights") && Contains("runtime-sized") && Contains("rules: wgsl-uniform"));
    CHECK_NOTHROW(compute(block, rules::wgsl_storage));
}

TEST_CASE("wgsl-uniform: the declaration carries @align(16) and @size exactly where needed", "[layout][wgsl][declare]")
{
    // s: S (4 bytes, align 4) needs @align(16) @size(16); a: A (24 bytes, align 8) needs
    // @align(16) @size(32); q: Q (32 bytes, align 16) needs nothing; m: array<mat2x2, 2>
    // (natural alignment 8) needs @align(16); k: array<vec4, 2> needs nothing.
    const block_desc block{{"U",
                            {{"x", "float"}, {"s", "S"}, {"a", "A"}, {"q", "Q"}, {"m", "mat2", 2},
                             {"k", "vec4", 2}, {"y", "float"}}},
                           {{"S", {{"v", "float"}}}, spec_struct_a(), {"Q", {{"p", "vec3"}, {"r", "vec4"}}}}};
    const struct_layout l = compute(block, rules::wgsl_uniform);
    check(l, "s", 16, 16, 16);
    check(l, "a", 32, 32, 16);
    check(l, "q", 64, 32, 16);
    CHECK(at(l, "m").offset == 96);
    CHECK(at(l, "k").offset == 128);
    check(l, "y", 160, 4, 4);
    CHECK(l.size == 176);

    const std::string text = declare(l, language::wgsl);
    CHECK_THAT(text, Contains("@align(16) @size(16) s: S,") && Contains("@align(16) @size(32) a: A,") &&
                         Contains("    q: Q,") && Contains("@align(16) m: array<mat2x2<f32>, 2>,") &&
                         Contains("    k: array<vec4<f32>, 2>,") && Contains("    y: f32,") &&
                         Contains("var<uniform> u: U;"));
    CHECK(count_of(text, "@align") == 3);
    CHECK(count_of(text, "@size") == 2);
}

} // namespace unity_test_layout_wgsl
