// common/edges.glsl -- the edges the 3 x 3 denoise reads (blur_denoise3.glsl), written by the
// AO pass of a -denoise3 variant (AO_WRITE_EDGES) beside its AO: the output texel is
// (ao, e(p, p + (1, 0)), e(p, p + (0, 1)), 1), so the denoise reads one texel per tap and
// no depth at all.
//
// THE EDGE
//   Between neighbouring target pixels a and b, with view depths z(a), z(b):
//       e(a, b) = exp(-AO_EDGE_SHARPNESS * |z(a) - z(b)| / min(|z(a)|, |z(b)|))
//   (aogen::blur_params::denoise3_edge_sharpness) -- 1 on a surface seen head-on, falling
//   with the relative step between the two depths; 0 when either is no tap: off the target,
//   background, or a depth whose view z is not finite (the path through it is cut). e is
//   symmetric, so each edge is one number, stored once: by the pixel on its left or above.
//   A pixel stores the two edges to its right and lower neighbours; the denoise finds the
//   edge to p's left in texel p - (1, 0), the one above in p - (0, 1).
//
// WHY RELATIVE
//   The AO pass's uniform block holds its technique's settings, not the blur's: a sharpness
//   per world unit (blur_params::linear_sharpness, the 5 x 5's) is not there to read. The
//   relative step is also what the depth buffer resolves -- the same edges for a scene in
//   millimetres or kilometres -- and the min() makes it the larger of the two ratios, so a
//   silhouette in front of a far wall is cut as hard as the wall behind a near one.
//
// WHY TWO EDGES, NOT FOUR AT TWO BITS (XeGTAO's packing)
//   Each edge belongs to two pixels; storing it once leaves 8 bits for it in a unorm8 channel
//   (rgba8: output_format_of widens r8), where four edges packed in one channel get 2 bits
//   each. Two neighbour depths per pixel are read for it, beside the taps the AO pass reads.
//
// COST
//   Two depth texels (the right and lower neighbours' full pixels), two view depths, one
//   exp each; the denoise then reads no depth.

#if !defined(AO_PASS_AO) || !defined(AO_WRITE_EDGES)
#error aogen: common/edges.glsl is the AO pass of a -denoise3 variant (AO_WRITE_EDGES)
#endif
#if !defined(AO_EDGE_SHARPNESS)
#error aogen: AO_EDGE_SHARPNESS is not defined (codegen writes it)
#endif

// The view depth of target pixel q, or 0 when it is no tap (off the target, background, not
// finite). A view depth is never 0 on a surface (it is at least the near plane away).
float ao_edge_depth(ivec2 q)
{
    ivec2 size = ao_target_size();
    if (q.x >= size.x || q.y >= size.y) return 0.0;
    ivec2 full = ao_full_pixel(q);
    float depth = ao_load_depth(full);
    if (ao_is_background(depth)) return 0.0;
    float z = abs(ao_pixel_view_z(full, depth));
    return ao_is_finite(z) ? z : 0.0;
}

// e(a, b) of the header from the two view depths (0 for no tap).
float ao_edge(float za, float zb)
{
    float nearer = min(za, zb);
    if (!(nearer > 0.0)) return 0.0;
    return exp(-AO_EDGE_SHARPNESS * abs(za - zb) / nearer);
}

// The edges from target pixel p to its right and lower neighbours: what the output texel
// holds in .g and .b.
vec2 ao_edges(ivec2 p)
{
    float z = ao_edge_depth(p);
    return vec2(ao_edge(z, ao_edge_depth(p + ivec2(1, 0))), ao_edge(z, ao_edge_depth(p + ivec2(0, 1))));
}
