// floor/gtao.glsl -- the fetch floor of gtao.glsl: per pixel the centre depth, the normal's
// fetches and the noise rotation, then, for each of AO_GTAO_SLICES slices rotated by the
// noise, AO_GTAO_STEPS samples on each side along the slice's screen direction at
// j / STEPS of the radius in pixels -- the positions gtao.glsl reads, each what
// common/slices.glsl's ao_slice_tap_surface fetches there (the four texels around it, read
// before any test of the tap) -- and no horizon, no slice integral.

// What ao_slice_tap_surface fetches for a tap at `pos`, `distance` pixels from the pixel:
// the four texels around pos at its level, read first, then counted only on screen, as
// gtao.glsl's ao_gtao_horizon_cos tests it after the read.
float ao_floor_slice_tap_fetches(vec2 pos, float distance)
{
    vec2 f, at;
    float depth;
    ivec2 texel;
    vec4 g = ao_depth_around(pos, ao_tap_level(distance), f, depth, at, texel);
    bool on_screen = all(bvec4(greaterThanEqual(pos, vec2(0.0)), lessThan(pos, vec2(ao_depth_size()))));
    return on_screen ? g.x + g.y + g.z + g.w : 0.0;
}

// ao_value (common/core.glsl): with bent normals the output's normal channels are written too.
ao_value ao_pass(ivec2 target_pixel)
{
    ivec2 p;
    float sum, radius_pixels;
    vec2 rotation;
    if (!ao_floor_centre(target_pixel, p, sum, rotation, radius_pixels)) return ao_make_value(1.0, vec3(0.0));
    vec2 centre = vec2(p) + 0.5;
    for (int s = 0; s < AO_GTAO_SLICES; ++s) {
        float angle = float(s) * (AO_PI / float(AO_GTAO_SLICES));
        vec2 base = vec2(cos(angle), sin(angle));
        vec2 dir = vec2(base.x * rotation.x - base.y * rotation.y, base.x * rotation.y + base.y * rotation.x);
        for (int j = 1; j <= AO_GTAO_STEPS; ++j) {
            float distance = radius_pixels * (float(j) / float(AO_GTAO_STEPS));
            vec2 offset = dir * distance;
            sum += ao_floor_slice_tap_fetches(centre + offset, distance) + ao_floor_slice_tap_fetches(centre - offset, distance);
        }
    }
    return ao_make_value(fract(sum), vec3(0.0));
}
