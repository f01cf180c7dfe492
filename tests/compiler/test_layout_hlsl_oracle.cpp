// Oracle: glslang's HLSL front end (EShSourceHlsl with EShMsgHlslOffsets, i.e. HLSL's
// cbuffer packing: 4-byte slots, a vector never straddles a 16-byte register) and
// SPIRV-Cross's reflection of the resulting Offset decorations.
//
// Random cbuffers of scalars and vectors (float/int/uint, 2..4 components) are laid out
// with rules::hlsl_cbuffer, declared with declare(..., language::hlsl), compiled by glslang
// as the cbuffer of a trivial compute shader, and every member offset, size and the
// buffer's size must equal what glslang decided.
//
// Trustworthy for exactly that subset: the register-packing rule for scalars and vectors
// is simple, documented by Microsoft ("Packing rules for constant variables") and
// implemented by glslang independently of aogen.
//
// Not an oracle for arrays, structs or matrices, which are therefore left out of the
// random structs. For all three glslang rounds the member up to whole 16-byte registers,
// so the next member starts in a fresh register, whereas DXC and FXC (and aogen, after
// LLVM's HLSL proposal 0034) leave the last register's unused tail to the next scalar:
//     float a[3];  float b;          glslang: b at 48   DXC: b at 36
//     S s (12 bytes); float b;       glslang: b at +16  DXC: b at +12
//     column_major float2x2 m; float b;   glslang: b at +32, DXC: b at +24
// The last test below pins that glslang behaviour down (so that a glslang that starts
// agreeing with DXC is noticed) and still compares what glslang does get right for
// matrices: their offset (a new register) and MatrixStride (16, one register per column).

#include "glsl_compile.hpp"
#include "random_structs.hpp"
#include "spirv_layout_compare.hpp"

#include <aogen/declare.hpp>
#include <aogen/layout.hpp>

#include <catch2/catch.hpp>

// One namespace per test file: the files of one executable share a translation unit
// (tests/CMakeLists.txt: a unity build), and their helpers must not meet.
namespace unity_test_layout_hlsl_oracle {

using namespace aogen::layout;

namespace {

constexpr uint32_t hlsl_structs = 220;

struct hlsl_compiled {
    std::string hlsl, log;
    std::vector<uint32_t> words;
};

hlsl_compiled compile_cbuffer(const struct_layout& l)
{
    hlsl_compiled out;
    out.hlsl = declare(l, language::hlsl);
    const member_layout& first = l.members.front();
    const std::string read = first.name + (first.value && first.value->is_vector() ? ".x" : first.value && first.value->is_matrix() ? "[0][0]" : "");
    const std::string shader = out.hlsl +
                               "RWStructuredBuffer<float> aogen_test_out : register(u0, space1);\n"
                               "[numthreads(1, 1, 1)]\n"
                               "void main() { aogen_test_out[0] = float(" + read + "); }\n";
    const aogen_test::spirv_result spirv = aogen_test::compile_compute(shader, aogen_test::source_language::hlsl, "main");
    if (!spirv.ok) out.log = spirv.log + "\n" + shader;
    out.words = spirv.words;
    return out;
}

} // namespace

TEST_CASE("glslang HLSL oracle: cbuffers of random scalars and vectors", "[layout][oracle][hlsl]")
{
    aogen_test::generator_options options;
    options.structs = options.arrays = options.matrices = false;
    options.min_members = 1;
    options.max_members = 14;
    int failures = 0;
    for (uint32_t seed = 1; seed <= hlsl_structs; ++seed) {
        const block_desc block = aogen_test::random_block(seed, options);
        const struct_layout l = compute(block, rules::hlsl_cbuffer);
        const hlsl_compiled compiled = compile_cbuffer(l);
        std::vector<std::string> errors;
        if (!compiled.log.empty()) {
            errors.push_back("glslang rejected the cbuffer: " + compiled.log);
        } else {
            spirv_cross::Compiler reflect(compiled.words);
            const spirv_cross::SPIRType* type = aogen_test::find_block_type(reflect, l.name);
            if (type) errors = aogen_test::compare_block(reflect, *type, l);
            else errors.push_back("cbuffer " + l.name + " not found in the SPIR-V");
        }
        if (errors.empty()) continue;
        if (++failures <= 5)
            FAIL_CHECK("seed " << seed << ", declaration:\n" << compiled.hlsl << aogen_test::join_lines(errors));
    }
    INFO(failures << " of " << hlsl_structs << " random cbuffers disagree with glslang");
    CHECK(failures == 0);
}

TEST_CASE("glslang HLSL oracle: matrices start a register and take one per column", "[layout][oracle][hlsl]")
{
    for (value_type t : all_value_types()) {
        if (!t.is_matrix()) continue;
        // A float before the matrix (it must move to the next register) and a float after it.
        const block_desc block{{"Blk", {{"a", "float"}, {"m", glsl_name(t)}, {"b", "float"}}}, {}};
        const struct_layout l = compute(block, rules::hlsl_cbuffer);
        const hlsl_compiled compiled = compile_cbuffer(l);
        INFO(compiled.hlsl);
        REQUIRE(compiled.log.empty());
        spirv_cross::Compiler reflect(compiled.words);
        const spirv_cross::SPIRType* type = aogen_test::find_block_type(reflect, l.name);
        REQUIRE(type);
        const member_layout& m = l.members[1];
        CHECK(reflect.type_struct_member_offset(*type, 1) == m.offset);
        CHECK(reflect.type_struct_member_matrix_stride(*type, 1) == m.matrix_stride);
        // glslang, unlike DXC, gives the matrix whole registers: the float after it starts
        // a new one. aogen follows DXC: it shares the last column's register when it fits.
        const uint32_t glslang_after = reflect.type_struct_member_offset(*type, 2);
        CHECK(glslang_after == m.offset + 16u * t.columns);
        const uint32_t dxc_after = m.offset + 16u * (t.columns - 1) + 4u * t.rows;
        CHECK(l.members[2].offset == (t.rows < 4 ? dxc_after : m.offset + 16u * t.columns));
    }
}

} // namespace unity_test_layout_hlsl_oracle
