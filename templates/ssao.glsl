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
//
// DECISIONS (variant axis `decisions`, aogen/axes.hpp). Above, each judgement is a step:
// occluded or not, judged or not, the plane's depth or the texel's, billboard or not. That
// is AO_SSAO_DECISIONS_STEP, the seeds' form. Each step turns a change in the last bit of a
// depth into a whole vote, 1 / N of the output times the strength -- 0.2 at 16 samples and a
// strength of 3.3 -- so one scene in two depth conventions, whose depths round differently,
// differed by that much. AO_SSAO_DECISIONS_SMOOTH (the default) makes each a weight that
// moves continuously over a narrow band (the bands are aogen/params.hpp's ssao_bands),
// centred on the seeds' threshold: a one-sided band moves the threshold by half its width,
// and with the Crytek kernel's samples gathered near the pixel, many sit that close to it
// (bands starting at the thresholds read 0.063 of the plank's true occlusion where the steps
// read 0.264; centred, 0.240);
//   the vote       clamp((scene z - (S.z + bias)) / band + 1/2, 0, 1), band the smaller of
//                  AO_SSAO_VOTE_BAND radius and the bias (so a surface compared with itself
//                  stays open; no bias, the step);
//   the own texel  a sample counts from 0 at its pixel's texel's edge to 1 at
//                  AO_SSAO_SELF_BAND_PIXELS past it (ao_ssao_self_weight);
//   the screen     a sample is judged from 0 at the border to 1 at AO_SSAO_EDGE_BAND_PIXELS
//                  inside it (ao_ssao_screen_weight; behind the camera it projects to
//                  infinity, past the border); the sum is divided by max(judged, 1), so
//                  it falls to 0 continuously as the last samples leave the screen;
//   silhouettes    both readings of ao_depth_at are voted on and mixed by depth.glsl's
//                  ao_depth_plane_weight;
//   point clouds   ssao_point_cloud.glsl's billboard test is a weight, the cavity AO mixed
//                  with the hemisphere's by it.
// What stays a step is what is no judgement of degree: a background texel (the sky has no
// depth to be near to) and a non-finite value.

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
#if (defined(AO_SSAO_DECISIONS_SMOOTH) + defined(AO_SSAO_DECISIONS_STEP)) != 1
#error aogen: define exactly one of AO_SSAO_DECISIONS_SMOOTH AO_SSAO_DECISIONS_STEP
#endif
#if defined(AO_SSAO_DECISIONS_SMOOTH) && !(defined(AO_SSAO_VOTE_BAND) && defined(AO_SSAO_SELF_BAND_PIXELS) && defined(AO_SSAO_EDGE_BAND_PIXELS) && defined(AO_DEPTH_PLANE_BAND))
#error aogen: smooth decisions need the bands AO_SSAO_*_BAND*, AO_DEPTH_PLANE_BAND (codegen writes them)
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
// hemisphere of `radius` (> 0: ao_ssao_radius): the ratio in float, the smoothstep of it (in
// [0, 1]) in ao_half. Without a branch: the ratio is clamped to 1 where the weight is 0 (taos)
// or 1 (seed004) from there on, which smoothstep gives exactly.
ao_half ao_ssao_range_weight(float abs_dz, float radius)
{
#if defined(AO_RANGE_CHECK_TAOS)
    // 1 - smoothstep(0, radius, |dz|): 0 from |dz| = radius on.
    return ao_half(1.0) - smoothstep(ao_half(0.0), ao_half(1.0), ao_half(min(abs_dz / radius, 1.0)));
#else
    // smoothstep(0, 1, radius / |dz|): 1 for |dz| <= radius, |dz| = 0 included.
    return smoothstep(ao_half(0.0), ao_half(1.0), ao_half(min(radius / max(abs_dz, 1e-30), 1.0)));
#endif
}

// A sample's vote at the bias: is the scene's view z where it projects, `scene_z`, in front
// of the sample's own, `sample_z`, by more than `bias`? A step (the seeds'), or a ramp over
// AO_SSAO_VOTE_BAND of the radius past the bias (DECISIONS above).
float ao_ssao_vote(float scene_z, float sample_z, float bias, float radius)
{
#if defined(AO_SSAO_DECISIONS_SMOOTH)
    // Centred on the bias, so that over the many depth differences a pixel's samples spread
    // across it the votes add up to what the step's add up to; at most the bias wide, so
    // what the bias keeps open (a surface compared with itself, 0 apart) stays open.
    float band = min(AO_SSAO_VOTE_BAND * radius, bias);
    float over = scene_z - (sample_z + bias);
    if (!(band > 0.0)) return over > 0.0 ? 1.0 : 0.0; // no bias: nothing to ramp within
    return clamp(over / band + 0.5, 0.0, 1.0);
#else
    return scene_z > sample_z + bias ? 1.0 : 0.0;
#endif
}

// The occlusion one sample adds, in [0, 1]: its vote times the range check's weight of the
// scene point's depth difference from the pixel's (non-finite scene z: none).
float ao_ssao_occlusion(float pixel_z, float sample_z, float scene_z, float radius, float bias)
{
    if (!ao_is_finite(scene_z)) return 0.0;
    float vote = ao_ssao_vote(scene_z, sample_z, bias, radius);
    return vote * float(ao_ssao_range_weight(abs(pixel_z - scene_z), radius));
}

#if defined(AO_SSAO_DECISIONS_SMOOTH)
// How much of a sample at screen position `pos` (full-resolution pixels) the screen judges:
// 1 inside, falling to 0 over the last AO_SSAO_EDGE_BAND_PIXELS before the border; 0 past it
// and for a NaN position.
float ao_ssao_screen_weight(vec2 pos, vec2 fsize)
{
    return ao_screen_edge_weight(pos, fsize, AO_SSAO_EDGE_BAND_PIXELS);
}

// How much a sample at `pos` counts against pixel `p`'s surface: 0 anywhere in p's own texel
// (a comparison of the surface with itself, which can only measure depth quantization), 1
// from AO_SSAO_SELF_BAND_PIXELS past its edge on (in the larger of x and y). Not centred on
// the edge as the vote is: inside the texel, where a silhouette leaves only the texel's own
// depth to compare with, a self-comparison at a grazing floor's far edge read 0.016 darker
// in standard depth than in reversed-infinite (where the floor goes on past the far plane).
float ao_ssao_self_weight(vec2 pos, ivec2 p)
{
    return ao_own_texel_weight(pos, p, AO_SSAO_SELF_BAND_PIXELS);
}
#endif

// The share of the judged samples occluded: the weighted count `occlusion` over `judged`
// (step: 0 when none is judged; smooth: over at least 1, so the share falls to 0 as the last
// samples leave the screen rather than jumping there).
float ao_ssao_occluded(float occlusion, float judged)
{
#if defined(AO_SSAO_DECISIONS_SMOOTH)
    return occlusion / max(judged, 1.0);
#else
    return judged > 0.0 ? occlusion / judged : 0.0;
#endif
}

// The output of an occluded share (the variant's output form; the settings are u's).
float ao_ssao_output(float occluded, float strength, float power, float intensity)
{
#if defined(AO_OUTPUT_STRENGTH)
    return clamp(1.0 - occluded * strength, 0.0, 1.0);
#else
    float visibility = 1.0 - occluded;
    float ao = visibility > 0.0 ? pow(visibility, power) : 0.0;
    return clamp(ao_lerp(1.0, ao, intensity), 0.0, 1.0);
#endif
}

// The hemisphere estimate of full-resolution pixel p (its depth `depth`, not background).
float ao_ssao_hemisphere(ivec2 target_pixel, ivec2 p, float depth)
{
    vec3 P = ao_view_position_at(vec2(p) + 0.5, depth);
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
#if defined(AO_SSAO_DECISIONS_SMOOTH)
        vec2 pos = uv * fsize;
        float on_screen = ao_ssao_screen_weight(pos, fsize);
        if (!(on_screen > 0.0)) continue; // off screen, or a NaN
        judged += on_screen;
        float counts = ao_ssao_self_weight(pos, p);
        if (!(counts > 0.0)) continue; // its own texel: judged open
        // The two readings of the scene's depth where S projects, mixed by how far the
        // texels around it lie on one plane (depth.glsl's ao_depth_readings), counted as far
        // as a surface is sure to be under it.
        float texel_depth, plane_depth, plane_weight, surface;
        vec2 texel_at;
        int level = ao_tap_level(length(pos - (vec2(p) + 0.5))); // its depth MIP level (0 without a chain)
        if (!ao_depth_readings(pos, level, texel_depth, texel_at, plane_depth, plane_weight, surface)) continue; // background: judged open
        float occ = 0.0;
        if (plane_weight < 1.0) occ = ao_ssao_occlusion(P.z, S.z, ao_view_z_at(texel_at, texel_depth), radius, bias);
        if (plane_weight > 0.0) occ = ao_lerp(occ, ao_ssao_occlusion(P.z, S.z, ao_view_z_at(pos, plane_depth), radius, bias), plane_weight);
        occlusion += on_screen * counts * surface * occ;
#else
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
        occlusion += ao_ssao_occlusion(P.z, S.z, ao_view_z_at(at, scene_depth), radius, bias);
#endif
    }
    return ao_ssao_output(ao_ssao_occluded(occlusion, judged), u.strength, u.power, u.intensity);
}

float ao_pass(ivec2 target_pixel)
{
    ivec2 p = ao_full_pixel(target_pixel);
    float depth = ao_load_depth(p);
    if (ao_is_background(depth)) return 1.0;
#if defined(AO_POINT_CLOUD_FALLBACK)
    // A billboard's interior takes the depth-cavity AO (a weight in [0, 1]: a step with the
    // seeds' decisions); only a partial billboard pays for both estimates.
    float cavity_ao;
    float billboard = ao_point_cloud_billboard(p, depth, cavity_ao);
    if (billboard >= 1.0) return cavity_ao;
    float hemisphere = ao_ssao_hemisphere(target_pixel, p, depth);
    return billboard > 0.0 ? ao_lerp(hemisphere, cavity_ao, billboard) : hemisphere;
#else
    return ao_ssao_hemisphere(target_pixel, p, depth);
#endif
}
