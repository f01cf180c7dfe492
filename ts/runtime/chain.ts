// ---- chain.ts: a variant's passes and what its chain uploads (aogen/plan.hpp, chain_inputs.hpp)

export type Technique = "ssao" | "gtao" | "vbao" | "sao";

/** One pass of a variant, as `aogen generate` planned and compiled it. */
export interface PassInfo {
    /** ao, blur_x, blur_y, blur, blur_denoise, blur_denoise3, history, upsample, prefilter (bindings.hpp's pass kinds). */
    readonly pass: string;
    readonly stage: "compute" | "fragment";
    /** The pass's WGSL: its compute shader, or its fragment shader (drawn with `vertexWgsl`'s fullscreen triangle). */
    readonly wgsl: string;
    readonly vertexWgsl?: string;
    readonly entryPoint: string;
    /** Compute: @workgroup_size; dispatch ceil(width / pixelsPerInvocation / x) x ceil(height / pixelsPerInvocation / y) groups
     *  over its output's size -- the prefilter's over the screen's. */
    readonly workgroupSize?: readonly [number, number, number];
    readonly pixelsPerInvocation: number;
    /** The output is the screen's size (the upsample); otherwise the AO target's, or the prefilter's atlas. */
    readonly screenSized: boolean;
    /** The prefilter's (a -mip variant): its output is the r32float atlas of the depth MIP chain made for this many
     *  levels (depthMipAtlasSize; the most a variant may have: a shorter chain lies at the same places). */
    readonly atlasLevels?: number;
    /** Its uniform block, laid out under WGSL's rules. */
    readonly block: BlockLayout;
    /** What it binds, bind group 0 (bindGroupLayoutDescriptor). */
    readonly bindings: readonly BindingInfo[];
}

/** A variant of the module: its name (aogen's canonical name) and what a chain of it needs. */
export interface VariantInfo {
    readonly name: string;
    readonly technique: Technique;
    readonly stage: "compute" | "fragment";
    readonly halfResolution: boolean;
    /** SSAO's kernel samples or SAO's spiral taps; 0 for GTAO and VBAO. */
    readonly samples: number;
    /** GTAO's and VBAO's slices and steps per side; 0 for SSAO and SAO. */
    readonly slices: number;
    readonly steps: number;
    /** The turn the noise makes over a frame sequence's period: 1 (SSAO, SAO) or half a slice's. */
    readonly periodTurns: number;
    readonly passes: readonly PassInfo[];
}

/** `name`'s variant, or an AogenError naming the variants this module holds. */
export function variantInfo(name: string): VariantInfo {
    const v = variants[name];
    if (v) return v;
    const names = Object.keys(variants);
    const shown = names.length > 8 ? names.slice(0, 8).join(", ") + `, ... (${names.length} in all)` : names.join(", ");
    throw new AogenError("variant", `'${name}' is not in this module`, `valid: ${shown}`);
}

/** The AO target's size for a screen of width x height: the screen's, or half of it rounded up. */
export function targetSize(v: VariantInfo, width: number, height: number): [number, number] {
    return v.halfResolution ? [Math.floor((width + 1) / 2), Math.floor((height + 1) / 2)] : [width, height];
}

/** Level `level` of a w x h depth buffer (aogen/depth_mips.hpp's level_size): a texel covers 2^level x 2^level pixels, the last row and column fewer; at least 1 x 1. */
function depthMipLevelSize(w: number, h: number, level: number): [number, number] {
    const k = 2 ** level;
    return [Math.max(1, Math.floor((w + k - 1) / k)), Math.max(1, Math.floor((h + k - 1) / k))];
}

/** The r32float atlas holding levels 1 .. levels - 1 of a w x h depth buffer (depth_mips.hpp's atlas_size): level 1 at the left,
 *  levels 2, 3, ... stacked in a column beside it; 0 x 0 for one level. */
export function depthMipAtlasSize(width: number, height: number, levels: number): [number, number] {
    if (levels <= 1) return [0, 0];
    const [w1, h1] = depthMipLevelSize(width, height, 1);
    if (levels === 2) return [w1, h1];
    let column = 0;
    for (let k = 2; k < levels; ++k) column += depthMipLevelSize(width, height, k)[1];
    return [w1 + depthMipLevelSize(width, height, 2)[0], Math.max(h1, column)];
}

/** What one frame of a chain reads besides the G-buffer (chain_settings). */
export interface ChainSettings {
    readonly camera: Camera;
    /** Any subset of the settings; the rest are aogen's defaults. */
    readonly settings?: SettingsInput;
    /** 0 (a still frame) unless accumulating frames; an unsigned 32-bit integer. */
    readonly frame?: number;
    readonly frameSequence?: FrameSequence;
    /** A history pass's previous frame camera (none: the camera stood still). */
    readonly previousCamera?: Camera;
    /** Drop the history this frame: a cut, a resize, a teleport. */
    readonly resetHistory?: boolean;
}

/** What a chain uploads: each pass's uniform bytes in pass order, and the noise tile. */
export interface ChainInputs {
    readonly uniforms: ArrayBuffer[];
    readonly noiseSize: number;
    /** noiseSize x noiseSize texels, rgba32float. */
    readonly noise: ArrayBuffer;
}

/**
 * Frame `chain.frame`'s inputs of variant `variant` on a screen of width x height pixels --
 * codegen::plan::inputs, byte for byte, under WGSL's rules. Throws an AogenError naming a
 * setting out of range, a size out of range or a variant this module does not hold.
 */
export function chainInputs(variant: string | VariantInfo, chain: ChainSettings, width: number, height: number): ChainInputs {
    const v = typeof variant === "string" ? variantInfo(variant) : variant;
    requireInteger("screen width", width, 1, 65536);
    requireInteger("screen height", height, 1, 65536);
    const s = resolveSettings(chain.settings);
    const sequence = chain.frameSequence ?? "van_der_corput";
    const frame = chain.frame ?? 0;
    const noiseSize = v.technique === "ssao" ? s.ssao.noise_size : 4;
    const target = targetSize(v, width, height);
    const e: Extras = { frameRotation: frameRotation(v.periodTurns, sequence, frame), frameStep: stepOffset(sequence, frame), albedo: s.finalize.albedo };
    const uniforms = v.passes.map((p) =>
        p.pass === "ao" ? packAo(v, p.block, s, chain.camera, target, noiseSize, e)
        : p.pass === "history" ? packHistory(p.block, s, chain.camera, chain.previousCamera ?? chain.camera, [width, height], chain.resetHistory ?? false)
        : packBlur(p.block, s, chain.camera, target));
    return { uniforms, noiseSize, noise: float32Bytes(noiseRotations(noiseSize, s.ssao.noise_seed)) };
}
