// common/depth.glsl -- the depth buffer: sizes, the full/half resolution mapping, the
// background test of each depth convention and view-space reconstruction through
// u.inv_proj (every pass block has it).
//
// Binding AO_BINDING_DEPTH: the depth buffer at full resolution as a float texture (a
// sampled D32/D24 depth image or an R32F copy), read with texelFetch from .r. Its size is
// the screen size; at AO_HALF_RESOLUTION the AO target is half of it, rounded up (1919 x
// 1079 -> 960 x 540), and target pixel p reads depth and normals at full-resolution
// pixel 2p (clamped to the screen; the last row/column of an odd size is not read).

layout(set = 0, binding = AO_BINDING_DEPTH) uniform sampler2D u_depth;

// The depth buffer's size in pixels (at least 1 x 1).
ivec2 ao_depth_size()
{
    return max(textureSize(u_depth, 0), ivec2(1));
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
    if (!ao_is_finite(depth)) return true;
#if defined(AO_DEPTH_STANDARD)
    return depth >= 1.0;
#else
    return depth <= 0.0;
#endif
}

// The homogeneous view-space point of (uv, depth): inv_proj * ndc. ndc.y = 1 - 2 uv.y.
vec4 ao_unproject(vec2 uv, float depth)
{
    return u.inv_proj * vec4(uv.x * 2.0 - 1.0, 1.0 - uv.y * 2.0, depth, 1.0);
}

// The view-space position of a depth-buffer value at `uv` (depth must not be background).
// Perspective: w = 1 / view distance > 0 for every depth in front of the camera; it is
// kept away from 0 so the division cannot fault (an absurd depth then gives a huge or
// non-finite position, which callers test with ao_is_finite). Orthographic: inv_proj is
// affine, w is exactly 1 and there is no division.
vec3 ao_view_position(vec2 uv, float depth)
{
    vec4 p = ao_unproject(uv, depth);
#if defined(AO_PROJECTION_ORTHOGRAPHIC)
    return p.xyz;
#else
    return p.xyz / max(p.w, 1e-30);
#endif
}

// Only the view-space z of ao_view_position (negative in front of the camera).
float ao_view_z(vec2 uv, float depth)
{
    vec4 p = ao_unproject(uv, depth);
#if defined(AO_PROJECTION_ORTHOGRAPHIC)
    return p.z;
#else
    return p.z / max(p.w, 1e-30);
#endif
}
