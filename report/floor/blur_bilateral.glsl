// floor/blur_bilateral.glsl -- the fetch floor of blur_bilateral.glsl: the centre's depth and
// AO, then the depth and AO of each of the 6 taps (3 per side along the blur's axis) inside
// the target. No depth weights.

#if defined(AO_PASS_BLUR_X)
#define AO_BLUR_DIRECTION ivec2(1, 0)
#else
#define AO_BLUR_DIRECTION ivec2(0, 1)
#endif

// u_ao_input: declared by aogen::codegen (aogen/bindings.hpp).

// ao_value (common/core.glsl): with bent normals the output's normal channels are written too.
ao_value ao_pass(ivec2 p)
{
    float depth = ao_load_depth(ao_full_pixel(p));
    if (ao_is_background(depth)) return ao_make_value(1.0, vec3(0.0));
    ivec2 size = max(textureSize(u_ao_input, 0), ivec2(1));
    float sum = depth + texelFetch(u_ao_input, clamp(p, ivec2(0), size - 1), 0).r;
    for (int i = 1; i <= 3; ++i) {
        for (int side = -1; side <= 1; side += 2) {
            ivec2 q = p + AO_BLUR_DIRECTION * (i * side);
            if (q.x < 0 || q.y < 0 || q.x >= size.x || q.y >= size.y) continue;
            sum += ao_load_depth(ao_full_pixel(q)) + texelFetch(u_ao_input, q, 0).r;
        }
    }
    return ao_make_value(fract(sum), vec3(0.0));
}
