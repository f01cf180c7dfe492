// gtao.glsl -- ground-truth AO (Jimenez et al. 2016), as Taos' GTAOPass (seed 001)
// describes it. Uniform block: GtaoUniforms (u.proj, u.inv_proj, u.world_to_view,
// u.radius, u.thickness_bias, u.strength).
//
// Per pixel, with P its view-space position, V the direction to the camera and n the
// normal (normals.glsl), for each of AO_GTAO_SLICES slices -- screen directions at angles
// s * pi / SLICES, all rotated by the pixel's noise rotation (the jitter):
//   1. march AO_GTAO_STEPS steps to each side along the direction in screen space, at
//      full resolution, step j at j / STEPS of the radius projected at P's depth (capped
//      at the screen's diagonal), keeping per side the largest cosine between V and the
//      direction to the sample's view-space point (the highest horizon). Samples off
//      screen, on background, on the pixel itself, or farther than
//      radius * (1 + thickness_bias * 10) from P do not raise the horizon;
//   2. project n onto the slice plane (spanned by V and the slice direction): length
//      |n_p|, signed angle n from V (positive toward the slice direction);
//   3. horizon angles h+ = acos(cos+), h- = -acos(cos-), each clamped to [n - pi/2, n + pi/2]
//      (the hemisphere around the projected normal);
//   4. the slice's visibility (sin(h+ - n) - sin(h- - n)) / 2, in [0, 1] (seed 001's
//      cosine-weighted slice integral; 1 for an unoccluded slice).
// The slices' visibilities are averaged weighted by |n_p| (sum |n_p| v / sum |n_p|, our
// reading of "weighted by the projected normal length ... averaged across slices": an open
// plane then gives exactly 1 at every tilt) and the result is raised to u.strength.

#if !defined(AO_PASS_AO) || !defined(AO_TECHNIQUE_GTAO)
#error aogen: gtao.glsl is the AO pass of the gtao technique
#endif
#if !defined(AO_GTAO_SLICES) || !defined(AO_GTAO_STEPS)
#error aogen: gtao.glsl needs AO_GTAO_SLICES and AO_GTAO_STEPS
#endif

// The cosine between V and the direction from P to the scene point under screen
// position `pos` (full-resolution pixels), or -1 (the lowest horizon) when that sample
// cannot raise the horizon.
float ao_gtao_horizon_cos(vec2 pos, ivec2 centre_pixel, vec3 P, vec3 V, float max_distance)
{
    ivec2 size = ao_depth_size();
    if (!(pos.x >= 0.0 && pos.y >= 0.0 && pos.x < float(size.x) && pos.y < float(size.y))) return -1.0;
    ivec2 q = ivec2(pos);
    if (q == centre_pixel) return -1.0;
    float depth = ao_load_depth(q);
    if (ao_is_background(depth)) return -1.0;
    vec3 w = ao_view_position(ao_pixel_uv(q), depth) - P;
    float distance = length(w);
    if (!(distance > 1e-30 && distance <= max_distance)) return -1.0; // NaN and inf fail too
    return dot(w, V) / distance;
}

float ao_pass(ivec2 target_pixel)
{
    ivec2 p = ao_full_pixel(target_pixel);
    float depth = ao_load_depth(p);
    if (ao_is_background(depth)) return 1.0;
    vec3 P = ao_view_position(ao_pixel_uv(p), depth);
    if (!ao_is_finite(P)) return 1.0;
    vec3 V = ao_view_direction(P);
    vec3 n;
    if (!ao_surface_normal(p, P, V, n)) return 1.0;

    // The radius in full-resolution pixels at P's depth: clip y = proj[1][1] * y (/ -z).
    vec2 fsize = vec2(ao_depth_size());
    float pixels_per_unit = 0.5 * fsize.y * abs(u.proj[1][1]);
#if !defined(AO_PROJECTION_ORTHOGRAPHIC)
    pixels_per_unit /= max(-P.z, 1e-30);
#endif
    float radius_pixels = min(u.radius * pixels_per_unit, length(fsize));
    if (!ao_is_finite(radius_pixels)) radius_pixels = 0.0;
    float max_distance = u.radius * (1.0 + u.thickness_bias * 10.0);

    vec2 rotation = ao_noise_rotation(target_pixel);
    vec2 centre = vec2(p) + 0.5;
    float visibility_sum = 0.0;
    float weight_sum = 0.0;
    for (int s = 0; s < AO_GTAO_SLICES; ++s) {
        float angle = float(s) * (AO_PI / float(AO_GTAO_SLICES));
        vec2 base = vec2(cos(angle), sin(angle));
        // The slice direction on screen (pixels, y down), and in view space (y up).
        vec2 dir = vec2(base.x * rotation.x - base.y * rotation.y, base.x * rotation.y + base.y * rotation.x);
        vec3 dir_view = vec3(dir.x, -dir.y, 0.0);
        vec3 side = ao_safe_normalize(dir_view - V * dot(dir_view, V), vec3(0.0)); // in the slice plane, perpendicular to V
        if (dot(side, side) < 0.5) continue;
        vec3 axis = cross(side, V); // the slice plane's normal (unit: side is perpendicular to V)
        vec3 n_projected = n - axis * dot(n, axis);
        float n_length = length(n_projected);
        if (!(n_length > 1e-6)) continue; // the normal is perpendicular to the slice
        // Signed angle of the projected normal from V, toward `side`; n faces V, so the
        // cosine dot(n_projected, V) = dot(n, V) >= 0 and the angle is in [-pi/2, pi/2].
        float n_angle = atan(dot(n_projected, side), max(dot(n_projected, V), 0.0));

        float cos_ahead = -1.0;
        float cos_behind = -1.0;
        for (int j = 1; j <= AO_GTAO_STEPS; ++j) {
            vec2 offset = dir * (radius_pixels * (float(j) / float(AO_GTAO_STEPS)));
            cos_ahead = max(cos_ahead, ao_gtao_horizon_cos(centre + offset, p, P, V, max_distance));
            cos_behind = max(cos_behind, ao_gtao_horizon_cos(centre - offset, p, P, V, max_distance));
        }
        float h_ahead = acos(clamp(cos_ahead, -1.0, 1.0));
        float h_behind = -acos(clamp(cos_behind, -1.0, 1.0));
        h_ahead = clamp(h_ahead, n_angle - AO_HALF_PI, n_angle + AO_HALF_PI);
        h_behind = clamp(h_behind, n_angle - AO_HALF_PI, n_angle + AO_HALF_PI);
        float slice_visibility = 0.5 * (sin(h_ahead - n_angle) - sin(h_behind - n_angle));
        visibility_sum += n_length * slice_visibility;
        weight_sum += n_length;
    }
    float visibility = weight_sum > 1e-6 ? clamp(visibility_sum / weight_sum, 0.0, 1.0) : 1.0;
    return visibility > 0.0 ? pow(visibility, u.strength) : 0.0;
}
