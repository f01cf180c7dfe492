// The fp16 variant axis on the Vulkan harness: the AO pass really is 16-bit (its SPIR-V
// declares the Float16 capability, its fp32 twin's does not), it runs where the device has
// shaderFloat16 (lavapipe does), keeps the contract (finite, in [0, 1], background exactly
// 1, an open plane unoccluded) and stays within a few 8-bit steps of its fp32 twin on a
// crease (a mean difference of a quarter step at most). Its error against the reference is the stability suite's and the report's job.
#include "harness.hpp"

#include <aogen/compile.hpp>

#include <catch2/catch.hpp>
#include <spirv_cross/spirv_cross.hpp>

#include <algorithm>
#include <cmath>
#include <vector>

// One namespace per test file: the files of one executable share a translation unit
// (tests/CMakeLists.txt: a unity build), and their helpers must not meet.
namespace unity_fp16_test {

using namespace aogen;
using namespace aogen_test;

namespace {

std::vector<variant> fp16_variants()
{
    std::vector<variant> out;
    for (const char* name : {"gtao-2x3-half-bilateral-gbufworld-std-persp-cs-fp16", "gtao-1x1-full-noblur-recon-std-persp-cs-fp16",
                             "ssao-s16-half-bilateral-gbufworld-std-persp-cs-fp16", "ssao-s64-full-noblur-recon-std-persp-fs-pc-rc004-fp16",
                             "ssao-s32-half-bilateral-gbufview-std-persp-fs-powint-fp16"})
        out.push_back(variant_from_name(name));
    return out;
}

// Whether SPIR-V module `words` declares the Float16 capability, as SPIRV-Cross reads it (an
// oracle of its own, not passes.hpp's scan that refuses such modules on devices without it).
bool declares_float16(const std::vector<uint32_t>& words)
{
    const spirv_cross::Compiler reader(words);
    const auto& caps = reader.get_declared_capabilities();
    return std::find(caps.begin(), caps.end(), spv::CapabilityFloat16) != caps.end();
}

} // namespace

TEST_CASE("vulkan: an fp16 variant's AO pass is 16-bit SPIR-V, its twin's is not")
{
    for (variant v : fp16_variants()) {
        INFO(to_name(v));
        for (bool fp16 : {true, false}) {
            v.fp16 = fp16;
            for (const codegen::shader_source& s : codegen::generate(codegen::make_plan(v, under_test()))) {
                INFO(s.name);
                // The AO pass only: the blurs and the vertex shader stay 32-bit.
                const bool ao_shader = s.pass == pass_kind::ao && s.stage != shader_stage::vertex;
                CHECK(declares_float16(compile::glsl_to_spirv(s.glsl, s.stage, s.name)) == (fp16 && ao_shader));
            }
        }
    }
}

TEST_CASE("vulkan: fp16 variants keep the contract and stay within 5/255 (mean 0.25/255) of their fp32 twins on a crease")
{
    vulkan::context* ctx = shared_context();
    if (!ctx) return;
    REQUIRE(ctx->shader_float16()); // lavapipe has it; a device without it refuses fp16 chains by name
    const int W = 96, H = 64;
    const float tan_half_fov_y = 0.6f;
    const mat4 proj = perspective(tan_half_fov_y, float(W) / H, 0.1f, 100.0f);
    const vulkan::gbuffer g = crease(W, H, tan_half_fov_y, proj);
    for (const variant& v : fp16_variants()) {
        INFO(to_name(v));
        check_facing_plane(*ctx, v);
        variant twin = v;
        twin.fp16 = false;
        const vulkan::chain_result half = chain_under_test(*ctx, v).run(g, settings_for(proj));
        const vulkan::chain_result full = chain_under_test(*ctx, twin).run(g, settings_for(proj));
        REQUIRE(half.ao.size() == full.ao.size());
        float largest = 0.0f, lowest = 1.0f;
        double sum = 0.0;
        for (size_t i = 0; i < half.ao.size(); ++i) {
            REQUIRE(std::isfinite(half.ao[i]));
            largest = std::max(largest, std::fabs(half.ao[i] - full.ao[i]));
            sum += std::fabs(half.ao[i] - full.ao[i]);
            lowest = std::min(lowest, half.ao[i]);
        }
        // A sample at the bias threshold may flip: one of 64 unblurred samples is 4/255.
        CHECK(largest <= 5.0f / 255.0f);
        CHECK(sum / double(half.ao.size()) <= 0.25 / 255.0);
        CHECK(lowest < 0.98f); // the crease is occluded: the comparison compares something
        require_clean(*ctx);
    }
}

} // namespace unity_fp16_test
