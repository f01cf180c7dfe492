// aogen/math.hpp — the few vector and matrix types aogen's data is made of.
//
// Plain structs whose names mirror GLSL (vec2, vec3, vec4, mat4), so host code that
// builds kernels and uniforms reads like the shader that consumes them. They are not a
// math library: only what kernels, noise tiles and camera uniforms need. Engines with
// GLM or their own types copy the floats across; every type here is a standard-layout
// aggregate of floats with no padding (vec3 is 12 bytes — see layout.hpp for how a
// vec3 is laid out in a GPU buffer, which is a different question).
//
// mat4 is column-major like GLSL: m.columns[c] is column c, and m[c][r] the element
// in column c, row r.
//
// Projections follow one convention everywhere in aogen: right-handed view space with
// the camera looking down −z, clip-space y up (as in GL and WebGPU; shaders map
// uv.y = 0.5 − 0.5·ndc.y), and depth in [0, 1] in one of three conventions:
//   standard            near → 0, far → 1
//   reversed            near → 1, far → 0 (better float precision far away)
//   reversed_infinite   near → 1, depth = near / view distance, no far plane
// They take tan(fov_y / 2) rather than an angle so that no libm call (whose last bit
// differs between C libraries) enters bytes that tests pin.
#pragma once

#include <cmath>

namespace aogen {

struct vec2 { float x = 0, y = 0; };
struct vec3 { float x = 0, y = 0, z = 0; };
struct vec4 { float x = 0, y = 0, z = 0, w = 0; };

inline vec3 operator+(vec3 a, vec3 b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
inline vec3 operator-(vec3 a, vec3 b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
inline vec3 operator*(vec3 a, float s) { return {a.x * s, a.y * s, a.z * s}; }
inline vec3 operator*(float s, vec3 a) { return a * s; }

inline float dot(vec3 a, vec3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
inline vec3 cross(vec3 a, vec3 b)
{
    return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
inline float length(vec3 a) { return std::sqrt(dot(a, a)); }
inline vec3 xyz(vec4 v) { return {v.x, v.y, v.z}; }

struct mat4 {
    vec4 columns[4] = {{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}, {0, 0, 0, 1}};

    float* operator[](int column) { return &columns[column].x; }
    const float* operator[](int column) const { return &columns[column].x; }
};

inline vec4 operator*(const mat4& m, vec4 v)
{
    vec4 r;
    const float in[4] = {v.x, v.y, v.z, v.w};
    float out[4] = {0, 0, 0, 0};
    for (int c = 0; c < 4; ++c)
        for (int row = 0; row < 4; ++row) out[row] += m[c][row] * in[c];
    r = {out[0], out[1], out[2], out[3]};
    return r;
}

inline mat4 operator*(const mat4& a, const mat4& b)
{
    mat4 r;
    for (int c = 0; c < 4; ++c) r.columns[c] = a * b.columns[c];
    return r;
}

enum class depth_convention { standard, reversed, reversed_infinite };

// Perspective projection. `tan_half_fov_y` = tan(vertical field of view / 2).
inline mat4 perspective(float tan_half_fov_y, float aspect, float near, float far,
                        depth_convention depth = depth_convention::standard)
{
    mat4 m;
    m[0][0] = 1.0f / (aspect * tan_half_fov_y);
    m[1][1] = 1.0f / tan_half_fov_y;
    m[2][3] = -1.0f; // w_clip = −z_view
    m[3][3] = 0.0f;
    switch (depth) { // z_clip = A·z_view + B, depth = z_clip / w_clip
    case depth_convention::standard:
        m[2][2] = far / (near - far), m[3][2] = near * far / (near - far);
        break;
    case depth_convention::reversed:
        m[2][2] = near / (far - near), m[3][2] = near * far / (far - near);
        break;
    case depth_convention::reversed_infinite:
        m[2][2] = 0.0f, m[3][2] = near;
        break;
    }
    return m;
}

// Orthographic projection of the box [left, right] × [bottom, top] × [−far, −near].
inline mat4 orthographic(float left, float right, float bottom, float top, float near, float far,
                         depth_convention depth = depth_convention::standard)
{
    mat4 m;
    m[0][0] = 2.0f / (right - left), m[3][0] = -(right + left) / (right - left);
    m[1][1] = 2.0f / (top - bottom), m[3][1] = -(top + bottom) / (top - bottom);
    const bool reversed = depth != depth_convention::standard; // an orthographic far plane is always finite
    const float z_near = reversed ? 1.0f : 0.0f, z_far = reversed ? 0.0f : 1.0f;
    m[2][2] = (z_far - z_near) / (near - far); // depth is linear in z_view
    m[3][2] = z_near + m[2][2] * near;
    return m;
}

// The inverse of a 4×4 matrix by cofactors, in double precision. A singular matrix
// gives a matrix of infinities/NaNs: callers pass projections and rigid transforms.
inline mat4 inverse(const mat4& m)
{
    double a[16], inv[16];
    for (int i = 0; i < 16; ++i) a[i] = m[i / 4][i % 4];
    inv[0] = a[5] * a[10] * a[15] - a[5] * a[11] * a[14] - a[9] * a[6] * a[15] + a[9] * a[7] * a[14] + a[13] * a[6] * a[11] - a[13] * a[7] * a[10];
    inv[4] = -a[4] * a[10] * a[15] + a[4] * a[11] * a[14] + a[8] * a[6] * a[15] - a[8] * a[7] * a[14] - a[12] * a[6] * a[11] + a[12] * a[7] * a[10];
    inv[8] = a[4] * a[9] * a[15] - a[4] * a[11] * a[13] - a[8] * a[5] * a[15] + a[8] * a[7] * a[13] + a[12] * a[5] * a[11] - a[12] * a[7] * a[9];
    inv[12] = -a[4] * a[9] * a[14] + a[4] * a[10] * a[13] + a[8] * a[5] * a[14] - a[8] * a[6] * a[13] - a[12] * a[5] * a[10] + a[12] * a[6] * a[9];
    inv[1] = -a[1] * a[10] * a[15] + a[1] * a[11] * a[14] + a[9] * a[2] * a[15] - a[9] * a[3] * a[14] - a[13] * a[2] * a[11] + a[13] * a[3] * a[10];
    inv[5] = a[0] * a[10] * a[15] - a[0] * a[11] * a[14] - a[8] * a[2] * a[15] + a[8] * a[3] * a[14] + a[12] * a[2] * a[11] - a[12] * a[3] * a[10];
    inv[9] = -a[0] * a[9] * a[15] + a[0] * a[11] * a[13] + a[8] * a[1] * a[15] - a[8] * a[3] * a[13] - a[12] * a[1] * a[11] + a[12] * a[3] * a[9];
    inv[13] = a[0] * a[9] * a[14] - a[0] * a[10] * a[13] - a[8] * a[1] * a[14] + a[8] * a[2] * a[13] + a[12] * a[1] * a[10] - a[12] * a[2] * a[9];
    inv[2] = a[1] * a[6] * a[15] - a[1] * a[7] * a[14] - a[5] * a[2] * a[15] + a[5] * a[3] * a[14] + a[13] * a[2] * a[7] - a[13] * a[3] * a[6];
    inv[6] = -a[0] * a[6] * a[15] + a[0] * a[7] * a[14] + a[4] * a[2] * a[15] - a[4] * a[3] * a[14] - a[12] * a[2] * a[7] + a[12] * a[3] * a[6];
    inv[10] = a[0] * a[5] * a[15] - a[0] * a[7] * a[13] - a[4] * a[1] * a[15] + a[4] * a[3] * a[13] + a[12] * a[1] * a[7] - a[12] * a[3] * a[5];
    inv[14] = -a[0] * a[5] * a[14] + a[0] * a[6] * a[13] + a[4] * a[1] * a[14] - a[4] * a[2] * a[13] - a[12] * a[1] * a[6] + a[12] * a[2] * a[5];
    inv[3] = -a[1] * a[6] * a[11] + a[1] * a[7] * a[10] + a[5] * a[2] * a[11] - a[5] * a[3] * a[10] - a[9] * a[2] * a[7] + a[9] * a[3] * a[6];
    inv[7] = a[0] * a[6] * a[11] - a[0] * a[7] * a[10] - a[4] * a[2] * a[11] + a[4] * a[3] * a[10] + a[8] * a[2] * a[7] - a[8] * a[3] * a[6];
    inv[11] = -a[0] * a[5] * a[11] + a[0] * a[7] * a[9] + a[4] * a[1] * a[11] - a[4] * a[3] * a[9] - a[8] * a[1] * a[7] + a[8] * a[3] * a[5];
    inv[15] = a[0] * a[5] * a[10] - a[0] * a[6] * a[9] - a[4] * a[1] * a[10] + a[4] * a[2] * a[9] + a[8] * a[1] * a[6] - a[8] * a[2] * a[5];
    const double det = a[0] * inv[0] + a[1] * inv[4] + a[2] * inv[8] + a[3] * inv[12];
    mat4 r; // + 0.0 turns the −0 that cofactors produce into +0: same value, tidier bytes
    for (int i = 0; i < 16; ++i) r[i / 4][i % 4] = static_cast<float>(inv[i] / det + 0.0);
    return r;
}

} // namespace aogen
