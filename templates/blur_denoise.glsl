// blur_denoise.glsl -- the single-pass 5 x 5 edge-aware denoiser (ours): one pass where the
// bilateral blur takes two, for the cost of XeGTAO's single denoise pass. Uniform block:
// BlurUniforms (u.inv_proj, u.linear_sharpness; the others are the blurs' common interface).
//
// Bindings: AO_BINDING_DEPTH the full-resolution depth, AO_BINDING_AO_INPUT the AO target
// to filter (AO target size; its value in .r).
//
// THE FILTER
//   out(p) = sum_q w(q - p) * e(p, q) * ao(q) / sum_q w(q - p) * e(p, q)
// over the 5 x 5 target pixels q around p (offsets -2..2 on each axis, AO_DENOISE_RADIUS),
//   w(dx, dy) = W[|dx|] * W[|dy|],  W = (1, 1, 1/2) for |d| = 0, 1, 2 (AO_DENOISE_WEIGHT_0..2)
//   e(p, q)   = the product of the edge weights exp(-|z(a) - z(b)| * u.linear_sharpness) of the
//               neighbouring pixels a, b on the path from p to q: along p's row to q's
//               column, then along that column to q (z: view-space depth, world units)
// W is aogen::blur_params::denoise_weights: offsets 4 apart share a phase of the 4 x 4 noise
// tile, and (1/2, 1, 1, 1, 1/2) gives each phase the same weight, so on a plane the tile's
// pattern averages out exactly, as under the 4 x 4 box, with a window centred on p. The
// depth term stops the filter at silhouettes, at every distance and for every depth
// convention. Taps off the target or on background are no taps, and a path through one is
// cut (their edges weigh 0); the centre's weight is 1, so the sum is never empty. Background
// pixels write exactly 1.
//
// WHY A PATH OF EDGES, NOT |z(q) - z(p)| PER TAP
//   The product of a path's edge weights is exp(-k * sum of the steps' |dz|). Along a row or
//   a column of one plane z is monotone (1/z is affine along a screen line), so on a plane the
//   sum is |z(q) - z(p)| -- the direct weight -- up to the corner of the path; across a
//   silhouette it is at least as large, so the path form stops at least as hard. What it buys:
//   the weights split by column. A column's sum
//       C(c) = sum_dy W[|dy|] e(c, c + (0, dy)) ao(c + (0, dy))   (and its weight sum)
//   does not depend on p, so it is computed once per column pixel and shared by the five
//   pixels of its row that read it:
//       out(p) = sum_dx W[|dx|] e(p, p + (dx, 0)) C(p + (dx, 0)) / (the same over weights).
//   Each edge is one exp; 4 per column pixel and 4 per pixel, where the direct weight took 25
//   per pixel.
//
// COST
//   In compute passes the workgroup first loads the (AO_WORKGROUP_X + 4) x (AO_WORKGROUP_Y + 4)
//   tile of taps it covers into shared memory, then the column sums of its rows'
//   (AO_WORKGROUP_X + 4) x AO_WORKGROUP_Y pixels (ao_load_tile, called by entry_compute.glsl
//   for every invocation, before its edge test: each phase ends in a barrier), so each texel
//   is fetched and converted about 2.25 times per 8 x 8 group's pixel and each column sum
//   made 1.5 times, instead of 25 taps per pixel. Fragment passes make the five column sums
//   themselves, with the same arithmetic in the same order (the same bits).

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
    float z = ao_pixel_view_z(full, depth);
    if (!ao_is_finite(z)) return vec2(-1.0, 0.0);
    return vec2(ao_finalize(texelFetch(u_ao_input, q, 0).r), z);
}

// The edge weight between neighbouring taps a and b: exp(-|z(a) - z(b)| * sharpness); 0 when
// either is no tap, which cuts every path through it.
float ao_denoise_edge(vec2 a, vec2 b)
{
    if (a.x < 0.0 || b.x < 0.0) return 0.0;
    return exp(-abs(a.y - b.y) * u.linear_sharpness);
}

// The bent normal of target pixel q (a -bn variant's: common/core.glsl's ao_value), zero off
// the target. Read only where ao_denoise_tap says q is a tap.
vec3 ao_denoise_tap_bent(ivec2 q)
{
    ivec2 size = max(textureSize(u_ao_input, 0), ivec2(1));
    if (q.x < 0 || q.y < 0 || q.x >= size.x || q.y >= size.y) return vec3(0.0);
    return ao_value_bent(ao_read_input(q));
}

#if defined(AO_STAGE_COMPUTE)
#define AO_TILE_WIDTH (AO_WORKGROUP_X + 2 * AO_DENOISE_RADIUS)
#define AO_TILE_HEIGHT (AO_WORKGROUP_Y + 2 * AO_DENOISE_RADIUS)
#define AO_PASS_LOADS_TILE
// The taps of the group's pixels and of the radius around them, then the column sums of the
// group's rows over the tile's width. With bent normals their normals and normal sums sit in
// arrays of their own, so the AO's arithmetic is the same with them as without.
shared vec2 ao_tile[AO_TILE_WIDTH * AO_TILE_HEIGHT];
shared vec2 ao_columns[AO_TILE_WIDTH * AO_WORKGROUP_Y];
#if defined(AO_BENT_NORMALS)
shared vec3 ao_tile_bent[AO_TILE_WIDTH * AO_TILE_HEIGHT];
shared vec3 ao_columns_bent[AO_TILE_WIDTH * AO_WORKGROUP_Y];
#endif

// The target pixel the tile's texel (0, 0) holds: the workgroup's first pixel - radius.
ivec2 ao_tile_origin()
{
    return ivec2(gl_WorkGroupID.xy) * ivec2(AO_WORKGROUP_X, AO_WORKGROUP_Y) - ivec2(AO_DENOISE_RADIUS);
}

// Where target pixel q, inside this group's tile, is in it.
int ao_tile_index(ivec2 q)
{
    ivec2 t = q - ao_tile_origin();
    return t.y * AO_TILE_WIDTH + t.x;
}

// The tap at target pixel q, inside this group's tile, and its bent normal.
vec2 ao_denoise_read(ivec2 q) { return ao_tile[ao_tile_index(q)]; }
#if defined(AO_BENT_NORMALS)
vec3 ao_denoise_read_bent(ivec2 q) { return ao_tile_bent[ao_tile_index(q)]; }
#else
vec3 ao_denoise_read_bent(ivec2 q) { return vec3(0.0); }
#endif
#else
vec2 ao_denoise_read(ivec2 q)
{
    return ao_denoise_tap(q);
}
vec3 ao_denoise_read_bent(ivec2 q)
{
    return ao_denoise_tap_bent(q);
}
#endif

// Column c's sum: (sum of w * ao, sum of w) over the taps c + (0, dy), |dy| <= radius, w the
// product of the edges from c to the tap times AO_DENOISE_WEIGHTS[|dy|]; (0, 0) when c is no
// tap. `bent`: the sum of w * bent normal over the same taps (zero without bent normals).
vec2 ao_denoise_column(ivec2 c, out vec3 bent)
{
    bent = vec3(0.0);
    vec2 centre = ao_denoise_read(c);
    if (centre.x < 0.0) return vec2(0.0);
    vec2 sum = AO_DENOISE_WEIGHTS[0] * vec2(centre.x, 1.0);
    bent = AO_DENOISE_WEIGHTS[0] * ao_denoise_read_bent(c);
    for (int side = -1; side <= 1; side += 2) {
        vec2 previous = centre;
        float path = 1.0;
        for (int d = 1; d <= AO_DENOISE_RADIUS; ++d) {
            ivec2 q = c + ivec2(0, side * d);
            vec2 tap = ao_denoise_read(q);
            path *= ao_denoise_edge(previous, tap);
            previous = tap;
            float w = AO_DENOISE_WEIGHTS[d] * path;
            if (w > 0.0) { // 0: cut or underflowed
                sum += w * vec2(tap.x, 1.0);
                bent += w * ao_denoise_read_bent(q);
            }
        }
    }
    return sum;
}

#if defined(AO_STAGE_COMPUTE)
// Every invocation of the group loads its share of the tile, waits for the others, makes its
// share of the column sums and waits again.
void ao_load_tile()
{
    ivec2 origin = ao_tile_origin();
    const int group_size = AO_WORKGROUP_X * AO_WORKGROUP_Y;
    for (int i = int(gl_LocalInvocationIndex); i < AO_TILE_WIDTH * AO_TILE_HEIGHT; i += group_size) {
        ivec2 q = origin + ivec2(i % AO_TILE_WIDTH, i / AO_TILE_WIDTH);
        ao_tile[i] = ao_denoise_tap(q);
#if defined(AO_BENT_NORMALS)
        ao_tile_bent[i] = ao_denoise_tap_bent(q);
#endif
    }
    barrier();
    for (int i = int(gl_LocalInvocationIndex); i < AO_TILE_WIDTH * AO_WORKGROUP_Y; i += group_size) {
        vec3 bent;
        ao_columns[i] = ao_denoise_column(origin + ivec2(i % AO_TILE_WIDTH, AO_DENOISE_RADIUS + i / AO_TILE_WIDTH), bent);
#if defined(AO_BENT_NORMALS)
        ao_columns_bent[i] = bent;
#endif
    }
    barrier();
}

// The column sum at target pixel c, a pixel of the group's rows within the tile's width, and
// its bent normals' sum.
vec2 ao_denoise_column_sum(ivec2 c, out vec3 bent)
{
    ivec2 t = c - ao_tile_origin() - ivec2(0, AO_DENOISE_RADIUS);
#if defined(AO_BENT_NORMALS)
    bent = ao_columns_bent[t.y * AO_TILE_WIDTH + t.x];
#else
    bent = vec3(0.0);
#endif
    return ao_columns[t.y * AO_TILE_WIDTH + t.x];
}
#else
vec2 ao_denoise_column_sum(ivec2 c, out vec3 bent)
{
    return ao_denoise_column(c, bent);
}
#endif

ao_value ao_pass(ivec2 p)
{
    vec2 centre = ao_denoise_read(p);
    if (centre.x < 0.0) {
        // Background writes exactly 1; a pixel whose view z is not finite keeps its own AO.
        if (ao_is_background(ao_load_depth(ao_full_pixel(p)))) return ao_open_value();
        return ao_read_input(p);
    }
    // Along p's row: each column's sum, weighed by the edges from p to the column; the bent
    // normals' sums likewise (without bent normals they are zero and unused).
    vec3 bent;
    vec2 sum = AO_DENOISE_WEIGHTS[0] * ao_denoise_column_sum(p, bent);
    vec3 bent_sum = AO_DENOISE_WEIGHTS[0] * bent;
    for (int side = -1; side <= 1; side += 2) {
        vec2 previous = centre;
        float path = 1.0;
        for (int d = 1; d <= AO_DENOISE_RADIUS; ++d) {
            ivec2 q = p + ivec2(side * d, 0);
            vec2 tap = ao_denoise_read(q);
            path *= ao_denoise_edge(previous, tap);
            previous = tap;
            float w = AO_DENOISE_WEIGHTS[d] * path;
            if (w > 0.0) {
                sum += w * ao_denoise_column_sum(q, bent);
                bent_sum += w * bent;
            }
        }
    }
    return ao_make_value(sum.y > 0.0 ? sum.x / sum.y : centre.x, bent_sum);
}
