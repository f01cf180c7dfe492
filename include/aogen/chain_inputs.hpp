// aogen/chain_inputs.hpp — what a variant's chain reads, as bytes: the G-buffer, each pass's
// uniform block, the noise tile; and the sizes of its target and its output.
//
// WHAT
//   The data every runner of a chain uploads, with no API in it: aogen::vulkan's harness and
//   aogen::gl's runner read the same bytes, so their outputs can be compared pixel for pixel.
//     gbuffer         raw depth, normals and albedo as floats, row-major, top row first
//     chain_settings  the run-time settings of every pass (params.hpp's ao_settings), the
//                     camera and the frame index (temporal.hpp: 0, a still frame, unless set)
//     plan::inputs(settings, w, h)   (codegen/plan.hpp, the door)
//                     the std140 uniform block of each pass of a planned variant, the noise
//                     tile the params name (4 × 4 for GTAO, VBAO and SAO) and, for SSAO, its
//                     kernel
//     target_size     the AO target: the G-buffer's size, or half of it rounded up
//     output_size     what the chain returns: the screen when it ends with the upsample
//
// USAGE
//     aogen::chain_settings s;                                      // params + camera
//     const aogen::codegen::plan p = aogen::codegen::make_plan(v);  // plan.hpp
//     aogen::chain_inputs in = p.inputs(s, w, h);                   // in.uniforms[pass]
#pragma once

#include "noise.hpp"
#include "techniques.hpp"
#include "temporal.hpp"
#include "uniforms.hpp"
#include "variant.hpp"

#include <cstdint>
#include <optional>
#include <utility>
#include <vector>

namespace aogen {

struct gbuffer {
    int width = 0, height = 0;
    std::vector<float> depth;   // width × height raw depth values
    std::vector<float> normals; // width × height × 4 (xyz used); may be empty for reconstructed normals
    // width × height × 4, linear reflectance in rgb (a unused); read by -mbg variants only
    // (common/core.glsl's ao_albedo), may be empty for every other
    std::vector<float> albedo;
    // width × height × 2, the renderer's motion vectors in .rg (history_params::motion says
    // their convention); read by -histmv variants only, may be empty for every other
    std::vector<float> motion;
};

// `g` with every pixel's albedo `rho` (grey): the albedo G-buffer of a renderer with one
// material -- a -mbg variant then writes what -mb writes with finalize_params::albedo = rho.
inline gbuffer with_uniform_albedo(gbuffer g, float rho)
{
    g.albedo.assign(static_cast<size_t>(g.width < 0 ? 0 : g.width) * static_cast<size_t>(g.height < 0 ? 0 : g.height) * 4, rho);
    return g;
}

// The bytes a chain's passes read besides the G-buffer.
struct chain_inputs {
    std::vector<std::vector<uint8_t>> uniforms; // one std140 block per pass, in pass order
    int noise_size = 4;                         // the noise tile is noise_size × noise_size
    std::vector<uint8_t> noise;                 // its RGBA32F texels, row-major
};

// What a chain of any variant reads at run time: the settings of each pass (a variant reads
// its technique's and its blur's), the camera, and which frame of a temporal accumulation
// this is (temporal.hpp; frame 0 is the single-frame output) and the sequence its frames
// turn the noise by (van der Corput, measured best; the others for comparison). A chain with
// a history pass also reads the previous frame's camera (none: the camera stood still) and
// whether to drop its history this frame (a camera cut, a resize, a teleport).
struct chain_settings : ao_settings {
    uniforms::camera camera;
    uint32_t frame = 0;
    temporal::sequence frame_sequence = temporal::sequence::van_der_corput;
    std::optional<uniforms::camera> previous_camera;
    bool reset_history = false;
};

// `settings` seen through `camera`.
inline chain_settings with_camera(const ao_settings& settings, const uniforms::camera& camera)
{
    chain_settings s;
    static_cast<ao_settings&>(s) = settings;
    s.camera = camera;
    return s;
}

// The AO target size of `v` for a G-buffer of w × h.
inline std::pair<int, int> target_size(const variant& v, int w, int h)
{
    return v.half_resolution ? std::pair<int, int>{(w + 1) / 2, (h + 1) / 2} : std::pair<int, int>{w, h};
}

// The size of `v`'s output for a G-buffer of w × h: the screen's when the chain ends with
// the depth-aware upsample pass, the AO target's otherwise.
inline std::pair<int, int> output_size(const variant& v, int w, int h)
{
    return has_upsample_pass(v) ? std::pair<int, int>{w, h} : target_size(v, w, h);
}

// How many screen pixels one output pixel of `v` covers along each axis: 2 for a
// half-resolution chain without the upsample pass, 1 otherwise. A harness upsamples the
// output by this factor to compare it with a screen-sized reference.
inline int output_scale(const variant& v)
{
    return v.half_resolution && !has_upsample_pass(v) ? 2 : 1;
}

namespace detail {

// What `v`'s passes read besides the G-buffer, for settings `s` and a G-buffer of
// screen_w × screen_h (its AO target's size from target_size): each pass's uniform block written into `blocks` (one laid-out block per
// pass, in pass order: a plan's, computed once) -- the AO pass's with frame s.frame's rotation
// of the noise and, GTAO's and VBAO's, its step offset; every one with the finalize settings --,
// the noise tile the params name (4×4 for GTAO, VBAO and SAO) and, for SSAO, the kernel inside
// its block (SAO's spiral is inside its own). `v` is a plan's: validated. The door is
// codegen::plan::inputs (plan.hpp).
inline chain_inputs pack_inputs(const variant& v, const chain_settings& s, int screen_w, int screen_h,
                                const std::vector<const layout::struct_layout*>& blocks)
{
    const auto [target_w, target_h] = target_size(v, screen_w, screen_h);
    const technique_desc& t = technique_of(v.tech);
    chain_inputs in;
    in.noise_size = t.noise_size(s);
    in.noise = noise::encode(noise::rotations(in.noise_size, s.ssao.noise_seed), noise::encoding::rgba32f);
    const vec2 tsize{float(target_w), float(target_h)};
    const uniforms::extras e{temporal::frame_rotation(v, s.frame, s.frame_sequence), s.finalize,
                            temporal::step_offset(s.frame_sequence, s.frame)};
    const std::vector<pass_kind> kinds = passes(v);
    const uniforms::history_frame frame{s.camera, s.previous_camera.value_or(s.camera), {float(screen_w), float(screen_h)}, s.reset_history};
    for (size_t i = 0; i < kinds.size(); ++i)
        in.uniforms.push_back(kinds[i] == pass_kind::ao        ? t.pack(v, s, s.camera, tsize, *blocks.at(i), e)
                              : kinds[i] == pass_kind::history ? uniforms::pack_history(s.history, frame, *blocks.at(i), e)
                                                               : uniforms::pack_blur(s.blur, s.camera.proj, tsize, *blocks.at(i), e));
    return in;
}

} // namespace detail

} // namespace aogen
