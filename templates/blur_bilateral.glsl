// blur_bilateral.glsl -- one direction of the separable 7-tap bilateral blur (Taos'
// 'quality' blur, seeds 000/002): pass blur_x runs along x, blur_y along y. Uniform block:
// BlurUniforms (u.inv_proj, u.texel_size, u.raw_depth_k, u.linear_sharpness).
//
// Bindings: AO_BINDING_DEPTH the full-resolution depth, AO_BINDING_AO_INPUT the AO target
// to blur (AO target size; its value in .r).
//
// Taps at offsets -3..3 along AO_BLUR_DIRECTION with the Gaussian weights
// AO_BLUR_WEIGHT_0..3 (0.196, 0.175, 0.122, 0.067 -- aogen::blur_params), each times a
// depth term exp(-|delta| * k) against the centre:
//   AO_BILATERAL_DEPTH_SEED_RAW  delta of raw depth-buffer values, k = u.raw_depth_k (1000)
//   AO_BILATERAL_DEPTH_LINEAR    delta of view-space z (world units), k = u.linear_sharpness
// Taps off the target or on background are left out, and the sum is divided by the weight
// actually accumulated (the seed's weights sum to 0.924, not 1). The centre's depth term
// is 1, so when every other tap's weight underflows the centre value comes through
// unchanged. Background pixels write exactly 1.

#if !defined(AO_PASS_BLUR_X) && !defined(AO_PASS_BLUR_Y)
#error aogen: blur_bilateral.glsl is the blur_x or blur_y pass
#endif
#if (defined(AO_BILATERAL_DEPTH_SEED_RAW) + defined(AO_BILATERAL_DEPTH_LINEAR)) != 1
#error aogen: define exactly one of AO_BILATERAL_DEPTH_SEED_RAW AO_BILATERAL_DEPTH_LINEAR
#endif
#if !defined(AO_BLUR_WEIGHT_0) || !defined(AO_BLUR_WEIGHT_1) || !defined(AO_BLUR_WEIGHT_2) || !defined(AO_BLUR_WEIGHT_3)
#error aogen: the bilateral weights AO_BLUR_WEIGHT_0..3 are not defined (codegen writes them)
#endif
#if !defined(AO_BINDING_AO_INPUT)
#error aogen: AO_BINDING_AO_INPUT is not defined (codegen writes the bindings)
#endif

#if defined(AO_PASS_BLUR_X)
#define AO_BLUR_DIRECTION ivec2(1, 0)
#else
#define AO_BLUR_DIRECTION ivec2(0, 1)
#endif

// u_ao_input: declared by aogen::codegen (aogen/bindings.hpp).

const float AO_BLUR_WEIGHTS[4] = float[4](AO_BLUR_WEIGHT_0, AO_BLUR_WEIGHT_1, AO_BLUR_WEIGHT_2, AO_BLUR_WEIGHT_3);

// The AO input at target pixel p (inside the target), made finite and in [0, 1].
// The AO (with bent normals, and the normal: common/core.glsl's ao_value) at target pixel p.
ao_value ao_blur_input(ivec2 p)
{
    return ao_read_input(p);
}

// The quantity the depth term compares, for a full-resolution pixel with depth `depth`.
float ao_blur_depth_key(ivec2 full_pixel, float depth)
{
#if defined(AO_BILATERAL_DEPTH_SEED_RAW)
    return depth;
#else
    return ao_pixel_view_z(full_pixel, depth);
#endif
}

ao_value ao_pass(ivec2 p)
{
    ivec2 full = ao_full_pixel(p);
    float depth = ao_load_depth(full);
    if (ao_is_background(depth)) return ao_open_value();
    ivec2 size = max(textureSize(u_ao_input, 0), ivec2(1));
    ao_value centre = ao_blur_input(clamp(p, ivec2(0), size - 1));
    float key = ao_blur_depth_key(full, depth);
    if (!ao_is_finite(key)) return centre;
#if defined(AO_BILATERAL_DEPTH_SEED_RAW)
    float k = u.raw_depth_k;
#else
    float k = u.linear_sharpness;
#endif
    ao_value sum = AO_BLUR_WEIGHTS[0] * centre;
    float weight_sum = AO_BLUR_WEIGHTS[0];
    for (int i = 1; i <= 3; ++i) {
        for (int side = -1; side <= 1; side += 2) {
            ivec2 q = p + AO_BLUR_DIRECTION * (i * side);
            if (q.x < 0 || q.y < 0 || q.x >= size.x || q.y >= size.y) continue;
            ivec2 q_full = ao_full_pixel(q);
            float q_depth = ao_load_depth(q_full);
            if (ao_is_background(q_depth)) continue;
            float w = AO_BLUR_WEIGHTS[i] * exp(-abs(ao_blur_depth_key(q_full, q_depth) - key) * k);
            if (!(w > 0.0)) continue; // underflowed (or NaN): the tap is left out
            sum += w * ao_blur_input(q);
            weight_sum += w;
        }
    }
    return weight_sum > 0.0 ? sum / weight_sum : centre;
}
