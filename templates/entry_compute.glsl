// entry_compute.glsl -- the compute entry point of every pass: one invocation per pixel
// of the pass's output (which pixel: ao_invocation_pixel), workgroups of AO_WORKGROUP_X x
// AO_WORKGROUP_Y. Dispatch
// ceil(width / AO_WORKGROUP_X) x ceil(height / AO_WORKGROUP_Y) groups for the output
// image's size; invocations past its edge write nothing. A pass that defines
// AO_PASS_LOADS_TILE has every invocation call its ao_load_tile() first (blur_denoise.glsl,
// blur_denoise3.glsl, upsample.glsl: tiles of inputs shared in the workgroup); one that defines
// AO_PASS_WRITES_QUADS writes 2 x 2 pixels per invocation (aogen::pixels_per_invocation):
// dispatch it over ceil(width / 2) x ceil(height / 2).
//
// Binding AO_BINDING_OUTPUT: the output, a storage image of the pass's output size (the AO target's; the screen's for upsample) in the
// format AO_OUTPUT_FORMAT (codegen::options::output_format): r8 (R8_UNORM, the default),
// rgba8 (for OpenGL ES 3.1, which has no r8 image format), r32f or rgba16f. The value
// written is ao_output(ao_pass(pixel), pixel), finite and in [0, 1], in .r; multi-channel
// formats get (ao, 0, 0, 1), or with AO_BENT_NORMALS (ao, encoded bent normal)
// (common/core.glsl's ao_value and ao_output_texel), or with AO_WRITE_EDGES -- the AO pass of
// a -denoise3 variant -- (ao, right edge, lower edge, 1) (common/edges.glsl).
//
// AO_DIAGNOSTICS (codegen::options::diagnostics) adds binding AO_BINDING_RAW, an r32f
// storage image of the same size that receives ao_pass(pixel) itself, before the guard:
// a harness counts the NaN, infinities and out-of-range values the pass produced, which
// the output can never show. The output is the same either way.

layout(local_size_x = AO_WORKGROUP_X, local_size_y = AO_WORKGROUP_Y, local_size_z = 1) in;

// u_output: declared by aogen::codegen (aogen/bindings.hpp).
// u_raw: declared by aogen::codegen (aogen/bindings.hpp).

// The pixel invocation `invocation` shades. By default the one at its global id. With
// AO_DEINTERLEAVED_LAYERS L (an AO pass of a -deint variant) the dispatch walks the target as
// L x L interleaved layers, each a ceil(size / L) lattice of the pixels L apart that share a
// noise rotation: invocation (x, y) inside layer (i, j) shades pixel (L x + i, L y + j). A
// warp then holds pixels of one layer, whose taps -- one rotation, centres L pixels apart --
// land side by side instead of scattered over the radius, as in deinterleaved rendering
// (Bavoil 2014); each pixel still reads what it always read, so the output is the same. The
// groups (sides multiples of L: aogen::validate) cover the L x L layers; invocations past them,
// and layer pixels past an edge that size does not divide, get a pixel outside the image.
ivec2 ao_invocation_pixel(ivec2 invocation, ivec2 size)
{
#if defined(AO_DEINTERLEAVED_LAYERS)
    const int layers = AO_DEINTERLEAVED_LAYERS;
    ivec2 layer_size = (size + (layers - 1)) / layers;
    ivec2 layer = invocation / layer_size; // one division per pixel, not per tap
    if (any(greaterThanEqual(layer, ivec2(layers)))) return size;
    return (invocation - layer * layer_size) * layers + layer;
#else
    return invocation;
#endif
}

#if defined(AO_PASS_WRITES_QUADS)
// A pass whose invocation writes a 2 x 2 square of output pixels (upsample.glsl): its
// ao_pass_quad(i) returns the pixels 2 i + (0, 0), (1, 0), (0, 1), (1, 1), and those inside
// the image are stored. Dispatch it over half the output's size, rounded up.
void main()
{
    ao_begin_invocation(); // common/depth.glsl: what every tap reads, once (the tile's load reads it too)
#if defined(AO_PASS_LOADS_TILE)
    ao_load_tile(); // as below: every invocation, before its edge test
#endif
    ivec2 invocation = ivec2(gl_GlobalInvocationID.xy);
    ivec2 size = imageSize(u_output);
    if (2 * invocation.x >= size.x || 2 * invocation.y >= size.y) return;
    ao_value4 ao = ao_pass_quad(invocation);
    for (int k = 0; k < 4; ++k) {
        ivec2 pixel = 2 * invocation + ivec2(k & 1, k >> 1);
        if (pixel.x >= size.x || pixel.y >= size.y) continue;
#if defined(AO_DIAGNOSTICS)
        imageStore(u_raw, pixel, vec4(ao_value_ao(ao[k])));
#endif
        imageStore(u_output, pixel, ao_output_texel(ao[k], pixel));
    }
}
#else
void main()
{
    ao_begin_invocation(); // common/depth.glsl: what every tap reads, once (the tile's load reads it too)
#if defined(AO_PASS_LOADS_TILE)
    // A pass that shares a tile of inputs across its workgroup (blur_denoise.glsl) loads it
    // here, in every invocation: the load ends in a barrier, which invocations past the
    // image's edge must reach too.
    ao_load_tile();
#endif
    ivec2 size = imageSize(u_output);
    ivec2 pixel = ao_invocation_pixel(ivec2(gl_GlobalInvocationID.xy), size);
    if (pixel.x >= size.x || pixel.y >= size.y) return;
    ao_value ao = ao_pass(pixel);
#if defined(AO_DIAGNOSTICS)
    imageStore(u_raw, pixel, vec4(ao_value_ao(ao)));
#endif
    vec4 texel = ao_output_texel(ao, pixel);
#if defined(AO_WRITE_EDGES)
    texel.yz = ao_edges(pixel); // common/edges.glsl: the 3 x 3 denoise's edges, beside the AO
#endif
    imageStore(u_output, pixel, texel);
}
#endif
