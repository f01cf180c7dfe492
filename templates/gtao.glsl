// gtao.glsl -- ground-truth AO (Jimenez et al. 2016), after Taos' GTAOPass (seed 001),
// with Jimenez's cosine-weighted slice integral in place of the seed's (see "Why not the
// seed's formula" below). Uniform block: GtaoUniforms (u.proj, u.inv_proj,
// u.world_to_view, u.radius, u.thickness_bias, u.strength, u.falloff_range,
// u.thin_occluder, u.frame_step).
//
// Per pixel, with P its view-space position, V the direction to the camera and n the
// normal (normals.glsl; it faces V), for each of AO_GTAO_SLICES slices -- screen
// directions at angles s * pi / SLICES, all rotated by the pixel's noise rotation (the
// jitter):
//   1. project n onto the slice plane (spanned by V and the slice direction `side`):
//      length |n_p|, signed angle n from V, positive toward `side`
//      (common/slices.glsl's ao_slice_projected_normal, as the radius and slice frame);
//   2. march AO_GTAO_STEPS steps to each side along the direction in screen space, at
//      full resolution, step j at j / STEPS of the radius projected at P's depth (capped
//      at half the screen's height; later frames move the inner steps within their strata:
//      common/slices.glsl's ao_slice_step_pixels, u.frame_step), keeping per side the
//      largest cosine between V and the direction to the sample's view-space point (the
//      highest horizon). Samples off screen, on background, on the pixel itself, or farther than
//      radius * (1 + thickness_bias * 10) from P do not raise the horizon; nearer ones
//      fade in over the falloff range (ao_gtao_horizon_cos: falloff, thin occluders);
//   3. horizon angles h+ = acos(cos+) in [0, pi], h- = -acos(cos-) in [-pi, 0], each
//      clamped to [n - pi/2, n + pi/2] (the hemisphere around the normal);
//   4. the slice integral a(h-, n) + a(h+, n) and its value for an unoccluded slice,
//      cos n + n sin n (ao_gtao_slice_integral below; ao_slice_arc, ao_slice_unoccluded);
//      with bent normals (-bn), the slice's bent vector between the horizons too
//      (common/slices.glsl's ao_slice_bent and THE BENT NORMAL).
// The visibility is sum |n_p| (a(h-, n) + a(h+, n)) / sum |n_p| (cos n + n sin n) over the
// slices, raised to u.strength.
//
// THE SLICE INTEGRAL (Jimenez et al. 2016, "Practical Real-Time Strategies for Accurate
// Indirect Occlusion"; the form XeGTAO uses)
//   aogen's AO is the cosine-weighted visibility (docs/design.md#ground-truth):
//       AO = 1/pi * integral over the hemisphere of V(w) (n . w) dw.
//   Write directions in slice coordinates around V: phi in [0, pi), the slice's angle on
//   screen, and theta in [-pi, pi], the signed angle of w from V within that slice's
//   plane (theta < 0 is the half-plane behind `side`). These are spherical coordinates
//   about V, each slice holding both half-planes, so dw = |sin theta| dtheta dphi; and
//   n . w = |n_p| cos(theta - n). A heightfield seen from V is visible between the two
//   horizons, h- <= 0 <= h+, so
//       AO = 1/pi * integral_0^pi |n_p| * integral_{h-}^{h+} cos(theta - n) |sin theta| dtheta dphi.
//   The inner integral splits at theta = 0, where |sin theta| changes sign, and both
//   halves have the same antiderivative form (cos(t - n) sin t = (sin(2t - n) + sin n) / 2):
//       h >= 0:  integral_0^h cos(t - n) sin t dt
//       h <= 0:  integral_h^0 cos(t - n) (-sin t) dt
//       both  =  a(h, n) = (-cos(2h - n) + cos n + 2 h sin n) / 4
//   and the slice's integral is a(h-, n) + a(h+, n). (Both halves are >= 0 for any h in
//   the clamped range: the integrand is >= 0 on [n - pi/2, n + pi/2].)
//   For an unoccluded slice, h+- = n +- pi/2, it is cos n + n sin n: 1 when n = 0, up to
//   pi/2 for a normal in the view plane -- not 1 per slice; only the integral over phi,
//   1/pi * integral_0^pi |n_p| (cos n + n sin n) dphi, is 1 (the unoccluded hemisphere).
//
// NORMALISING
//   With finitely many slices, XeGTAO divides sum |n_p| (a- + a+) by the slice count:
//   right on average over the jitter, but an open plane tilted to the view then gets a
//   value other than 1 (more or less, depending on where the slices fall). aogen divides
//   by the same sum for the unoccluded hemisphere, sum |n_p| (cos n + n sin n), which
//   converges to the same integral as the slices get dense (its exact value is 1), gives
//   exactly 1 for an open plane at every tilt, slice count and jitter, and is never 0
//   for a slice that counts (cos n + n sin n >= 1, and slices with |n_p| ~ 0 are skipped).
//
// WHY NOT THE SEED'S FORMULA
//   Seed 001 calls (sin(h+ - n) - sin(h- - n)) / 2 "the cosine-weighted slice integral".
//   It is 1/2 * integral_{h-}^{h+} cos(theta - n) dtheta: the integral without the
//   |sin theta| of dw, which weighs every theta of the slice alike, so directions near V
//   (which cover little solid angle) count as much as those near the view plane, where
//   occluders sit. It is not the cosine-weighted visibility and reads too light: a floor
//   point next to an infinite wall (exact 0.5) gives 0.62-0.64 for oblique views with
//   exact horizons, Jimenez's integral 0.5000; the apex of a 90-degree groove (exact
//   0.7071): seed 0.82, Jimenez 0.7071. The seed's form is not kept as an option: it
//   would be a second integral, normalisation and test set to maintain for a result our
//   definition of AO calls wrong. (Where the scene is not a heightfield seen from V -- a
//   sphere resting on the floor, with open directions below it -- horizons over-occlude
//   whichever slice integral is used; that error is the horizon model's, not the integral's.)
//
// NUMERICS
//   Horizon cosines that are NaN or outside [-1, 1] are clamped (NaN: no horizon, -1)
//   before acos; n comes from atan with a positive x (or is +-pi/2 for a normal in the
//   view plane); every angle handed to cos/sin is finite. The sums are finite and the
//   result is in [0, 1]; ao_finalize (core.glsl) catches anything else.

#if !defined(AO_PASS_AO) || !defined(AO_TECHNIQUE_GTAO)
#error aogen: gtao.glsl is the AO pass of the gtao technique
#endif
#if !defined(AO_GTAO_SLICES) || !defined(AO_GTAO_STEPS)
#error aogen: gtao.glsl needs AO_GTAO_SLICES and AO_GTAO_STEPS
#endif

// What decides how much a sample counts (FALLOFF AND THIN OCCLUDERS), fixed per pixel.
struct ao_gtao_falloff {
    float max_distance; // d_max: radius * (1 + thickness_bias * 10)
    float stretch;      // t (2 + t), t = u.thin_occluder: |w + t (w . V) V|^2 = |w|^2 + stretch (w . V)^2
    float inverse_fade; // 1 / (u.falloff_range d_max); 0 for a hard cut-off (falloff_range 0)
};

ao_gtao_falloff ao_gtao_falloff_of(float max_distance)
{
    ao_gtao_falloff f;
    f.max_distance = max_distance;
    f.stretch = u.thin_occluder * (2.0 + u.thin_occluder);
    float fade_length = u.falloff_range * max_distance;
    f.inverse_fade = fade_length > 0.0 ? 1.0 / fade_length : 0.0;
    return f;
}

// The horizon cosine one sample offers: the cosine between V and the direction from P to
// the scene point under screen position `pos` (full-resolution pixels), moved toward
// `unoccluded` (the cosine of the hemisphere's edge on that side) by the falloff weight;
// `unoccluded` itself when the sample cannot raise the horizon.
//
// FALLOFF AND THIN OCCLUDERS
//   The distance d that decides whether a sample counts is measured with the part of its
//   offset w along the view ray stretched by 1 + u.thin_occluder:
//       d = |w + t (w . V) V|,  t = u.thin_occluder,
//   so an occluder far in front of or behind P (the usual case of a thin pole or leg, whose
//   depth the heightfield model extends to infinity) stops counting sooner. V is a unit
//   vector, so with a = w . V
//       d^2 = |w|^2 + 2 t a^2 + t^2 a^2 = |w|^2 + t (2 + t) a^2
//   -- the same dot products the cosine needs, and no second vector. A sample with
//   d > d_max does not count; below, its weight is
//       f = clamp((d_max - d) / (u.falloff_range d_max), 0, 1)
//   (the division hoisted: ao_gtao_falloff's inverse_fade) and its horizon is
//   mix(unoccluded, cos, f): 1 well inside the radius, fading to no occlusion at d_max. With
//   falloff_range 0 the weight is 1 up to d_max (a hard cut-off). The cosine itself is always
//   the true direction's, a / |w| (one inverse square root): the falloff changes how much a
//   sample counts, never where it is.
float ao_gtao_horizon_cos(vec2 pos, float pixels, ivec2 centre_pixel, vec3 P, vec3 V, ao_gtao_falloff f, float unoccluded)
{
    // The surface the sample lands on (common/slices.glsl's ao_slice_tap_surface), `pixels`
    // from the pixel: near it, on a plane, its point under pos on the slice line, at a
    // silhouette the nearest texel's own point; farther, the texel's own point. Read first,
    // before any test (ao_slice_tap_surface says why).
    float depth;
    vec2 at;
    ivec2 q;
    bool surface = ao_slice_tap_surface(pos, pixels, depth, at, q);
    // On screen (NaN fails); all() of the four tests, not &&, which branches.
    if (!all(bvec4(greaterThanEqual(pos, vec2(0.0)), lessThan(pos, vec2(ao_depth_size()))))) return unoccluded;
    if (!surface || q == centre_pixel) return unoccluded;
    vec3 w = ao_view_position_at(at, depth) - P;
    float along_view = dot(w, V);
    float length_squared = dot(w, w);
    float distance = sqrt(length_squared + f.stretch * (along_view * along_view));
    // |w| > 3e-19, a sample at P itself no sample (1e-37: a normal float, so no epsilon of scale);
    // NaN and inf fail too.
    if (!(length_squared > 1e-37 && distance <= f.max_distance)) return unoccluded;
    float weight = f.inverse_fade > 0.0 ? clamp((f.max_distance - distance) * f.inverse_fade, 0.0, 1.0) : 1.0;
    return ao_lerp(unoccluded, along_view * inversesqrt(length_squared), weight);
}

// The horizon angles (h-, h+) from the horizon cosines of the two sides (-1: no horizon),
// clamped to the hemisphere around the projected normal's angle n.
ao_half2 ao_gtao_horizons(ao_half n_angle, ao_half cos_behind, ao_half cos_ahead)
{
    const ao_half half_pi = ao_half(AO_HALF_PI);
    ao_half n = clamp(n_angle, -half_pi, half_pi);
    // ao_is_finite first: clamp() of a NaN is undefined; a NaN horizon is no horizon.
    ao_half c_ahead = ao_is_finite(float(cos_ahead)) ? clamp(cos_ahead, ao_half(-1.0), ao_half(1.0)) : ao_half(-1.0);
    ao_half c_behind = ao_is_finite(float(cos_behind)) ? clamp(cos_behind, ao_half(-1.0), ao_half(1.0)) : ao_half(-1.0);
    // h+ in [0, pi], h- in [-pi, 0]; the clamp keeps h- <= 0 <= h+, as n +- pi/2 straddle 0.
    ao_half h_ahead = clamp(ao_acos(c_ahead), n - half_pi, n + half_pi);
    ao_half h_behind = clamp(-ao_acos(c_behind), n - half_pi, n + half_pi);
    return ao_half2(h_behind, h_ahead);
}

// The slice integral a(h-, n) + a(h+, n), without the |n_p| factor, from the horizon
// cosines of the two sides (-1: no horizon) and the projected normal's angle n.
ao_half ao_gtao_slice_integral(ao_half n_angle, ao_half cos_behind, ao_half cos_ahead)
{
    ao_half n = clamp(n_angle, ao_half(-AO_HALF_PI), ao_half(AO_HALF_PI));
    ao_half2 horizons = ao_gtao_horizons(n, cos_behind, cos_ahead);
    return ao_slice_arc(horizons.x, n) + ao_slice_arc(horizons.y, n);
}

ao_value ao_pass(ivec2 target_pixel)
{
    ivec2 p;
    vec3 P, V, n;
    if (!ao_pass_surface(target_pixel, p, P, V, n)) return ao_open_value(); // background, or no surface to integrate over

    // The search radius on screen, capped at half its height, and the world radius the cap
    // leaves, which bounds the horizon search as u.radius does (common/slices.glsl).
    float radius_pixels, radius;
    ao_slice_radius(P, radius_pixels, radius);
    ao_gtao_falloff falloff = ao_gtao_falloff_of(radius * (1.0 + u.thickness_bias * 10.0));

    vec2 rotation = ao_noise_rotation(target_pixel);
    vec2 centre = vec2(p) + 0.5;
    float visibility_sum = 0.0; // sum of |n_p| (a(h-, n) + a(h+, n))
    float unoccluded_sum = 0.0; // sum of |n_p| (cos n + n sin n)
    vec3 bent_sum = vec3(0.0);  // with bent normals: sum of |n_p| b_s, the slices' vectors (common/slices.glsl's THE BENT NORMAL)
    vec3 open_sum = vec3(0.0);  //   and of |n_p| u_s, the open slices' (its CONTROL VARIATE)
    for (int s = 0; s < AO_GTAO_SLICES; ++s) {
        vec2 dir;  // on screen (pixels, y down)
        vec3 side; // in the slice plane, perpendicular to V
        if (!ao_slice_frame(s, AO_GTAO_SLICES, rotation, V, dir, side)) continue;
        ao_half2 projected = ao_slice_projected_normal(n, V, side); // (|n_p|, n)
        if (!(projected.x > ao_half(0.0))) continue; // the normal is perpendicular to the slice

        // The horizons: the highest cosine on each side (in float: a max of floats; each
        // cosine comes from 32-bit view positions, the one place precision decides),
        // starting from the hemisphere's edges h+- = n +- pi/2: cos(n + pi/2) = -sin n ahead,
        // cos(n - pi/2) = sin n behind (h- = -acos(cos-)).
        float sin_n = sin(float(projected.y));
        float cos_ahead = -sin_n;
        float cos_behind = sin_n;
        for (int j = 1; j <= AO_GTAO_STEPS; ++j) {
            float distance = ao_slice_step_pixels(j, AO_GTAO_STEPS, radius_pixels, u.frame_step);
            vec2 offset = dir * distance;
            cos_ahead = max(cos_ahead, ao_gtao_horizon_cos(centre + offset, distance, p, P, V, falloff, -sin_n));
            cos_behind = max(cos_behind, ao_gtao_horizon_cos(centre - offset, distance, p, P, V, falloff, sin_n));
        }
        ao_half integral = ao_gtao_slice_integral(projected.y, ao_half(cos_behind), ao_half(cos_ahead));
        visibility_sum += float(projected.x * integral);
        unoccluded_sum += float(projected.x * ao_slice_unoccluded(projected.y));
#if defined(AO_BENT_NORMALS)
        // The same horizons again (the compiler computes them once), and the slice's vectors.
        vec2 horizons = vec2(ao_gtao_horizons(projected.y, ao_half(cos_behind), ao_half(cos_ahead)));
        vec2 bent = float(projected.x) * ao_slice_bent(float(projected.y), horizons); // common/slices.glsl
        vec2 open = float(projected.x) * ao_slice_open_bent(float(projected.y));
        bent_sum += bent.x * V + bent.y * side;
        open_sum += open.x * V + open.y * side;
#endif
    }
    float visibility = unoccluded_sum > 0.0 ? clamp(visibility_sum / unoccluded_sum, 0.0, 1.0) : 1.0;
    float ao = visibility > 0.0 ? pow(visibility, u.strength) : 0.0;
    return ao_make_value(ao, ao_slices_bent_normal(bent_sum, open_sum, AO_GTAO_SLICES, visibility, n));
}
