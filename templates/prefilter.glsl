// prefilter.glsl -- the depth MIP chain (aogen/depth_mips.hpp): levels 1 .. AO_MIP_LEVELS - 1
// of the depth buffer, written to one r32f atlas (u_output) in one dispatch, before the AO
// pass, whose far taps read them (common/depth.glsl's ao_depth_at). Uniform block:
// BlurUniforms (not read: every pass has a block). Level 0 is the depth buffer itself.
//
// Bindings: AO_BINDING_DEPTH the full-resolution depth, AO_BINDING_OUTPUT the atlas (its size
// aogen::depth_mips::atlas_size; level L at ao_mip_origin(L), ao_mip_size(L) texels).
//
// ONE TEXEL FROM FOUR
//   A texel of level L holds, for its four texels of level L - 1 (d00, d10, d01, d11):
//     - their mean, when the four lie on one plane (ao_depth_off_plane, the test ao_depth_at
//       makes): raw depth is affine in screen space over a plane, so the mean is the plane's
//       depth at the texel's centre, and the bilinear mix of four level-L texels stays the
//       plane's depth under any tap, as at level 0;
//     - the one nearest the camera, when they are not one plane or some are background (a
//       silhouette): a real surface point -- a mean there would be a point between two
//       surfaces, in front of the far one, which taps would read as an occluder; the nearer
//       surface is the one that occludes;
//     - background (1 for standard depth, 0 for the reversed conventions) when all four are.
//   A level's last row and column, where the level before has an odd size, take the texel
//   past its edge as the edge texel itself (clamp to edge, as every read of the chain does).
//
// THE DISPATCH
//   Workgroups of 8 x 8 (aogen::depth_mips::workgroup_side), one per 16 x 16 block of the
//   depth buffer: each invocation reduces a 2 x 2 block to one texel of level 1 (one gather),
//   keeps it in shared memory, and the group's first 4 x 4, 2 x 2 and 1 invocations reduce
//   those to levels 2, 3 and 4, a barrier between levels. Dispatch ceil(width / 16) x
//   ceil(height / 16) groups. Every depth texel is read once and every atlas texel written
//   once: the pass is a copy of a third of the depth buffer's size.

#if !defined(AO_PASS_PREFILTER) || !defined(AO_STAGE_COMPUTE)
#error aogen: prefilter.glsl is the prefilter pass, a compute shader
#endif
#if !defined(AO_MIP_LEVELS) || AO_MIP_LEVELS < 2 || AO_MIP_LEVELS > 5
#error aogen: prefilter.glsl builds 2 to 5 levels (AO_MIP_LEVELS)
#endif
#if AO_WORKGROUP_X != 8 || AO_WORKGROUP_Y != 8
#error aogen: prefilter.glsl reduces 16 x 16 blocks in 8 x 8 workgroups
#endif

layout(local_size_x = 8, local_size_y = 8, local_size_z = 1) in;

// u_output: declared by aogen::codegen (aogen/bindings.hpp).

// The cleared depth of the variant's convention (common/depth.glsl's ao_is_background).
float ao_background_depth()
{
#if defined(AO_DEPTH_STANDARD)
    return 1.0;
#else
    return 0.0;
#endif
}

// One texel of the next level from four of this one (ONE TEXEL FROM FOUR).
float ao_mip_reduce(float d00, float d10, float d01, float d11)
{
    bool b00 = ao_is_background(d00), b10 = ao_is_background(d10), b01 = ao_is_background(d01), b11 = ao_is_background(d11);
    if (b00 && b10 && b01 && b11) return ao_background_depth();
    if (!(b00 || b10 || b01 || b11) && !ao_depth_off_plane(d00, d10, d01, d11)) return 0.25 * ((d00 + d10) + (d01 + d11));
    float nearest = b00 ? (b10 ? (b01 ? d11 : d01) : d10) : d00; // one that is not background
    if (!b10) nearest = ao_depth_nearer(nearest, d10);
    if (!b01) nearest = ao_depth_nearer(nearest, d01);
    if (!b11) nearest = ao_depth_nearer(nearest, d11);
    return nearest;
}

// The texels of levels 1, 2 and 3 this group made, for the level after.
shared float ao_level1[64];
shared float ao_level2[16];
shared float ao_level3[4];

// Texel `t` of level `level`, stored in the atlas when it lies inside the level (a group at
// the right or bottom edge makes texels past it, which the next level's clamp never reads).
void ao_mip_store(int level, ivec2 t, float depth)
{
    if (t.x < ao_mip_size(level).x && t.y < ao_mip_size(level).y) imageStore(u_output, ao_mip_origin(level) + t, vec4(depth));
}

// The local index of child c (of level `level` - 1, global texel index) in a block `side`
// wide starting at `first`, clamped to that level's size.
int ao_child_index(int level, ivec2 c, ivec2 first, int side)
{
    c = min(c, ao_mip_size(level - 1) - 1);
    ivec2 local = c - first;
    return local.y * side + local.x;
}

void main()
{
    ao_begin_invocation(); // common/depth.glsl: the depth buffer's size, once
    ivec2 local = ivec2(gl_LocalInvocationID.xy);
    ivec2 group = ivec2(gl_WorkGroupID.xy);

    // Level 1: this invocation's 2 x 2 block of the depth buffer, clamped to its edge.
    ivec2 t1 = group * 8 + local;
    vec4 g = ao_depth_quad(2 * t1); // textureGather's order: (0, 1), (1, 1), (1, 0), (0, 0)
    float d1 = ao_mip_reduce(g.w, g.z, g.x, g.y);
    ao_mip_store(1, t1, d1);
    ao_level1[local.y * 8 + local.x] = d1;
    barrier();

#if AO_MIP_LEVELS > 2
    // Level 2 from the group's 8 x 8 texels of level 1.
    if (local.x < 4 && local.y < 4) {
        ivec2 t2 = group * 4 + local, first = group * 8;
        ivec2 c = 2 * t2;
        float d2 = ao_mip_reduce(ao_level1[ao_child_index(2, c, first, 8)], ao_level1[ao_child_index(2, c + ivec2(1, 0), first, 8)],
                                 ao_level1[ao_child_index(2, c + ivec2(0, 1), first, 8)], ao_level1[ao_child_index(2, c + ivec2(1, 1), first, 8)]);
        ao_mip_store(2, t2, d2);
        ao_level2[local.y * 4 + local.x] = d2;
    }
    barrier();
#endif
#if AO_MIP_LEVELS > 3
    if (local.x < 2 && local.y < 2) {
        ivec2 t3 = group * 2 + local, first = group * 4;
        ivec2 c = 2 * t3;
        float d3 = ao_mip_reduce(ao_level2[ao_child_index(3, c, first, 4)], ao_level2[ao_child_index(3, c + ivec2(1, 0), first, 4)],
                                 ao_level2[ao_child_index(3, c + ivec2(0, 1), first, 4)], ao_level2[ao_child_index(3, c + ivec2(1, 1), first, 4)]);
        ao_mip_store(3, t3, d3);
        ao_level3[local.y * 2 + local.x] = d3;
    }
    barrier();
#endif
#if AO_MIP_LEVELS > 4
    if (local.x == 0 && local.y == 0) {
        ivec2 first = group * 2;
        ivec2 c = 2 * group;
        float d4 = ao_mip_reduce(ao_level3[ao_child_index(4, c, first, 2)], ao_level3[ao_child_index(4, c + ivec2(1, 0), first, 2)],
                                 ao_level3[ao_child_index(4, c + ivec2(0, 1), first, 2)], ao_level3[ao_child_index(4, c + ivec2(1, 1), first, 2)]);
        ao_mip_store(4, group, d4);
    }
#endif
}
