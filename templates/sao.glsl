// sao.glsl -- scalable ambient obscurance (McGuire, Mara, Luebke, HPG 2012): the Alchemy
// estimator (McGuire, Osman, Bukowski, Hennessy, HPG 2011) summed over taps on a spiral in
// screen space, far taps reading a coarser level of the depth MIP chain when the variant has
// one. Uniform block: SaoUniforms (u.proj, u.inv_proj, u.world_to_view, u.radius, u.bias,
// u.intensity, u.contrast, u.spiral[AO_SAO_SAMPLES]).
//
// THE ESTIMATOR
//   Ambient obscurance at P (view space, normal n) is 1 - (1/pi) * integral over the
//   hemisphere of the occluded directions, cosine-weighted. Alchemy estimates it from N
//   surface points Q_i the depth buffer shows near P: the point Q seen from P under the solid
//   angle a patch of the depth buffer covers there, weighted by the cosine n . v / |v| and
//   by a falloff u(|v|) that the paper chooses proportional to |v| so that the square roots
//   cancel, leaves
//       A = max(0, 1 - (2 sigma / N) * sum_i max(0, v_i . n - beta) / (v_i . v_i + epsilon))^k
//   with v_i = Q_i - P. Points below P's tangent plane (v . n <= beta) do not occlude; a point
//   near P occludes more than a far one of the same elevation (1 / |v|, the solid angle of a
//   patch falling with distance). SAO adds a smooth cut-off at the radius, here its cubic
//   f(v) = max(0, 1 - v . v / r^2)^3, so the sum ends where the radius ends without a ring.
//
//   aogen writes every length as a share of the radius r (v = (Q - P) / r, beta = u.bias,
//   epsilon = AO_SAO_EPSILON): the sum is then dimensionless, and one intensity serves every
//   scene scale (the paper's has units of a length, and its bias is in world units).
//
// THE TAPS (aogen/spiral.hpp)
//   Tap i lies at alpha_i = (i + 1/2) / N of the radius projected to the screen at P's depth,
//   at the angle i * golden angle, the spiral turned by the pixel's noise rotation. The disc is
//   the view-plane disc of radius r through P: on screen an ellipse when pixels are not square
//   (its x and y scales are proj[0][0] and proj[1][1]'s), capped at half the screen's height
//   as SSAO's and GTAO's radii are (a larger disc sends its taps off screen, where they say
//   nothing). Each tap reads the surface under it: the plane of the four texels around it,
//   or the texel itself at a silhouette (depth.glsl's ao_depth_readings, mixed by how far the
//   four lie on one plane); with a depth MIP chain, at the level its distance calls for.
//
// NOTHING STEPS (as SSAO's smooth decisions, ssao.glsl's DECISIONS)
//   The bias is a ramp (max(0, v . n - beta) starts at 0), the falloff reaches 0 at the
//   radius continuously; a tap fades out over AO_SAO_EDGE_BAND_PIXELS before the screen's
//   border and the sum is divided by the taps the screen judges (at least 1), not by N: a tap
//   off screen is not taken for an open one; a tap beside background counts as far as a
//   surface is sure to be under it; a tap in the pixel's own texel counts from 0 at the
//   texel's edge to fully AO_SAO_SELF_BAND_PIXELS past it (as SSAO's: there the four texels
//   around it, clamped at the screen's edge, make a plane of the pixel's own depth that the
//   surface's tilt reads as an occluder -- a 1 x 1 image read half dark); a tap on a
//   non-finite texel (no depth at all, unlike background) is not judged. So a depth that rounds differently (another depth
//   convention, another GPU) moves the output by about what it moved the depth.
//   Only background (no depth to be near to) and non-finite values are steps.

#if !defined(AO_PASS_AO) || !defined(AO_TECHNIQUE_SAO)
#error aogen: sao.glsl is the AO pass of the sao technique
#endif
#if !defined(AO_SAO_SAMPLES) || !defined(AO_SAO_EDGE_BAND_PIXELS) || !defined(AO_SAO_SELF_BAND_PIXELS) || !defined(AO_SAO_EPSILON) || !defined(AO_DEPTH_PLANE_BAND)
#error aogen: sao.glsl needs AO_SAO_SAMPLES and the constants AO_SAO_EDGE_BAND_PIXELS, AO_SAO_SELF_BAND_PIXELS, AO_SAO_EPSILON, AO_DEPTH_PLANE_BAND (codegen writes them)
#endif

// Full-resolution pixels per view-space unit along x and y at P's depth (proj[0][0] and
// proj[1][1] scale clip x and y; a perspective divides by -z), and the radius that fits the
// screen: u.radius, at most half the screen's height in world units at P's depth.
void ao_sao_radius(vec3 P, out vec2 pixels_per_unit, out float radius)
{
    vec2 fsize = vec2(ao_depth_size());
    pixels_per_unit = 0.5 * fsize * abs(vec2(u.proj[0][0], u.proj[1][1]));
#if !defined(AO_PROJECTION_ORTHOGRAPHIC)
    pixels_per_unit /= max(-P.z, 1e-30);
#endif
    radius = pixels_per_unit.y > 0.0 ? min(u.radius, 0.5 * fsize.y / pixels_per_unit.y) : u.radius;
    if (!ao_is_finite(radius)) radius = 0.0;
}

// What the surface point Q adds to the sum at P (normal n; lengths over `radius`): the
// Alchemy term f(v) * max(0, v . n - bias) / (v . v + epsilon), v = (Q - P) / radius.
// 0 for a non-finite Q.
float ao_sao_term(vec3 P, vec3 n, vec3 Q, float radius)
{
    vec3 v = (Q - P) / radius;
    float vv = dot(v, v);
    float elevation = dot(v, n) - u.bias;
    float f = max(1.0 - vv, 0.0);
    float term = f * f * f * max(elevation, 0.0) / (vv + AO_SAO_EPSILON);
    return ao_is_finite(term) ? term : 0.0;
}

// The share of the screen a tap at `pos` (full-resolution pixels) is judged by: 1 inside, 0
// past the border and for a NaN, over the last AO_SAO_EDGE_BAND_PIXELS between.
float ao_sao_screen_weight(vec2 pos, vec2 fsize)
{
    return ao_screen_edge_weight(pos, fsize, AO_SAO_EDGE_BAND_PIXELS);
}

float ao_pass(ivec2 target_pixel)
{
    ivec2 p;
    vec3 P, V, n;
    if (!ao_pass_surface(target_pixel, p, P, V, n)) return 1.0; // background, or no surface
    vec2 pixels_per_unit;
    float radius;
    ao_sao_radius(P, pixels_per_unit, radius);
    if (!(radius > 0.0)) return 1.0; // no disc: nothing near enough to occlude

    vec2 fsize = vec2(ao_depth_size());
    vec2 centre = vec2(p) + 0.5;
    vec2 ellipse = radius * pixels_per_unit; // the disc's semi-axes on screen, in pixels
    vec2 r = ao_noise_rotation(target_pixel);
    float sum = 0.0;
    float judged = 0.0;
    for (int i = 0; i < AO_SAO_SAMPLES; ++i) {
        vec4 t = u.spiral[i]; // (cos, sin) of the tap's angle, its share of the radius
        vec2 dir = vec2(t.x * r.x - t.y * r.y, t.x * r.y + t.y * r.x);
        vec2 offset = dir * (t.z * ellipse);
        vec2 pos = centre + offset;
        float on_screen = ao_sao_screen_weight(pos, fsize);
        if (!(on_screen > 0.0)) continue; // off screen, or a NaN
        judged += on_screen;
        float counts = ao_own_texel_weight(pos, p, AO_SAO_SELF_BAND_PIXELS);
        if (!(counts > 0.0)) continue; // its own texel: judged open
        float texel_depth, plane_depth, plane_weight, surface;
        vec2 texel_at;
        if (!ao_depth_readings(pos, ao_tap_level(length(offset)), texel_depth, texel_at, plane_depth, plane_weight, surface)) {
            if (!ao_is_finite(texel_depth)) judged -= on_screen; // a NaN texel says nothing
            continue;                                            // background: judged open
        }
        float term = 0.0;
        if (plane_weight < 1.0) term = ao_sao_term(P, n, ao_view_position_at(texel_at, texel_depth), radius);
        if (plane_weight > 0.0) term = ao_lerp(term, ao_sao_term(P, n, ao_view_position_at(pos, plane_depth), radius), plane_weight);
        sum += on_screen * counts * surface * term;
    }
    float visibility = clamp(1.0 - 2.0 * u.intensity * sum / max(judged, 1.0), 0.0, 1.0);
    return visibility > 0.0 ? pow(visibility, u.contrast) : 0.0;
}
