// floor/blur_box.glsl -- the fetch floor of blur_box.glsl: the centre's depth, then the
// AO_BLUR_BOX_SIZE x AO_BLUR_BOX_SIZE AO taps inside the target. No average.

// u_ao_input: declared by aogen::codegen (aogen/bindings.hpp).

// ao_value (common/core.glsl): with bent normals the output's normal channels are written too.
ao_value ao_pass(ivec2 p)
{
    float depth = ao_load_depth(ao_full_pixel(p));
    if (ao_is_background(depth)) return ao_make_value(1.0, vec3(0.0));
    ivec2 size = max(textureSize(u_ao_input, 0), ivec2(1));
    const int first = -(AO_BLUR_BOX_SIZE / 2);
    float sum = depth;
    for (int y = first; y < first + AO_BLUR_BOX_SIZE; ++y) {
        for (int x = first; x < first + AO_BLUR_BOX_SIZE; ++x) {
            ivec2 q = p + ivec2(x, y);
            if (q.x < 0 || q.y < 0 || q.x >= size.x || q.y >= size.y) continue;
            sum += texelFetch(u_ao_input, q, 0).r;
        }
    }
    return ao_make_value(fract(sum), vec3(0.0));
}
