// floor/normals.glsl -- the fetch floor's common/normals.glsl: the texel fetches that
// finding the surface normal costs, without the normal itself; and what both AO floors
// (ssao.glsl, gtao.glsl) read at the centre pixel before their samples.

// u_normals: declared by aogen::codegen (aogen/bindings.hpp).

// The depth at full-resolution pixel q, or 0 off screen (the real passes skip those).
float ao_floor_depth(ivec2 q)
{
    ivec2 size = ao_depth_size();
    if (q.x < 0 || q.y < 0 || q.x >= size.x || q.y >= size.y) return 0.0;
    return ao_load_depth(q);
}

// What common/depth.glsl's ao_depth_at reads for a sample at screen position pos, `distance`
// pixels from the pixel: the 2x2 texels around pos (ao_depth_quad: one gather in compute
// passes, four loads in fragment passes) -- with a depth MIP chain, of the level the distance
// calls for (ao_tap_level, ao_mip_quad).
float ao_floor_surface_fetches(vec2 pos, float distance)
{
    ivec2 size = ao_depth_size();
    if (!(pos.x >= 0.0 && pos.y >= 0.0 && pos.x < float(size.x) && pos.y < float(size.y))) return 0.0;
    int level = ao_tap_level(distance);
#if defined(AO_MIP_LEVELS)
    vec4 g = level == 0 ? ao_depth_quad(ivec2(floor(pos - 0.5))) : ao_mip_quad(ivec2(floor(pos * ao_exp2i(-level) - 0.5)), level);
#else
    vec4 g = ao_depth_quad(ivec2(floor(pos - 0.5)));
#endif
    return g.x + g.y + g.z + g.w;
}

// The sum of what the normal's fetches read at full-resolution pixel p: the G-buffer
// texel, or the four neighbours' depths common/normals.glsl reconstructs it from.
float ao_floor_normal_fetches(ivec2 p)
{
#if defined(AO_NORMALS_RECONSTRUCTED)
    return ao_floor_depth(p + ivec2(1, 0)) + ao_floor_depth(p - ivec2(1, 0)) + ao_floor_depth(p + ivec2(0, 1)) +
           ao_floor_depth(p - ivec2(0, 1));
#else
    return texelFetch(u_normals, p, 0).x;
#endif
}

// The AO radius in full-resolution pixels at view depth view_z, as gtao.glsl computes it
// (clip y = proj[1][1] * y / -z), capped at half the screen's height.
float ao_floor_radius_pixels(float view_z)
{
    vec2 fsize = vec2(ao_depth_size());
    float pixels_per_unit = 0.5 * fsize.y * abs(u.proj[1][1]);
#if !defined(AO_PROJECTION_ORTHOGRAPHIC)
    pixels_per_unit /= max(-view_z, 1e-30);
#endif
    float radius_pixels = min(u.radius * pixels_per_unit, 0.5 * fsize.y);
    return ao_is_finite(radius_pixels) ? radius_pixels : 0.0;
}

// common/noise.glsl, which comes after this file, defines it.
vec2 ao_noise_rotation(ivec2 p);

// The centre of an AO floor at target pixel t: false on background (as the real passes,
// which return 1 there); otherwise its full-resolution pixel p, the sum of the centre's
// depth, normal and noise fetches, the noise rotation and the radius in pixels.
bool ao_floor_centre(ivec2 target_pixel, out ivec2 p, out float sum, out vec2 rotation, out float radius_pixels)
{
    p = ao_full_pixel(target_pixel);
    float depth = ao_load_depth(p);
    sum = depth;
    rotation = vec2(1.0, 0.0);
    radius_pixels = 0.0;
    if (ao_is_background(depth)) return false;
    sum += ao_floor_normal_fetches(p);
    radius_pixels = ao_floor_radius_pixels(ao_pixel_view_z(p, depth));
    rotation = ao_noise_rotation(target_pixel);
    return true;
}
