// history.glsl -- the history pass (-hist, -histmv): this frame's filtered AO blended with the
// chain's own AO of the frames before, as UE5's, HDRP's and three.js's GTAO do after their
// spatial filter. At the AO target's resolution, after the blur, before the upsample.
// Uniform block: HistoryUniforms (aogen/uniforms.hpp; history_params in aogen/params.hpp).
//
// Bindings (aogen/bindings.hpp's history family):
//   AO_BINDING_DEPTH           this frame's depth, full resolution
//   AO_BINDING_AO_INPUT        this frame's filtered AO (the blur's output; the AO pass's
//                              without a blur), the AO target's size
//   AO_BINDING_HISTORY         the previous frame's history: what AO_BINDING_HISTORY_OUTPUT
//                              held after the previous frame (the engine swaps the two)
//   AO_BINDING_HISTORY_OUTPUT  this frame's history, rgba16f, the AO target's size (compute; a
//                              fragment pass writes it as colour attachment 1)
//   AO_BINDING_MOTION          (-histmv) the renderer's motion vectors, full resolution, .rg
//   AO_BINDING_OUTPUT          the AO, as every filter pass writes it: what the upsample (or
//                              the renderer) reads. The history is kept apart from it so that
//                              the AO image keeps the chain's format and, at a reset, its
//                              bytes are the blur's own.
//
// THE HISTORY TEXEL: .r the AO (before any multi-bounce: the output's finalize step is
// applied to what is written to the output, never to what is kept); .g log2 of the view
// depth of the surface the pixel saw (log2: 16-bit floats then hold every scale, from
// micrometres to kilometres, to 2^-11 of a unit of log2 -- depth to 0.1 % and better); .b the
// frames it holds, n (0: none -- a cleared history, background, a pixel just uncovered).
//
// THE STEPS, per target pixel p (it stands for full-resolution pixel P = ao_full_pixel(p)):
// 1. Where was the surface point x at P a frame ago? Its view position x (this frame's
//    inverse projection) moved rigidly into the previous view: x' = view_to_previous_view x.
//    With the camera alone (-hist) the previous uv is x' projected by the previous
//    projection; behind the previous camera (clip w <= 0) it was nowhere on screen. With
//    motion vectors (-histmv) the previous uv is uv + motion_scale * m(P), whatever moved.
//    Either way x' gives the depth x had then, -x'.z (exact for a static surface; for a moving
//    one off by its own motion in depth along the view, which the tolerance takes).
// 2. The history there. A texel counts by how far it can stand for this point: 0 when it is not
//    finite or holds no frame; else by its depth against log2 -x'.z -- 1 within half of
//    log2(1 + depth_tolerance), 0 past all of it (another surface's history: a disocclusion),
//    linear between. The bilinear read of the 2 x 2 texels about the previous uv, each by its
//    bilinear weight times its count, is mixed toward the Catmull-Rom read of the 4 x 4 about
//    it (each tap's weight times its count, over the sum of those: the taps of the point's own
//    surface) as that sum goes from 0.5 to 1: Catmull-Rom reproduces quadratics, so the history does
//    not blur a little more each frame the camera moves, as a bilinear read makes it
//    (measured: a lower error in motion, BENCHMARKS.md). The history is trusted as far as the
//    bilinear weights' sum reaches 0.5 (its confidence): a sliver of the footprint as little as
//    it covers. Every one of these is continuous in the inputs -- a band, never a step --
//    so a depth or a position one ulp apart on two compilers moves the output by about as
//    much. A still camera lands on the texel itself (weights 0, 1, 0, 0 each way), so its
//    history is exactly the pixel's own.
// 3. The clamp (history_params::clamp): the history held to this frame's neighbourhood of
//    filtered AO -- +-range about the pixel (UE5), the 3 x 3 [min, max] widened (HDRP), or the
//    3 x 3 mean +- gamma standard deviations (variance clipping).
// 4. The blend: out = mix(history, this frame, w), w = max(blend, 1 / (n + 1)): the first
//    frames of a history average evenly (a still camera's n-th frame is the mean of its n
//    frames), later ones decay by 1 - blend per frame; then mixed toward this frame as far as
//    the history is not trusted. n' = min(1 + n * confidence, 1024).
// With `reset` (a camera cut, a resize, the first frame), no history, or background, the
// pass writes this frame's AO as it read it -- the same bytes as the chain without the pass --
// and a history of n' = 1 (background: n' = 0, AO 1).
//
// NUMERICS: every history texel is tested for finiteness before it is used, so a NaN or an
// infinity planted in the history is dropped the frame it is read and never written back;
// the AO written is a blend of finite values in [0, 1].

#if !defined(AO_PASS_HISTORY)
#error aogen: history.glsl is the history pass
#endif
#if (defined(AO_HISTORY_CAMERA) + defined(AO_HISTORY_MOTION_VECTORS)) != 1
#error aogen: exactly one of AO_HISTORY_CAMERA, AO_HISTORY_MOTION_VECTORS must be defined
#endif
#if !defined(AO_BINDING_AO_INPUT) || !defined(AO_BINDING_HISTORY)
#error aogen: AO_BINDING_AO_INPUT and AO_BINDING_HISTORY are not defined (codegen writes the bindings)
#endif
#if defined(AO_STAGE_COMPUTE) && !defined(AO_BINDING_HISTORY_OUTPUT)
#error aogen: a compute history pass stores its history to AO_BINDING_HISTORY_OUTPUT, which is not defined
#endif
#if defined(AO_HISTORY_MOTION_VECTORS) && !defined(AO_BINDING_MOTION)
#error aogen: a -histmv pass reads motion vectors, and AO_BINDING_MOTION is not defined
#endif

// u_ao_input, u_history, u_history_output (compute), u_motion: declared by aogen::codegen (aogen/bindings.hpp).

// This frame's history texel for target pixel `p`: a storage image in compute; in fragment the
// pass's second colour attachment (location 1, rgba16f), the AO being the first
// (entry_fragment.glsl) -- a render target per image, as engines draw their temporal passes.
#if defined(AO_STAGE_FRAGMENT)
layout(location = 1) out vec4 o_history;
void ao_store_history(ivec2 p, vec4 texel) { o_history = texel; }
#else
void ao_store_history(ivec2 p, vec4 texel) { imageStore(u_history_output, p, texel); }
#endif

// The most frames a history texel counts: enough for every blend (1 / 0.01 = 100), exact in 16 bits.
const float AO_HISTORY_MAX_FRAMES = 1024.0;

// The history's depth code of a view distance (THE HISTORY TEXEL).
float ao_history_depth_code(float view_distance)
{
    return log2(view_distance);
}

// Step 1: the uv the surface point at full-resolution pixel `full` (raw depth `depth`) had in
// the previous frame, and its depth code then; false when it was behind the previous camera
// or the arithmetic left the finite numbers.
bool ao_history_previous(ivec2 full, float depth, out vec2 previous_uv, out float expected)
{
    vec2 uv = ao_pixel_uv(full);
    vec4 x = u.view_to_previous_view * vec4(ao_view_position_uv(uv, depth), 1.0);
    expected = ao_history_depth_code(-x.z);
#if defined(AO_HISTORY_MOTION_VECTORS)
    previous_uv = uv + u.motion_scale * texelFetch(u_motion, full, 0).rg;
#else
    vec4 clip = u.previous_proj * x;
    previous_uv = vec2(0.0);
    if (!(clip.w > 0.0)) return false; // behind the previous camera (NaN fails too)
    vec2 ndc = clip.xy / clip.w;
    previous_uv = vec2(ndc.x * 0.5 + 0.5, 0.5 - ndc.y * 0.5); // ndc.y = 1 - 2 uv.y (common/depth.glsl)
#endif
    return -x.z > 0.0 && ao_is_finite(expected) && ao_is_finite(previous_uv.x) && ao_is_finite(previous_uv.y);
}

// How far history texel `h` can stand for a surface of depth code `expected`: 0 when it is not
// finite or holds no frame; else by its depth, 1 within half the tolerance, 0 past it, and
// linear between -- a band, not a step, so that a depth one ulp apart on two compilers of the
// same text (GLSL's and SPIR-V's front ends) moves the output by about an ulp, never by a
// texel taken or dropped.
float ao_history_weight(vec4 h, float expected)
{
    bool finite = ao_is_finite(h.r) && ao_is_finite(h.g) && h.b >= 1.0 && h.b <= AO_HISTORY_MAX_FRAMES;
    if (!finite) return 0.0;
    return clamp(2.0 - 2.0 * abs(h.g - expected) / u.depth_tolerance, 0.0, 1.0);
}

// Catmull-Rom's four weights for taps at -1, 0, 1, 2 about a point `f` (in [0, 1)) past tap 0.
vec4 ao_catmull_rom(float f)
{
    return vec4(f * (-0.5 + f * (1.0 - 0.5 * f)), 1.0 + f * f * (-2.5 + 1.5 * f), f * (0.5 + f * (2.0 - 1.5 * f)), f * f * (-0.5 + 0.5 * f));
}

// Step 2: (AO, frames, confidence) of the history at `previous_uv` for a surface of depth code
// `expected`: the bilinear read of the 2 x 2 texels about it, each by its bilinear weight times
// ao_history_weight, mixed toward the Catmull-Rom read of the 4 x 4 about it. That read weighs
// each tap by its Catmull-Rom weight times its count and divides by the sum S of those: the
// quadratic through the taps of this surface. It is mixed in by 2 S - 1 clamped to [0, 1]
// (all 16 count: S = 1, Catmull-Rom alone; a corner tap another surface's: S a little below
// 1, nearly all Catmull-Rom -- measured lower in motion than a mix by the least count, which
// gave a thin surface's edge pixels the bilinear read's blur; S <= 0.5: bilinear alone, and the
// division never meets a small S).
// Confidence: the bilinear weights' sum over 0.5, at most 1 -- half the footprint is enough, a
// sliver of it trusted as little as it covers; a bilinear texel off the image weighs 0, so a
// point leaving the previous screen fades out of its history. Catmull-Rom's taps are clamped
// to the image, so its read does not jump where the point nears an edge. (Its negative lobes
// may take the AO past [0, 1]: it is clamped.)
vec3 ao_history_fetch(vec2 previous_uv, float expected)
{
    ivec2 last = textureSize(u_history, 0) - 1;
    // The target pixel a uv stands for, continuously: full-resolution pixel centre P + 0.5 is
    // uv * size, and target pixel p stands for P = p (full) or 2 p (half).
    vec2 t = previous_uv * vec2(ao_depth_size()) - 0.5;
#if defined(AO_HALF_RESOLUTION)
    t *= 0.5;
#endif
    vec2 base = floor(t);
    vec2 f = t - base;
    ivec2 i0 = ivec2(base);
    float weight = 0.0, ao = 0.0, frames = 0.0;
    for (int k = 0; k < 4; ++k) {
        ivec2 o = ivec2(k & 1, k >> 1);
        ivec2 q = i0 + o;
        if (any(lessThan(q, ivec2(0))) || any(greaterThan(q, last))) continue; // off the image: its weight fades to 0 there
        vec4 h = texelFetch(u_history, q, 0);
        float w = (o.x == 1 ? f.x : 1.0 - f.x) * (o.y == 1 ? f.y : 1.0 - f.y) * ao_history_weight(h, expected);
        if (!(w > 0.0)) continue;
        weight += w;
        ao += w * clamp(h.r, 0.0, 1.0);
        frames += w * h.b;
    }
    if (!(weight > 1e-6)) return vec3(0.0);
    ao /= weight, frames /= weight;
    // Catmull-Rom over the 4 x 4 taps that count: a bilinear read blurs the history a little
    // every frame it moves, and the blur adds up.
    vec4 wx = ao_catmull_rom(f.x), wy = ao_catmull_rom(f.y);
    float sharp = 0.0, sum = 0.0;
    for (int j = 0; j < 4; ++j) {
        for (int i = 0; i < 4; ++i) {
            vec4 h = texelFetch(u_history, clamp(i0 + ivec2(i - 1, j - 1), ivec2(0), last), 0);
            float w = wx[i] * wy[j] * ao_history_weight(h, expected);
            if (w != 0.0) sharp += w * h.r, sum += w; // finite: a texel that is not has weight 0
        }
    }
    float share = clamp(2.0 * sum - 1.0, 0.0, 1.0);
    if (share > 0.0) ao = mix(ao, clamp(sharp / sum, 0.0, 1.0), share);
    return vec3(ao, frames, min(weight * 2.0, 1.0));
}

// Step 3: the interval the history is clamped to, for this frame's AO `c` at target pixel `p`.
vec2 ao_history_bounds(ivec2 p, float c)
{
    int kind = u.clamp_kind; // history_clamp: 0 none, 1 range, 2 min_max, 3 variance
    if (kind == 0) return vec2(0.0, 1.0);
    if (kind == 1) return vec2(c - u.clamp_width, c + u.clamp_width);
    ivec2 size = max(textureSize(u_ao_input, 0), ivec2(1));
    float lo = c, hi = c, sum = 0.0, sum_squares = 0.0, count = 0.0;
    for (int dy = -1; dy <= 1; ++dy) {
        for (int dx = -1; dx <= 1; ++dx) {
            ivec2 q = p + ivec2(dx, dy);
            if (q.x < 0 || q.y < 0 || q.x >= size.x || q.y >= size.y) continue;
            float a = ao_value_ao(ao_read_input(q));
            lo = min(lo, a), hi = max(hi, a);
            sum += a, sum_squares += a * a, count += 1.0;
        }
    }
    if (kind == 2) return vec2(lo - u.clamp_width, hi + u.clamp_width);
    float mean = sum / count;
    float deviation = sqrt(max(sum_squares / count - mean * mean, 0.0));
    return vec2(mean - u.clamp_width * deviation, mean + u.clamp_width * deviation);
}

ao_value ao_pass(ivec2 p)
{
    ivec2 full = ao_full_pixel(p);
    float depth = ao_load_depth(full);
    if (ao_is_background(depth)) {
        ao_store_history(p, vec4(1.0, 0.0, 0.0, 0.0));
        return ao_open_value();
    }
    ao_value current = ao_read_input(p);
    float c = ao_value_ao(current);
    float result = c, frames = 1.0;
    vec2 previous_uv;
    float expected;
    bool same_size = all(equal(textureSize(u_history, 0), ao_target_size()));
    if (u.reset < 0.5 && same_size && ao_history_previous(full, depth, previous_uv, expected)) {
        vec3 history = ao_history_fetch(previous_uv, expected);
        if (history.z > 0.0) {
            vec2 bounds = ao_history_bounds(p, c);
            float held = clamp(history.x, bounds.x, bounds.y);
            // Step 4, as far as the history is trusted (its confidence: 1 but at an edge).
            result = mix(c, mix(held, c, max(u.blend, 1.0 / (history.y + 1.0))), history.z);
            frames = min(1.0 + history.y * history.z, AO_HISTORY_MAX_FRAMES);
        }
    }
    float own = ao_history_depth_code(-ao_view_position_uv(ao_pixel_uv(full), depth).z);
    ao_store_history(p, ao_is_finite(own) ? vec4(result, own, frames, 0.0) : vec4(result, 0.0, 0.0, 0.0));
    return ao_make_value(result, ao_value_bent(current));
}
