// aogen/techniques/ssao.hpp — hemisphere SSAO (seeds 000, 002, 003, 004): its block, its bytes,
// its shaders' parts.
//
// WHAT
//   uniforms::ssao_block(samples)   SsaoUniforms: the camera, radius, bias, strength, power,
//                                   intensity, kernel[samples]
//   uniforms::pack_ssao(...)        its bytes under any rule set
//   techniques::ssao                the table's row (descriptor.hpp): the kernel from the
//                                   settings, the noise tile ssao_params names, ssao.glsl (and
//                                   ssao_point_cloud.glsl with -pc), the decision bands
//
// USAGE
//     auto kernel = aogen::kernel::crytek(16, 1);
//     std::vector<uint8_t> bytes = aogen::uniforms::pack_ssao(aogen::ssao_params{}, cam, kernel,
//                                                             {960, 540}, aogen::layout::rules::std140);
//
// ERRORS
//   aogen::error: a kernel of a size outside variant::samples_range, a setting out of range.
#pragma once

#include <aogen/kernel.hpp>
#include "descriptor.hpp"

#include <array>

namespace aogen {

namespace uniforms {

// SsaoUniforms' settings, in block order after the camera members.
inline const std::array<settings_member<ssao_params>, 5> ssao_members{{
    {"radius", [](const ssao_params& p, const extras&) { return p.radius; }},
    {"bias", [](const ssao_params& p, const extras&) { return p.bias; }},
    {"strength", [](const ssao_params& p, const extras&) { return p.strength; }},
    {"power", [](const ssao_params& p, const extras&) { return p.power; }},
    {"intensity", [](const ssao_params& p, const extras&) { return p.intensity; }},
}};

inline layout::block_desc ssao_block(int samples)
{
    require_in("ssao block samples", samples, variant::samples_range);
    layout::struct_desc s = block_of("SsaoUniforms", ssao_members);
    s.members.push_back({"kernel", "vec4", static_cast<uint32_t>(samples)});
    return {s, {}};
}

// SsaoUniforms bytes. `kernel` holds the variant's samples (its size is the block's N, in
// variant::samples_range); `target_size` is the AO target's size in pixels (half the
// screen at half resolution); `e` the frame's turn of the noise and the finalize settings.
inline std::vector<uint8_t> pack_ssao(const ssao_params& p, const camera& cam, const std::vector<vec4>& kernel,
                                      vec2 target_size, const layout::struct_layout& block, const extras& e = {})
{
    validate(p);
    layout::writer w = settings_writer(block, ssao_members, p, cam, target_size, p.noise_size, e);
    w.set("kernel", kernel); // an aogen::error unless the kernel has the block's samples
    return w.bytes();
}
// The same under `rules` (ssao_block(kernel size) laid out here).
inline std::vector<uint8_t> pack_ssao(const ssao_params& p, const camera& cam, const std::vector<vec4>& kernel,
                                      vec2 target_size, layout::rules rules, const extras& e = {})
{
    const int_range n = variant::samples_range;
    if (kernel.size() < size_t(n.lo) || kernel.size() > size_t(n.hi))
        fail("ssao kernel", std::to_string(kernel.size()) + " samples given", "valid: " + to_string(n) + " samples, the variant's samples");
    return pack_ssao(p, cam, kernel, target_size, layout::compute(ssao_block(int(kernel.size())), rules), e);
}

} // namespace uniforms

namespace techniques {

inline constexpr technique_desc ssao{
    technique::ssao,
    [](const variant& v) { return uniforms::ssao_block(v.samples); },
    [](const variant& v, const ao_settings& s, const uniforms::camera& camera, vec2 target_size, const layout::struct_layout& block,
       const uniforms::extras& e) {
        const std::vector<vec4> k = kernel::generate(kernel::distribution_from_name(s.ssao.kernel), v.samples, s.ssao.kernel_seed);
        return uniforms::pack_ssao(s.ssao, camera, k, target_size, block, e);
    },
    [](const ao_settings& s) { return s.ssao.noise_size; },
    [](const variant& v) {
        std::vector<std::string> files;
        if (v.point_cloud_fallback) files.push_back("ssao_point_cloud.glsl");
        files.push_back("ssao.glsl");
        return files;
    },
    [](const variant& v) {
        std::vector<define> d{{"AO_SSAO_SAMPLES", std::to_string(v.samples)},
                              choice_define("RANGE_CHECK", to_name(v.range_check)),
                              choice_define("OUTPUT", to_name(v.output)),
                              choice_define("SSAO_DECISIONS", to_name(v.decisions))};
        if (v.point_cloud_fallback) d.push_back({"AO_POINT_CLOUD_FALLBACK", ""});
        return d;
    },
    [](const variant& v) {
        std::vector<define> c;
        if (v.decisions == ssao_decisions::smooth) {
            c.push_back({"AO_SSAO_VOTE_BAND", glsl_float(ssao_bands::vote_per_radius)});
            c.push_back({"AO_SSAO_SELF_BAND_PIXELS", glsl_float(ssao_bands::self_pixels)});
            c.push_back({"AO_SSAO_EDGE_BAND_PIXELS", glsl_float(ssao_bands::edge_pixels)});
            c.push_back({"AO_DEPTH_PLANE_BAND", glsl_float(ssao_bands::plane_per_spread)});
            if (v.point_cloud_fallback) {
                c.push_back({"AO_PC_SAME_BAND", glsl_float(ssao_bands::point_cloud_same_per_tolerance)});
                c.push_back({"AO_PC_CAVITY_BAND", glsl_float(ssao_bands::point_cloud_cavity_per_threshold)});
            }
        }
        if (v.point_cloud_fallback) {
            c.push_back({"AO_PC_BACKGROUND_DEPTH", glsl_float(point_cloud::background_depth)});
            c.push_back({"AO_PC_SAME_DEPTH", glsl_float(point_cloud::same_depth_tolerance)});
            c.push_back({"AO_PC_CAVITY_THRESHOLD", glsl_float(point_cloud::cavity_threshold)});
            c.push_back({"AO_PC_RING_PIXELS", std::to_string(point_cloud::ring_pixels)});
        }
        return c;
    },
    [](const variant&) { return 1.0; }, // the kernel turns whole
    [](const variant& v) { return "ssao: " + std::to_string(v.samples) + " samples"; },
    1, // taps per iteration: a sample reads one tap
};

} // namespace techniques
} // namespace aogen
