// floor/bandwidth/blur_ao_only.glsl -- the bandwidth floor of a blur that reads no depth
// (blur_denoise3.glsl: its AO pass wrote the edges beside the AO): per pixel its AO texel read
// once, the output written once.

// u_ao_input: declared by aogen::codegen (aogen/bindings.hpp).

ao_value ao_pass(ivec2 p)
{
    vec3 t = texelFetch(u_ao_input, p, 0).rgb;
    return ao_make_value(fract(t.x + t.y + t.z), vec3(0.0));
}
