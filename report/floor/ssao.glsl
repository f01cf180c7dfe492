// floor/ssao.glsl -- the fetch floor of ssao.glsl: per pixel the centre depth, the normal's
// fetches and the noise rotation, then per kernel sample a depth fetch and a 2x2 gather
// (depth.glsl's ao_depth_at) at the kernel's xy, rotated by the noise and scaled by the radius in pixels: where a sample of a surface
// facing the camera projects. No tangent frame, no projection, no range check.

float ao_pass(ivec2 target_pixel)
{
    ivec2 p;
    float sum, radius_pixels;
    vec2 r;
    if (!ao_floor_centre(target_pixel, p, sum, r, radius_pixels)) return 1.0;
    vec2 centre = vec2(p) + 0.5;
    for (int i = 0; i < AO_SSAO_SAMPLES; ++i) {
        vec2 k = u.kernel[i].xy;
        vec2 offset = vec2(k.x * r.x - k.y * r.y, k.x * r.y + k.y * r.x) * radius_pixels;
        sum += ao_floor_surface_fetches(centre + offset, length(offset));
    }
    return fract(sum);
}
