// floor/bandwidth/blur.glsl -- the bandwidth floor of every blur pass (blur_bilateral.glsl in
// x and y, blur_box.glsl, blur_denoise.glsl): per pixel its AO texel and the depth at its
// full-resolution pixel read once, the output written once. No tap beyond the pixel.

// u_ao_input: declared by aogen::codegen (aogen/bindings.hpp).

// ao_value (common/core.glsl): with bent normals the output's normal channels are written too.
ao_value ao_pass(ivec2 p)
{
    float depth = ao_load_depth(ao_full_pixel(p));
    if (ao_is_background(depth)) return ao_make_value(1.0, vec3(0.0));
    return ao_make_value(fract(depth + texelFetch(u_ao_input, p, 0).r), vec3(0.0));
}
