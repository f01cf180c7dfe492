// Params: std140 layout, 144 bytes, aligned to 16
struct Light {
    vec3 color;       // offset 0
    float intensity;  // offset 12
};
layout(std140, set = 0, binding = 3) uniform Params {
    float radius;    // offset 0
    vec4 kernel[4];  // offset 16, stride 16
    Light light;     // offset 80
    float tail;      // offset 96
    mat2x3 basis;    // offset 112, matrix stride 16
} params;
