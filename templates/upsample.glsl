// upsample.glsl -- the depth-aware (joint bilateral) upsample of a half-resolution AO
// target to the screen's resolution: the last pass of a half-resolution variant with
// upsample_mode::depth_aware. Uniform block: BlurUniforms (u.inv_proj, u.linear_sharpness).
//
// Bindings: AO_BINDING_DEPTH the full-resolution depth, AO_BINDING_AO_INPUT the AO target
// (half resolution, its value in .r). Unlike every other pass, its output is the screen's
// size: fragment passes run per screen pixel, compute passes per target texel, each
// invocation writing the 2 x 2 screen pixels the texel covers (see ao_pass_quad).
//
// THE WEIGHTS
//   Target texel q stands for screen pixel 2q (depth.glsl: it read its depth and normal
//   there), so a screen pixel P lies a fraction f = (P - 2 q0) / 2, 0 or 1/2 on each axis,
//   of the way from q0 = P / 2 to q0 + 1. Each of those four texels q counts with
//       b(q) * exp(-|z(q) - z(P)| * u.linear_sharpness)
//   b the bilinear weight for f, z the view-space depth (of 2q and of P): a plain bilinear
//   upsample where the surface is continuous, and no blending across a silhouette, where
//   the texel on the other surface gets a weight of ~0. Where every weight underflows (a
//   pixel of a thin feature the target did not sample, a steep floor far away), P takes the
//   texel nearest to it in depth. Pixels at 2q (f = 0) get texel q's value unchanged, as
//   nearest upsampling would. Background pixels write exactly 1; a pixel with no
//   foreground texel around it keeps q0's value.

#if !defined(AO_PASS_UPSAMPLE)
#error aogen: upsample.glsl is the upsample pass
#endif
#if !defined(AO_HALF_RESOLUTION)
#error aogen: upsample.glsl upsamples a half-resolution AO target
#endif
#if !defined(AO_BINDING_AO_INPUT)
#error aogen: AO_BINDING_AO_INPUT is not defined (codegen writes the bindings)
#endif

// u_ao_input: declared by aogen::codegen (aogen/bindings.hpp).

// Target texel q as a candidate for the screen pixels around it: (ao, z, counts) -- the AO of q
// clamped to the target (finite, in [0, 1]), the view z of the full-resolution pixel it
// stands for, and 1 when it counts (inside the target, on a surface, with a finite z), else 0.
vec3 ao_upsample_candidate(ivec2 q)
{
    ivec2 size = max(textureSize(u_ao_input, 0), ivec2(1));
    bool inside = q.x < size.x && q.y < size.y;
    ivec2 qc = min(q, size - 1);
    float ao = ao_finalize(texelFetch(u_ao_input, qc, 0).r);
    ivec2 q_full = ao_full_pixel(qc);
    float q_depth = ao_load_depth(q_full);
    float z = ao_is_background(q_depth) ? 0.0 : ao_pixel_view_z(q_full, q_depth);
    bool counts = inside && !ao_is_background(q_depth) && ao_is_finite(z);
    return vec3(ao, z, counts ? 1.0 : 0.0);
}

// The bent normal of target texel q, clamped to the target as above (a -bn variant's: common/
// core.glsl's ao_value; zero without bent normals).
vec3 ao_upsample_candidate_bent(ivec2 q)
{
    ivec2 size = max(textureSize(u_ao_input, 0), ivec2(1));
    return ao_value_bent(ao_read_input(min(q, size - 1)));
}

#if defined(AO_STAGE_COMPUTE)
// Compute passes: one invocation per target texel q0, writing the 2 x 2 screen pixels it
// covers (entry_compute.glsl: AO_PASS_WRITES_QUADS; dispatch over the target's size). The
// candidates q0 .. q0 + (1, 1) of the group's invocations form a (AO_WORKGROUP_X + 1) x
// (AO_WORKGROUP_Y + 1) tile, loaded once into shared memory (AO_PASS_LOADS_TILE: every
// invocation calls ao_load_tile first); an invocation then reads its four candidates there and
// gathers its own four depths -- about 3.5 fetches per 4 pixels, each input texel read about
// once, where each invocation used to fetch its candidates itself (6 per 4 pixels, every
// candidate's depth fetched and converted by four invocations).
#define AO_PASS_WRITES_QUADS
#define AO_PASS_LOADS_TILE
#define AO_TILE_WIDTH (AO_WORKGROUP_X + 1)
#define AO_TILE_HEIGHT (AO_WORKGROUP_Y + 1)
shared vec3 ao_tile[AO_TILE_WIDTH * AO_TILE_HEIGHT];
#if defined(AO_BENT_NORMALS)
shared vec3 ao_tile_bent[AO_TILE_WIDTH * AO_TILE_HEIGHT]; // their bent normals
#endif

// The target texel the tile's (0, 0) holds: the group's first invocation's.
ivec2 ao_tile_origin()
{
    return ivec2(gl_WorkGroupID.xy) * ivec2(AO_WORKGROUP_X, AO_WORKGROUP_Y);
}

// Every invocation of the group loads its share of the tile, then waits for the others.
void ao_load_tile()
{
    ivec2 origin = ao_tile_origin();
    for (int i = int(gl_LocalInvocationIndex); i < AO_TILE_WIDTH * AO_TILE_HEIGHT; i += AO_WORKGROUP_X * AO_WORKGROUP_Y) {
        ivec2 q = origin + ivec2(i % AO_TILE_WIDTH, i / AO_TILE_WIDTH);
        ao_tile[i] = ao_upsample_candidate(q);
#if defined(AO_BENT_NORMALS)
        ao_tile_bent[i] = ao_upsample_candidate_bent(q);
#endif
    }
    barrier();
}

// Where candidate q, inside this group's tile, is in it.
int ao_tile_index(ivec2 q)
{
    ivec2 t = q - ao_tile_origin();
    return t.y * AO_TILE_WIDTH + t.x;
}

// Candidate q, inside this group's tile, and its bent normal.
vec3 ao_upsample_read(ivec2 q) { return ao_tile[ao_tile_index(q)]; }
#if defined(AO_BENT_NORMALS)
vec3 ao_upsample_read_bent(ivec2 q) { return ao_tile_bent[ao_tile_index(q)]; }
#else
vec3 ao_upsample_read_bent(ivec2 q) { return vec3(0.0); }
#endif
#else
vec3 ao_upsample_read(ivec2 q)
{
    return ao_upsample_candidate(q);
}

vec3 ao_upsample_read_bent(ivec2 q)
{
    return ao_upsample_candidate_bent(q);
}
#endif

// The four target texels around screen pixel 2 q0 .. 2 q0 + 1, in the order q0, q0 + (1, 0),
// q0 + (0, 1), q0 + (1, 1): their AO (with bent normals, AO and normal: common/core.glsl's
// ao_value), their view z, and whether each counts.
struct ao_candidates {
    ao_value4 value;
    vec4 z;
    bvec4 valid;
};

ao_candidates ao_upsample_candidates(ivec2 q0)
{
    ao_candidates c;
    for (int k = 0; k < 4; ++k) {
        ivec2 q = q0 + ivec2(k & 1, k >> 1);
        vec3 candidate = ao_upsample_read(q);
        c.value[k] = ao_make_value(candidate.x, ao_upsample_read_bent(q));
        c.z[k] = candidate.y;
        c.valid[k] = candidate.z > 0.0;
    }
    return c;
}

// The upsampled AO of screen pixel P, with raw depth `depth` (not background), from the
// candidates around it (q0 = P / 2): the weights of the header, the nearest texel in depth
// where they all underflow, q0's value where no candidate counts.
ao_value ao_upsample_blend(ivec2 P, float depth, ivec2 q0, ao_candidates c)
{
    float z = ao_pixel_view_z(P, depth);
    if (!ao_is_finite(z)) return c.value[0];
    vec2 f = vec2(P - 2 * q0) * 0.5;
    vec4 bilinear = vec4((1.0 - f.x) * (1.0 - f.y), f.x * (1.0 - f.y), (1.0 - f.x) * f.y, f.x * f.y);
    ao_value sum = ao_value(0.0);
    float weight_sum = 0.0;
    ao_value nearest = c.value[0];
    float nearest_dz = -1.0; // none yet
    for (int k = 0; k < 4; ++k) {
        if (!c.valid[k]) continue;
        float dz = abs(c.z[k] - z);
        if (!ao_is_finite(dz)) continue;
        if (nearest_dz < 0.0 || dz < nearest_dz) {
            nearest_dz = dz;
            nearest = c.value[k];
        }
        if (!(bilinear[k] > 0.0)) continue; // off the footprint: no exp to pay for
        float w = bilinear[k] * exp(-dz * u.linear_sharpness);
        if (!(w > 0.0)) continue; // underflowed
        sum += w * c.value[k];
        weight_sum += w;
    }
    return weight_sum > 0.0 ? sum / weight_sum : nearest;
}

#if defined(AO_STAGE_COMPUTE)
// The screen pixels 2 q0 + (0, 0), (1, 0), (0, 1), (1, 1), in that order.
ao_value4 ao_pass_quad(ivec2 q0)
{
    vec4 g = ao_depth_quad(2 * q0); // textureGather's order: (0, 1), (1, 1), (1, 0), (0, 0)
    vec4 depth = vec4(g.w, g.z, g.x, g.y);
    if (all(ao_is_background(depth)))
        return ao_quad_of(vec4(1.0));
    ivec2 last = ao_depth_size() - 1;
    ao_candidates c = ao_upsample_candidates(q0);
    ao_value4 ao;
    for (int k = 0; k < 4; ++k) {
        ivec2 P = min(2 * q0 + ivec2(k & 1, k >> 1), last);
        ao[k] = ao_is_background(depth[k]) ? ao_open_value() : ao_upsample_blend(P, depth[k], q0, c);
    }
    return ao;
}
#else
// Fragment passes: one fragment per screen pixel.
ao_value ao_pass(ivec2 pixel)
{
    ivec2 P = clamp(pixel, ivec2(0), ao_depth_size() - 1);
    float depth = ao_load_depth(P);
    if (ao_is_background(depth)) return ao_open_value();
    ivec2 size = max(textureSize(u_ao_input, 0), ivec2(1));
    ivec2 q0 = clamp(P / 2, ivec2(0), size - 1);
    return ao_upsample_blend(P, depth, q0, ao_upsample_candidates(q0));
}
#endif
