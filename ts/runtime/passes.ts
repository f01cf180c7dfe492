// ---- passes.ts: a variant's chain on a WebGPU device (pipelines, bind groups, dispatches) ------
// What an engine's pass class needs and should not write: each pass's bind group layout (the
// webgpu binding model of aogen/bindings.hpp, carried per pass as PassInfo.bindings), its
// pipeline, its uniform buffer and intermediate target, and the commands that run the chain:
//
//     const chain = AoChain.create(device, "ssao-s16-half-bilateral-gbufworld-std-persp-cs", 1920, 1080);
//     chain.update({ camera, settings: { ssao: { radius: 0.8 } } });   // each frame: uniforms, noise
//     chain.record(encoder, { depth, normals, output });              // each frame: every pass
//
// `output` is the chain's last target at chain.outputSize: rgba8unorm with STORAGE_BINDING for a
// compute variant (the AO in .r), r8unorm with RENDER_ATTACHMENT for a fragment one. Every
// texture's format and size is checked before anything is recorded.

/** One binding of a pass (bind group 0), as aogen planned it. */
export interface BindingInfo {
    readonly binding: number;
    /** uniforms, depth, normals, noise, ao_input, output, depth_mips, gbuffer_albedo, history, history_output, motion (bindings.hpp's roles). */
    readonly role: string;
    readonly kind: "uniform_buffer" | "sampled_image" | "sampler" | "storage_image";
    /** A storage image's WebGPU format. */
    readonly format?: GPUTextureFormat;
}

// WebGPU's flag values (the spec's; the globals GPUShaderStage, GPUTextureUsage and
// GPUBufferUsage are not defined everywhere this module runs, e.g. before a Node.js binding sets them).
const shaderStage = { fragment: 0x2, compute: 0x4 } as const;
const textureUsage = { copySrc: 0x01, copyDst: 0x02, textureBinding: 0x04, storageBinding: 0x08, renderAttachment: 0x10 } as const;
const bufferUsage = { copyDst: 0x08, uniform: 0x40 } as const;

/** Pass `p`'s bind group layout: every texture unfilterable-float (read with textureLoad or gathered), every sampler non-filtering. */
export function bindGroupLayoutDescriptor(p: PassInfo): GPUBindGroupLayoutDescriptor {
    const visibility = p.stage === "compute" ? shaderStage.compute : shaderStage.fragment;
    return {
        label: `aogen ${p.pass}`,
        entries: p.bindings.map((b): GPUBindGroupLayoutEntry => {
            switch (b.kind) {
            case "uniform_buffer": return { binding: b.binding, visibility, buffer: { type: "uniform" } };
            case "sampled_image": return { binding: b.binding, visibility, texture: { sampleType: "unfilterable-float" } };
            case "sampler": return { binding: b.binding, visibility, sampler: { type: "non-filtering" } };
            case "storage_image": return { binding: b.binding, visibility, storageTexture: { access: "write-only", format: b.format! } };
            }
        }),
    };
}

/** What a chain reads and writes of the engine's, each frame: all of the screen's size but the output. */
export interface ChainTextures {
    /** The depth buffer: r32float or depth32float. */
    readonly depth: GPUTexture;
    /** G-buffer normals (world or view, as the variant says) in .xyz: rgba16float or rgba32float. Not for -recon variants. */
    readonly normals?: GPUTexture;
    /** The G-buffer's albedo in .rgb (a -mbg variant's last pass): rgba8unorm, rgba16float or rgba32float. */
    readonly albedo?: GPUTexture;
    /** The renderer's motion vectors in .rg (a -histmv variant): rg16float, rg32float or rgba16float. */
    readonly motion?: GPUTexture;
    /** The chain's output, at outputSize: rgba8unorm (compute, STORAGE_BINDING) or r8unorm (fragment, RENDER_ATTACHMENT). */
    readonly output: GPUTexture;
}

/** ChainTextures' views, each checked (record's). */
type TextureViews = { -readonly [K in keyof ChainTextures]?: GPUTextureView };

/** The formats each of ChainTextures' members may have (the shaders read every one as floats). */
const textureFormats: { readonly [K in keyof ChainTextures]-?: readonly GPUTextureFormat[] } = {
    depth: ["r32float", "depth32float"],
    normals: ["rgba16float", "rgba32float"],
    albedo: ["rgba8unorm", "rgba16float", "rgba32float"],
    motion: ["rg16float", "rg32float", "rgba16float"],
    output: ["rgba8unorm", "r8unorm"],
};

/** The chain's own images a pass may bind, as record() goes: the last AO pass's output, this pass's output, the history
 *  images it reads and writes, the prefilter's atlas. */
interface PassViews {
    readonly previous?: GPUTextureView;
    readonly output: GPUTextureView;
    readonly read?: GPUTextureView;
    readonly written?: GPUTextureView;
    readonly atlas?: GPUTextureView;
}

interface PassState {
    readonly info: PassInfo;
    readonly layout: GPUBindGroupLayout;
    readonly compute?: GPUComputePipeline;
    readonly render?: GPURenderPipeline;
    readonly uniforms: GPUBuffer;
    readonly size: [number, number]; // its output's
    readonly dispatch: [number, number]; // the size it is dispatched over: its output's, the prefilter's the screen's
    readonly target?: GPUTexture; // its output, unless it is the last pass (the engine's)
    readonly history?: [GPUTexture, GPUTexture]; // a history pass's two images, swapped each frame
}

/** A variant's chain for one screen size on one device: every pass's pipeline, buffers and targets, made once. */
export class AoChain {
    /** The size of ChainTextures.output: the screen's, or the AO target's (a half-resolution chain without the upsample). */
    readonly outputSize: [number, number];
    readonly outputFormat: GPUTextureFormat;
    private readonly passes: PassState[];
    private readonly sampler: GPUSampler;
    private noise?: GPUTexture; // the tile, exactly its size (the shaders wrap by textureDimensions)
    private frames = 0; // recorded, for the history images' turn

    private constructor(private readonly device: GPUDevice, readonly variant: VariantInfo, readonly width: number, readonly height: number) {
        const target = targetSize(variant, width, height);
        const last = variant.passes[variant.passes.length - 1]!;
        this.outputSize = last.screenSized ? [width, height] : target;
        this.outputFormat = variant.stage === "compute" ? "rgba8unorm" : "r8unorm";
        this.sampler = device.createSampler({ label: "aogen clamp", addressModeU: "clamp-to-edge", addressModeV: "clamp-to-edge" });
        this.passes = variant.passes.map((info, i) => {
            const last = i === variant.passes.length - 1;
            if (info.atlasLevels !== undefined) return this.makePass(info, depthMipAtlasSize(width, height, info.atlasLevels), [width, height], last);
            const size = last ? this.outputSize : target;
            return this.makePass(info, size, size, last);
        });
    }

    /** The chain of `variant` (a name of this module, or its VariantInfo) for a screen of width x height; an AogenError names a variant or size that is not valid. */
    static create(device: GPUDevice, variant: string | VariantInfo, width: number, height: number): AoChain {
        const v = typeof variant === "string" ? variantInfo(variant) : variant;
        requireInteger("screen width", width, 1, 65536);
        requireInteger("screen height", height, 1, 65536);
        return new AoChain(device, v, width, height);
    }

    /** Writes frame `chain.frame`'s uniforms and the noise tile (chainInputs) into the chain's buffers. */
    update(chain: ChainSettings): void {
        const inputs = chainInputs(this.variant, chain, this.width, this.height);
        this.passes.forEach((p, i) => this.device.queue.writeBuffer(p.uniforms, 0, inputs.uniforms[i]!));
        const n = inputs.noiseSize;
        if (this.noise?.width !== n) {
            this.noise?.destroy();
            this.noise = this.device.createTexture({ label: "aogen noise", size: [n, n], format: "rgba32float", usage: textureUsage.textureBinding | textureUsage.copyDst });
        }
        this.device.queue.writeTexture({ texture: this.noise }, inputs.noise, { bytesPerRow: 16 * n }, [n, n]);
    }

    /** Records every pass into `encoder`: the AO pass, its filters and history, the upsample. Call update() first. */
    record(encoder: GPUCommandEncoder, textures: ChainTextures): void {
        if (!this.noise) throw new AogenError("AoChain.record", "called before update()", "valid: update(chainSettings) once before the first record");
        const t = this.views(textures);
        let previous: GPUTextureView | undefined;
        let atlas: GPUTextureView | undefined; // the prefilter's depth MIP atlas
        for (const p of this.passes) {
            const output = p.target ? p.target.createView() : t.output!;
            if (p.info.atlasLevels !== undefined) atlas = output;
            const read = p.history ? p.history[this.frames % 2]!.createView() : undefined;
            const written = p.history ? p.history[(this.frames + 1) % 2]!.createView() : undefined;
            const entries = p.info.bindings
                .filter((b) => !(b.role === "history_output" && p.info.stage === "fragment"))
                .map((b): GPUBindGroupEntry => ({ binding: b.binding, resource: this.resource(p, b, t, { previous, output, read, written, atlas }) }));
            const group = this.device.createBindGroup({ label: `aogen ${p.info.pass}`, layout: p.layout, entries });
            if (p.compute) {
                const pass = encoder.beginComputePass({ label: `aogen ${p.info.pass}` });
                pass.setPipeline(p.compute);
                pass.setBindGroup(0, group);
                const [wx, wy] = p.info.workgroupSize!;
                const ppi = p.info.pixelsPerInvocation;
                pass.dispatchWorkgroups(Math.ceil(p.dispatch[0] / ppi / wx), Math.ceil(p.dispatch[1] / ppi / wy));
                pass.end();
            } else {
                const attachment = (view: GPUTextureView): GPURenderPassColorAttachment => ({ view, loadOp: "clear", clearValue: [0, 0, 0, 0], storeOp: "store" });
                const pass = encoder.beginRenderPass({ label: `aogen ${p.info.pass}`, colorAttachments: written ? [attachment(output), attachment(written)] : [attachment(output)] });
                pass.setPipeline(p.render!);
                pass.setBindGroup(0, group);
                pass.setViewport(0, 0, p.size[0], p.size[1], 0, 1);
                pass.draw(3);
                pass.end();
            }
            if (p.info.atlasLevels === undefined) previous = output;
        }
        this.frames += 1;
    }

    /** `textures` checked (format, size; the ones the variant reads present) and viewed. */
    private views(textures: ChainTextures): TextureViews {
        const bound = new Set(this.variant.passes.flatMap((p) => p.bindings.map((b) => b.role)));
        const needed: { readonly [K in keyof ChainTextures]-?: boolean } = {
            depth: true, normals: bound.has("normals"), albedo: bound.has("gbuffer_albedo"), motion: bound.has("motion"), output: true,
        };
        const out: TextureViews = {};
        for (const key of Object.keys(textureFormats) as (keyof ChainTextures)[]) {
            const texture = textures[key];
            const [w, h] = key === "output" ? this.outputSize : [this.width, this.height];
            const formats = key === "output" ? [this.outputFormat] : textureFormats[key];
            const valid = `valid: ${formats.join(" or ")}, ${w}x${h}`;
            if (!texture) {
                if (needed[key]) throw new AogenError(`AoChain.record textures.${key}`, `is missing (${this.variant.name} reads it)`, valid);
                continue;
            }
            if (!formats.includes(texture.format) || texture.width !== w || texture.height !== h)
                throw new AogenError(`AoChain.record textures.${key}`, `is ${texture.format} ${texture.width}x${texture.height}`, valid);
            out[key] = texture.createView();
        }
        return out;
    }

    /** Frees the chain's buffers and textures (not the engine's). */
    destroy(): void {
        for (const p of this.passes) {
            p.uniforms.destroy();
            p.target?.destroy();
            p.history?.forEach((h) => h.destroy());
        }
        this.noise?.destroy();
    }

    private makePass(info: PassInfo, size: [number, number], dispatch: [number, number], last: boolean): PassState {
        const d = this.device;
        const layout = d.createBindGroupLayout(bindGroupLayoutDescriptor(info));
        const pipelineLayout = d.createPipelineLayout({ bindGroupLayouts: [layout] });
        const module = d.createShaderModule({ label: `aogen ${info.pass}`, code: info.wgsl });
        const compute = info.stage === "compute";
        const history = info.pass === "history";
        const written = compute ? textureUsage.storageBinding : textureUsage.renderAttachment;
        // The AO images' format, or the prefilter's (its storage binding's: r32float).
        const format: GPUTextureFormat = info.bindings.find((b) => b.role === "output" && b.format)?.format ?? (compute ? "rgba8unorm" : "r8unorm");
        return {
            info, layout, size, dispatch,
            compute: compute ? d.createComputePipeline({ layout: pipelineLayout, compute: { module, entryPoint: info.entryPoint } }) : undefined,
            render: compute ? undefined : d.createRenderPipeline({
                layout: pipelineLayout,
                vertex: { module: d.createShaderModule({ label: "aogen fullscreen triangle", code: info.vertexWgsl! }), entryPoint: "main" },
                fragment: { module, entryPoint: info.entryPoint, targets: history ? [{ format }, { format: "rgba16float" }] : [{ format }] },
                primitive: { topology: "triangle-list" },
            }),
            uniforms: d.createBuffer({ label: `aogen ${info.block.name}`, size: Math.ceil(info.block.size / 16) * 16, usage: bufferUsage.uniform | bufferUsage.copyDst }),
            target: last ? undefined : d.createTexture({ label: `aogen ${info.pass}`, size, format, usage: written | textureUsage.textureBinding | textureUsage.copySrc }),
            // Two images cleared to 0 (a history of no frames): the pass writes this frame alone.
            history: history ? [0, 1].map(() => d.createTexture({ label: "aogen history", size, format: "rgba16float", usage: written | textureUsage.textureBinding })) as [GPUTexture, GPUTexture] : undefined,
        };
    }

    private resource(p: PassState, b: BindingInfo, t: TextureViews, v: PassViews): GPUBindingResource {
        if (b.kind === "sampler") return this.sampler;
        const need = (view: GPUTextureView | undefined, what: string): GPUTextureView => {
            if (view) return view;
            throw new AogenError(`AoChain.record ${p.info.pass}`, `needs ${what}`, `valid: ChainTextures with ${what} for ${this.variant.name}`);
        };
        switch (b.role) {
        case "uniforms": return { buffer: p.uniforms };
        case "depth": return t.depth!;
        case "normals": return need(t.normals, "normals");
        case "noise": return this.noise!.createView();
        case "ao_input": return need(v.previous, "the previous pass's output");
        case "output": return v.output;
        case "depth_mips": return need(v.atlas, "the prefilter's depth MIP atlas");
        case "gbuffer_albedo": return need(t.albedo, "albedo");
        case "motion": return need(t.motion, "motion");
        case "history": return need(v.read, "a history");
        case "history_output": return need(v.written, "a history");
        }
        throw new AogenError(`AoChain ${p.info.pass}`, `binds '${b.role}', which this module does not provide`, "valid: regenerate the module with this aogen");
    }
}
