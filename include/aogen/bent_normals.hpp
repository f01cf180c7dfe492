// aogen/bent_normals.hpp — how a bent-normal variant (-bn) stores its bent normal, and how to
// read it back.
//
// WHAT
//   A -bn variant (variant::bent_normals; GTAO, compute) writes, beside the AO, each pixel's
//   bent normal: the cosine-weighted mean of its unoccluded directions, in view space (the
//   camera looks down -z), the direction engines use for specular occlusion and for sampling
//   indirect light. Its passes write four channels (codegen::output_format_of widens r8 to
//   rgba8):
//       .r    the AO, as every variant writes it
//       .gba  the unit bent normal n as (127 n + 128) / 255: in 8 bits the bytes 128 + 127 n
//   (not n * 0.5 + 0.5, which puts a zero component on a rounding's midpoint, byte 127.5,
//   where two compilers of one shader can round apart). A pixel with no bent normal --
//   background, or no surface normal to bend -- stores the zero vector, bytes (128, 128, 128),
//   which decodes to exactly 0; a unit normal decodes to a length within 0.01 of 1.
//   The shader side is common/core.glsl's ao_value and ao_output_texel; a renderer decodes it
//   as decode_bent_normal does: n = (texel.gba * 255 - 128) / 127, renormalised.
//
// USAGE
//     aogen::vec3 n = aogen::decode_bent_normal(g, b, a);              // one rgba8 texel's .gba bytes
//     std::vector<float> ns = aogen::decode_bent_normals(rgba, texels); // 3 floats per texel
#pragma once

#include "math.hpp"

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace aogen {

// The bent normal of one rgba8 texel's .gba bytes: unit, or (0, 0, 0) where it stores none.
inline vec3 decode_bent_normal(uint8_t g, uint8_t b, uint8_t a)
{
    const vec3 n{(float(g) - 128.0f) / 127.0f, (float(b) - 128.0f) / 127.0f, (float(a) - 128.0f) / 127.0f};
    const float length = std::sqrt(n.x * n.x + n.y * n.y + n.z * n.z);
    if (!(length >= 0.5f)) return {0.0f, 0.0f, 0.0f};
    return {n.x / length, n.y / length, n.z / length};
}

// `texels` rgba8 texels (4 bytes each, tightly packed) decoded: 3 floats per texel.
inline std::vector<float> decode_bent_normals(const uint8_t* rgba, size_t texels)
{
    std::vector<float> out(3 * texels);
    for (size_t k = 0; k < texels; ++k) {
        const vec3 n = decode_bent_normal(rgba[4 * k + 1], rgba[4 * k + 2], rgba[4 * k + 3]);
        out[3 * k] = n.x, out[3 * k + 1] = n.y, out[3 * k + 2] = n.z;
    }
    return out;
}

} // namespace aogen
