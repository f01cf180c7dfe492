// vbao.glsl -- visibility-bitmask AO (Therrien, Levesque and Gilet 2023, "Screen Space
// Indirect Lighting with Visibility Bitmask"), on gtao.glsl's slices, with sectors weighted
// so that the result is aogen's cosine-weighted AO. Uniform block: VbaoUniforms (u.proj,
// u.inv_proj, u.world_to_view, u.radius, u.thickness in world units, u.strength,
// u.frame_step).
//
// Per pixel, with P its view-space position, V the direction to the camera and n the
// normal (normals.glsl; it faces V), for each of AO_VBAO_SLICES slices -- screen
// directions at angles s * pi / SLICES, all rotated by the pixel's noise rotation, as GTAO's:
//   1. project n onto the slice plane (spanned by V and the slice direction `side`):
//      length |n_p| and signed angle n from V, positive toward `side`
//      (common/slices.glsl's ao_slice_projected_normal). The directions of the slice that
//      lie in the hemisphere around the normal are the angles theta in [n - pi/2, n + pi/2],
//      theta measured from V, positive toward `side`;
//   2. march AO_VBAO_STEPS steps to each side at gtao.glsl's screen positions (step j at
//      j / STEPS of the radius projected at P's depth, capped at half the screen's height;
//      later frames move the inner steps: common/slices.glsl's ao_slice_step_pixels).
//      A sample's surface point S (its front) and S pushed u.thickness away from the camera
//      along its view ray (its back) are seen from P at two angles; the object is taken to
//      fill the wedge between them, so the sectors of that wedge are marked occluded in the
//      slice's 32-bit mask (ao_vbao_sectors). Samples off screen (or within half a texel of
//      its edge), on background, on the pixel itself, whose front lies farther than the
//      radius from P, or at or below P's tangent plane mark nothing;
//   3. the slice's visibility is the unmarked share of its sectors, 1 - popcount / 32,
//      times its unoccluded integral cos n + n sin n (gtao.glsl's), weighted by |n_p|; with
//      bent normals (-bn), its bent vector from the unmarked directions (ao_vbao_slice_bent).
// The visibility is sum |n_p| (1 - popcount / 32) (cos n + n sin n) / sum |n_p| (cos n + n sin n)
// over the slices, raised to u.strength.
//
// WHY A BITMASK
//   A horizon says "everything below me is occluded": GTAO treats every object as infinitely
//   deep, so under a plank, beside a thin pole or behind a railing the floor is shadowed as
//   if a wall stood there. A sample here occludes only the wedge its own thickness covers,
//   and several samples on one side add their wedges together (a bitwise or), which a
//   single horizon cannot: a gap between two occluders stays visible. One constant thickness
//   for every object is the method's model (the depth buffer holds front faces only); with
//   a thickness far larger than the radius every wedge reaches down to the hemisphere's
//   edge and the mask is GTAO's horizon, quantised to 32 sectors.
//
// COSINE-WEIGHTED SECTORS
//   aogen's AO is the cosine-weighted visibility (docs/design.md#ground-truth); in slice
//   coordinates (gtao.glsl's derivation) AO = 1/pi * integral over phi of |n_p| * integral of V(theta)
//   cos(theta - n) |sin theta| dtheta. So the measure of an angle interval within a slice is
//   m(theta) dtheta = cos(theta - n) |sin theta| dtheta, not dtheta: directions near V cover
//   little solid angle, directions near the view plane much. Sectors of equal angle would
//   count an occluder near V as much as one near the view plane (the error gtao.glsl's
//   "Why not the seed's formula" describes). Instead the 32 sectors are of equal *measure*:
//   an angle theta is mapped to the normalised cumulative measure
//       c(theta) = integral_{n - pi/2}^{theta} m / integral_{n - pi/2}^{n + pi/2} m   in [0, 1]
//   and sector k covers c in [k / 32, (k + 1) / 32). Then popcount / 32 is the occluded
//   share of the slice's measure (to the quantisation below), and the slice's visible
//   measure is (1 - popcount / 32) times the whole, cos n + n sin n -- exactly gtao.glsl's
//   a(h-, n) + a(h+, n) when the mask is a heightfield's (a large thickness), so the two
//   converge to the same integral.
//   The cumulative: F(t) = (-cos(2t - n) + cos n + 2t sin n) / 4 (gtao.glsl's a(t, n)) has
//   F' = cos(t - n) sin t and F(0) = 0, so integral_0^t m = F(t) for t >= 0 and
//   integral_t^0 m = F(t) for t <= 0 (|sin t| = -sin t there; F(t) >= 0 either way). With
//   lo = n - pi/2 <= 0 <= hi = n + pi/2:
//       integral_lo^theta m = F(lo) + sign(theta) F(theta),
//       integral_lo^hi m    = F(lo) + F(hi) = cos n + n sin n            (in [1, pi/2])
//   (ao_vbao_cumulative).
//
// QUANTISATION
//   A wedge [theta_a, theta_b] marks sectors round(32 c(theta_a)) up to round(32 c(theta_b))
//   - 1: a boundary lands on the nearest sector boundary, so each moves the slice's visible
//   share by at most 1/64, and without bias (floor/ceil would make every wedge grow or shrink
//   by half a sector on average). A heightfield slice has one boundary per side whose far
//   end is the hemisphere's edge (c = 1 or 0, exact), so its visibility is within 1/32 of the
//   exact slice integral, and over many slices with jittered boundaries much closer. A
//   wedge narrower than half a sector can mark nothing: thin objects at grazing angles
//   flicker by a sector, which the blur averages.
//
// NUMERICS
//   Cosines come from 32-bit view positions (float, as gtao.glsl's horizons); a NaN or a
//   cosine outside [-1, 1] marks nothing. Angles are clamped to the hemisphere [lo, hi]
//   before the cumulative, and the cumulative's result to [0, 1], so sector indices are in
//   0..32 and every shift is by less than 32 (a shift by 32 is undefined in GLSL:
//   ao_vbao_sectors_below adds the top bit instead). With AO_FP16 the angles, the cumulative and the slice
//   weights are ao_half: a half's 4.9e-4 relative error moves a sector boundary by at most
//   0.02 of a sector. The sums are float and finite; the result is in [0, 1]; ao_finalize
//   (core.glsl) catches anything else.

#if !defined(AO_PASS_AO) || !defined(AO_TECHNIQUE_VBAO)
#error aogen: vbao.glsl is the AO pass of the vbao technique
#endif
#if !defined(AO_VBAO_SLICES) || !defined(AO_VBAO_STEPS)
#error aogen: vbao.glsl needs AO_VBAO_SLICES and AO_VBAO_STEPS
#endif

const uint AO_VBAO_SECTORS = 32u;

// c(theta): the share of the slice's cosine-weighted measure between n - pi/2 and theta,
// in [0, 1]; theta is clamped to the hemisphere first.
ao_half ao_vbao_cumulative(ao_half theta, ao_half n)
{
    const ao_half half_pi = ao_half(AO_HALF_PI);
    ao_half t = clamp(theta, n - half_pi, n + half_pi);
    ao_half below_zero = ao_slice_arc(n - half_pi, n); // integral_lo^0 (common/slices.glsl)
    ao_half up_to_t = below_zero + sign(t) * ao_slice_arc(t, n);
    return clamp(up_to_t / ao_slice_unoccluded(n), ao_half(0.0), ao_half(1.0));
}

// The mask of sectors 0 .. k - 1, for k in 0..32. A shift by 32 is undefined, so k = 32 is
// (1 << 31) - 1 with the top bit added; written without a branch.
uint ao_vbao_sectors_below(uint k)
{
    return ((1u << min(k, 31u)) - 1u) | (uint(k >= AO_VBAO_SECTORS) << 31u);
}

// The sectors the wedge between angles theta_a and theta_b (either order) covers: from
// round(32 c(lower)) to round(32 c(upper)) - 1.
uint ao_vbao_sectors(ao_half theta_a, ao_half theta_b, ao_half n)
{
    const ao_half count = ao_half(AO_VBAO_SECTORS);
    uint first = uint(floor(ao_vbao_cumulative(min(theta_a, theta_b), n) * count + ao_half(0.5)));
    uint end = uint(floor(ao_vbao_cumulative(max(theta_a, theta_b), n) * count + ao_half(0.5)));
    return ao_vbao_sectors_below(end) & ~ao_vbao_sectors_below(first);
}

// The number of set bits of `mask`. Fragment passes also go to ESSL 3.00 (OpenGL ES 3.0,
// WebGL 2), which has no bitCount, so there the bits are summed in parallel: in pairs, then
// nibbles, then bytes, and a multiply adds the four byte counts into the top byte. Compute
// passes go to ESSL 3.10 at the lowest, which has bitCount.
uint ao_vbao_bit_count(uint mask)
{
#if defined(AO_STAGE_FRAGMENT)
    uint pairs = mask - ((mask >> 1u) & 0x55555555u);
    uint nibbles = (pairs & 0x33333333u) + ((pairs >> 2u) & 0x33333333u);
    uint bytes = (nibbles + (nibbles >> 4u)) & 0x0f0f0f0fu;
    return (bytes * 0x01010101u) >> 24u;
#else
    return uint(bitCount(mask));
#endif
}

// The unmarked share of a slice's sectors, 1 - popcount / 32.
ao_half ao_vbao_slice_visible(uint occluded)
{
    return ao_half(1.0) - ao_half(ao_vbao_bit_count(occluded)) / ao_half(AO_VBAO_SECTORS);
}

#if defined(AO_BENT_NORMALS)
// A slice's bent vector (common/slices.glsl's THE BENT NORMAL) from its mask is the open
// slice's (ao_slice_open_bent, exact) less the occluded directions', which this returns. The
// mask holds sectors of equal measure whose angles the cumulative c(theta) does not give back
// in closed form, so the occluded part is integrated over theta instead, by the midpoint rule
// at AO_VBAO_BENT_PROBES angles spread evenly over the hemisphere [n - pi/2, n + pi/2]: a
// probe at theta counts when the sector c(theta) falls in is marked, with its measure
// cos(theta - n) |sin theta| dtheta along (cos theta, sin theta). An open slice is exact; an
// occluded wedge's edges are placed to within half a probe's spacing (pi / 32), finer than
// the 8-bit output's normal needs after the slices' and the filters' averaging.
const int AO_VBAO_BENT_PROBES = 16;

// (along V, along side), without |n_p|.
vec2 ao_vbao_slice_occluded_bent(uint occluded, ao_half n)
{
    vec2 occluded_bent = vec2(0.0);
    if (occluded == 0u) return occluded_bent;
    float n_angle = float(n);
    const float spacing = AO_PI / float(AO_VBAO_BENT_PROBES);
    for (int j = 0; j < AO_VBAO_BENT_PROBES; ++j) {
        float theta = n_angle - AO_HALF_PI + (float(j) + 0.5) * spacing;
        uint sector = min(uint(float(ao_vbao_cumulative(ao_half(theta), n)) * float(AO_VBAO_SECTORS)), AO_VBAO_SECTORS - 1u);
        if ((occluded & (1u << sector)) == 0u) continue;
        occluded_bent += cos(theta - n_angle) * abs(sin(theta)) * spacing * vec2(cos(theta), sin(theta));
    }
    return occluded_bent;
}
#endif

// The signed angle from V of the direction from P to view-space point X, on the side
// `toward` (+1 ahead, -1 behind), or false when it cannot be known (X at P, not finite).
bool ao_vbao_angle(vec3 X, vec3 P, vec3 V, float toward, out ao_half theta)
{
    vec3 w = X - P;
    float distance = length(w);
    theta = ao_half(0.0);
    if (!(distance > 1e-30 && ao_is_finite(distance))) return false;
    float c = dot(w, V) / distance;
    if (!(c >= -1.0 && c <= 1.0)) c = clamp(c, -1.0, 1.0); // rounding past +-1; NaN was excluded above
    theta = ao_half(toward) * ao_half(ao_acos(c));
    return true;
}

// The sectors one sample at screen position `pos` (full-resolution pixels, `pixels` from the
// pixel along the slice) marks, on the side `toward` of the slice whose projected normal has angle n: its front S and back S -
// V_S thickness (V_S: toward the camera from S), or 0 when it marks nothing.
uint ao_vbao_sample(vec2 pos, float pixels, ivec2 centre_pixel, vec3 P, vec3 V, vec3 normal, float toward, ao_half n, float radius)
{
    ivec2 size = ao_depth_size();
    // On screen, and between the outermost texel centres: in the half texel beyond them
    // ao_depth_at's clamped 2x2 quad repeats a row or column, reads as one plane, and gives
    // the border texels' depth at a point half a texel away -- off the surface, above it as
    // often as below, and above it a sector's worth on a steep plane (GTAO's horizon moves
    // by little there; a sector is 1/32 of a slice).
    // (The surface is read first, before any test: common/slices.glsl's ao_slice_tap_surface.)
    float depth;
    vec2 at;
    ivec2 q;
    bool surface = ao_slice_tap_surface(pos, pixels, depth, at, q);
    if (!all(bvec4(greaterThanEqual(pos, vec2(0.5)), lessThanEqual(pos, vec2(size) - 0.5)))) return 0u;
    if (!surface || q == centre_pixel) return 0u; // common/slices.glsl, as gtao.glsl
    vec3 front = ao_view_position_at(at, depth);
    vec3 w = front - P;
    float distance = length(w);
    if (!(distance <= radius)) return 0u; // beyond the AO radius; NaN and inf fail too
    // A front at or below P's tangent plane marks nothing: its back lies farther below (the
    // camera is above that plane, and the back is farther from the camera), so the whole
    // wedge is outside the hemisphere. Its angle says so only for points on the slice's own
    // plane; a silhouette texel's centre (ao_depth_at) lies up to half a texel off it, and
    // its angle from V can then read up to a sector above the hemisphere's edge -- an open
    // plane would lose a sector near every silhouette. 1e-3: an elevation of 0.06 degrees,
    // above the rounding of points on the plane, below anything that occludes a sector.
    if (!(dot(w, normal) > 1e-3 * distance)) return 0u;
    vec3 back = front - ao_view_direction(front) * u.thickness;
    ao_half theta_front, theta_back;
    if (!ao_vbao_angle(front, P, V, toward, theta_front)) return 0u;
    if (!ao_vbao_angle(back, P, V, toward, theta_back)) theta_back = ao_half(toward * AO_PI); // back at P: down to the edge
    return ao_vbao_sectors(theta_front, theta_back, n);
}

ao_value ao_pass(ivec2 target_pixel)
{
    ivec2 p;
    vec3 P, V, n;
    if (!ao_pass_surface(target_pixel, p, P, V, n)) return ao_open_value(); // background, or no surface to integrate over

    // The search radius on screen and the world radius its cap leaves (common/slices.glsl,
    // as gtao.glsl): the latter bounds the samples' distance.
    float radius_pixels, radius;
    ao_slice_radius(P, radius_pixels, radius);

    vec2 rotation = ao_noise_rotation(target_pixel);
    vec2 centre = vec2(p) + 0.5;
    float visibility_sum = 0.0; // sum of |n_p| (1 - popcount / 32) (cos n + n sin n)
    float unoccluded_sum = 0.0; // sum of |n_p| (cos n + n sin n)
    vec3 bent_sum = vec3(0.0);  // with bent normals: sum of |n_p| b_s, the slices' vectors (ao_vbao_slice_bent)
    vec3 open_sum = vec3(0.0);  //   and of |n_p| u_s, the open slices' (common/slices.glsl's CONTROL VARIATE)
    for (int s = 0; s < AO_VBAO_SLICES; ++s) {
        vec2 dir;  // on screen (pixels, y down)
        vec3 side; // in the slice plane, perpendicular to V
        if (!ao_slice_frame(s, AO_VBAO_SLICES, rotation, V, dir, side)) continue;
        ao_half2 projected = ao_slice_projected_normal(n, V, side); // (|n_p|, n)
        if (!(projected.x > ao_half(0.0))) continue;

        uint occluded = 0u;
        for (int j = 1; j <= AO_VBAO_STEPS; ++j) {
            float distance = ao_slice_step_pixels(j, AO_VBAO_STEPS, radius_pixels, u.frame_step);
            vec2 offset = dir * distance;
            occluded |= ao_vbao_sample(centre + offset, distance, p, P, V, n, 1.0, projected.y, radius);
            occluded |= ao_vbao_sample(centre - offset, distance, p, P, V, n, -1.0, projected.y, radius);
        }
        float whole = float(projected.x * ao_slice_unoccluded(projected.y));
        visibility_sum += whole * float(ao_vbao_slice_visible(occluded));
        unoccluded_sum += whole;
#if defined(AO_BENT_NORMALS)
        vec2 open = float(projected.x) * ao_slice_open_bent(float(projected.y));
        vec2 bent = open - float(projected.x) * ao_vbao_slice_occluded_bent(occluded, projected.y);
        bent_sum += bent.x * V + bent.y * side;
        open_sum += open.x * V + open.y * side;
#endif
    }
    float visibility = unoccluded_sum > 0.0 ? clamp(visibility_sum / unoccluded_sum, 0.0, 1.0) : 1.0;
    float ao = visibility > 0.0 ? pow(visibility, u.strength) : 0.0;
    return ao_make_value(ao, ao_slices_bent_normal(bent_sum, open_sum, AO_VBAO_SLICES, visibility, n));
}
