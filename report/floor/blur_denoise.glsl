// floor/blur_denoise.glsl -- the fetch floor of blur_denoise.glsl: the same workgroup tile of
// (depth, AO) loaded into shared memory (floors are compute kernels), then the column sums of
// the group's rows made from it (5 taps each, into shared memory), then each pixel's 5 column
// sums read. No view depth, no weights.

// u_ao_input: declared by aogen::codegen (aogen/bindings.hpp).

#define AO_TILE_WIDTH (AO_WORKGROUP_X + 2 * AO_DENOISE_RADIUS)
#define AO_TILE_HEIGHT (AO_WORKGROUP_Y + 2 * AO_DENOISE_RADIUS)
#define AO_PASS_LOADS_TILE
shared vec2 ao_tile[AO_TILE_WIDTH * AO_TILE_HEIGHT];
shared vec2 ao_columns[AO_TILE_WIDTH * AO_WORKGROUP_Y];

ivec2 ao_tile_origin()
{
    return ivec2(gl_WorkGroupID.xy) * ivec2(AO_WORKGROUP_X, AO_WORKGROUP_Y) - ivec2(AO_DENOISE_RADIUS);
}

void ao_load_tile()
{
    ivec2 origin = ao_tile_origin();
    ivec2 size = max(textureSize(u_ao_input, 0), ivec2(1));
    for (int i = int(gl_LocalInvocationIndex); i < AO_TILE_WIDTH * AO_TILE_HEIGHT; i += AO_WORKGROUP_X * AO_WORKGROUP_Y) {
        ivec2 q = origin + ivec2(i % AO_TILE_WIDTH, i / AO_TILE_WIDTH);
        bool inside = q.x >= 0 && q.y >= 0 && q.x < size.x && q.y < size.y;
        ao_tile[i] = inside ? vec2(ao_load_depth(ao_full_pixel(q)), texelFetch(u_ao_input, q, 0).r) : vec2(0.0);
    }
    barrier();
    for (int i = int(gl_LocalInvocationIndex); i < AO_TILE_WIDTH * AO_WORKGROUP_Y; i += AO_WORKGROUP_X * AO_WORKGROUP_Y) {
        int x = i % AO_TILE_WIDTH, y = AO_DENOISE_RADIUS + i / AO_TILE_WIDTH;
        vec2 sum = vec2(0.0);
        for (int dy = -AO_DENOISE_RADIUS; dy <= AO_DENOISE_RADIUS; ++dy) sum += ao_tile[(y + dy) * AO_TILE_WIDTH + x];
        ao_columns[i] = sum;
    }
    barrier();
}

// ao_value (common/core.glsl): with bent normals the output's normal channels are written too.
ao_value ao_pass(ivec2 p)
{
    ivec2 t = p - ao_tile_origin();
    vec2 sum = vec2(0.0);
    for (int dx = -AO_DENOISE_RADIUS; dx <= AO_DENOISE_RADIUS; ++dx) sum += ao_columns[(t.y - AO_DENOISE_RADIUS) * AO_TILE_WIDTH + t.x + dx];
    return ao_make_value(fract(sum.x + sum.y), vec3(0.0));
}
