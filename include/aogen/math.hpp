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

} // namespace aogen
