// common/depth.glsl -- the depth buffer: sizes, the full/half resolution mapping, the
// background test of each depth convention and view-space reconstruction through
// u.inv_proj (every pass block has it), in screen pixels (THE UNPROJECTION IN PIXELS).
//
// Binding AO_BINDING_DEPTH: the depth buffer at full resolution as a float texture (a
// sampled D32/D24 depth image or an R32F copy), read with texelFetch from .r. Its size is
// the screen size; at AO_HALF_RESOLUTION the AO target is half of it, rounded up (1919 x
// 1079 -> 960 x 540), and target pixel p reads depth and normals at full-resolution
// pixel 2p (clamped to the screen; the last row/column of an odd size is not read).

// u_depth: declared by aogen::codegen (aogen/bindings.hpp).

// ---- read once per invocation ---------------------------------------------------------------
// What every tap needs and no tap changes: the depth buffer's size and the inverse projection
// in screen pixels (THE UNPROJECTION IN PIXELS, below). ao_begin_invocation() sets them, first
// thing in every entry point's main; before, each tap of a GTAO step queried the size four
// times and divided its position by it (aogen/loops.hpp counts what a tap costs).
ivec2 ao_invocation_depth_size = ivec2(1);
vec4 ao_unproject_per_x = vec4(0.0), ao_unproject_per_y = vec4(0.0), ao_unproject_origin = vec4(0.0);

// THE UNPROJECTION IN PIXELS
//   A screen position (x, y) in full-resolution pixels (centres at +0.5, y down) is at
//   ndc = (2 x / W - 1, 1 - 2 y / H), so with c0 .. c3 the columns of u.inv_proj
//       inv_proj * (ndc, d, 1) = c0 ndc.x + c1 ndc.y + c2 d + c3
//                              = (2 / W) c0 x + (-2 / H) c1 y + c2 d + (c3 - c0 + c1):
//   three columns fixed per invocation (ao_unproject_per_x, _per_y, _origin) and c2 itself, so a
//   tap's homogeneous point is three vector multiply-adds -- no division of its position by the
//   screen's size, no mapping to ndc -- and any projection matrix keeps working (an engine's
//   jittered, off-centre or oblique one), which a form with the matrix's structure assumed
//   (XeGTAO's NDCToViewMul / Add on a linear depth) would not.
void ao_begin_invocation()
{
    ao_invocation_depth_size = max(textureSize(u_depth, 0), ivec2(1));
    vec2 to_ndc = 2.0 / vec2(ao_invocation_depth_size);
    ao_unproject_per_x = u.inv_proj[0] * to_ndc.x;
    ao_unproject_per_y = u.inv_proj[1] * -to_ndc.y;
    ao_unproject_origin = u.inv_proj[3] - u.inv_proj[0] + u.inv_proj[1];
}

// The depth buffer's size in pixels (at least 1 x 1).
ivec2 ao_depth_size()
{
    return ao_invocation_depth_size;
}

// The AO target's size in pixels: the AO image and the blur passes' input and output.
ivec2 ao_target_size()
{
#if defined(AO_HALF_RESOLUTION)
    return (ao_depth_size() + 1) / 2;
#else
    return ao_depth_size();
#endif
}

// The full-resolution pixel that target pixel `p` reads depth (and normals) from.
ivec2 ao_full_pixel(ivec2 p)
{
#if defined(AO_HALF_RESOLUTION)
    p *= 2;
#endif
    return clamp(p, ivec2(0), ao_depth_size() - 1);
}

// The screen pixel under output pixel `p` of this pass: the upsample writes the screen
// itself; every other pass writes the AO target, whose pixel p stands for ao_full_pixel(p).
ivec2 ao_output_screen_pixel(ivec2 p)
{
#if defined(AO_PASS_UPSAMPLE)
    return p;
#else
    return ao_full_pixel(p);
#endif
}

// The raw depth-buffer value at a full-resolution pixel (inside the screen).
float ao_load_depth(ivec2 full_pixel)
{
    return texelFetch(u_depth, full_pixel, 0).r;
}

// The uv of a full-resolution pixel's centre.
vec2 ao_pixel_uv(ivec2 full_pixel)
{
    return (vec2(full_pixel) + 0.5) / vec2(ao_depth_size());
}

// Cleared depth (nothing drawn): 1 for standard depth, 0 for both reversed conventions;
// values past the clear value and non-finite values (a NaN texel) count as background too.
bool ao_is_background(float depth)
{
    // any() of both tests, not ||: GLSL's || branches (a tap makes five of these tests).
#if defined(AO_DEPTH_STANDARD)
    return any(bvec2(!ao_is_finite(depth), depth >= 1.0));
#else
    return any(bvec2(!ao_is_finite(depth), depth <= 0.0));
#endif
}

// ao_is_background of four depths at once (a gather's), without a branch.
bvec4 ao_is_background(vec4 depth)
{
    uvec4 not_finite = uvec4(equal(floatBitsToUint(depth) & uvec4(0x7f800000u), uvec4(0x7f800000u)));
#if defined(AO_DEPTH_STANDARD)
    uvec4 cleared = uvec4(greaterThanEqual(depth, vec4(1.0)));
#else
    uvec4 cleared = uvec4(lessThanEqual(depth, vec4(0.0)));
#endif
    return notEqual(not_finite | cleared, uvec4(0u));
}

// The homogeneous view-space point of screen position `pos` (full-resolution pixels) at raw
// depth `depth`: inv_proj * (ndc, depth, 1) in pixels (THE UNPROJECTION IN PIXELS).
vec4 ao_unproject_pixels(vec2 pos, float depth)
{
    return ao_unproject_per_x * pos.x + (ao_unproject_per_y * pos.y + (u.inv_proj[2] * depth + ao_unproject_origin));
}

// The view-space position of a depth-buffer value at screen position `pos` (full-resolution
// pixels; depth must not be background) -- every tap's and every pixel's own point, so that
// both round alike. Perspective: w = 1 / view distance > 0 for every depth in front of the
// camera; it is kept away from 0 so the reciprocal cannot fault (an absurd depth then gives a
// huge or non-finite position, which callers test with ao_is_finite). Orthographic: inv_proj
// is affine, w is exactly 1 and there is no division.
vec3 ao_view_position_at(vec2 pos, float depth)
{
    vec4 p = ao_unproject_pixels(pos, depth);
#if defined(AO_PROJECTION_ORTHOGRAPHIC)
    return p.xyz;
#else
    return p.xyz * (1.0 / max(p.w, 1e-30)); // one reciprocal, three multiplies
#endif
}

// The view-space position of a depth-buffer value at `uv` through u.inv_proj itself, for the
// history pass (history.glsl), whose reprojection projects it back through the matrices: a
// still camera's round trip then lands on the pixel's centre to the bit, where the pixel form
// above lands an ulp or two beside it, and the history's bilinear read mixes in a neighbour.
vec3 ao_view_position_uv(vec2 uv, float depth)
{
    vec4 p = u.inv_proj * vec4(uv.x * 2.0 - 1.0, 1.0 - uv.y * 2.0, depth, 1.0);
#if defined(AO_PROJECTION_ORTHOGRAPHIC)
    return p.xyz;
#else
    return p.xyz / max(p.w, 1e-30);
#endif
}

// Only the view-space z of ao_view_position_at (negative in front of the camera).
float ao_view_z_at(vec2 pos, float depth)
{
    vec4 p = ao_unproject_pixels(pos, depth);
#if defined(AO_PROJECTION_ORTHOGRAPHIC)
    return p.z;
#else
    return p.z / max(p.w, 1e-30);
#endif
}

// The view-space z of full-resolution pixel `full_pixel`'s centre at depth `depth`.
float ao_pixel_view_z(ivec2 full_pixel, float depth)
{
    return ao_view_z_at(vec2(full_pixel) + 0.5, depth);
}

// The four depths of the 2x2 texels whose centres surround `pos`, from texel `i0` (the
// one with the smallest indices) on, clamped at the image's edges: (i0, j1), (i1, j1), (i1, j0), (i0, j0),
// textureGather's order. Compute passes gather them in one instruction; fragment passes
// load them one by one, since ESSL 3.00 has no textureGather (the values are the same).
vec4 ao_depth_quad(ivec2 i0)
{
    ivec2 last = ao_depth_size() - 1;
#if defined(AO_STAGE_COMPUTE)
    // The texels' shared corner, in uv; clamp-to-edge repeats the border texels past it.
    return textureGather(u_depth, vec2(i0 + 1) / vec2(last + 1), 0);
#else
    ivec2 c0 = clamp(i0, ivec2(0), last), c1 = clamp(i0 + 1, ivec2(0), last);
    return vec4(ao_load_depth(ivec2(c0.x, c1.y)), ao_load_depth(c1), ao_load_depth(ivec2(c1.x, c0.y)), ao_load_depth(c0));
#endif
}

// The plane test of four raw depths of a 2 x 2 block (d00, d10 the first row): x, how far
// their diagonals' sums differ; y, the threshold past which they lie off one plane (a quarter
// of their spread, with a few ulps of slack for the rounding of depths near 1); z, the spread.
vec3 ao_depth_planarity(float d00, float d10, float d01, float d11)
{
    float spread = abs(d10 - d00) + abs(d01 - d00) + abs(d11 - d00);
    float planarity = abs(d00 + d11 - d10 - d01);
    return vec3(planarity, 0.25 * spread + 2.5e-7 * abs(d00), spread);
}

// Do four raw depths of a 2 x 2 block (d00, d10 the first row) lie off one plane? On a plane
// their diagonals' sums agree: raw depth is affine on screen over a plane (ao_depth_at). Off
// it when the sums differ by more than a quarter of the block's spread (a silhouette), with a
// few ulps of slack for the rounding of depths near 1.
bool ao_depth_off_plane(float d00, float d10, float d01, float d11)
{
    vec3 test = ao_depth_planarity(d00, d10, d01, d11);
    return test.x > test.y;
}

// Of two raw depths (neither background), the one nearer the camera.
float ao_depth_nearer(float a, float b)
{
#if defined(AO_DEPTH_STANDARD)
    return min(a, b);
#else
    return max(a, b);
#endif
}

#if defined(AO_MIP_LEVELS)
// THE DEPTH MIP CHAIN (aogen/depth_mips.hpp; prefilter.glsl builds it): level L of the depth
// buffer has ceil(size / 2^L) texels, each standing for 2^L x 2^L pixels; levels 1 ..
// AO_MIP_LEVELS - 1 lie in one atlas, level 1 at (0, 0), level L >= 2 beside it at (the width
// of level 1, the heights of levels 2 .. L - 1).

// Level `level`'s size in texels (at least 1 x 1): ceil(size / 2^level), as a shift (an
// integer division by a variable costs a GPU twenty instructions; a tap pays this per sample).
ivec2 ao_mip_size(int level)
{
    return max((ao_depth_size() + ((1 << level) - 1)) >> level, ivec2(1));
}

// 2^e for a small integer e, exactly (the float's exponent field; exp2 need not be exact).
float ao_exp2i(int e)
{
    return uintBitsToFloat(uint(127 + e) << 23);
}

// Where level `level` >= 1 starts in the atlas.
ivec2 ao_mip_origin(int level)
{
    if (level <= 1) return ivec2(0);
    int y = 0;
    for (int k = 2; k < level; ++k) y += ao_mip_size(k).y;
    return ivec2(ao_mip_size(1).x, y);
}
#endif

#if defined(AO_MIP_LEVELS) && defined(AO_PASS_AO)
// u_depth_mips: declared by aogen::codegen (aogen/bindings.hpp): the atlas.

// The level a tap `offset` full-resolution pixels from the pixel reads (depth_mips.hpp's
// level_for): texels about 1 / 2^AO_MIP_LEVEL_OFFSET of its distance apart.
int ao_mip_level(float offset)
{
    return clamp(int(floor(log2(max(offset, 1.0)) - AO_MIP_LEVEL_OFFSET)), 0, AO_MIP_LEVELS - 1);
}

// ao_depth_quad at level `level` >= 1: texels i0 .. i0 + 1 of that level, clamped to it, in
// textureGather's order. One gather inside the level; four loads where the quad crosses its
// edge (a gather there would read the next level's texels in the atlas). The values are the
// same either way.
vec4 ao_mip_quad(ivec2 i0, int level)
{
    ivec2 last = ao_mip_size(level) - 1, origin = ao_mip_origin(level);
    if (all(greaterThanEqual(i0, ivec2(0))) && all(lessThan(i0, last)))
        return textureGather(u_depth_mips, vec2(origin + i0 + 1) / vec2(textureSize(u_depth_mips, 0)), 0);
    ivec2 c0 = origin + clamp(i0, ivec2(0), last), c1 = origin + clamp(i0 + 1, ivec2(0), last);
    return vec4(texelFetch(u_depth_mips, ivec2(c0.x, c1.y), 0).r, texelFetch(u_depth_mips, c1, 0).r, texelFetch(u_depth_mips, ivec2(c1.x, c0.y), 0).r,
                texelFetch(u_depth_mips, c0, 0).r);
}
#endif

// Screen position `pos` (full-resolution pixels) in level `level`'s texels, measured from the
// first texel's centre: its floor is the first of the four texels whose centres surround pos,
// its fraction pos's place between their centres.
vec2 ao_depth_quad_coords(vec2 pos, int level)
{
#if defined(AO_MIP_LEVELS) && defined(AO_PASS_AO)
    return pos * ao_exp2i(-level) - 0.5; // exact: a power of two
#else
    return pos - 0.5;
#endif
}

// The depths of level `level`'s texels i0 .. i0 + 1 (ao_depth_quad at level 0, ao_mip_quad
// above it), clamped to the level, in textureGather's order.
vec4 ao_depth_quad_at(ivec2 i0, int level)
{
#if defined(AO_MIP_LEVELS) && defined(AO_PASS_AO)
    if (level == 0) return ao_depth_quad(i0); // a branch, not a select: one of the two reads per tap
    return ao_mip_quad(i0, level);
#else
    return ao_depth_quad(i0);
#endif
}

// The four texels of level `level` whose centres surround screen position `pos` (full-
// resolution pixels), in textureGather's order; `f`, pos's place between their centres; and
// pos's own texel among them (the one whose centre is within half a texel): its depth, its
// centre `at` in full-resolution pixels and `nearest`, the full-resolution pixel under it.
vec4 ao_depth_around(vec2 pos, int level, out vec2 f, out float own_depth, out vec2 at, out ivec2 nearest)
{
    ivec2 size = ao_depth_size();
#if defined(AO_MIP_LEVELS) && defined(AO_PASS_AO)
    float texel = ao_exp2i(level); // a level-`level` texel's side in pixels
    ivec2 level_size = level == 0 ? size : ao_mip_size(level);
#else
    ivec2 level_size = size;
#endif
    vec2 t = ao_depth_quad_coords(pos, level);
    ivec2 i0 = ivec2(floor(t));
    f = t - floor(t);
    vec4 g = ao_depth_quad_at(i0, level);
    float d00 = g.w, d10 = g.z, d01 = g.x, d11 = g.y;
    ivec2 own = clamp(i0 + ivec2(greaterThanEqual(f, vec2(0.5))), ivec2(0), level_size - 1);
    own_depth = f.y >= 0.5 ? (f.x >= 0.5 ? d11 : d01) : (f.x >= 0.5 ? d10 : d00);
#if defined(AO_MIP_LEVELS) && defined(AO_PASS_AO)
    at = (vec2(own) + 0.5) * texel;
    nearest = level == 0 ? own : clamp(ivec2(floor(at)), ivec2(0), size - 1);
#else
    // Without a chain, exactly the arithmetic of before it: a tap is ALU-bound, and the
    // conversions above cost every variant 5-7 % on the H200 (BENCHMARKS.md, 2026-12-03).
    at = vec2(own) + 0.5;
    nearest = own;
#endif
    return g;
}

// The bilinear mix of four depths `g` (textureGather's order) at `f` between their centres.
float ao_depth_bilinear(vec4 g, vec2 f)
{
    return ao_lerp(ao_lerp(g.w, g.z, f.x), ao_lerp(g.x, g.y, f.x), f.y);
}

// ao_depth_at's decision, from what ao_depth_around read around `pos` -- the four texels `g`,
// pos's place `f` between their centres, and pos's own texel's `depth` at its centre `at` --
// for a caller that reads first and decides after (common/slices.glsl's ao_slice_tap_surface):
// the plane's depth under pos itself (at = pos) between four texels of one plane, else the own
// texel's as read; false on background.
bool ao_depth_at_quad(vec4 g, vec2 f, vec2 pos, inout float depth, inout vec2 at)
{
    if (ao_is_background(depth)) return false;
    if (any(ao_is_background(g))) return true;
    if (ao_depth_off_plane(g.w, g.z, g.x, g.y)) return true; // not one plane (d00, d10, d01, d11)
    depth = ao_depth_bilinear(g, f);
    at = pos;
    return true;
}

// The raw depth of the surface a sample at screen position `pos` (full-resolution pixels,
// centres at +0.5) lands on, and `at`, the screen position that depth belongs to; false on
// background. `nearest` gets pos's texel.
//
// Between four texels of one plane it is the plane's depth under pos itself (at = pos): raw
// depth is affine in screen space over a plane in every convention (standard and reversed
// depth are affine in 1/z, and 1/z is affine over a plane on screen; orthographic depth is
// affine in z), so the bilinear mix of the four is exact. That matters where depth changes
// fast from texel to texel -- a floor seen at a grazing angle, a wide lens's edges, a screen
// a few pixels tall: a texel's own depth taken at a point up to half a texel away lies above
// the floor, and samples read such points as occluders (distant floors banded dark, a 175
// degree view's open floor at 0.92 under GTAO, a 256x8 view's open floor at 0.6 under SSAO).
// Where the four do not lie on one plane (a silhouette: their diagonals' sums differ by more
// than a quarter of their spread), or one is background, it is the nearest texel's own depth
// at its centre (at = the centre): a real surface point, where that depth at pos would be a
// point on no surface -- on a face seen edge-on, one texel wide, such a point sat in front of
// the face and read as an occluder.
//
// With a depth MIP chain (AO_MIP_LEVELS) the same holds at every level: `level` (ao_mip_level
// of the tap's distance) picks the level whose four texels around pos are read, `at` at a
// silhouette is that level's texel's centre, and `nearest` the full-resolution pixel under it.
// Level 0 is the depth buffer, read as without a chain.
bool ao_depth_at(vec2 pos, int level, out float depth, out vec2 at, out ivec2 nearest)
{
    vec2 f;
    vec4 g = ao_depth_around(pos, level, f, depth, at, nearest);
    return ao_depth_at_quad(g, f, pos, depth, at);
}

#if defined(AO_DEPTH_PLANE_BAND)
// How far the four depths `g` (textureGather's order, none background) lie on one plane: 1
// up to ao_depth_off_plane's threshold, falling linearly to 0 over AO_DEPTH_PLANE_BAND of
// their spread past it. Continuous in every depth (four alike: 1, with no 0 / 0).
float ao_depth_plane_weight(vec4 g)
{
    vec3 test = ao_depth_planarity(g.w, g.z, g.x, g.y);
    return clamp(1.0 - (test.x - test.y) / max(AO_DEPTH_PLANE_BAND * test.z, 1e-30), 0.0, 1.0);
}

// ao_depth_at's two readings of the surface under `pos`, for a caller that blends them
// rather than switching between them (ssao.glsl's smooth decisions): the texel reading,
// pos's own texel's depth `texel_depth` at its centre `texel_at`; the plane reading, the
// depth `plane_depth` of the plane under pos itself; `plane_weight`, how far to trust the
// plane reading (ao_depth_plane_weight; 0 where it cannot be made); and `surface`, how surely
// a surface is under pos at all. False when pos's own texel is background.
//
// Between four surface texels the plane is their bilinear mix (ao_depth_at says why it is
// exact), and surface is 1. Beside background -- a floor's last row under the sky, an object's
// outline -- the plane is extended from the side away from the background: the two texels
// along it and the two behind them, mixed linearly past their centres (exact for a plane as
// the mix is). Without it only the texel reading is left, the last row's centre depth, which
// lies in front of every sample above the row beside the pixel: a floor whose truth is 1
// read 175/255 along its far edge, and a floor cut by the far plane (standard depth) read up
// to 0.5 darker along the cut than the same floor running on (reversed-infinite depth).
// Where the surface ends between the last centre and the background is unknown: surface
// falls from 1 at the texel's centre to 0 at its edge toward the background, where the
// sample meets background and counts as open.
bool ao_depth_readings(vec2 pos, int level, out float texel_depth, out vec2 texel_at, out float plane_depth, out float plane_weight,
                       out float surface)
{
    vec2 f;
    ivec2 nearest;
    vec4 g = ao_depth_around(pos, level, f, texel_depth, texel_at, nearest);
    plane_depth = texel_depth;
    plane_weight = 0.0;
    surface = 0.0;
    if (ao_is_background(texel_depth)) return false;
    bvec4 gap = ao_is_background(g);
    if (!any(gap)) {
        surface = 1.0;
        plane_weight = ao_depth_plane_weight(g);
        if (plane_weight > 0.0) plane_depth = ao_depth_bilinear(g, f);
        return true;
    }
    // The bilinear share of the four that is surface: 1 at the own texel's centre, 1/2 at its
    // edge toward a background texel; doubled past 1/2 to reach 0 at that edge.
    vec4 bilinear = vec4((1.0 - f.x) * f.y, f.x * f.y, f.x * (1.0 - f.y), (1.0 - f.x) * (1.0 - f.y));
    surface = clamp(2.0 * dot(vec4(not(gap)), bilinear) - 1.0, 0.0, 1.0);
    // A row or column of the four that is all surface, and the quad one texel beyond it
    // (g's order: x = (i0, j1), y = (i1, j1), z = (i1, j0), w = (i0, j0)).
    ivec2 step;
    if (!gap.w && !gap.z) step = ivec2(0, -1);      // row j0: extended from rows j0 - 1, j0
    else if (!gap.x && !gap.y) step = ivec2(0, 1);  // row j1: from j1, j1 + 1
    else if (!gap.w && !gap.x) step = ivec2(-1, 0); // column i0
    else if (!gap.z && !gap.y) step = ivec2(1, 0);  // column i1
    else return true;                                 // one texel of surface: its centre only
    vec4 h = ao_depth_quad_at(ivec2(floor(ao_depth_quad_coords(pos, level))) + step, level);
    if (any(ao_is_background(h))) return true;
    plane_weight = ao_depth_plane_weight(h);
    if (plane_weight > 0.0) plane_depth = ao_depth_bilinear(h, f - vec2(step)); // past h's centres, along `step`
    return true;
}
#endif

// The surface point of the texel under screen position `pos` (full-resolution pixels): its
// own depth at its centre (at, and nearest, the texel); false on background. One fetch, no
// plane test: a true surface point, but up to 0.71 pixels from pos (common/slices.glsl's
// ao_slice_tap_surface says where that is good enough; fragment passes read far taps so).
bool ao_depth_texel(vec2 pos, out float depth, out vec2 at, out ivec2 nearest)
{
    nearest = clamp(ivec2(floor(pos)), ivec2(0), ao_depth_size() - 1);
    depth = ao_load_depth(nearest);
    at = vec2(nearest) + 0.5;
    return !ao_is_background(depth);
}

// How much of a tap at screen position `pos` (full-resolution pixels) the screen shows, for
// the passes whose taps fade at the border rather than stop there (ssao.glsl's smooth
// decisions, sao.glsl): 1 inside, falling to 0 over the last `band` pixels before the border;
// 0 past it and for a NaN position.
float ao_screen_edge_weight(vec2 pos, vec2 fsize, float band)
{
    vec2 inside = min(pos, fsize - pos);
    float d = min(inside.x, inside.y);
    return d > 0.0 ? min(d / band, 1.0) : 0.0;
}

// How much a tap at screen position `pos` counts against full-resolution pixel `p`'s own
// surface: 0 anywhere in p's own texel (a comparison of the surface with its own depth, which
// can only measure how the depth was quantized or clamped at the screen's edge), 1 from `band`
// pixels past the texel's edge on (in the larger of x and y).
float ao_own_texel_weight(vec2 pos, ivec2 p, float band)
{
    vec2 off = abs(pos - (vec2(p) + 0.5));
    return clamp((max(off.x, off.y) - 0.5) / band, 0.0, 1.0);
}

// The level a tap `offset` full-resolution pixels from the pixel reads: ao_mip_level with a
// depth MIP chain, 0 (the depth buffer) without one.
int ao_tap_level(float offset)
{
#if defined(AO_MIP_LEVELS) && defined(AO_PASS_AO)
    return ao_mip_level(offset);
#else
    return 0;
#endif
}

#if defined(AO_SLICE_TEXEL_CENTRE_PIXELS)
// Does a slice tap `distance` pixels from its pixel read its texel at the centre
// (ao_depth_texel's point) rather than ao_depth_at? From AO_SLICE_TEXEL_CENTRE_PIXELS on, unless a
// depth MIP chain gives it a coarser level (common/slices.glsl's ao_slice_tap_surface says why).
bool ao_slice_tap_reads_texel(float distance)
{
    return ao_tap_level(distance) == 0 && distance >= AO_SLICE_TEXEL_CENTRE_PIXELS;
}
#endif

// ao_depth_at at level 0: the depth buffer itself.
bool ao_depth_at(vec2 pos, out float depth, out vec2 at, out ivec2 nearest)
{
    return ao_depth_at(pos, 0, depth, at, nearest);
}
