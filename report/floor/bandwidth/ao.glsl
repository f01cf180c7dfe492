// floor/bandwidth/ao.glsl -- the bandwidth floor of every AO pass (ssao.glsl, gtao.glsl,
// vbao.glsl): per target pixel, each input the pass cannot do without read once at the pixel
// itself -- its depth, its normal (bandwidth/normals.glsl) and its noise texel -- and the
// output written once. No sample beyond the pixel: what any AO pass of this size, these
// formats and this output must move, whatever its technique.

// ao_value (common/core.glsl): with bent normals the output's normal channels are written too.
ao_value ao_pass(ivec2 target_pixel)
{
    ivec2 p = ao_full_pixel(target_pixel);
    float depth = ao_load_depth(p);
    if (ao_is_background(depth)) return ao_make_value(1.0, vec3(0.0));
    return ao_make_value(fract(depth + ao_bandwidth_normal(p) + ao_noise_rotation(target_pixel).x), vec3(0.0));
}
