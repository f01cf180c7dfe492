// floor/bandwidth/upsample.glsl -- the bandwidth floor of upsample.glsl's compute pass: per
// invocation, the one target texel under its 2 x 2 screen pixels and one gather of their
// depths -- every input texel read once -- and the four pixels written once. No neighbours,
// no weights.

// u_ao_input: declared by aogen::codegen (aogen/bindings.hpp).

#define AO_PASS_WRITES_QUADS

// ao_quad_of (common/core.glsl): with bent normals the output's normal channels are written too.
ao_value4 ao_pass_quad(ivec2 q0)
{
    ivec2 size = max(textureSize(u_ao_input, 0), ivec2(1));
    return ao_quad_of(fract(ao_depth_quad(2 * q0) + texelFetch(u_ao_input, min(q0, size - 1), 0).r));
}
