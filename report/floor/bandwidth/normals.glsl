// floor/bandwidth/normals.glsl -- the bandwidth floor's common/normals.glsl: one read of the
// G-buffer normal at the pixel (a reconstructed normal reads no input beyond the depth the
// pass reads anyway), and nothing of the normal itself.

// u_normals: declared by aogen::codegen (aogen/bindings.hpp).

float ao_bandwidth_normal(ivec2 p)
{
#if defined(AO_NORMALS_RECONSTRUCTED)
    return 0.0;
#else
    return texelFetch(u_normals, p, 0).x;
#endif
}

// common/noise.glsl, which comes after this file, defines it.
vec2 ao_noise_rotation(ivec2 p);
