// floor/ssao.glsl -- the fetch floor of ssao.glsl: per pixel the centre depth, the normal's
// fetches and the noise rotation, then one depth fetch per kernel sample at the kernel's
// xy, rotated by the noise and scaled by the radius in pixels: where a sample of a surface
// facing the camera projects. No tangent frame, no projection, no range check.

float ao_pass(ivec2 target_pixel)
{
    ivec2 p = ao_full_pixel(target_pixel);
    float depth = ao_load_depth(p);
    if (ao_is_background(depth)) return 1.0;
    float sum = depth + ao_floor_normal_fetches(p);
    float radius_pixels = ao_floor_radius_pixels(ao_view_z(ao_pixel_uv(p), depth));
    vec2 r = ao_noise_rotation(target_pixel);
    vec2 centre = vec2(p) + 0.5;
    for (int i = 0; i < AO_SSAO_SAMPLES; ++i) {
        vec2 k = u.kernel[i].xy;
        vec2 offset = vec2(k.x * r.x - k.y * r.y, k.x * r.y + k.y * r.x) * radius_pixels;
        sum += ao_floor_depth(ivec2(centre + offset));
    }
    return fract(sum);
}
