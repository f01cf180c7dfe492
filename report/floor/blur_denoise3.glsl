// floor/blur_denoise3.glsl -- the fetch floor of blur_denoise3.glsl: the same workgroup tile of
// (AO, right edge, lower edge) texels loaded into shared memory (group + 1 on each side), then
// each pixel's 9 taps read from it. No depth (the pass reads none), no weights.

// u_ao_input: declared by aogen::codegen (aogen/bindings.hpp).

#define AO_TILE_WIDTH (AO_WORKGROUP_X + 2)
#define AO_TILE_HEIGHT (AO_WORKGROUP_Y + 2)
#define AO_PASS_LOADS_TILE
shared vec3 ao_tile[AO_TILE_WIDTH * AO_TILE_HEIGHT];

ivec2 ao_tile_origin()
{
    return ivec2(gl_WorkGroupID.xy) * ivec2(AO_WORKGROUP_X, AO_WORKGROUP_Y) - ivec2(1);
}

void ao_load_tile()
{
    ivec2 origin = ao_tile_origin();
    ivec2 size = max(textureSize(u_ao_input, 0), ivec2(1));
    for (int i = int(gl_LocalInvocationIndex); i < AO_TILE_WIDTH * AO_TILE_HEIGHT; i += AO_WORKGROUP_X * AO_WORKGROUP_Y) {
        ivec2 q = origin + ivec2(i % AO_TILE_WIDTH, i / AO_TILE_WIDTH);
        bool inside = q.x >= 0 && q.y >= 0 && q.x < size.x && q.y < size.y;
        ao_tile[i] = inside ? texelFetch(u_ao_input, q, 0).rgb : vec3(0.0);
    }
    barrier();
}

ao_value ao_pass(ivec2 p)
{
    ivec2 t = p - ao_tile_origin();
    vec3 sum = vec3(0.0);
    for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) sum += ao_tile[(t.y + dy) * AO_TILE_WIDTH + t.x + dx];
    return ao_make_value(fract(sum.x + sum.y + sum.z), vec3(0.0));
}
