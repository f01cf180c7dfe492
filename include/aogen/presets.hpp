// aogen/presets.hpp — the seeds' own configurations: a name, a variant and its settings.
//
// WHAT
//   A preset is what an engine runs: the variant its shaders are compiled as (variant.hpp:
//   sample counts, blur, normals, resolution, stage) and the run-time settings of each pass
//   (params.hpp: radius, bias, exponents, the blur's depth constants). The four seeds'
//   configurations:
//
//     presets::taos_ssao()               Taos SSAOPass (seeds 000, 002)
//     presets::taos_gtao()               Taos GTAOPass (seed 001)
//     presets::unique_engine_ssao()      Unique Engine UeSSAOPass (seed 003)
//     presets::pointcloud_viewer_ssao()  the point-cloud viewer's ssao.wgsl (seed 004)
//     presets::seeds()                   all four, in that order
//
//   The default matrix's seed variants (matrix.hpp) and `aogen seeds` are made from these.
//
// USAGE
//     #include <aogen/presets.hpp>
//     aogen::preset p = aogen::presets::taos_ssao();
//     aogen::to_name(p.variant);          // "ssao-s16-half-bilateral-gbufworld-std-persp-fs-rawdepth-nearest"
//     p.settings.ssao.radius = 0.8f;      // tune a run-time setting
//     aogen::validate(p);                 // throws aogen::error naming the field
//
// WHY
//   Each number is stored once: what is compiled in on the variant, what is uploaded in the
//   settings. Numbers the seeds state are used exactly; numbers they leave open are marked
//   "(ours)" where they are chosen.
#pragma once

#include "params.hpp"
#include "variant.hpp"

#include <vector>

namespace aogen {

struct preset {
    const char* name;
    aogen::variant variant; // what is compiled in
    ao_settings settings;   // what each pass's uniform block and data carry
};

inline void validate(const preset& p)
{
    validate(p.variant);
    validate(p.settings);
}

namespace presets {

// The seeds' blur constants: the 'quality' bilateral's depth term exp(−|Δ raw depth| · 1000).
inline blur_params taos_quality_blur()
{
    blur_params b;
    b.raw_depth_k = 1000.0f;
    return b;
}

// The variant every seed engine runs its pass as: a fullscreen fragment pass, a
// half-resolution target left for the engine to upsample (the seeds have no upsample pass)
// and, for SSAO, the seeds' step decisions (a sample occluded or not at the bias).
inline variant seed_engine_variant(technique t)
{
    variant v;
    v.tech = t;
    v.stage = pipeline_stage::fragment;
    v.upsample = upsample_mode::nearest;
    v.decisions = ssao_decisions::step;
    return v;
}

// Taos SSAOPass (seeds 000, 002): 16 crytek samples, 4×4 noise, half resolution,
// world-space G-buffer normals, range check 1 − smoothstep(0, radius, |Δz|), output
// clamp(1 − occlusion/N · strength, 0, 1), then the bilateral 'quality' blur on raw
// depth × 1000. The seeds give no radius, bias or strength: 0.5, 0.025 and 1.0 are ours
// (Unique Engine's radius and bias, and the unscaled average).
inline preset taos_ssao()
{
    preset p{"taos_ssao", seed_engine_variant(technique::ssao), {}};
    p.variant.samples = 16;
    p.variant.half_resolution = true;
    p.variant.normals = normal_source::gbuffer_world;
    p.variant.range_check = ssao_range_check::taos;
    p.variant.output = ssao_output::strength;
    p.variant.blur = blur_mode::bilateral;
    p.variant.blur_depth = bilateral_depth::seed_raw;
    p.settings.ssao.radius = 0.5f;    // ours
    p.settings.ssao.bias = 0.025f;    // ours
    p.settings.ssao.strength = 1.0f;  // ours
    p.settings.ssao.kernel = "crytek";
    p.settings.ssao.noise_size = 4;
    p.settings.blur = taos_quality_blur();
    return p;
}

// Taos GTAOPass (seed 001): radius 1.0, thickness bias 0.1, strength exponent 2.0, and
// "the same separable bilateral / box-blur pipelines as SSAO" — the 'quality' blur.
// Slices × steps are not in the seed: 2 × 3 is the variant's default (ours; docs/design.md
// § Variant axes). Half
// resolution and G-buffer world normals are assumed from Taos' SSAO pass.
inline preset taos_gtao()
{
    preset p{"taos_gtao", seed_engine_variant(technique::gtao), {}};
    p.variant.slices = 2;  // ours (the variant's default)
    p.variant.steps = 3;   // ours (the variant's default)
    p.variant.half_resolution = true;
    p.variant.normals = normal_source::gbuffer_world;
    p.variant.blur = blur_mode::bilateral;
    p.variant.blur_depth = bilateral_depth::seed_raw;
    p.settings.gtao.radius = 1.0f;
    p.settings.gtao.thickness_bias = 0.1f;
    p.settings.gtao.falloff_range = 0.0f;  // seed 001: a hard cut-off
    p.settings.gtao.thin_occluder = 0.0f;  // seed 001: plain distance
    p.settings.gtao.strength = 2.0f;
    p.settings.blur = taos_quality_blur();
    return p;
}

// Unique Engine UeSSAOPass (seed 003): radius 0.5, bias 0.025, power 1.0, intensity 1.0,
// 32 hemisphere samples, view-space normals from its normal pre-pass, output
// pow(1 − occlusion/N, power) mixed by intensity, then a bilateral blur "comparing depth
// differences". Not stated by the seed, so ours: the blur's depth term (linear view
// depth, sharpness 10 per world unit), the range check (Taos'), the crytek kernel, the
// 4×4 noise tile and half resolution.
inline preset unique_engine_ssao()
{
    preset p{"unique_engine_ssao", seed_engine_variant(technique::ssao), {}};
    p.variant.samples = 32;
    p.variant.half_resolution = true;                    // ours
    p.variant.normals = normal_source::gbuffer_view;
    p.variant.range_check = ssao_range_check::taos;      // ours
    p.variant.output = ssao_output::power_intensity;
    p.variant.blur = blur_mode::bilateral;
    p.variant.blur_depth = bilateral_depth::linear;      // ours
    p.settings.ssao.radius = 0.5f;
    p.settings.ssao.bias = 0.025f;
    p.settings.ssao.power = 1.0f;
    p.settings.ssao.intensity = 1.0f;
    p.settings.ssao.strength = 1.0f;  // not read by its output form; the seeds' 1, so its block's bytes stay
    p.settings.ssao.kernel = "crytek";                   // ours
    p.settings.ssao.noise_size = 4;                      // ours
    p.settings.blur.linear_sharpness = 10.0f;            // ours
    return p;
}

// The point-cloud viewer's ssao.wgsl (seed 004): 64 samples, 4×4 noise, range check
// smoothstep(0, 1, radius / |Δz|), ao = 1 − occlusion/64 (the strength form with
// strength 1), full resolution, normals reconstructed from depth, the point-cloud
// fallback on, no blur. Its radius and bias are uniforms without values in the seed:
// 0.5 and 0.025 are ours.
inline preset pointcloud_viewer_ssao()
{
    preset p{"pointcloud_viewer_ssao", seed_engine_variant(technique::ssao), {}};
    p.variant.samples = 64;
    p.variant.half_resolution = false;
    p.variant.normals = normal_source::reconstructed;
    p.variant.point_cloud_fallback = true;
    p.variant.range_check = ssao_range_check::seed004;
    p.variant.output = ssao_output::strength;
    p.variant.blur = blur_mode::none;
    p.settings.ssao.radius = 0.5f;    // ours
    p.settings.ssao.bias = 0.025f;    // ours
    p.settings.ssao.strength = 1.0f;
    p.settings.ssao.kernel = "crytek"; // ours (the seed only says "64 hemisphere samples")
    p.settings.ssao.noise_size = 4;
    return p;
}

inline std::vector<preset> seeds()
{
    return {taos_ssao(), taos_gtao(), unique_engine_ssao(), pointcloud_viewer_ssao()};
}

} // namespace presets

} // namespace aogen
