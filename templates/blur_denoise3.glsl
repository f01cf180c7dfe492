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
//   One invocation filters a 2 x 2 quad of pixels (AO_PASS_WRITES_QUADS: dispatched over half
//   the target, rounded up; aogen::pixels_per_invocation), as XeGTAO's denoiser does two: the
//   quads' 4 x 4 windows overlap, so a quad reads 16 texels where four lone pixels read 36,
//   and what an invocation pays once (its place, the tile's barrier, the store's address) is
//   paid per four pixels. The workgroup loads the (2 AO_WORKGROUP_X + 2) x (2 AO_WORKGROUP_Y
//   + 2) texels its quads cover into shared memory once (AO_PASS_LOADS_TILE), each packed into
//   one 32-bit word (ao_denoise3_tap): 18^2 / 256 = 1.27 texel fetches per pixel of an 8 x 8
//   group, no depth, no exp, no loop; then per pixel 8 taps and 12 edges in straight-line
//   code (ao_denoise3_at). A 32 x 32 group's tile (66^2 words, 17,424 bytes) is more shared
//   memory than Vulkan guarantees (16,384): aogen::validate refuses it.

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

// What the filter reads of target pixel q, packed in one word: the AO, made finite and in [0,
// 1], as a 16-bit unorm in bits 0..15 (packUnorm2x16), the edges to the right and below as
// 8-bit unorms in bits 16..23 and 24..31 (packUnorm4x8's third and fourth); zero off the
// target (its neighbours' edges to it are 0 already), and a NaN edge reads 0, cutting the
// path. From the AO pass's rgba8 texel (the default) nothing is lost: an 8-bit k / 255 is the
// 16-bit 257 k / 65535, and the edges were 8-bit. From an rgba16f texel the AO moves by at
// most 1 / 131070 (fp16 itself is 1 / 2048 apart below 1) and the edges are rounded to the
// 8 bits the rgba8 texel holds.
uint ao_denoise3_tap(ivec2 q)
{
    ivec2 size = max(textureSize(u_ao_input, 0), ivec2(1));
    if (q.x < 0 || q.y < 0 || q.x >= size.x || q.y >= size.y) return 0u;
    vec3 t = texelFetch(u_ao_input, q, 0).rgb;
    vec2 e = mix(vec2(0.0), t.gb, bvec2(ao_is_finite(t.g), ao_is_finite(t.b)));
    return (packUnorm2x16(vec2(ao_finalize(t.r), 0.0)) & 0xffffu) | (packUnorm4x8(vec4(0.0, 0.0, e)) & 0xffff0000u);
}

#define AO_PASS_WRITES_QUADS
#define AO_PASS_LOADS_TILE
#define AO_TILE_WIDTH (2 * AO_WORKGROUP_X + 2)
#define AO_TILE_HEIGHT (2 * AO_WORKGROUP_Y + 2)
shared uint ao_tile[AO_TILE_WIDTH * AO_TILE_HEIGHT];

// The target pixel the tile's texel (0, 0) holds: the workgroup's first quad's first pixel
// - (1, 1).
ivec2 ao_tile_origin()
{
    return ivec2(gl_WorkGroupID.xy) * ivec2(2 * AO_WORKGROUP_X, 2 * AO_WORKGROUP_Y) - ivec2(1);
}

// Every invocation of the group loads its share of the tile, then waits for the others.
void ao_load_tile()
{
    ivec2 origin = ao_tile_origin();
    for (int i = int(gl_LocalInvocationIndex); i < AO_TILE_WIDTH * AO_TILE_HEIGHT; i += AO_WORKGROUP_X * AO_WORKGROUP_Y)
        ao_tile[i] = ao_denoise3_tap(origin + ivec2(i % AO_TILE_WIDTH, i / AO_TILE_WIDTH));
    barrier();
}

// The tile's texel (x, y), unpacked: (ao, e right, e lower).
vec3 ao_denoise3_read(int x, int y)
{
    uint word = ao_tile[y * AO_TILE_WIDTH + x];
    return vec3(unpackUnorm2x16(word).x, unpackUnorm4x8(word).zw);
}

// THE FILTER at one pixel c from its 3 x 3 neighbourhood (u: the row above, d: below; l, r:
// left, right), each texel (ao, e right, e lower). The edge from c to a side neighbour is the
// right or lower edge of whichever of the two is left of or above the other; a diagonal's two
// paths each cross one of c's side edges and one edge of the side neighbour or the diagonal
// texel itself -- for d r: (c -> r -> dr) r's lower edge, (c -> d -> dr) d's right edge; for
// d l: l's lower edge, dl's right edge; for u r: ur's lower edge, u's right edge; for u l:
// ul's lower and right edges.
float ao_denoise3_at(vec3 ul, vec3 u, vec3 ur, vec3 l, vec3 c, vec3 r, vec3 dl, vec3 d, vec3 dr)
{
    const float centre = AO_DENOISE3_WEIGHT_0 * AO_DENOISE3_WEIGHT_0;
    const float side = AO_DENOISE3_WEIGHT_0 * AO_DENOISE3_WEIGHT_1;
    const float diagonal = AO_DENOISE3_WEIGHT_1 * AO_DENOISE3_WEIGHT_1;
    float e_l = l.y, e_r = c.y, e_u = u.z, e_d = c.z;
    vec4 sides = side * vec4(e_l, e_r, e_u, e_d);
    vec4 corners = diagonal * 0.5 * vec4(e_l * ul.z + e_u * ul.y, e_r * ur.z + e_u * u.y, e_l * l.z + e_d * dl.y, e_r * r.z + e_d * d.y);
    float sum = centre * c.x + dot(sides, vec4(l.x, r.x, u.x, d.x)) + dot(corners, vec4(ul.x, ur.x, dl.x, dr.x));
    float weight = centre + dot(sides, vec4(1.0)) + dot(corners, vec4(1.0));
    return sum / weight;
}

// The quad of target pixels 2 q .. 2 q + 1 (entry_compute.glsl's order: (0, 0), (1, 0), (0,
// 1), (1, 1)), from the 4 x 4 texels of the tile around it -- rows a .. d, columns 0 .. 3,
// the quad at b1, b2, c1, c2 -- read once each, in straight-line code (no array: an indexed
// local array can live in memory rather than registers).
ao_value4 ao_pass_quad(ivec2 q)
{
    ivec2 o = 2 * ivec2(gl_LocalInvocationID.xy); // a0's place in the tile
    vec3 a0 = ao_denoise3_read(o.x, o.y), a1 = ao_denoise3_read(o.x + 1, o.y);
    vec3 a2 = ao_denoise3_read(o.x + 2, o.y), a3 = ao_denoise3_read(o.x + 3, o.y);
    vec3 b0 = ao_denoise3_read(o.x, o.y + 1), b1 = ao_denoise3_read(o.x + 1, o.y + 1);
    vec3 b2 = ao_denoise3_read(o.x + 2, o.y + 1), b3 = ao_denoise3_read(o.x + 3, o.y + 1);
    vec3 c0 = ao_denoise3_read(o.x, o.y + 2), c1 = ao_denoise3_read(o.x + 1, o.y + 2);
    vec3 c2 = ao_denoise3_read(o.x + 2, o.y + 2), c3 = ao_denoise3_read(o.x + 3, o.y + 2);
    vec3 d0 = ao_denoise3_read(o.x, o.y + 3), d1 = ao_denoise3_read(o.x + 1, o.y + 3);
    vec3 d2 = ao_denoise3_read(o.x + 2, o.y + 3), d3 = ao_denoise3_read(o.x + 3, o.y + 3);
    return ao_quad_of(vec4(ao_denoise3_at(a0, a1, a2, b0, b1, b2, c0, c1, c2),   // b1
                           ao_denoise3_at(a1, a2, a3, b1, b2, b3, c1, c2, c3),   // b2
                           ao_denoise3_at(b0, b1, b2, c0, c1, c2, d0, d1, d2),   // c1
                           ao_denoise3_at(b1, b2, b3, c1, c2, c3, d1, d2, d3))); // c2
}
