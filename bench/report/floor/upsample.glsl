// floor/upsample.glsl -- the fetch floor of upsample.glsl: the screen pixel's depth, then the
// depth and AO of the (up to) four target texels around it. No weights.

layout(set = 0, binding = AO_BINDING_AO_INPUT) uniform sampler2D u_ao_input;

float ao_pass(ivec2 pixel)
{
    ivec2 P = clamp(pixel, ivec2(0), ao_depth_size() - 1);
    float depth = ao_load_depth(P);
    if (ao_is_background(depth)) return 1.0;
    ivec2 size = max(textureSize(u_ao_input, 0), ivec2(1));
    ivec2 q0 = clamp(P / 2, ivec2(0), size - 1);
    float sum = depth;
    for (int j = 0; j <= 1; ++j)
        for (int i = 0; i <= 1; ++i) {
            ivec2 q = q0 + ivec2(i, j);
            if (q.x >= size.x || q.y >= size.y) continue;
            sum += ao_load_depth(ao_full_pixel(q)) + texelFetch(u_ao_input, q, 0).r;
        }
    return fract(sum);
}
