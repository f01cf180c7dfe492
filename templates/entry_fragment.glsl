// entry_fragment.glsl -- the fragment entry point of every pass: one fragment per pixel
// of the render target (the AO target: half the screen at AO_HALF_RESOLUTION), drawn with
// common/fullscreen_vertex.glsl (3 vertices, no vertex buffers) and a viewport covering
// the target. The colour attachment, location 0, is a one-channel target (R8_UNORM);
// the value written is ao_finalize(ao_pass(pixel)): finite and in [0, 1].

layout(location = 0) out float o_ao;

void main()
{
    o_ao = ao_finalize(ao_pass(ivec2(gl_FragCoord.xy)));
}
