// floor/bandwidth/blur_ao_only.glsl -- the bandwidth floor of a blur that reads no depth
// (blur_denoise3.glsl: its AO pass wrote the edges beside the AO): per invocation the 2 x 2
// quad the pass writes (AO_PASS_WRITES_QUADS), each pixel's AO texel read once, the output
// written once.

// u_ao_input: declared by aogen::codegen (aogen/bindings.hpp).

#define AO_PASS_WRITES_QUADS

// ao_quad_of (common/core.glsl): four pixels' values from the AO alone.
ao_value4 ao_pass_quad(ivec2 q)
{
    ivec2 last = max(textureSize(u_ao_input, 0), ivec2(1)) - 1;
    vec4 sum;
    for (int k = 0; k < 4; ++k) {
        vec3 t = texelFetch(u_ao_input, min(2 * q + ivec2(k & 1, k >> 1), last), 0).rgb;
        sum[k] = t.x + t.y + t.z;
    }
    return ao_quad_of(fract(sum));
}
