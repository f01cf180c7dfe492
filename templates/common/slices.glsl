// common/slices.glsl -- what the slice-based AO passes (gtao.glsl, vbao.glsl) share: the
// search radius on screen, each slice's direction and plane, the
// normal projected onto that plane, the slice's cosine-weighted measure, and (-bn) its bent
// vector. gtao.glsl's header derives the measure.
//
// Each slice marches its steps at ao_slice_step_pixels (this frame's step positions).
//
// A slice is the plane through P spanned by V (toward the camera) and `side`, the screen
// direction `dir` made perpendicular to V. Angles within it are signed angles from V,
// positive toward `side`; the hemisphere around the normal is [n - pi/2, n + pi/2], n the
// projected normal's angle. Over it the visible measure of directions is
//     integral cos(t - n) |sin t| dt,
// whose antiderivative from 0 is ao_slice_arc (both signs of t alike) and whose total is
// ao_slice_unoccluded(n) = cos n + n sin n. The surface at the pixel is normals.glsl's
// ao_pass_surface.

// The search radius at P: `radius_pixels`, the world radius u.radius projected at P's depth
// in full-resolution pixels (clip y = proj[1][1] * y (/ -z)), capped at half the screen's
// height -- a radius past the screen spread its steps a third of the screen apart and
// stepped over every contact; the capped one finds what the screen shows -- and the world
// radius the cap leaves, which bounds how far a sample may lie from P.
void ao_slice_radius(vec3 P, out float radius_pixels, out float radius)
{
    vec2 fsize = vec2(ao_depth_size());
    float pixels_per_unit = 0.5 * fsize.y * abs(u.proj[1][1]);
#if !defined(AO_PROJECTION_ORTHOGRAPHIC)
    pixels_per_unit /= max(-P.z, 1e-30);
#endif
    radius_pixels = min(u.radius * pixels_per_unit, 0.5 * fsize.y);
    if (!ao_is_finite(radius_pixels)) radius_pixels = 0.0;
    radius = pixels_per_unit > 0.0 ? min(u.radius, radius_pixels / pixels_per_unit) : u.radius;
}

// How far step j (1..steps) of a slice's march lies from the pixel, in full-resolution
// pixels, for a radius of `radius_pixels`: j / steps of it at frame 0, and from there each
// inner step j < steps moved inward by `frame_step` (u.frame_step, temporal::step_offset:
// in [0, 1) of a step, 0 at frame 0) to (j - frame_step) / steps, so that frames put it
// anywhere in its stratum ((j - 1) / steps, j / steps]. The outermost step stays at the
// radius: horizons are maxima, and the farthest step is the one that sees a wall's top
// (aogen/temporal.hpp). At frame 0, j - 0 is j exactly: the still frame's steps to the bit.
float ao_slice_step_pixels(int j, int steps, float radius_pixels, float frame_step)
{
    float shift = j < steps ? frame_step : 0.0;
    return radius_pixels * ((float(j) - shift) / float(steps));
}

// The surface a slice tap at screen position `pos`, `distance` full-resolution pixels from
// the pixel along its slice, lands on: depth, at and nearest as depth.glsl's ao_depth_at
// gives them; false on background.
//   Near taps read ao_depth_at: over a plane, the plane's depth under pos itself, exactly --
// a texel's depth taken up to half a texel from its centre lies above a grazing floor or a
// wide lens's edges and reads as an occluder (issue 11).
//   From AO_SLICE_TEXEL_CENTRE_PIXELS on (aogen::slice_taps), the texel under pos at its
// centre (ao_depth_texel's point): a true surface point, whose direction from P leaves the slice's
// plane by at most 0.71 / distance radians. On an open plane that can lift a horizon a
// little above the hemisphere's edge, where the slice integral is flat: the change is of
// second order, below 1/255. No plane test and no bilinear mix. Taps that read the depth MIP
// chain (level >= 1) keep its reading.
//   Compute passes take both readings from one read, made first, before any decision: the
// four texels around pos (ao_depth_around, one gather), among which is pos's own texel -- the
// one whose centre is within half a texel, floor(pos), ao_depth_texel's. A read behind a
// branch waits for the branch; one ahead of every test of the tap lets the GPU have a step's
// taps in flight together (callers read first too: an off-screen pos reads clamped border
// texels, which are never used). Fragment passes have no gather (ESSL 3.00: four fetches for
// the four texels) and keep one fetch for a far tap.
bool ao_slice_tap_surface(vec2 pos, float distance, out float depth, out vec2 at, out ivec2 nearest)
{
#if defined(AO_STAGE_COMPUTE)
    vec2 f;
    vec4 g = ao_depth_around(pos, ao_tap_level(distance), f, depth, at, nearest);
    if (ao_slice_tap_reads_texel(distance)) return !ao_is_background(depth);
    return ao_depth_at_quad(g, f, pos, depth, at);
#else
    if (ao_slice_tap_reads_texel(distance)) return ao_depth_texel(pos, depth, at, nearest);
    return ao_depth_at(pos, ao_tap_level(distance), depth, at, nearest);
#endif
}

// Slice s of `count`: the screen direction `dir` (pixels, y down) at angle s * pi / count,
// rotated by the pixel's noise `rotation`, and `side`, its view-space direction (y up) made
// perpendicular to V. False when the two are (nearly) parallel: no plane to integrate.
bool ao_slice_frame(int s, int count, vec2 rotation, vec3 V, out vec2 dir, out vec3 side)
{
    float angle = float(s) * (AO_PI / float(count));
    vec2 base = vec2(cos(angle), sin(angle));
    dir = vec2(base.x * rotation.x - base.y * rotation.y, base.x * rotation.y + base.y * rotation.x);
    vec3 dir_view = vec3(dir.x, -dir.y, 0.0);
    side = ao_safe_normalize(dir_view - V * dot(dir_view, V), vec3(0.0));
    return dot(side, side) >= 0.5;
}

// The normal projected onto the slice plane: (|n_p|, n), n the signed angle of n_p from V,
// positive toward `side`, in [-pi/2, pi/2]. V and `side` are unit and perpendicular, an
// orthonormal basis of the plane, so n_p = x V + y side with x = dot(n, V), y = dot(n, side);
// n faces V, so x >= 0. (0, 0) when the normal is (nearly) perpendicular to the plane. From
// here on a slice's arithmetic is ao_half (16-bit with the fp16 axis): angles and cosines in
// [-pi, pi], where a half's 4.9e-4 relative error is well below what the 8-bit output shows.
ao_half2 ao_slice_projected_normal(vec3 n, vec3 V, vec3 side)
{
    float x = dot(n, V);
    float y = dot(n, side);
    float n_length = sqrt(x * x + y * y);
    if (!(n_length > 1e-6)) return ao_half2(0.0);
    // atan(y, x) is undefined at x = 0 = y; x <= 0 (rounding) is a normal in the view plane.
    ao_half n_angle = x > 0.0 ? ao_atan2(ao_half(y), ao_half(x)) : ao_half(y < 0.0 ? -AO_HALF_PI : AO_HALF_PI);
    return ao_half2(n_length, clamp(n_angle, ao_half(-AO_HALF_PI), ao_half(AO_HALF_PI)));
}

// a(h, n) = integral from 0 to h of cos(t - n) |sin t| dt, for h of either sign (gtao.glsl's
// header): (-cos(2h - n) + cos n + 2 h sin n) / 4, >= 0 on the hemisphere.
ao_half ao_slice_arc(ao_half h, ao_half n)
{
    return ao_half(0.25) * (-cos(ao_half(2.0) * h - n) + cos(n) + ao_half(2.0) * h * sin(n));
}

// The measure of the whole hemisphere, a(n - pi/2, n) + a(n + pi/2, n) = cos n + n sin n, in
// [1, pi/2].
ao_half ao_slice_unoccluded(ao_half n_angle)
{
    ao_half n = clamp(n_angle, ao_half(-AO_HALF_PI), ao_half(AO_HALF_PI));
    return cos(n) + n * sin(n);
}

// THE BENT NORMAL (a -bn variant; without one, nothing calls what follows and it is not in the code)
//   The bent normal is the cosine-weighted mean of the unoccluded directions,
//       B = normalize( integral over the hemisphere of V(w) (n . w) w dw ),
//   the direction the truth traces (aogen_truth's estimate::bent_normal). In slice coordinates
//   w = cos theta V + sin theta side (gtao.glsl's header), so a slice adds
//       |n_p| * integral over its visible theta of cos(theta - n) |sin theta| (cos theta V + sin theta side) dtheta
//   -- the AO's slice integral with w inside. The slices' vectors are summed in view space
//   and normalised when the pass writes them.
//   Between two horizons h- <= 0 <= h+ (GTAO's visible arc), with cos(t - n) = cos t cos n +
//   sin t sin n, the two components have the antiderivatives (for sin t >= 0)
//       along V:     G(t) = (sin n sin^3 t - cos n cos^3 t) / 3
//       along side:  H(t) = (cos n sin^3 t + sin n (cos^3 t - 3 cos t)) / 3
//   and, |sin t| flipping sign at 0 as in the AO's integral, both sides sum to
//       along V:     G(h+) + G(h-) - 2 G(0) = G(h+) + G(h-) + 2 cos n / 3
//       along side:  H(h+) + H(h-) - 2 H(0) = H(h+) + H(h-) + 4 sin n / 3.
//   An open slice with n = 0 gives (2/3, 0): along V; a wall at h+ = 0 tilts it to
//   (1/3, -1/3), away from the wall. At the hemisphere's edges h+- = n +- pi/2 the G and H
//   terms cancel and an open slice gives (2 cos n, 4 sin n) / 3 (ao_slice_open_bent): it
//   leans further toward the view plane than n_p itself (|sin t| weighs directions near it
//   more), so a few slices of an open plane sum to a direction off the normal, by as much as
//   their turn decides -- only the integral over phi is the normal:
//       integral_0^pi |n_p| (2 cos n, 4 sin n) / 3 dphi = (2 pi / 3) n.
// CONTROL VARIATE
//   So the open part is not estimated, it is known: with S slices at stratified turns,
//   sum |n_p| b_s estimates (S / pi) times the integral, and sum |n_p| u_s (u_s the open
//   slice's vector) estimates (S / pi) (2 pi / 3) n = (2 S / 3) n, which is exact. The
//   estimate
//       sum |n_p| b_s + beta ((2 S / 3) n - sum |n_p| u_s)
//   has the same mean for any beta and, with beta near the optimal Cov(b, u) / Var(u), less
//   noise: an open pixel's b_s is u_s, so beta = 1 gives it the normal exactly, and a closed
//   one's b_s does not follow u_s at all (beta = 0). aogen takes beta = the pixel's
//   visibility (the share of the open measure its slices saw unoccluded, before `strength`):
//   between those two, as b_s follows u_s in proportion to what is open (ao_slices_bent_normal).
// The open slice's vector (along V, along side), without |n_p|: ao_slice_bent at n +- pi/2.
vec2 ao_slice_open_bent(float n)
{
    return vec2(2.0 * cos(n), 4.0 * sin(n)) / 3.0;
}

// The bent normal's direction from the slices' sums (CONTROL VARIATE): `bent_sum` = sum |n_p|
// b_s and `open_sum` = sum |n_p| u_s in view space, `slices` = S, `visibility` = beta, `n` the
// surface normal -- which is also the answer where nothing is left (a fully occluded pixel).
vec3 ao_slices_bent_normal(vec3 bent_sum, vec3 open_sum, int slices, float visibility, vec3 n)
{
    vec3 bent = bent_sum + visibility * ((2.0 * float(slices) / 3.0) * n - open_sum);
    return dot(bent, n) > 1e-6 * length(bent) ? bent : n;
}

// The slice's vector between horizons (h-, h+), without |n_p|: (along V, along side).
vec2 ao_slice_bent(float n, vec2 horizons)
{
    float sin_n = sin(n), cos_n = cos(n);
    vec2 s = sin(horizons), c = cos(horizons);
    vec2 s3 = s * s * s, c3 = c * c * c;
    vec2 along_v = (sin_n * s3 - cos_n * c3) / 3.0;
    vec2 along_side = (cos_n * s3 + sin_n * (c3 - 3.0 * c)) / 3.0;
    return vec2(along_v.x + along_v.y + 2.0 * cos_n / 3.0, along_side.x + along_side.y + 4.0 * sin_n / 3.0);
}
