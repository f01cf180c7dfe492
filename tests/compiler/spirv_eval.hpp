// tests/compiler/spirv_eval.hpp -- runs what spirv-opt leaves of a test shader's main() on the
// CPU, so that a template's functions can be checked against independent references with
// the shader's own SPIR-V (test_gtao_slice.cpp, test_vbao_slice.cpp).
//
// The test shader's main() stores expressions into a buffer, ao_test.r[i]; glslang compiles
// it and spirv-opt's performance passes inline the calls and fold most of the arithmetic to
// constants. What they leave -- straight-line float arithmetic (the Fma instructions the
// folder makes of a multiply and an add), conversions, 32-bit integer and bit operations --
// run_main() evaluates: float arithmetic in float, as on a GPU; integers as 32-bit unsigned
// words (every value is held as a double, which holds a float and a 32-bit integer exactly).
// Anything else (a branch, an instruction it does not know) fails the test, naming it.
#pragma once

#include <aogen/codegen.hpp>
#include <aogen/compile.hpp>

#include "mutants/mutants.hpp"

#include <catch2/catch.hpp>

#include <spirv_cross/GLSL.std.450.h>
#include <spirv_cross/spirv.hpp>

#include <algorithm>
#include <bitset>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace aogen_test {

// Runs main() of an optimized module on the CPU, as far as spirv-opt left anything to
// run: straight-line float arithmetic, GLSL.std.450 calls, conversions and 32-bit integer
// operations on constants (its folder leaves, for instance, the Fma instructions it makes
// of a multiply and an add). Returns the floats main() stores into ao_test.r[i], by i.
// Branches, loops, memory other than the stores, and instructions not listed below fail
// the test, naming the opcode. Float arithmetic is in float, as on a GPU; integers are
// 32-bit unsigned words (signed operations below reinterpret them).
inline std::vector<float> run_main(const std::vector<uint32_t>& words, size_t count)
{
    // id -> components: a float's value, an integer's 32-bit word, a bool as 0 / 1; a double
    // holds each exactly.
    std::map<uint32_t, std::vector<double>> values;
    std::map<uint32_t, uint32_t> chain_index;      // access chain -> its last index's id
    std::map<uint32_t, bool> float_type;           // scalar and vector types: float or not
    uint32_t main_function = 0;
    bool in_main = false, seen_label = false;
    std::vector<std::optional<float>> out(count);
    auto value = [&](uint32_t id) -> const std::vector<double>& {
        auto v = values.find(id);
        if (v == values.end()) FAIL("SPIR-V id " << id << " has no value (not a constant, nor computed before use)");
        return v->second;
    };
    auto scalar = [&](uint32_t id) {
        const std::vector<double>& v = value(id);
        REQUIRE(v.size() == 1);
        return v[0];
    };
    // Component-wise float operations, in float.
    auto map = [&](uint32_t a, auto f) {
        std::vector<double> r = value(a);
        for (double& x : r) x = f(float(x));
        return r;
    };
    auto map2 = [&](uint32_t a, uint32_t b, auto f) {
        std::vector<double> r = value(a);
        const std::vector<double>& y = value(b);
        REQUIRE(y.size() == r.size());
        for (size_t i = 0; i < r.size(); ++i) r[i] = f(float(r[i]), float(y[i]));
        return r;
    };
    // Component-wise operations on 32-bit words (results of comparisons are 0 / 1).
    auto word = [](double x) { return static_cast<uint32_t>(static_cast<int64_t>(x)); };
    auto imap = [&](uint32_t a, auto f) {
        std::vector<double> r = value(a);
        for (double& x : r) x = double(f(word(x)));
        return r;
    };
    auto imap2 = [&](uint32_t a, uint32_t b, auto f) {
        std::vector<double> r = value(a);
        const std::vector<double>& y = value(b);
        REQUIRE(y.size() == r.size());
        for (size_t i = 0; i < r.size(); ++i) r[i] = double(f(word(r[i]), word(y[i])));
        return r;
    };
    for (size_t i = 5; i < words.size();) {
        const uint32_t length = words[i] >> 16;
        const auto op = static_cast<spv::Op>(words[i] & 0xffffu);
        REQUIRE(length > 0);
        REQUIRE(i + length <= words.size());
        const uint32_t* w = &words[i];
        i += length;
        switch (op) {
        case spv::OpEntryPoint: main_function = w[2]; continue;
        case spv::OpTypeFloat: float_type[w[1]] = true; continue;
        case spv::OpTypeInt:
        case spv::OpTypeBool: float_type[w[1]] = false; continue;
        case spv::OpTypeVector: float_type[w[1]] = float_type[w[2]]; continue;
        case spv::OpConstant: {
            float f;
            std::memcpy(&f, &w[3], sizeof f);
            values[w[2]] = {float_type[w[1]] ? double(f) : double(w[3])};
            continue;
        }
        case spv::OpConstantTrue: values[w[2]] = {1.0f}; continue;
        case spv::OpConstantFalse: values[w[2]] = {0.0f}; continue;
        case spv::OpConstantComposite:
            if (!in_main) {
                std::vector<double> v;
                bool ok = true;
                for (uint32_t k = 3; k < length; ++k) {
                    auto c = values.find(w[k]);
                    if (c == values.end()) ok = false;
                    else v.insert(v.end(), c->second.begin(), c->second.end());
                }
                if (ok) values[w[2]] = v;
            }
            continue;
        case spv::OpFunction: in_main = w[2] == main_function; continue;
        case spv::OpFunctionEnd: in_main = false; continue;
        default: break;
        }
        if (!in_main) continue;
        switch (op) {
        case spv::OpLabel:
            if (seen_label) FAIL("main() has more than one block: branches were not folded away");
            seen_label = true;
            break;
        case spv::OpReturn: break;
        case spv::OpAccessChain:
        case spv::OpInBoundsAccessChain: chain_index[w[2]] = w[length - 1]; break;
        case spv::OpStore: {
            auto chain = chain_index.find(w[1]);
            REQUIRE(chain != chain_index.end());
            const size_t slot = static_cast<size_t>(scalar(chain->second));
            REQUIRE(slot < count);
            out[slot] = float(scalar(w[2]));
            break;
        }
        case spv::OpCompositeExtract: values[w[2]] = {value(w[3]).at(w[4])}; break;
        case spv::OpCompositeConstruct: {
            std::vector<double> v;
            for (uint32_t k = 3; k < length; ++k) v.insert(v.end(), value(w[k]).begin(), value(w[k]).end());
            values[w[2]] = v;
            break;
        }
        case spv::OpFNegate: values[w[2]] = map(w[3], [](float x) { return -x; }); break;
        case spv::OpFAdd: values[w[2]] = map2(w[3], w[4], [](float x, float y) { return x + y; }); break;
        case spv::OpFSub: values[w[2]] = map2(w[3], w[4], [](float x, float y) { return x - y; }); break;
        case spv::OpFMul: values[w[2]] = map2(w[3], w[4], [](float x, float y) { return x * y; }); break;
        case spv::OpFDiv: values[w[2]] = map2(w[3], w[4], [](float x, float y) { return x / y; }); break;
        case spv::OpSelect: values[w[2]] = scalar(w[3]) != 0.0 ? value(w[4]) : value(w[5]); break;
        // Conversions and 32-bit integer operations (vbao.glsl's sector masks).
        case spv::OpConvertFToU: values[w[2]] = map(w[3], [](float x) { return double(uint32_t(x)); }); break;
        case spv::OpConvertFToS: values[w[2]] = map(w[3], [](float x) { return double(uint32_t(int32_t(x))); }); break;
        case spv::OpConvertUToF: values[w[2]] = imap(w[3], [](uint32_t x) { return float(x); }); break;
        case spv::OpConvertSToF: values[w[2]] = imap(w[3], [](uint32_t x) { return float(int32_t(x)); }); break;
        case spv::OpBitcast: values[w[2]] = value(w[3]); break; // int <-> uint: the same word
        case spv::OpIAdd: values[w[2]] = imap2(w[3], w[4], [](uint32_t x, uint32_t y) { return x + y; }); break;
        case spv::OpISub: values[w[2]] = imap2(w[3], w[4], [](uint32_t x, uint32_t y) { return x - y; }); break;
        case spv::OpBitwiseAnd: values[w[2]] = imap2(w[3], w[4], [](uint32_t x, uint32_t y) { return x & y; }); break;
        case spv::OpBitwiseOr: values[w[2]] = imap2(w[3], w[4], [](uint32_t x, uint32_t y) { return x | y; }); break;
        case spv::OpBitwiseXor: values[w[2]] = imap2(w[3], w[4], [](uint32_t x, uint32_t y) { return x ^ y; }); break;
        case spv::OpNot: values[w[2]] = imap(w[3], [](uint32_t x) { return ~x; }); break;
        // A shift by 32 or more is undefined in SPIR-V; here it is 0, and a shader whose result
        // depended on it would pass only by luck (vbao.glsl selects around it).
        case spv::OpShiftLeftLogical: values[w[2]] = imap2(w[3], w[4], [](uint32_t x, uint32_t y) { return y < 32 ? x << y : 0u; }); break;
        case spv::OpShiftRightLogical: values[w[2]] = imap2(w[3], w[4], [](uint32_t x, uint32_t y) { return y < 32 ? x >> y : 0u; }); break;
        case spv::OpBitCount: values[w[2]] = imap(w[3], [](uint32_t x) { return uint32_t(std::bitset<32>(x).count()); }); break;
        case spv::OpIEqual: values[w[2]] = imap2(w[3], w[4], [](uint32_t x, uint32_t y) { return uint32_t(x == y); }); break;
        case spv::OpINotEqual: values[w[2]] = imap2(w[3], w[4], [](uint32_t x, uint32_t y) { return uint32_t(x != y); }); break;
        case spv::OpULessThan: values[w[2]] = imap2(w[3], w[4], [](uint32_t x, uint32_t y) { return uint32_t(x < y); }); break;
        case spv::OpUGreaterThan: values[w[2]] = imap2(w[3], w[4], [](uint32_t x, uint32_t y) { return uint32_t(x > y); }); break;
        case spv::OpUGreaterThanEqual: values[w[2]] = imap2(w[3], w[4], [](uint32_t x, uint32_t y) { return uint32_t(x >= y); }); break;
        case spv::OpULessThanEqual: values[w[2]] = imap2(w[3], w[4], [](uint32_t x, uint32_t y) { return uint32_t(x <= y); }); break;
        case spv::OpFOrdLessThan: values[w[2]] = map2(w[3], w[4], [](float x, float y) { return double(x < y); }); break;
        case spv::OpFOrdGreaterThan: values[w[2]] = map2(w[3], w[4], [](float x, float y) { return double(x > y); }); break;
        case spv::OpFOrdLessThanEqual: values[w[2]] = map2(w[3], w[4], [](float x, float y) { return double(x <= y); }); break;
        case spv::OpFOrdGreaterThanEqual: values[w[2]] = map2(w[3], w[4], [](float x, float y) { return double(x >= y); }); break;
        case spv::OpExtInst: {
            const uint32_t a = w[5];
            switch (static_cast<GLSLstd450>(w[4])) {
            case GLSLstd450Sin: values[w[2]] = map(a, [](float x) { return std::sin(x); }); break;
            case GLSLstd450Cos: values[w[2]] = map(a, [](float x) { return std::cos(x); }); break;
            case GLSLstd450Acos: values[w[2]] = map(a, [](float x) { return std::acos(x); }); break;
            case GLSLstd450Sqrt: values[w[2]] = map(a, [](float x) { return std::sqrt(x); }); break;
            case GLSLstd450Atan2: values[w[2]] = map2(a, w[6], [](float y, float x) { return std::atan2(y, x); }); break;
            case GLSLstd450FMin: values[w[2]] = map2(a, w[6], [](float x, float y) { return std::min(x, y); }); break;
            case GLSLstd450FMax: values[w[2]] = map2(a, w[6], [](float x, float y) { return std::max(x, y); }); break;
            case GLSLstd450UMin: values[w[2]] = imap2(a, w[6], [](uint32_t x, uint32_t y) { return std::min(x, y); }); break;
            case GLSLstd450UMax: values[w[2]] = imap2(a, w[6], [](uint32_t x, uint32_t y) { return std::max(x, y); }); break;
            case GLSLstd450Floor: values[w[2]] = map(a, [](float x) { return std::floor(x); }); break;
            case GLSLstd450FAbs: values[w[2]] = map(a, [](float x) { return std::fabs(x); }); break;
            case GLSLstd450FSign: values[w[2]] = map(a, [](float x) { return float(x > 0) - float(x < 0); }); break;
            case GLSLstd450SmoothStep: {
                const std::vector<double> e0 = value(a), e1 = value(w[6]);
                std::vector<double> r = value(w[7]);
                REQUIRE(e0.size() == r.size());
                REQUIRE(e1.size() == r.size());
                for (size_t k = 0; k < r.size(); ++k) {
                    const float t = std::min(std::max((float(r[k]) - float(e0[k])) / (float(e1[k]) - float(e0[k])), 0.0f), 1.0f);
                    r[k] = t * t * (3.0f - 2.0f * t);
                }
                values[w[2]] = r;
                break;
            }
            case GLSLstd450FClamp: {
                const std::vector<double> lo = value(w[6]), hi = value(w[7]);
                std::vector<double> r = value(a);
                REQUIRE(lo.size() == r.size());
                REQUIRE(hi.size() == r.size());
                for (size_t k = 0; k < r.size(); ++k) r[k] = std::min(std::max(r[k], lo[k]), hi[k]);
                values[w[2]] = r;
                break;
            }
            case GLSLstd450Fma: {
                const std::vector<double> y = value(w[6]), z = value(w[7]);
                std::vector<double> r = value(a);
                REQUIRE(y.size() == r.size());
                REQUIRE(z.size() == r.size());
                for (size_t k = 0; k < r.size(); ++k) r[k] = std::fma(float(r[k]), float(y[k]), float(z[k]));
                values[w[2]] = r;
                break;
            }
            default: FAIL("main() calls GLSL.std.450 instruction " << w[4] << ", which this test does not evaluate");
            }
            break;
        }
        default: FAIL("main() has opcode " << int(op) << ", which this test does not evaluate");
        }
    }
    std::vector<float> r;
    for (size_t k = 0; k < count; ++k) {
        INFO("ao_test.r[" << k << "]");
        REQUIRE(out[k].has_value());
        r.push_back(*out[k]);
    }
    return r;
}

// `x` as a GLSL float literal (rounded to float first): what the test expressions are built of.
inline std::string glsl_literal(double x)
{
    return aogen::glsl_float(static_cast<float>(x));
}

// Each GLSL float expression evaluated with the AO pass of `v` (its templates up to and
// including the technique's) in scope: the pass is generated as usual with
// entry_compute.glsl replaced by a main() that stores the expressions, then compiled,
// optimised and run by run_main. `name` names the module in compiler messages.
inline std::vector<float> evaluate_in_ao_pass(const aogen::variant& v, const std::vector<std::string>& expressions, const std::string& name)
{
    std::string entry = "layout(local_size_x = 1, local_size_y = 1, local_size_z = 1) in;\n"
                        "layout(std430, set = 1, binding = 0) writeonly buffer AoTest { float r[]; } ao_test;\n"
                        "void main()\n{\n";
    for (size_t i = 0; i < expressions.size(); ++i)
        entry += "    ao_test.r[" + std::to_string(i) + "] = " + expressions[i] + ";\n";
    entry += "}\n";
    const aogen::codegen::template_reader read = [&entry](const std::string& path) {
        return path == "entry_compute.glsl" ? entry : aogen_test::template_under_test(path);
    };
    aogen::codegen::options o;
    o.templates = read;
    const std::vector<aogen::codegen::shader_source> sources = aogen::codegen::generate(aogen::codegen::make_plan(v, o));
    const auto ao = std::find_if(sources.begin(), sources.end(), [](const aogen::codegen::shader_source& s) { return s.pass == aogen::pass_kind::ao; });
    if (ao == sources.end() || ao->stage != aogen::shader_stage::compute) aogen::fail("evaluate_in_ao_pass", aogen::to_name(v) + " has no compute AO pass", "valid: a compute variant");
    const aogen::codegen::shader_source& s = *ao;
    const std::vector<uint32_t> words = aogen::compile::optimize_spirv(aogen::compile::glsl_to_spirv(s.glsl, aogen::shader_stage::compute, name), name);
    return run_main(words, expressions.size());
}

} // namespace aogen_test
