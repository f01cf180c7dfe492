// ssao_point_cloud.glsl -- the point-cloud fallback of seed 004 (ssao.wgsl), compiled
// into a variant only with AO_POINT_CLOUD_FALLBACK (codegen leaves this file out
// otherwise). Comes before ssao.glsl, which calls ao_point_cloud_billboard first.
//
// Point billboards are drawn at one constant depth each, so a billboard's interior
// pixels all hold exactly the same depth, where hemisphere sampling is unreliable.
//   1. Billboard test: of the 8 neighbours at distance 1 (clamped to the screen), those
//      not background all have a depth within AO_PC_SAME_DEPTH of the centre's, and
//      there is at least one.
//   2. Depth-cavity test instead: of the 8 neighbours at distance AO_PC_RING_PIXELS
//      (clamped), not background, the fraction closer to the camera than the centre by
//      more than AO_PC_CAVITY_THRESHOLD in depth; AO = 1 - that fraction.
// The constants are seed 004's (aogen::point_cloud in aogen/params.hpp, written by
// codegen) on depth values of a standard [0, 1] buffer. A reversed buffer holds 1 - d of
// the standard one (exactly; reversed-infinite is a standard buffer with an infinite far
// plane), so differences keep their size and only "closer" changes sign. Inside this test
// a neighbour counts as background from standard depth AO_PC_BACKGROUND_DEPTH on, as in
// the seed; the centre pixel itself uses the exact background test of depth.glsl.
// With smooth decisions (ssao.glsl's DECISIONS) both tests are weights, each ramping over a
// band past its constant (AO_PC_SAME_BAND, AO_PC_CAVITY_BAND times it), and ssao.glsl mixes
// the two estimates.

#if !defined(AO_POINT_CLOUD_FALLBACK) || !defined(AO_TECHNIQUE_SSAO)
#error aogen: ssao_point_cloud.glsl belongs to ssao variants with AO_POINT_CLOUD_FALLBACK
#endif
#if !defined(AO_PC_BACKGROUND_DEPTH) || !defined(AO_PC_SAME_DEPTH) || !defined(AO_PC_CAVITY_THRESHOLD) || !defined(AO_PC_RING_PIXELS)
#error aogen: the point-cloud constants AO_PC_* are not defined (codegen writes them)
#endif
#if defined(AO_SSAO_DECISIONS_SMOOTH) && !(defined(AO_PC_SAME_BAND) && defined(AO_PC_CAVITY_BAND))
#error aogen: smooth decisions need AO_PC_SAME_BAND and AO_PC_CAVITY_BAND (codegen writes them)
#endif

const ivec2 AO_PC_NEIGHBOURS[8] = ivec2[8](ivec2(1, 0), ivec2(-1, 0), ivec2(0, 1), ivec2(0, -1),
                                           ivec2(1, 1), ivec2(-1, 1), ivec2(1, -1), ivec2(-1, -1));

bool ao_pc_is_background(float depth)
{
    if (ao_is_background(depth)) return true;
#if defined(AO_DEPTH_STANDARD)
    return depth >= AO_PC_BACKGROUND_DEPTH;
#else
    return depth <= 1.0 - AO_PC_BACKGROUND_DEPTH;
#endif
}

// How far `neighbour` is closer to the camera than `centre` by more than the cavity
// threshold: a step with the seeds' decisions; smooth, a ramp from the threshold to
// 1 + AO_PC_CAVITY_BAND times it.
float ao_pc_closer(float neighbour, float centre)
{
#if defined(AO_SSAO_DECISIONS_SMOOTH)
#if defined(AO_DEPTH_STANDARD)
    float closer_by = centre - neighbour;
#else
    float closer_by = neighbour - centre;
#endif
    return clamp((closer_by - AO_PC_CAVITY_THRESHOLD) / (AO_PC_CAVITY_BAND * AO_PC_CAVITY_THRESHOLD), 0.0, 1.0);
#elif defined(AO_DEPTH_STANDARD)
    return neighbour < centre - AO_PC_CAVITY_THRESHOLD ? 1.0 : 0.0; // seed 004's comparison, exactly
#else
    return neighbour > centre + AO_PC_CAVITY_THRESHOLD ? 1.0 : 0.0;
#endif
}

// How far a neighbour's depth `d` counts as the centre's `depth` (within the same-depth
// tolerance): a step with the seeds' decisions; smooth, 1 within the tolerance falling to 0
// at 1 + AO_PC_SAME_BAND times it.
float ao_pc_same(float d, float depth)
{
#if defined(AO_SSAO_DECISIONS_SMOOTH)
    return clamp(1.0 - (abs(d - depth) - AO_PC_SAME_DEPTH) / (AO_PC_SAME_BAND * AO_PC_SAME_DEPTH), 0.0, 1.0);
#else
    return abs(d - depth) < AO_PC_SAME_DEPTH ? 1.0 : 0.0;
#endif
}

// How far full-resolution pixel p (depth `depth`, not background) is a billboard interior,
// in [0, 1]: the least sameness of its drawn neighbours (0 with none drawn; a step with the
// seeds' decisions). `ao` is its depth-cavity AO.
float ao_point_cloud_billboard(ivec2 p, float depth, out float ao)
{
    ao = 1.0;
    ivec2 last = ao_depth_size() - 1;
    float billboard = 1.0;
    int drawn = 0;
    for (int k = 0; k < 8; ++k) {
        float d = ao_load_depth(clamp(p + AO_PC_NEIGHBOURS[k], ivec2(0), last));
        if (ao_pc_is_background(d)) continue;
        ++drawn;
        billboard = min(billboard, ao_pc_same(d, depth));
    }
    if (drawn == 0 || !(billboard > 0.0)) return 0.0;

    float closer = 0.0;
    float valid = 0.0;
    for (int k = 0; k < 8; ++k) {
        float d = ao_load_depth(clamp(p + AO_PC_NEIGHBOURS[k] * AO_PC_RING_PIXELS, ivec2(0), last));
        if (ao_pc_is_background(d)) continue;
        valid += 1.0;
        closer += ao_pc_closer(d, depth);
    }
    ao = valid > 0.0 ? 1.0 - closer / valid : 1.0;
    return billboard;
}
