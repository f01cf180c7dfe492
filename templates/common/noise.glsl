// common/noise.glsl -- the noise tile: one rotation per AO target pixel.
//
// Binding AO_BINDING_NOISE: the tile (aogen/noise.hpp, e.g. 4 x 4 texels of
// (cos t, sin t, 0, 1)) as a FLOAT texture: rgba32f, rgba16f or rg16f from
// aogen::noise::encode. .xy is used as stored -- there is no "* 2 - 1" decoding, so an
// rgba8_unorm tile is not what these templates expect (rgba8_snorm reads back as floats
// and works, to 8-bit precision). The tile repeats over the AO target: pixel p reads
// texel p % tile size with texelFetch (no sampler state involved).

// u_noise: declared by aogen::codegen (aogen/bindings.hpp).

// The unit rotation (cos t, sin t) for AO target pixel p (p >= 0). A zero or non-finite
// texel gives (1, 0): no rotation.
vec2 ao_noise_rotation(ivec2 p)
{
    ivec2 size = max(textureSize(u_noise, 0), ivec2(1));
    // Unsigned: p >= 0, and naga (the WGSL target) mis-types GLSL's signed % (OpSMod) of vectors.
    vec2 r = texelFetch(u_noise, ivec2(uvec2(p) % uvec2(size)), 0).xy;
    float len2 = dot(r, r);
    if (!ao_is_finite(len2) || !(len2 > 1e-12)) return vec2(1.0, 0.0);
    return r * inversesqrt(len2);
}
