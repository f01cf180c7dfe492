// common/noise.glsl -- the noise tile: one rotation per AO target pixel.
//
// Binding AO_BINDING_NOISE: the tile (aogen/noise.hpp, e.g. 4 x 4 texels of
// (cos t, sin t, 0, 1)) as a FLOAT texture: rgba32f, rgba16f or rg16f from
// aogen::noise::encode. .xy is used as stored -- there is no "* 2 - 1" decoding, so an
// rgba8_unorm tile is not what these templates expect (rgba8_snorm reads back as floats
// and works, to 8-bit precision). The tile repeats over the AO target: pixel p reads
// texel p % tile size with texelFetch (no sampler state involved).

// u_noise: declared by aogen::codegen (aogen/bindings.hpp).

// The unit rotation (cos t, sin t) for AO target pixel p (p >= 0): the tile's texel,
// turned by this frame's rotation u.frame_rotation (aogen/temporal.hpp), so that frames
// averaged by TAA see every pixel's samples at angles spread over the period. A zero or
// non-finite texel counts as (1, 0): no rotation of its own.
//   Frame 0's rotation is (1, 0) exactly: the products below are then exact (times 1,
// times 0), whether or not the compiler fuses them, and the output is the single-frame
// output bit for bit.
vec2 ao_noise_rotation(ivec2 p)
{
    ivec2 size = max(textureSize(u_noise, 0), ivec2(1));
    // Unsigned: p >= 0, and naga (the WGSL target) mis-types GLSL's signed % (OpSMod) of vectors.
    vec2 r = texelFetch(u_noise, ivec2(uvec2(p) % uvec2(size)), 0).xy;
    float len2 = dot(r, r);
    vec2 texel = ao_is_finite(len2) && len2 > 1e-12 ? r * inversesqrt(len2) : vec2(1.0, 0.0);
    vec2 turn = u.frame_rotation;
    return vec2(texel.x * turn.x - texel.y * turn.y, texel.x * turn.y + texel.y * turn.x);
}
