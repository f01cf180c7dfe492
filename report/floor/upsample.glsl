// floor/upsample.glsl -- the fetch floor of upsample.glsl's compute pass (floors are compute
// kernels): per invocation, for the 2 x 2 screen pixels of target texel q0, one gather of
// their depths, the depths of the four target texels around them and one gather of those
// texels' AO. No weights.

// u_ao_input: declared by aogen::codegen (aogen/bindings.hpp).

#define AO_PASS_WRITES_QUADS

vec4 ao_pass_quad(ivec2 q0)
{
    ivec2 size = max(textureSize(u_ao_input, 0), ivec2(1));
    vec4 sum = ao_depth_quad(2 * q0) + textureGather(u_ao_input, vec2(q0 + 1) / vec2(size), 0);
    for (int k = 0; k < 4; ++k) sum[k] += ao_load_depth(ao_full_pixel(min(q0 + ivec2(k & 1, k >> 1), size - 1)));
    return fract(sum);
}
