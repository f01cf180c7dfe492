// floor/sao.glsl -- the fetch floor of sao.glsl: per pixel the centre depth, the normal's
// fetches and the noise rotation, then per spiral tap the 2x2 gather (depth.glsl's
// ao_depth_at, of the level its distance calls for) where the tap lands on a surface facing
// the camera: the spiral's direction, rotated by the noise, at its share of the radius in
// pixels. No view positions, no Alchemy term, no readings mixed.

float ao_pass(ivec2 target_pixel)
{
    ivec2 p;
    float sum, radius_pixels;
    vec2 r;
    if (!ao_floor_centre(target_pixel, p, sum, r, radius_pixels)) return 1.0;
    vec2 centre = vec2(p) + 0.5;
    for (int i = 0; i < AO_SAO_SAMPLES; ++i) {
        vec4 t = u.spiral[i];
        vec2 offset = vec2(t.x * r.x - t.y * r.y, t.x * r.y + t.y * r.x) * (t.z * radius_pixels);
        sum += ao_floor_surface_fetches(centre + offset, length(offset));
    }
    return fract(sum);
}
