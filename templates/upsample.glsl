// upsample.glsl -- the depth-aware (joint bilateral) upsample of a half-resolution AO
// target to the screen's resolution: the last pass of a half-resolution variant with
// upsample_mode::depth_aware. Uniform block: BlurUniforms (u.inv_proj, u.linear_sharpness).
//
// Bindings: AO_BINDING_DEPTH the full-resolution depth, AO_BINDING_AO_INPUT the AO target
// (half resolution, its value in .r). Unlike every other pass, this one runs per screen
// pixel: its output is the screen's size.
//
// THE WEIGHTS
//   Target texel q stands for screen pixel 2q (depth.glsl: it read its depth and normal
//   there), so a screen pixel P lies a fraction f = (P - 2 q0) / 2, 0 or 1/2 on each axis,
//   of the way from q0 = P / 2 to q0 + 1. Each of those four texels q counts with
//       b(q) * exp(-|z(q) - z(P)| * u.linear_sharpness)
//   b the bilinear weight for f, z the view-space depth (of 2q and of P): a plain bilinear
//   upsample where the surface is continuous, and no blending across a silhouette, where
//   the texel on the other surface gets a weight of ~0. Where every weight underflows (a
//   pixel of a thin feature the target did not sample, a steep floor far away), P takes the
//   texel nearest to it in depth. Pixels at 2q (f = 0) get texel q's value unchanged, as
//   nearest upsampling would. Background pixels write exactly 1; a pixel with no
//   foreground texel around it keeps q0's value.

#if !defined(AO_PASS_UPSAMPLE)
#error aogen: upsample.glsl is the upsample pass
#endif
#if !defined(AO_HALF_RESOLUTION)
#error aogen: upsample.glsl upsamples a half-resolution AO target
#endif
#if !defined(AO_BINDING_AO_INPUT)
#error aogen: AO_BINDING_AO_INPUT is not defined (codegen writes the bindings)
#endif

layout(set = 0, binding = AO_BINDING_AO_INPUT) uniform sampler2D u_ao_input;

// The AO of target texel q (inside the target), made finite and in [0, 1].
float ao_upsample_input(ivec2 q)
{
    return ao_finalize(texelFetch(u_ao_input, q, 0).r);
}

// `pixel` is a screen pixel here, not a target pixel.
float ao_pass(ivec2 pixel)
{
    ivec2 P = clamp(pixel, ivec2(0), ao_depth_size() - 1);
    float depth = ao_load_depth(P);
    if (ao_is_background(depth)) return 1.0;
    ivec2 size = max(textureSize(u_ao_input, 0), ivec2(1));
    ivec2 q0 = clamp(P / 2, ivec2(0), size - 1);
    float z = ao_view_z(ao_pixel_uv(P), depth);
    if (!ao_is_finite(z)) return ao_upsample_input(q0);

    vec2 f = vec2(P - 2 * q0) * 0.5;
    float sum = 0.0;
    float weight_sum = 0.0;
    float nearest = ao_upsample_input(q0);
    float nearest_dz = -1.0; // none yet
    for (int j = 0; j <= 1; ++j) {
        for (int i = 0; i <= 1; ++i) {
            ivec2 q = q0 + ivec2(i, j);
            if (q.x >= size.x || q.y >= size.y) continue;
            ivec2 q_full = ao_full_pixel(q);
            float q_depth = ao_load_depth(q_full);
            if (ao_is_background(q_depth)) continue;
            float dz = abs(ao_view_z(ao_pixel_uv(q_full), q_depth) - z);
            if (!ao_is_finite(dz)) continue;
            float ao = ao_upsample_input(q);
            if (nearest_dz < 0.0 || dz < nearest_dz) {
                nearest_dz = dz;
                nearest = ao;
            }
            float bilinear = (i == 1 ? f.x : 1.0 - f.x) * (j == 1 ? f.y : 1.0 - f.y);
            float w = bilinear * exp(-dz * u.linear_sharpness);
            if (!(w > 0.0)) continue; // off the footprint, or underflowed
            sum += w * ao;
            weight_sum += w;
        }
    }
    return weight_sum > 0.0 ? sum / weight_sum : nearest;
}
