// entry_fragment.glsl -- the fragment entry point of every pass: one fragment per pixel
// of the render target (the AO target: half the screen at AO_HALF_RESOLUTION), drawn with
// common/fullscreen_vertex.glsl (3 vertices, no vertex buffers) and a viewport covering
// the target. The colour attachment, location 0, is a one-channel target (R8_UNORM);
// the value written is ao_output(ao_pass(pixel), pixel): finite and in [0, 1]. The history
// pass writes a second, location 1 (rgba16f): its history (history.glsl's ao_store_history).
//
// AO_DIAGNOSTICS (codegen::options::diagnostics) adds binding AO_BINDING_RAW, an r32f
// storage image of the target's size that receives ao_pass(pixel) before the guard (as
// in entry_compute.glsl); storing from a fragment shader needs the device's
// fragmentStoresAndAtomics.

layout(location = 0) out float o_ao;
// u_raw: declared by aogen::codegen (aogen/bindings.hpp).

void main()
{
    ao_begin_invocation(); // common/depth.glsl: what every tap reads, once
    ivec2 pixel = ivec2(gl_FragCoord.xy);
    float ao = ao_pass(pixel);
#if defined(AO_DIAGNOSTICS)
    imageStore(u_raw, pixel, vec4(ao));
#endif
    o_ao = ao_output(ao, pixel);
}
