// blur_box.glsl -- the single-pass box blur (Taos' 'performance' blur, seeds 000/002): the
// unweighted average of the AO_BLUR_BOX_SIZE x AO_BLUR_BOX_SIZE (4 x 4) square of AO
// target pixels at offsets -size/2 .. size/2 - 1 (for 4: -2..1) on each axis. Uniform
// block: BlurUniforms (declared for a common blur interface; the box reads none of it).
//
// Bindings: AO_BINDING_DEPTH the full-resolution depth (only for the background test),
// AO_BINDING_AO_INPUT the AO target to blur. Taps off the target are left out of the
// average (the centre never is). Background pixels write exactly 1.

#if !defined(AO_PASS_BLUR_BOX)
#error aogen: blur_box.glsl is the blur_box pass
#endif
#if !defined(AO_BLUR_BOX_SIZE)
#error aogen: AO_BLUR_BOX_SIZE is not defined (codegen writes it)
#endif
#if !defined(AO_BINDING_AO_INPUT)
#error aogen: AO_BINDING_AO_INPUT is not defined (codegen writes the bindings)
#endif

// u_ao_input: declared by aogen::codegen (aogen/bindings.hpp).

ao_value ao_pass(ivec2 p)
{
    if (ao_is_background(ao_load_depth(ao_full_pixel(p)))) return ao_open_value();
    ivec2 size = max(textureSize(u_ao_input, 0), ivec2(1));
    const int first = -(AO_BLUR_BOX_SIZE / 2);
    ao_value sum = ao_value(0.0); // with bent normals, their sum too (common/core.glsl's ao_value)
    float count = 0.0;
    for (int y = first; y < first + AO_BLUR_BOX_SIZE; ++y) {
        for (int x = first; x < first + AO_BLUR_BOX_SIZE; ++x) {
            ivec2 q = p + ivec2(x, y);
            if (q.x < 0 || q.y < 0 || q.x >= size.x || q.y >= size.y) continue;
            sum += ao_read_input(q);
            count += 1.0;
        }
    }
    return count > 0.0 ? sum / count : ao_open_value();
}
