// floor/upsample.glsl -- the fetch floor of upsample.glsl's compute pass (floors are compute
// kernels): the same workgroup tile of candidates -- each target texel's AO and the depth of
// the full-resolution pixel it stands for -- loaded into shared memory, then per invocation
// one gather of its 2 x 2 screen pixels' depths and its four candidates read from the tile.
// No view depth, no weights.

// u_ao_input: declared by aogen::codegen (aogen/bindings.hpp).

#define AO_PASS_WRITES_QUADS
#define AO_PASS_LOADS_TILE
#define AO_TILE_WIDTH (AO_WORKGROUP_X + 1)
#define AO_TILE_HEIGHT (AO_WORKGROUP_Y + 1)
shared vec2 ao_tile[AO_TILE_WIDTH * AO_TILE_HEIGHT];

ivec2 ao_tile_origin()
{
    return ivec2(gl_WorkGroupID.xy) * ivec2(AO_WORKGROUP_X, AO_WORKGROUP_Y);
}

void ao_load_tile()
{
    ivec2 origin = ao_tile_origin();
    ivec2 size = max(textureSize(u_ao_input, 0), ivec2(1));
    for (int i = int(gl_LocalInvocationIndex); i < AO_TILE_WIDTH * AO_TILE_HEIGHT; i += AO_WORKGROUP_X * AO_WORKGROUP_Y) {
        ivec2 q = min(origin + ivec2(i % AO_TILE_WIDTH, i / AO_TILE_WIDTH), size - 1);
        ao_tile[i] = vec2(texelFetch(u_ao_input, q, 0).r, ao_load_depth(ao_full_pixel(q)));
    }
    barrier();
}

// ao_quad_of (common/core.glsl): with bent normals the output's normal channels are written too.
ao_value4 ao_pass_quad(ivec2 q0)
{
    ivec2 t = q0 - ao_tile_origin();
    vec4 sum = ao_depth_quad(2 * q0);
    for (int k = 0; k < 4; ++k) {
        vec2 c = ao_tile[(t.y + (k >> 1)) * AO_TILE_WIDTH + t.x + (k & 1)];
        sum[k] += c.x + c.y;
    }
    return ao_quad_of(fract(sum));
}
