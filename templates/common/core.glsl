// common/core.glsl -- what every aogen pass shares: the #define contract, constants and
// numeric guards.
//
// aogen's codegen (include/aogen/codegen.hpp) writes, before this file: `#version 450`,
// the pass's #defines (aogen::defines(variant, pass) in aogen/variant.hpp), the binding
// numbers (AO_BINDING_*), compute passes' output format (AO_OUTPUT_FORMAT) and constants taken from aogen's headers (AO_BLUR_*, AO_DENOISE_*, AO_PC_*),
// and the declaration of the pass's uniform block, instance `u`, made from
// aogen/uniforms.hpp by aogen::layout::declare (std140, set 0, binding 0). The template
// files follow in a fixed order; none of them declares the uniform block.
//
// Conventions (aogen/math.hpp): right-handed view space, the camera looks down -z, clip
// y up, uv.y = 0.5 - 0.5 * ndc.y (uv (0, 0) is the top-left texel of every texture);
// depth in [0, 1] as AO_DEPTH_STANDARD (near 0, far 1), AO_DEPTH_REVERSED (near 1, far 0)
// or AO_DEPTH_REVERSED_INFINITE (depth = near / distance).
//
// Every pass writes a value that is finite and in [0, 1], 1 meaning "not occluded";
// background pixels get exactly 1.

// ---- the #define contract (exactly one value of each choice) -------------------------
#if (defined(AO_STAGE_COMPUTE) + defined(AO_STAGE_FRAGMENT)) != 1
#error aogen: define exactly one of AO_STAGE_COMPUTE AO_STAGE_FRAGMENT
#endif
#if defined(AO_STAGE_COMPUTE) && !(defined(AO_WORKGROUP_X) && defined(AO_WORKGROUP_Y))
#error aogen: a compute pass needs AO_WORKGROUP_X and AO_WORKGROUP_Y
#endif
#if (defined(AO_DEPTH_STANDARD) + defined(AO_DEPTH_REVERSED) + defined(AO_DEPTH_REVERSED_INFINITE)) != 1
#error aogen: define exactly one of AO_DEPTH_STANDARD AO_DEPTH_REVERSED AO_DEPTH_REVERSED_INFINITE
#endif
#if (defined(AO_PROJECTION_PERSPECTIVE) + defined(AO_PROJECTION_ORTHOGRAPHIC)) != 1
#error aogen: define exactly one of AO_PROJECTION_PERSPECTIVE AO_PROJECTION_ORTHOGRAPHIC
#endif
#if (defined(AO_PASS_AO) + defined(AO_PASS_BLUR_X) + defined(AO_PASS_BLUR_Y) + defined(AO_PASS_BLUR_BOX) + defined(AO_PASS_BLUR_DENOISE) + defined(AO_PASS_BLUR_DENOISE3) + defined(AO_PASS_UPSAMPLE) + defined(AO_PASS_PREFILTER) + defined(AO_PASS_HISTORY)) != 1
#error aogen: define exactly one of AO_PASS_AO AO_PASS_BLUR_X AO_PASS_BLUR_Y AO_PASS_BLUR_BOX AO_PASS_BLUR_DENOISE AO_PASS_BLUR_DENOISE3 AO_PASS_UPSAMPLE AO_PASS_PREFILTER AO_PASS_HISTORY
#endif
#if defined(AO_MIP_LEVELS) && defined(AO_PASS_AO) && (!defined(AO_BINDING_DEPTH_MIPS) || !defined(AO_MIP_LEVEL_OFFSET))
#error aogen: an AO pass with AO_MIP_LEVELS needs AO_BINDING_DEPTH_MIPS and AO_MIP_LEVEL_OFFSET (codegen writes them)
#endif
#if !defined(AO_BINDING_DEPTH)
#error aogen: AO_BINDING_DEPTH is not defined (codegen writes the bindings)
#endif
#if defined(AO_STAGE_COMPUTE) && !defined(AO_BINDING_OUTPUT)
#error aogen: AO_BINDING_OUTPUT is not defined (codegen writes the bindings)
#endif
#if defined(AO_DIAGNOSTICS) && !defined(AO_BINDING_RAW)
#error aogen: AO_DIAGNOSTICS needs AO_BINDING_RAW (codegen writes the bindings)
#endif
#if defined(AO_STAGE_COMPUTE) && !defined(AO_OUTPUT_FORMAT)
#error aogen: AO_OUTPUT_FORMAT is not defined (codegen writes the output image's format)
#endif

// ---- arithmetic precision ------------------------------------------------------------------
// ao_half is the type of the arithmetic a pass can do in 16 bits (variant axis fp16: codegen
// then enables GL_EXT_shader_explicit_arithmetic_types_float16 after #version): a float16_t
// with AO_FP16, a float otherwise, so one template serves both. A half has 11 significant
// bits (relative error 4.9e-4) and a largest finite value of 65504: what needs more -- depth,
// view positions, screen positions, sums over many samples -- stays float.
#if defined(AO_FP16)
#define ao_half float16_t
#define ao_half2 f16vec2
#define ao_half3 f16vec3
#define ao_half3x3 f16mat3
#else
#define ao_half float
#define ao_half2 vec2
#define ao_half3 vec3
#define ao_half3x3 mat3
#endif

// ---- constants --------------------------------------------------------------------------
const float AO_PI = 3.14159265358979;
const float AO_HALF_PI = 1.57079632679490;

// ---- numeric guards -----------------------------------------------------------------------

// False for NaN and +-infinity. A test of the exponent bits rather than isnan/isinf, which
// a driver compiling with fast-math may assume false and remove.
bool ao_is_finite(float x)
{
    return (floatBitsToUint(x) & 0x7f800000u) != 0x7f800000u;
}

bool ao_is_finite(vec3 v)
{
    return ao_is_finite(v.x) && ao_is_finite(v.y) && ao_is_finite(v.z);
}

// `v` scaled to unit length, or `fallback` when v is zero, tiny or not finite. v is first
// divided by its largest component, so the dot product neither overflows nor underflows.
vec3 ao_safe_normalize(vec3 v, vec3 fallback)
{
    if (!ao_is_finite(v)) return fallback;
    float m = max(max(abs(v.x), abs(v.y)), abs(v.z));
    if (!(m > 1e-30)) return fallback;
    v /= m;
    return v * inversesqrt(dot(v, v)); // dot(v, v) is in [1, 3]
}

// ---- arithmetic every target evaluates alike -----------------------------------------------

// a + (b - a) t: GLSL's mix(a, b, t), written out. Why not mix: Mesa lowers mix to plain
// arithmetic in one of two forms, a + t (b - a) or a (1 - t) + b t, chosen by looking at the
// other mixes in the shader, and its GLSL and SPIR-V front ends hand it differently shaped
// shaders. The same text then interpolated a depth one ulp apart on OpenGL and on Vulkan, and
// a sample exactly at its occlusion threshold flipped: a whole SSAO vote (31/255 at 8
// samples) or a VBAO sector (issue 13's target check). Written out, every target computes the
// same operations.
float ao_lerp(float a, float b, float t)
{
    return a + (b - a) * t;
}

// acos and atan, written out for the same reason: Mesa's GLSL front end builds them from its
// own GLSL built-in library and its SPIR-V front end from NIR's, two polynomials that differ
// in the last bits (a GTAO pixel came out 1/255 apart on GL and on Vulkan). Polynomials fitted
// for aogen (near-minimax, iteratively reweighted least squares in double precision); the
// error of the exact polynomial is below 1.3e-8 rad for acos and 6e-9 rad for atan, under the
// 1.2e-7 a float has at pi/2, so in float they are as good as a driver's own.

// acos(x), x in [-1, 1]: acos(a) = sqrt(1 - a) P(a) on [0, 1], and acos(-a) = pi - acos(a).
float ao_acos(float x)
{
    float a = min(abs(x), 1.0);
    float p = -0.0014411922;
    p = p * a + 0.0072444812;
    p = p * a - 0.0178077109;
    p = p * a + 0.0313346423;
    p = p * a - 0.0503125079;
    p = p * a + 0.0889992192;
    p = p * a - 0.2145998925;
    p = p * a + 1.5707963705;
    float r = sqrt(1.0 - a) * p;
    return mix(r, AO_PI - r, x < 0.0); // a select
}

// atan(y, x) in [-pi, pi]: t = min(|x|, |y|) / max(|x|, |y|) in [0, 1], atan t = t Q(t^2),
// then the octant: pi/2 - r above the diagonal, pi - r for x < 0, and y's sign. 0 at the
// origin; the divisor is at least 1e-30, so only points closer to it than that lose accuracy.
float ao_atan2(float y, float x)
{
    float ax = abs(x), ay = abs(y);
    float t = min(ax, ay) / max(max(ax, ay), 1e-30);
    float t2 = t * t;
    float q = 0.0024461593;
    q = q * t2 - 0.0143560125;
    q = q * t2 + 0.0397009812;
    q = q * t2 - 0.0722731128;
    q = q * t2 + 0.1049489677;
    q = q * t2 - 0.1415999383;
    q = q * t2 + 0.1998570710;
    q = q * t2 - 0.3333258331;
    q = q * t2 + 0.9999998808;
    float r = t * q;
    // mix with a bool is a select (no branch, nothing interpolated)
    r = mix(r, AO_HALF_PI - r, ay > ax);
    r = mix(r, AO_PI - r, x < 0.0);
    return mix(r, -r, y < 0.0);
}

#if defined(AO_FP16)
// The 16-bit forms evaluate in 32 bits: the same operations on every target.
ao_half ao_acos(ao_half x)
{
    return ao_half(ao_acos(float(x)));
}
ao_half ao_atan2(ao_half y, ao_half x)
{
    return ao_half(ao_atan2(float(y), float(x)));
}
#endif

#if defined(AO_MULTI_BOUNCE)
// Multi-bounce (Jimenez et al. 2016, "Practical Real-Time Strategies for Accurate Indirect
// Occlusion", eq. 10). AO counts light that reaches a point straight from the sky; light
// that bounced off the occluders around it arrives too, the more so the higher their albedo
// rho and the more of the sky they hide. The paper ray-traced that multi-bounce visibility
// over many scenes and fitted it by a cubic in the single-bounce visibility v whose
// coefficients are linear in rho:
//     a = 2.0404 rho - 0.3324,  b = -4.7951 rho + 0.6417,  c = 2.7552 rho + 0.6903,
//     multi-bounce visibility = max(v, ((v a + b) v + c) v).
// At v = 1 the cubic is a + b + c = 0.9996 + 0.0005 rho: an open pixel stays 1 (the max),
// and the clamp keeps the rounding at rho = 1 from passing it. At rho = 0 the cubic lies
// under v but near v = 0.97, where it passes it by 1.3e-6: the output is v to far below
// an 8-bit step.
float ao_multi_bounce(float v, float albedo)
{
    float a = 2.0404 * albedo - 0.3324;
    float b = -4.7951 * albedo + 0.6417;
    float c = 2.7552 * albedo + 0.6903;
    return clamp(max(v, ((v * a + b) * v + c) * v), 0.0, 1.0);
}

#if defined(AO_BINDING_GBUFFER_ALBEDO)
// -mbg: each pixel's albedo from the renderer's G-buffer (u_gbuffer_albedo, bindings.hpp's
// gbuffer_albedo role): linear reflectance in .rgb at the screen's resolution (an _SRGB view
// decodes for us), read at the screen pixel the output pixel stands for. One channel of AO holds
// one rho: the albedo's luminance (Rec. 709 weights). The cubic is linear in rho, so its
// value there is the luminance of the three channels' cubics; only the max() tells them
// apart, where a dark channel's cubic falls under v -- exact for grey, at most 0.035 (9/255,
// a saturated red of 0.85 at v = 0.32) for any colour. An engine that wants coloured
// multi-bounce applies ao_multi_bounce per channel to a plain variant's AO. A texel that is
// not finite bounces no light (rho = 0); one outside [0, 1] (a float G-buffer's) is clamped.
ivec2 ao_output_screen_pixel(ivec2 pixel); // common/depth.glsl
float ao_albedo(ivec2 pixel)
{
    float rho = dot(texelFetch(u_gbuffer_albedo, ao_output_screen_pixel(pixel), 0).rgb, vec3(0.2126, 0.7152, 0.0722));
    return ao_is_finite(rho) ? clamp(rho, 0.0, 1.0) : 0.0;
}
#else
// -mb: one albedo for the image, finalize_params::albedo (checked on the host to be in [0, 1]).
float ao_albedo(ivec2 pixel)
{
    return u.albedo;
}
#endif
#endif

// An AO value made safe to write or to read: finite and in [0, 1]. Anything else (a NaN from
// input the guards did not foresee) becomes 1, no occlusion. Passes apply it to what they
// read from the pass before, too.
float ao_finalize(float ao)
{
    return ao_is_finite(ao) ? clamp(ao, 0.0, 1.0) : 1.0;
}

// What a pass writes at output pixel `pixel` (the entry points): ao_finalize's value, and in
// the chain's last pass of a -mb or -mbg variant (AO_MULTI_BOUNCE) the multi-bounce light for
// the albedo there (ao_albedo) on top -- once, on what the renderer reads, never on what a
// later pass would filter.
float ao_output(float ao, ivec2 pixel)
{
    float v = ao_finalize(ao);
#if defined(AO_MULTI_BOUNCE)
    v = ao_multi_bounce(v, ao_albedo(pixel));
#endif
    return v;
}

// ---- the value a pass carries: the AO, or the AO and its bent normal -------------------
// A bent-normal variant (-bn: AO_BENT_NORMALS) carries per pixel the AO and its bent normal
// -- the cosine-weighted mean of the unoccluded directions, in view space (gtao.glsl) -- as
// one vec4 (ao, normal.xyz) through every pass; every other variant a float. The filter
// passes weigh and sum an ao_value exactly as they would the AO alone: the weighted sum of
// the normals is the direction of their weighted mean, renormalised when it is written, so
// one template serves both and a -bn variant's AO is its twin's bit for bit.
//   Stored (ao_output_texel) in a four-channel image (aogen::codegen::output_format_of):
//   .r the AO as ao_output writes it, .gba the unit normal as (127 n + 128) / 255 -- in 8
//   bits the byte 128 + 127 n, within 0.5 degrees. Not n * 0.5 + 0.5: that puts a zero
//   component at byte 127.5, a rounding's midpoint, where a one-ulp difference between two
//   compilers of the same shader (GL's GLSL and Vulkan's SPIR-V front ends) picks another
//   byte; here zero is byte 128 exactly. A pixel with no bent normal (background, no surface
//   normal) stores the zero vector, (128, 128, 128) / 255, which a reader recognises by its
//   length and the filters never see (they skip background by weight).
#if defined(AO_BENT_NORMALS)
#if defined(AO_STAGE_FRAGMENT)
#error aogen: bent normals need the compute stage (a fragment pass's target is one channel)
#endif
#define ao_value vec4
#define ao_value4 mat4 // four pixels' values (an upsample invocation's 2 x 2): column k, pixel k
ao_value ao_make_value(float ao, vec3 bent_normal) { return vec4(ao, bent_normal); }
float ao_value_ao(ao_value v) { return v.x; }
vec3 ao_value_bent(ao_value v) { return v.yzw; }
// A unit normal as (127 n + 128) / 255; the zero vector (and anything not finite) as 128 / 255.
vec3 ao_encode_normal(vec3 n)
{
    float length_squared = dot(n, n);
    if (!(length_squared > 1e-12 && length_squared < 1e30)) return vec3(128.0 / 255.0); // NaN fails too
    return clamp(n * inversesqrt(length_squared) * (127.0 / 255.0) + (128.0 / 255.0), 0.0, 1.0);
}
vec4 ao_output_texel(ao_value v, ivec2 pixel) { return vec4(ao_output(v.x, pixel), ao_encode_normal(v.yzw)); }
ao_value4 ao_quad_of(vec4 ao) { return mat4(vec4(ao.x, 0.0, 0.0, 0.0), vec4(ao.y, 0.0, 0.0, 0.0), vec4(ao.z, 0.0, 0.0, 0.0), vec4(ao.w, 0.0, 0.0, 0.0)); }
#if defined(AO_BINDING_AO_INPUT)
// What a filter pass reads of the pass before at q: its AO made safe, its normal decoded.
ao_value ao_read_input(ivec2 q)
{
    vec4 texel = texelFetch(u_ao_input, q, 0);
    return vec4(ao_finalize(texel.r), (texel.gba * 255.0 - 128.0) / 127.0);
}
#endif
#else
#define ao_value float
#define ao_value4 vec4
ao_value ao_make_value(float ao, vec3 bent_normal) { return ao; }
float ao_value_ao(ao_value v) { return v; }
vec3 ao_value_bent(ao_value v) { return vec3(0.0); }
vec4 ao_output_texel(ao_value v, ivec2 pixel) { return vec4(ao_output(v, pixel), 0.0, 0.0, 1.0); }
ao_value4 ao_quad_of(vec4 ao) { return ao; }
#if defined(AO_BINDING_AO_INPUT)
ao_value ao_read_input(ivec2 q) { return ao_finalize(texelFetch(u_ao_input, q, 0).r); }
#endif
#endif
// ao_quad_of(ao): four pixels' values from their AO alone, with no bent normal (what an
// upsample invocation's 2 x 2 holds when every pixel is open).
// An open pixel's value: AO exactly 1, no bent normal.
ao_value ao_open_value() { return ao_make_value(1.0, vec3(0.0)); }
