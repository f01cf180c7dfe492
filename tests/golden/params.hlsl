// Params: hlsl-cbuffer layout, 144 bytes, aligned to 16
struct Light {
    float3 color;     // offset 0
    float intensity;  // offset 12
};
cbuffer Params : register(b0, space0) {
    float radius;                 // offset 0
    float4 kernel[4];             // offset 16, stride 16
    Light light;                  // offset 80
    float tail;                   // offset 96
    column_major float3x2 basis;  // offset 112, matrix stride 16
};
