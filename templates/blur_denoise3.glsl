// blur_denoise3.glsl -- the single-pass 3 x 3 edge-aware denoiser (ours; XeGTAO's kernel size)
// that reads no depth: its AO pass wrote each pixel's edges beside its AO (common/edges.glsl).
// Uniform block: BlurUniforms (the blurs' common interface; it reads none of it but the
// albedo of a -mb variant's last pass). Compute stage only (aogen::validate).
//
// Bindings: AO_BINDING_AO_INPUT the AO pass's output, (ao, e right, e lower, 1) per target
// pixel. The depth binding is declared, as in every filter pass (one layout), and not read.
//
// THE FILTER
//   out(p) = sum_q w(q - p) * e(p, q) * ao(q) / sum_q w(q - p) * e(p, q)
// over the 3 x 3 target pixels q around p:
//   w(dx, dy) = W[|dx|] * W[|dy|],  W = (1, 1/2)   (AO_DENOISE3_WEIGHT_0, _1:
//                                                    aogen::blur_params::denoise3_weights)
//   e(p, q)   = the edge between them for the four side taps; for a diagonal tap the mean of
//               its two paths' products, along the row then the column and along the column
//               then the row: (e(p, h) e(h, q) + e(p, v) e(v, q)) / 2, h = (q.x, p.y),
//               v = (p.x, q.y) -- symmetric in x and y, unlike one path's.
// The centre's weight is 1, so the sum is never empty: a pixel with no edge left (background,
// whose AO pass wrote exactly 1 and edges 0; a pixel whose view z is not finite) keeps its
// own value -- background writes exactly 1 with no depth read. A tap off the target has edge 0
// (the AO pass found no depth there), and the tile holds zeros for it.
//
// WHY (1/2, 1, 1/2)
//   The 4 x 4 noise tile's pattern along an axis has periods 2 and 4. A 3-tap filter (a, 1, a)
//   answers period 2 with (1 - 2a) / (1 + 2a) and period 4 with 1 / (1 + 2a): a = 1/2 removes
//   period 2 and halves period 4. No 3-tap filter removes both; the 5 x 5 (blur_denoise.glsl)
//   does, for about twice the work -- the report measures what each leaves.
//
// COST
//   The workgroup loads the (AO_WORKGROUP_X + 2) x (AO_WORKGROUP_Y + 2) texels it covers into
//   shared memory once (AO_PASS_LOADS_TILE: entry_compute.glsl calls ao_load_tile in every
//   invocation): (8 + 2)^2 / 64 = 1.56 texel fetches per pixel of an 8 x 8 group, no depth, no
//   exp; then 9 taps and 12 edges from the tile.

#if !defined(AO_PASS_BLUR_DENOISE3)
#error aogen: blur_denoise3.glsl is the blur_denoise3 pass
#endif
#if !defined(AO_STAGE_COMPUTE)
#error aogen: blur_denoise3.glsl is a compute pass (its AO pass writes the edges in a storage image)
#endif
#if !defined(AO_DENOISE3_WEIGHT_0) || !defined(AO_DENOISE3_WEIGHT_1)
#error aogen: AO_DENOISE3_WEIGHT_0 and _1 are not defined (codegen writes them)
#endif
#if !defined(AO_BINDING_AO_INPUT)
#error aogen: AO_BINDING_AO_INPUT is not defined (codegen writes the bindings)
#endif

// u_ao_input: declared by aogen::codegen (aogen/bindings.hpp).

// An edge as read: finite and in [0, 1], else 0 (the path is cut).
float ao_denoise3_edge_read(float e)
{
    return ao_is_finite(e) ? clamp(e, 0.0, 1.0) : 0.0;
}

// What the filter reads of target pixel q: (ao, edge to the right, edge below), the AO made
// finite and in [0, 1]; zeros off the target (its neighbours' edges to it are 0 already).
vec3 ao_denoise3_tap(ivec2 q)
{
    ivec2 size = max(textureSize(u_ao_input, 0), ivec2(1));
    if (q.x < 0 || q.y < 0 || q.x >= size.x || q.y >= size.y) return vec3(0.0);
    vec3 t = texelFetch(u_ao_input, q, 0).rgb;
    return vec3(ao_finalize(t.r), ao_denoise3_edge_read(t.g), ao_denoise3_edge_read(t.b));
}

#define AO_TILE_WIDTH (AO_WORKGROUP_X + 2)
#define AO_TILE_HEIGHT (AO_WORKGROUP_Y + 2)
#define AO_PASS_LOADS_TILE
shared vec3 ao_tile[AO_TILE_WIDTH * AO_TILE_HEIGHT];

// The target pixel the tile's texel (0, 0) holds: the workgroup's first pixel - (1, 1).
ivec2 ao_tile_origin()
{
    return ivec2(gl_WorkGroupID.xy) * ivec2(AO_WORKGROUP_X, AO_WORKGROUP_Y) - ivec2(1);
}

// Every invocation of the group loads its share of the tile, then waits for the others.
void ao_load_tile()
{
    ivec2 origin = ao_tile_origin();
    for (int i = int(gl_LocalInvocationIndex); i < AO_TILE_WIDTH * AO_TILE_HEIGHT; i += AO_WORKGROUP_X * AO_WORKGROUP_Y)
        ao_tile[i] = ao_denoise3_tap(origin + ivec2(i % AO_TILE_WIDTH, i / AO_TILE_WIDTH));
    barrier();
}

// Target pixel q, inside this group's tile.
vec3 ao_denoise3_read(ivec2 q)
{
    ivec2 t = q - ao_tile_origin();
    return ao_tile[t.y * AO_TILE_WIDTH + t.x];
}

// The edge between target pixel a and its neighbour a + d (d one step along an axis): the
// right edge (.y) or the lower edge (.z) of whichever of the two is left of or above the other.
float ao_denoise3_edge(ivec2 a, ivec2 d)
{
    vec3 owner = ao_denoise3_read(a + min(d, ivec2(0)));
    return d.x != 0 ? owner.y : owner.z;
}

ao_value ao_pass(ivec2 p)
{
    const float W[2] = float[2](AO_DENOISE3_WEIGHT_0, AO_DENOISE3_WEIGHT_1);
    float centre = ao_denoise3_read(p).x;
    vec2 sum = W[0] * W[0] * vec2(centre, 1.0);
    for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
            if (dx == 0 && dy == 0) continue;
            ivec2 h = ivec2(dx, 0), v = ivec2(0, dy), q = p + h + v;
            float e;
            if (dy == 0) e = ao_denoise3_edge(p, h);
            else if (dx == 0) e = ao_denoise3_edge(p, v);
            else e = 0.5 * (ao_denoise3_edge(p, h) * ao_denoise3_edge(p + h, v) + ao_denoise3_edge(p, v) * ao_denoise3_edge(p + v, h));
            float w = W[abs(dx)] * W[abs(dy)] * e;
            if (w > 0.0) sum += w * vec2(ao_denoise3_read(q).x, 1.0);
        }
    return ao_make_value(sum.x / sum.y, vec3(0.0));
}
