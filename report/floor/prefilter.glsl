// floor/prefilter.glsl -- both floors of prefilter.glsl: the pass already reads every depth
// texel once (one gather per invocation) and writes every atlas texel once, so its fetch
// floor and its bandwidth floor are one kernel: the same gather, the same shared memory and
// barriers, the same stores, and a plain sum where the pass reduces four texels to one.

layout(local_size_x = 8, local_size_y = 8, local_size_z = 1) in;

// u_output: declared by aogen::codegen (aogen/bindings.hpp).

shared float ao_level1[64];
shared float ao_level2[16];
shared float ao_level3[4];

void ao_floor_store(int level, ivec2 t, float value)
{
    if (t.x < ao_mip_size(level).x && t.y < ao_mip_size(level).y) imageStore(u_output, ao_mip_origin(level) + t, vec4(value));
}

void main()
{
    ao_begin_invocation(); // common/depth.glsl, as prefilter.glsl
    ivec2 local = ivec2(gl_LocalInvocationID.xy);
    ivec2 group = ivec2(gl_WorkGroupID.xy);
    ivec2 t1 = group * 8 + local;
    vec4 g = ao_depth_quad(2 * t1);
    float d1 = g.x + g.y + g.z + g.w;
    ao_floor_store(1, t1, d1);
    ao_level1[local.y * 8 + local.x] = d1;
    barrier();
#if AO_MIP_LEVELS > 2
    if (local.x < 4 && local.y < 4) {
        int i = 2 * local.y * 8 + 2 * local.x;
        float d2 = ao_level1[i] + ao_level1[i + 1] + ao_level1[i + 8] + ao_level1[i + 9];
        ao_floor_store(2, group * 4 + local, d2);
        ao_level2[local.y * 4 + local.x] = d2;
    }
    barrier();
#endif
#if AO_MIP_LEVELS > 3
    if (local.x < 2 && local.y < 2) {
        int i = 2 * local.y * 4 + 2 * local.x;
        float d3 = ao_level2[i] + ao_level2[i + 1] + ao_level2[i + 4] + ao_level2[i + 5];
        ao_floor_store(3, group * 2 + local, d3);
        ao_level3[local.y * 2 + local.x] = d3;
    }
    barrier();
#endif
#if AO_MIP_LEVELS > 4
    if (local.x == 0 && local.y == 0) ao_floor_store(4, group, ao_level3[0] + ao_level3[1] + ao_level3[2] + ao_level3[3]);
#endif
}
