// common/normals.glsl -- the surface normal in view space, for the AO pass.
//
// AO_NORMALS_GBUFFER_WORLD  binding AO_BINDING_NORMALS: world-space normals, rotated into
//                           view space by mat3(u.world_to_view) (Taos).
// AO_NORMALS_GBUFFER_VIEW   binding AO_BINDING_NORMALS: view-space normals (Unique Engine's
//                           normal pre-pass).
//   Both G-buffer forms store the normal as plain floats in .xyz of a float texture
//   (rgba16f or rgba32f), components in [-1, 1], no encoding (no *2-1, no octahedral);
//   it need not be unit length. A zero or non-finite normal means "no normal": AO 1.
// AO_NORMALS_RECONSTRUCTED  no normal texture (the pass declares no binding 2): the normal
//   comes from the depth buffer alone, without derivatives (so compute passes can use
//   it): on each axis the neighbour pixel on the side whose view depth is closer to the
//   centre's gives the surface step, so silhouettes do not bend the normal; the cross
//   product of the two steps is the normal. A pixel with no usable neighbour on an axis
//   (background or off screen on both sides) faces the camera.
//
// Normals that face away from the camera (a back face, an interpolated or normal-mapped
// normal past the silhouette) are flipped: a visible surface faces the viewer.

#if (defined(AO_NORMALS_GBUFFER_WORLD) + defined(AO_NORMALS_GBUFFER_VIEW) + defined(AO_NORMALS_RECONSTRUCTED)) != 1
#error aogen: define exactly one of AO_NORMALS_GBUFFER_WORLD AO_NORMALS_GBUFFER_VIEW AO_NORMALS_RECONSTRUCTED
#endif

// u_normals: declared by aogen::codegen (aogen/bindings.hpp).

// The unit vector from a view-space point toward the camera.
vec3 ao_view_direction(vec3 P)
{
#if defined(AO_PROJECTION_ORTHOGRAPHIC)
    return vec3(0.0, 0.0, 1.0);
#else
    return ao_safe_normalize(-P, vec3(0.0, 0.0, 1.0));
#endif
}

#if defined(AO_NORMALS_RECONSTRUCTED)

// The view-space position of full-resolution pixel q, if q is on screen and not background.
bool ao_neighbour_position(ivec2 q, out vec3 position)
{
    position = vec3(0.0);
    ivec2 size = ao_depth_size();
    if (q.x < 0 || q.y < 0 || q.x >= size.x || q.y >= size.y) return false;
    float depth = ao_load_depth(q);
    if (ao_is_background(depth)) return false;
    position = ao_view_position_at(vec2(q) + 0.5, depth);
    return ao_is_finite(position);
}

// The view-space step from pixel p to its neighbour one pixel along +axis, taken on the
// side (p + axis or p - axis) whose view z is closer to P's. False if neither side has one.
bool ao_surface_step(ivec2 p, ivec2 axis, vec3 P, out vec3 step_along_axis)
{
    vec3 ahead, behind;
    bool has_ahead = ao_neighbour_position(p + axis, ahead);
    bool has_behind = ao_neighbour_position(p - axis, behind);
    if (has_ahead && (!has_behind || abs(ahead.z - P.z) <= abs(behind.z - P.z))) {
        step_along_axis = ahead - P;
        return true;
    }
    step_along_axis = P - behind;
    return has_behind;
}

vec3 ao_reconstructed_normal(ivec2 p, vec3 P, vec3 V)
{
    vec3 step_x, step_y;
    if (!ao_surface_step(p, ivec2(1, 0), P, step_x)) return V;
    if (!ao_surface_step(p, ivec2(0, 1), P, step_y)) return V;
    // Pixel +x is view +x and pixel +y is view -y, so cross(step_y, step_x) points toward
    // the camera for a surface facing it. Steps are scaled before the cross product so
    // that neither tiny (near) nor huge (far) steps underflow or overflow.
    step_x = ao_safe_normalize(step_x, vec3(1.0, 0.0, 0.0));
    step_y = ao_safe_normalize(step_y, vec3(0.0, -1.0, 0.0));
    return ao_safe_normalize(cross(step_y, step_x), V);
}

#endif

// The unit view-space normal at full-resolution pixel p (view position P, view direction
// V), facing the camera. False when there is no usable normal (zero or non-finite).
bool ao_surface_normal(ivec2 p, vec3 P, vec3 V, out vec3 n)
{
#if defined(AO_NORMALS_RECONSTRUCTED)
    n = ao_reconstructed_normal(p, P, V);
#else
    vec3 g = texelFetch(u_normals, p, 0).xyz;
#if defined(AO_NORMALS_GBUFFER_WORLD)
    if (!ao_is_finite(g)) g = vec3(0.0); // keep a NaN out of the rotation
    g = mat3(u.world_to_view) * g;
#endif
    n = ao_safe_normalize(g, vec3(0.0));
#endif
    if (!(dot(n, n) > 0.5)) return false;
    if (dot(n, V) < 0.0) n = -n;
    return true;
}

// The surface an AO pass (gtao.glsl, vbao.glsl, sao.glsl) works on at target pixel
// `target_pixel`: `p`, the full-resolution pixel it reads; P, the view-space point there; V,
// the unit direction from P to the camera; n, the normal facing V. False on background, a
// non-finite P or no usable normal: the pass writes 1 there.
bool ao_pass_surface(ivec2 target_pixel, out ivec2 p, out vec3 P, out vec3 V, out vec3 n)
{
    p = ao_full_pixel(target_pixel);
    P = vec3(0.0), V = vec3(0.0, 0.0, 1.0), n = vec3(0.0, 0.0, 1.0);
    float depth = ao_load_depth(p);
    if (ao_is_background(depth)) return false;
    P = ao_view_position_at(vec2(p) + 0.5, depth);
    if (!ao_is_finite(P)) return false;
    V = ao_view_direction(P);
    return ao_surface_normal(p, P, V, n);
}
