// ---- uniforms.ts: each pass's uniform bytes (aogen/uniforms.hpp, chain_inputs.hpp) ------------
// Every block is laid out by aogen under WGSL's uniform rules (layout::rules::wgsl_uniform) and
// carried here as data (BlockLayout): the packer writes each member's value at its offset as
// layout_writer.hpp does, so the bytes are pack_*'s, byte for byte.

/** One member of a uniform block, laid out: where each of its scalars goes. */
export interface MemberLayout {
    readonly name: string;
    readonly offset: number;
    readonly scalar: "f32" | "i32" | "u32";
    readonly columns: number; // 1, or a matrix's columns
    readonly rows: number; // a vector's or a matrix column's components
    readonly elements: number; // 1, or an array's length
    readonly arrayStride: number;
    readonly matrixStride: number;
}

/** A uniform block laid out under WGSL's rules: its struct's name, its size and its members. */
export interface BlockLayout {
    readonly name: string;
    readonly size: number;
    readonly members: readonly MemberLayout[];
}

/** The view and projection every pass reads; both column-major (Mat4). */
export interface Camera {
    /** World to view space: rotates world-space G-buffer normals into view space. */
    readonly worldToView: Mat4;
    /** View to clip space, aogen's conventions: right-handed view space looking down -z, clip y up, depth in [0, 1]. */
    readonly proj: Mat4;
}

/** Writes members of one block into its bytes (layout::writer). */
class BlockWriter {
    private readonly view: DataView;
    readonly bytes: ArrayBuffer;

    constructor(private readonly block: BlockLayout) {
        this.bytes = new ArrayBuffer(block.size);
        this.view = new DataView(this.bytes);
    }

    /** Member `name`'s values, column after column, element after element. */
    set(name: string, values: ArrayLike<number>): void {
        const m = this.block.members.find((x) => x.name === name);
        if (!m) throw new AogenError(`${this.block.name}.${name}`, "is not a member", `valid: ${this.block.members.map((x) => x.name).join(", ")}`);
        const expected = m.elements * m.columns * m.rows;
        if (values.length !== expected) throw new AogenError(`${this.block.name}.${name}`, `given ${values.length} values`, `valid: ${expected} values`);
        for (let e = 0; e < m.elements; ++e)
            for (let c = 0; c < m.columns; ++c)
                for (let r = 0; r < m.rows; ++r) {
                    const at = m.offset + e * m.arrayStride + c * m.matrixStride + 4 * r;
                    const v = values[(e * m.columns + c) * m.rows + r]!;
                    if (m.scalar === "f32") this.view.setFloat32(at, v, true);
                    else if (m.scalar === "i32") this.view.setInt32(at, v, true);
                    else this.view.setUint32(at, v, true);
                }
    }
}

/** What every AO block carries besides its technique's settings (uniforms_common.hpp's extras). */
interface Extras {
    readonly frameRotation: [number, number];
    readonly frameStep: number;
    readonly albedo: number;
}

/** A size in (0, 65536], or an AogenError (require_finite_above). */
function requireSize(subject: string, value: number): void {
    if (!Number.isFinite(value) || !(value > 0) || value > 65536)
        throw new AogenError(subject, `${formatFloat(value)} is out of range`, "valid: > 0 and <= 65536");
}

/** The camera members every AO block starts with (uniforms_common.hpp's set_camera). */
function setCamera(w: BlockWriter, camera: Camera, target: [number, number], noiseSize: number, e: Extras): void {
    requireSize("uniforms target width", target[0]);
    requireSize("uniforms target height", target[1]);
    w.set("proj", floats(camera.proj, "camera.proj"));
    w.set("inv_proj", inverse(camera.proj));
    w.set("world_to_view", floats(camera.worldToView, "camera.worldToView"));
    w.set("noise_scale", [Math.fround(target[0] / noiseSize), Math.fround(target[1] / noiseSize)]);
    w.set("texel_size", [Math.fround(1 / target[0]), Math.fround(1 / target[1])]);
    w.set("frame_rotation", e.frameRotation);
    w.set("albedo", [e.albedo]);
}

/** Each technique's members after the camera's, by name: what its settings_member table writes. */
const techniqueMembers: { readonly [T in Technique]: { readonly [member: string]: (s: Settings, e: Extras) => number } } = {
    ssao: { radius: (s) => s.ssao.radius, bias: (s) => s.ssao.bias, strength: (s) => s.ssao.strength, power: (s) => s.ssao.power, intensity: (s) => s.ssao.intensity },
    gtao: {
        radius: (s) => s.gtao.radius, thickness_bias: (s) => s.gtao.thickness_bias, strength: (s) => s.gtao.strength,
        falloff_range: (s) => s.gtao.falloff_range, thin_occluder: (s) => s.gtao.thin_occluder, frame_step: (_, e) => e.frameStep,
    },
    vbao: { radius: (s) => s.vbao.radius, thickness: (s) => Math.fround(s.vbao.thickness * s.vbao.radius), strength: (s) => s.vbao.strength, frame_step: (_, e) => e.frameStep },
    sao: { radius: (s) => s.sao.radius, bias: (s) => s.sao.bias, intensity: (s) => s.sao.intensity, contrast: (s) => s.sao.contrast },
};

/** The camera members: every AO block's first seven (uniforms_common.hpp's camera_members). */
const cameraMembers = ["proj", "inv_proj", "world_to_view", "noise_scale", "texel_size", "frame_rotation", "albedo"];

/** The AO pass's block of variant `v` (its technique's pack_*). */
function packAo(v: VariantInfo, block: BlockLayout, s: Settings, camera: Camera, target: [number, number], noiseSize: number, e: Extras): ArrayBuffer {
    const w = new BlockWriter(block);
    setCamera(w, camera, target, noiseSize, e);
    const members = techniqueMembers[v.technique];
    for (const m of block.members) {
        if (cameraMembers.includes(m.name)) continue;
        if (m.name === "kernel") w.set("kernel", makeKernel(s.ssao.kernel, v.samples, s.ssao.kernel_seed));
        else if (m.name === "spiral") w.set("spiral", spiralTaps(v.samples));
        else if (members[m.name]) w.set(m.name, [members[m.name]!(s, e)]);
        else throw new AogenError(`${block.name}.${m.name}`, "has no value in this module", "valid: the members of aogen's blocks (regenerate the module with this aogen)");
    }
    return w.bytes;
}

/** BlurUniforms: every filter pass's and the upsample's (pack_blur). */
function packBlur(block: BlockLayout, s: Settings, camera: Camera, target: [number, number]): ArrayBuffer {
    requireSize("uniforms target width", target[0]);
    requireSize("uniforms target height", target[1]);
    const w = new BlockWriter(block);
    w.set("inv_proj", inverse(camera.proj));
    w.set("texel_size", [Math.fround(1 / target[0]), Math.fround(1 / target[1])]);
    w.set("raw_depth_k", [s.blur.raw_depth_k]);
    w.set("linear_sharpness", [s.blur.linear_sharpness]);
    w.set("albedo", [s.finalize.albedo]);
    return w.bytes;
}

/** The uv offset per unit of a motion vector (uniforms.hpp's motion_scale), in float arithmetic. */
function motionScale(m: MotionConvention, screen: [number, number]): [number, number] {
    const unitX = m.units === "uv" ? 1 : m.units === "ndc" ? 0.5 : Math.fround(1 / screen[0]);
    const unitY = m.units === "uv" ? 1 : m.units === "ndc" ? 0.5 : Math.fround(1 / screen[1]);
    const sign = m.direction === "current_to_previous" ? 1 : -1;
    const flip = m.y === "up" ? -1 : 1;
    return [Math.fround(sign * unitX), Math.fround(Math.fround(sign * flip) * unitY)];
}

/** HistoryUniforms (pack_history): this and the previous frame's camera, the clamp, the blend. */
function packHistory(block: BlockLayout, s: Settings, current: Camera, previous: Camera, screen: [number, number], reset: boolean): ArrayBuffer {
    requireSize("uniforms screen width", screen[0]);
    requireSize("uniforms screen height", screen[1]);
    const h = s.history;
    const w = new BlockWriter(block);
    w.set("inv_proj", inverse(current.proj));
    // A camera that stood still moves nothing, exactly (M M^-1 in floats is the identity only to a few ulps).
    const now = floats(current.worldToView, "camera.worldToView"), before = floats(previous.worldToView, "previousCamera.worldToView");
    const still = now.every((x, i) => Object.is(x, before[i])); // bit for bit, as C++'s memcmp
    w.set("view_to_previous_view", still ? identity() : multiply(before, inverse(now)));
    w.set("previous_proj", floats(previous.proj, "previousCamera.proj"));
    w.set("motion_scale", motionScale(h.motion, screen));
    w.set("blend", [h.blend]);
    w.set("clamp_kind", [historyClamps.indexOf(h.clamp)]);
    w.set("clamp_width", [h.clamp === "range" ? h.range : h.clamp === "min_max" ? h.min_max_widening : h.variance_gamma]);
    w.set("depth_tolerance", [Math.fround(Math.log2(Math.fround(1 + h.depth_tolerance)))]);
    w.set("reset", [reset ? 1 : 0]);
    w.set("albedo", [s.finalize.albedo]);
    return w.bytes;
}
