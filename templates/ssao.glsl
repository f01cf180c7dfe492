// ssao.glsl -- hemisphere SSAO (Crytek style), as Taos' SSAOPass (seeds 000, 002),
// Unique Engine's UeSSAOPass (seed 003) and the point-cloud viewer's ssao.wgsl (seed 004)
// describe it. Uniform block: SsaoUniforms (u.proj, u.inv_proj, u.world_to_view,
// u.radius, u.bias, u.strength, u.power, u.intensity, u.kernel[AO_SSAO_SAMPLES]).
//
// Per pixel: reconstruct the view-space position P; take the normal n (normals.glsl);
// build a tangent frame around n, rotated by the pixel's noise vector (Gram-Schmidt);
// for each kernel sample (a point of the unit hemisphere around +z):
//   S = P + TBN * kernel[i].xyz * radius, projected to the screen with u.proj, where radius
//   is u.radius capped at half the screen's height in world units at P's depth
//   (ao_ssao_radius: a hemisphere larger than the screen only sends samples off it);
//   samples behind the camera or projecting off screen are not judged: the screen says
//   nothing about them, so the sum is divided by the N samples that land on it (the seeds
//   divide by all AO_SSAO_SAMPLES, which counts every unknown sample as open and lightens
//   pixels near the border and wide radii); samples landing on background are judged
//   open, and so are samples landing in the pixel's own texel
//   (ours, not the seeds'): comparing the surface with its own depth can only measure
//   depth quantization -- at grazing angles, or when the radius projects below a pixel,
//   it darkens open planes -- never an occluder;
//   the sample is occluded when the scene's view z where it projects (depth.glsl's
//   ao_depth_at: a plane's depth under the sample itself, or at a silhouette its texel's)
//   is > S.z + bias (the
//   visible surface is closer to the camera than the sample: the sample is inside
//   geometry). Comparing with the sample's z, not the pixel's, keeps the bias
//   slope-invariant on flat surfaces;
//   an occluded sample counts with the range-check weight of |dz| = |P.z - scene z|:
//     AO_RANGE_CHECK_TAOS     1 - smoothstep(0, radius, |dz|)   (0 from |dz| = radius on)
//     AO_RANGE_CHECK_SEED004  smoothstep(0, 1, radius / |dz|)   (1 while |dz| <= radius,
//                                                               so |dz| = 0 divides nothing)
// Output, with occ the weighted count and N the samples judged (no sample judged: occ / N = 0):
//   AO_OUTPUT_STRENGTH         clamp(1 - occ / N * strength, 0, 1)            (seeds 000, 004)
//   AO_OUTPUT_POWER_INTENSITY  clamp(mix(1, pow(max(1 - occ / N, 0), power), intensity), 0, 1)
//                                                                              (seed 003)
// With AO_POINT_CLOUD_FALLBACK (seed 004), ssao_point_cloud.glsl comes before this file
// and billboard-interior pixels take its depth-cavity test instead.

#if !defined(AO_PASS_AO) || !defined(AO_TECHNIQUE_SSAO)
#error aogen: ssao.glsl is the AO pass of the ssao technique
#endif
#if !defined(AO_SSAO_SAMPLES)
#error aogen: ssao.glsl needs AO_SSAO_SAMPLES
#endif
#if (defined(AO_RANGE_CHECK_TAOS) + defined(AO_RANGE_CHECK_SEED004)) != 1
#error aogen: define exactly one of AO_RANGE_CHECK_TAOS AO_RANGE_CHECK_SEED004
#endif
#if (defined(AO_OUTPUT_STRENGTH) + defined(AO_OUTPUT_POWER_INTENSITY)) != 1
#error aogen: define exactly one of AO_OUTPUT_STRENGTH AO_OUTPUT_POWER_INTENSITY
#endif

// The tangent frame (columns t, b, n) around unit normal n, its tangent the part of the
// noise vector (r, 0) perpendicular to n. When (r, 0) is (anti-)parallel to n -- a wall
// seen edge-on whose normal points along the noise vector -- a coordinate axis not
// parallel to n takes its place. Unit vectors: ao_half (16-bit with the fp16 axis) holds
// them to 4.9e-4, a thousandth of the radius once scaled.
ao_half3x3 ao_ssao_frame(vec3 normal, vec2 r)
{
    ao_half3 n = ao_half3(normal);
    ao_half3 noise = ao_half3(r, 0.0);
    ao_half3 t = noise - n * dot(noise, n);
    if (!(dot(t, t) > ao_half(1e-4))) {
        ao_half3 axis = abs(n.x) < ao_half(0.9) ? ao_half3(1.0, 0.0, 0.0) : ao_half3(0.0, 1.0, 0.0);
        t = axis - n * dot(axis, n); // |t|^2 >= 0.19
    }
    t = normalize(t);
    return ao_half3x3(t, cross(n, t), n);
}

// The radius a pixel at view-space P can use: u.radius, but at most the world size of half
// the screen's height at P's depth. A larger hemisphere sends most samples off screen or
// behind the camera, where they count as unoccluded: a radius past the screen read about
// twice as wrong as a normal one, all of it too light. Within the screen, the samples find
// what the screen can show.
float ao_ssao_radius(vec3 P)
{
#if defined(AO_PROJECTION_ORTHOGRAPHIC)
    float half_height = 1.0 / abs(u.proj[1][1]);
#else
    float half_height = max(-P.z, 0.0) / abs(u.proj[1][1]);
#endif
    float r = min(u.radius, half_height);
    return r > 0.0 ? r : u.radius; // a degenerate projection keeps the radius as given
}

// The weight of an occluded sample whose scene point is |dz| away in view depth, for a
// hemisphere of `radius`: the ratio in float, the smoothstep of it (in [0, 1]) in ao_half.
ao_half ao_ssao_range_weight(float abs_dz, float radius)
{
#if defined(AO_RANGE_CHECK_TAOS)
    // 1 - smoothstep(0, radius, |dz|), written so that radius 0 is a step, not 0 / 0.
    if (!(abs_dz < radius)) return ao_half(0.0);
    return ao_half(1.0) - smoothstep(ao_half(0.0), ao_half(1.0), ao_half(abs_dz / radius)); // radius > abs_dz >= 0
#else
    // smoothstep(0, 1, radius / |dz|): 1 for |dz| <= radius, |dz| = 0 included.
    if (abs_dz <= radius) return ao_half(1.0);
    return smoothstep(ao_half(0.0), ao_half(1.0), ao_half(radius / max(abs_dz, 1e-30)));
#endif
}

float ao_pass(ivec2 target_pixel)
{
    ivec2 p = ao_full_pixel(target_pixel);
    float depth = ao_load_depth(p);
    if (ao_is_background(depth)) return 1.0;
#if defined(AO_POINT_CLOUD_FALLBACK)
    float cavity_ao;
    if (ao_point_cloud_billboard(p, depth, cavity_ao)) return cavity_ao;
#endif
    vec3 P = ao_view_position(ao_pixel_uv(p), depth);
    if (!ao_is_finite(P)) return 1.0;
    vec3 V = ao_view_direction(P);
    vec3 n;
    if (!ao_surface_normal(p, P, V, n)) return 1.0;
    ao_half3x3 tbn = ao_ssao_frame(n, ao_noise_rotation(target_pixel));
    float radius = ao_ssao_radius(P);
    float bias = u.bias * (radius / u.radius); // a capped hemisphere keeps the bias's share of it

    ivec2 size = ao_depth_size();
    vec2 fsize = vec2(size);
    float occlusion = 0.0;
    float judged = 0.0; // samples that land on screen, in front of the camera
    for (int i = 0; i < AO_SSAO_SAMPLES; ++i) {
#if defined(AO_FP16)
        vec3 S = P + vec3(tbn * ao_half3(u.kernel[i].xyz)) * radius; // the unit-scale rotation in 16 bits, the scale in 32
#else
        vec3 S = P + tbn * (u.kernel[i].xyz * radius);
#endif
        vec4 clip = u.proj * vec4(S, 1.0);
        if (!(clip.w > 1e-30)) continue; // behind the camera (perspective)
        vec2 ndc = clip.xy / clip.w;
        vec2 uv = vec2(ndc.x * 0.5 + 0.5, 0.5 - ndc.y * 0.5);
        // Off screen (a NaN fails every comparison and is skipped too).
        if (!(uv.x >= 0.0 && uv.y >= 0.0 && uv.x < 1.0 && uv.y < 1.0)) continue;
        judged += 1.0;
        // The scene's depth where S projects (depth.glsl's ao_depth_at: on a plane, under S
        // itself; at a silhouette, the nearest texel's).
        float scene_depth;
        vec2 at;
        ivec2 q;
        vec2 pos = uv * fsize;
        int level = ao_tap_level(length(pos - (vec2(p) + 0.5))); // its depth MIP level (0 without a chain)
        if (!ao_depth_at(pos, level, scene_depth, at, q)) continue; // background: judged open
        if (q == p) continue; // its own texel: a self-comparison that can only measure depth quantization
        float scene_z = ao_view_z(at / fsize, scene_depth);
        if (scene_z > S.z + bias && ao_is_finite(scene_z))
            occlusion += float(ao_ssao_range_weight(abs(P.z - scene_z), radius));
    }
    float occluded = judged > 0.0 ? occlusion / judged : 0.0;
#if defined(AO_OUTPUT_STRENGTH)
    return clamp(1.0 - occluded * u.strength, 0.0, 1.0);
#else
    float visibility = 1.0 - occluded;
    float ao = visibility > 0.0 ? pow(visibility, u.power) : 0.0;
    return clamp(ao_lerp(1.0, ao, u.intensity), 0.0, 1.0);
#endif
}
