// floor/blur_denoise3.glsl -- the fetch floor of blur_denoise3.glsl: the same workgroup tile --
// the (2 group + 2)^2 texels its invocations' 2 x 2 quads cover, one packed word a texel --
// loaded into shared memory, then each invocation's 4 x 4 window read from it and its quad
// written. No depth (the pass reads none), no weights.

// u_ao_input: declared by aogen::codegen (aogen/bindings.hpp).

#define AO_PASS_WRITES_QUADS
#define AO_PASS_LOADS_TILE
#define AO_TILE_WIDTH (2 * AO_WORKGROUP_X + 2)
#define AO_TILE_HEIGHT (2 * AO_WORKGROUP_Y + 2)
shared uint ao_tile[AO_TILE_WIDTH * AO_TILE_HEIGHT];

ivec2 ao_tile_origin()
{
    return ivec2(gl_WorkGroupID.xy) * ivec2(2 * AO_WORKGROUP_X, 2 * AO_WORKGROUP_Y) - ivec2(1);
}

void ao_load_tile()
{
    ivec2 origin = ao_tile_origin();
    ivec2 size = max(textureSize(u_ao_input, 0), ivec2(1));
    for (int i = int(gl_LocalInvocationIndex); i < AO_TILE_WIDTH * AO_TILE_HEIGHT; i += AO_WORKGROUP_X * AO_WORKGROUP_Y) {
        ivec2 q = origin + ivec2(i % AO_TILE_WIDTH, i / AO_TILE_WIDTH);
        bool inside = q.x >= 0 && q.y >= 0 && q.x < size.x && q.y < size.y;
        ao_tile[i] = inside ? packUnorm4x8(texelFetch(u_ao_input, q, 0)) : 0u;
    }
    barrier();
}

// ao_quad_of (common/core.glsl): four pixels' values from the AO alone.
ao_value4 ao_pass_quad(ivec2 q)
{
    ivec2 o = 2 * ivec2(gl_LocalInvocationID.xy); // the window's first texel in the tile
    uint sum = 0u;
    for (int k = 0; k < 16; ++k) sum += ao_tile[(o.y + (k >> 2)) * AO_TILE_WIDTH + o.x + (k & 3)];
    return ao_quad_of(fract(vec4(float(sum & 0xffffu), float(sum >> 16), float(sum & 0xffu), float(sum >> 24)) * (1.0 / 255.0)));
}
