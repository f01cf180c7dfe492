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

#if !defined(AO_POINT_CLOUD_FALLBACK) || !defined(AO_TECHNIQUE_SSAO)
#error aogen: ssao_point_cloud.glsl belongs to ssao variants with AO_POINT_CLOUD_FALLBACK
#endif
#if !defined(AO_PC_BACKGROUND_DEPTH) || !defined(AO_PC_SAME_DEPTH) || !defined(AO_PC_CAVITY_THRESHOLD) || !defined(AO_PC_RING_PIXELS)
#error aogen: the point-cloud constants AO_PC_* are not defined (codegen writes them)
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

// Is `neighbour` closer to the camera than `centre` by more than the cavity threshold?
bool ao_pc_closer(float neighbour, float centre)
{
#if defined(AO_DEPTH_STANDARD)
    return neighbour < centre - AO_PC_CAVITY_THRESHOLD;
#else
    return neighbour > centre + AO_PC_CAVITY_THRESHOLD;
#endif
}

// True when full-resolution pixel p (depth `depth`, not background) is a billboard
// interior; `ao` is then its depth-cavity AO.
bool ao_point_cloud_billboard(ivec2 p, float depth, out float ao)
{
    ao = 1.0;
    ivec2 last = ao_depth_size() - 1;
    int same = 0;
    int drawn = 0;
    for (int k = 0; k < 8; ++k) {
        float d = ao_load_depth(clamp(p + AO_PC_NEIGHBOURS[k], ivec2(0), last));
        if (ao_pc_is_background(d)) continue;
        ++drawn;
        if (abs(d - depth) < AO_PC_SAME_DEPTH) ++same;
    }
    if (drawn == 0 || same < drawn) return false;

    float closer = 0.0;
    float valid = 0.0;
    for (int k = 0; k < 8; ++k) {
        float d = ao_load_depth(clamp(p + AO_PC_NEIGHBOURS[k] * AO_PC_RING_PIXELS, ivec2(0), last));
        if (ao_pc_is_background(d)) continue;
        valid += 1.0;
        if (ao_pc_closer(d, depth)) closer += 1.0;
    }
    ao = valid > 0.0 ? 1.0 - closer / valid : 1.0;
    return true;
}
