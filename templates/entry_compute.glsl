// entry_compute.glsl -- the compute entry point of every pass: one invocation per pixel
// of the pass's output, workgroups of AO_WORKGROUP_X x AO_WORKGROUP_Y. Dispatch
// ceil(width / AO_WORKGROUP_X) x ceil(height / AO_WORKGROUP_Y) groups for the output
// image's size; invocations past its edge write nothing.
//
// Binding AO_BINDING_OUTPUT: the output, an r8 (R8_UNORM) storage image of the AO target
// size. The value written is ao_finalize(ao_pass(pixel)): finite and in [0, 1].

layout(local_size_x = AO_WORKGROUP_X, local_size_y = AO_WORKGROUP_Y, local_size_z = 1) in;

layout(set = 0, binding = AO_BINDING_OUTPUT, r8) uniform writeonly image2D u_output;

void main()
{
    ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
    ivec2 size = imageSize(u_output);
    if (pixel.x >= size.x || pixel.y >= size.y) return;
    imageStore(u_output, pixel, vec4(ao_finalize(ao_pass(pixel)), 0.0, 0.0, 1.0));
}
