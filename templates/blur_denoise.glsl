// blur_denoise.glsl -- the single-pass 5 x 5 edge-aware denoiser (ours): one pass where the
// bilateral blur takes two, for the cost of XeGTAO's single denoise pass. Uniform block:
// BlurUniforms (u.inv_proj, u.linear_sharpness; the others are the blurs' common interface).
//
// Bindings: AO_BINDING_DEPTH the full-resolution depth, AO_BINDING_AO_INPUT the AO target
// to filter (AO target size; its value in .r).
//
// THE FILTER
//   out(p) = sum_q w(q - p) * e(q) * ao(q) / sum_q w(q - p) * e(q)
// over the 5 x 5 target pixels q around p (offsets -2..2 on each axis, AO_DENOISE_RADIUS),
//   w(dx, dy) = W[|dx|] * W[|dy|],  W = (1, 1, 1/2) for |d| = 0, 1, 2 (AO_DENOISE_WEIGHT_0..2)
//   e(q)      = exp(-|z(q) - z(p)| * u.linear_sharpness)   z: view-space depth, world units
// W is aogen::blur_params::denoise_weights: offsets 4 apart share a phase of the 4 x 4 noise
// tile, and (1/2, 1, 1, 1, 1/2) gives each phase the same weight, so on a plane the tile's
// pattern averages out exactly, as under the 4 x 4 box, with a window centred on p. The
// depth term e is the bilateral blur's (linear view depth): it stops the filter at
// silhouettes, at every distance and for every depth convention. Taps off the target or on
// background are left out; the centre's weight is 1, so the sum is never empty. Background
// pixels write exactly 1.
//
// COST
//   25 taps, each an AO value and a depth turned into view z. In compute passes the
//   workgroup first loads the (AO_WORKGROUP_X + 4) x (AO_WORKGROUP_Y + 4) tile of taps it
//   covers into shared memory (ao_load_tile, called by entry_compute.glsl for every
//   invocation, before its edge test: the tile load ends in a barrier), so each texel is
//   fetched and converted about 1.6 times per pixel (8 x 8 groups) instead of 25. Fragment
//   passes fetch the 25 taps themselves.

#if !defined(AO_PASS_BLUR_DENOISE)
#error aogen: blur_denoise.glsl is the blur_denoise pass
#endif
#if !defined(AO_DENOISE_RADIUS) || !defined(AO_DENOISE_WEIGHT_0) || !defined(AO_DENOISE_WEIGHT_1) || !defined(AO_DENOISE_WEIGHT_2)
#error aogen: AO_DENOISE_RADIUS and AO_DENOISE_WEIGHT_0..2 are not defined (codegen writes them)
#endif
#if AO_DENOISE_RADIUS != 2
#error aogen: blur_denoise.glsl is written for a radius of 2 (three weights)
#endif
#if !defined(AO_BINDING_AO_INPUT)
#error aogen: AO_BINDING_AO_INPUT is not defined (codegen writes the bindings)
#endif

// u_ao_input: declared by aogen::codegen (aogen/bindings.hpp).

const float AO_DENOISE_WEIGHTS[3] = float[3](AO_DENOISE_WEIGHT_0, AO_DENOISE_WEIGHT_1, AO_DENOISE_WEIGHT_2);

// What the filter reads of target pixel q: (ao, z), the AO made finite and in [0, 1] and the
// view-space depth; ao = -1 marks a pixel that is no tap (off the target, background, or a
// depth whose view z is not finite).
vec2 ao_denoise_tap(ivec2 q)
{
    ivec2 size = max(textureSize(u_ao_input, 0), ivec2(1));
    if (q.x < 0 || q.y < 0 || q.x >= size.x || q.y >= size.y) return vec2(-1.0, 0.0);
    ivec2 full = ao_full_pixel(q);
    float depth = ao_load_depth(full);
    if (ao_is_background(depth)) return vec2(-1.0, 0.0);
    float z = ao_view_z(ao_pixel_uv(full), depth);
    if (!ao_is_finite(z)) return vec2(-1.0, 0.0);
    return vec2(ao_finalize(texelFetch(u_ao_input, q, 0).r), z);
}

#if defined(AO_STAGE_COMPUTE)
#define AO_TILE_WIDTH (AO_WORKGROUP_X + 2 * AO_DENOISE_RADIUS)
#define AO_TILE_HEIGHT (AO_WORKGROUP_Y + 2 * AO_DENOISE_RADIUS)
#define AO_PASS_LOADS_TILE
shared vec2 ao_tile[AO_TILE_WIDTH * AO_TILE_HEIGHT];

// The target pixel the tile's texel (0, 0) holds: the workgroup's first pixel - radius.
ivec2 ao_tile_origin()
{
    return ivec2(gl_WorkGroupID.xy) * ivec2(AO_WORKGROUP_X, AO_WORKGROUP_Y) - ivec2(AO_DENOISE_RADIUS);
}

// Every invocation of the group loads its share of the tile, then waits for the others.
void ao_load_tile()
{
    ivec2 origin = ao_tile_origin();
    for (int i = int(gl_LocalInvocationIndex); i < AO_TILE_WIDTH * AO_TILE_HEIGHT; i += AO_WORKGROUP_X * AO_WORKGROUP_Y)
        ao_tile[i] = ao_denoise_tap(origin + ivec2(i % AO_TILE_WIDTH, i / AO_TILE_WIDTH));
    barrier();
}

// The tap at target pixel q, inside this group's tile.
vec2 ao_denoise_read(ivec2 q)
{
    ivec2 t = q - ao_tile_origin();
    return ao_tile[t.y * AO_TILE_WIDTH + t.x];
}
#else
vec2 ao_denoise_read(ivec2 q)
{
    return ao_denoise_tap(q);
}
#endif

float ao_pass(ivec2 p)
{
    vec2 centre = ao_denoise_read(p);
    if (centre.x < 0.0) {
        // Background writes exactly 1; a pixel whose view z is not finite keeps its own AO.
        if (ao_is_background(ao_load_depth(ao_full_pixel(p)))) return 1.0;
        return ao_finalize(texelFetch(u_ao_input, p, 0).r);
    }
    float sum = 0.0;
    float weight_sum = 0.0;
    for (int dy = -AO_DENOISE_RADIUS; dy <= AO_DENOISE_RADIUS; ++dy) {
        for (int dx = -AO_DENOISE_RADIUS; dx <= AO_DENOISE_RADIUS; ++dx) {
            vec2 tap = ao_denoise_read(p + ivec2(dx, dy));
            if (tap.x < 0.0) continue;
            float w = AO_DENOISE_WEIGHTS[abs(dx)] * AO_DENOISE_WEIGHTS[abs(dy)] * exp(-abs(tap.y - centre.y) * u.linear_sharpness);
            if (!(w > 0.0)) continue; // underflowed (or NaN): the tap is left out
            sum += w * tap.x;
            weight_sum += w;
        }
    }
    return weight_sum > 0.0 ? sum / weight_sum : centre.x;
}
