// aogen_wgsl.mjs — aogen's WGSL tools: SPIR-V → WGSL with naga, every WGSL text validated by
// naga and by Tint (Dawn's WGSL compiler), and WGSL → SPIR-V with naga for the round trip.
// Called by include/aogen/wgsl.hpp, one process for a whole batch of shaders:
//
//   node aogen_wgsl.mjs from-spirv DIR   for every DIR/<id>.<comp|vert|frag>.spv: naga reads and
//                                        validates it and writes WGSL, then parses and validates
//                                        that text again: DIR/<id>.wgsl, or DIR/<id>.error naming
//                                        the tool and its message
//   node aogen_wgsl.mjs tint DIR         for every DIR/<id>.wgsl: Tint compiles it (a compute
//                                        shader also into a pipeline with the layout WebGPU
//                                        derives); DIR/<id>.error where it fails
//   Tint runs in a process of its own: with naga's WebAssembly loaded, Dawn's shader compiler
//   crashes (seen with naga-wasm 30.1.0 and webgpu 0.6.2: a segmentation fault in
//   createShaderModule).
//   node aogen_wgsl.mjs to-spirv DIR     for every DIR/<id>.wgsl: naga's SPIR-V as DIR/<id>.spv.out
//                                        (little-endian words), or DIR/<id>.error
//   node aogen_wgsl.mjs run DIR          executes a chain's WGSL on a real WebGPU device:
//                                        Dawn's OpenGL ES backend (Tint → GLSL ES, Mesa's llvmpipe
//                                        through EGL surfaceless), from DIR/chain.txt (below);
//                                        writes DIR/out.bin, the last pass's output, one byte a
//                                        pixel (.r of rgba8unorm), and DIR/texels.bin, its whole
//                                        texels packed (4 bytes for rgba8unorm, 1 for r8unorm), or
//                                        DIR/run.error
//   node aogen_wgsl.mjs versions         the versions of naga and of this script's Node.js
//
// Exit status: 0 when every file was handled (each with its output or its .error), 2 for a
// usage error, 3 when a tool cannot be loaded (its message on stderr).
import { existsSync, readdirSync, readFileSync, writeFileSync } from "node:fs";
import { join } from "node:path";

const [command, dir] = process.argv.slice(2);

function usage() {
    process.stderr.write("usage: node aogen_wgsl.mjs from-spirv DIR | tint DIR | to-spirv DIR | run DIR | versions\n");
    process.exit(2);
}

async function load(name) {
    try {
        return await import(name);
    } catch (e) {
        process.stderr.write(`cannot load the npm package ${name} (${e.message.split("\n")[0]}); scripts/install-deps.sh installs it\n`);
        process.exit(3);
    }
}

let naga; // loaded by the commands that use it (not with Tint: see above)
let gpu;

// naga's error as one block of text: its formatted report where it has one.
function nagaMessage(e) {
    return (e.formatted || e.message || String(e)).trim();
}

// naga: SPIR-V words → validated module → WGSL text. Handles are freed on every path.
function spirvToWgsl(bytes) {
    const module = naga.parseSpirv(new Uint8Array(bytes));
    try {
        const info = naga.validate(module);
        try {
            return naga.writeWgsl(module, info);
        } finally {
            info.free();
        }
    } finally {
        module.free();
    }
}

// naga: WGSL text → validated module → SPIR-V words, with the names of variables and struct
// members (debug) for reflection. The coordinate-space adjustment stays on (naga's default both
// ways): the SPIR-V reader flipped the vertex position's y into WebGPU's convention, and the
// writer flips it back into Vulkan's.
function wgslToSpirv(text) {
    const module = naga.parseWgsl(text);
    try {
        const info = naga.validate(module);
        try {
            return naga.writeSpirv(module, info, { flags: { debug: true } });
        } finally {
            info.free();
        }
    } finally {
        module.free();
    }
}

// Tint, through Dawn's null backend (compiles, runs nothing): the text's compilation messages,
// and for a compute shader the errors of a pipeline with the layout WebGPU derives from it.
async function makeTint() {
    const webgpu = await load("webgpu");
    Object.assign(globalThis, webgpu.globals);
    // Held for the whole run: when the GPU object is collected, Dawn's instance goes with it
    // and the device crashes or hangs a few shaders later.
    gpu = webgpu.create(["backend=null"]);
    const adapter = await gpu.requestAdapter();
    if (!adapter) {
        process.stderr.write("Dawn's null backend gave no WebGPU adapter\n");
        process.exit(3);
    }
    const device = await adapter.requestDevice();
    return async (text, stage) => {
        device.pushErrorScope("validation");
        const module = device.createShaderModule({ code: text });
        const info = await module.getCompilationInfo();
        const errors = info.messages
            .filter((m) => m.type === "error")
            .map((m) => `${m.lineNum}:${m.linePos}: ${m.message}`);
        if (errors.length === 0 && stage === "comp")
            device.createComputePipeline({ layout: "auto", compute: { module, entryPoint: "main" } });
        const scope = await device.popErrorScope();
        if (errors.length === 0 && scope) errors.push(scope.message.trim());
        return errors.join("\n");
    };
}

function ids(ending) {
    return readdirSync(dir)
        .filter((f) => f.endsWith(ending))
        .sort()
        .map((f) => f.slice(0, -ending.length));
}

async function fromSpirv() {
    naga = await load("naga-wasm");
    for (const id of ids(".spv")) {
        const stage = id.split(".").pop();
        let text;
        try {
            text = spirvToWgsl(readFileSync(join(dir, id + ".spv")));
        } catch (e) {
            writeFileSync(join(dir, id + ".error"), `naga could not translate the SPIR-V to WGSL:\n${nagaMessage(e)}\n`);
            continue;
        }
        try {
            wgslToSpirv(text); // naga's own front end and validator on the text it wrote
        } catch (e) {
            writeFileSync(join(dir, id + ".error"), `naga rejected the WGSL it wrote:\n${nagaMessage(e)}\n`);
            continue;
        }
        writeFileSync(join(dir, id + ".wgsl"), text);
    }
}

async function checkWithTint() {
    const tint = await makeTint();
    for (const id of ids(".wgsl")) {
        const errors = await tint(readFileSync(join(dir, id + ".wgsl"), "utf8"), id.split(".").pop());
        if (errors) writeFileSync(join(dir, id + ".error"), `Tint rejected the WGSL:\n${errors}\n`);
    }
}

async function toSpirv() {
    naga = await load("naga-wasm");
    for (const id of ids(".wgsl")) {
        try {
            const words = wgslToSpirv(readFileSync(join(dir, id + ".wgsl"), "utf8"));
            writeFileSync(join(dir, id + ".spv.out"), new Uint8Array(words.buffer, words.byteOffset, words.byteLength));
        } catch (e) {
            writeFileSync(join(dir, id + ".error"), `naga rejected the WGSL:\n${nagaMessage(e)}\n`);
        }
    }
}

// chain.txt, one line each:
//   gbuffer W H            depth.f32 (W×H floats, r32float) and, if present, normals.f32 (W×H×4)
//                          and motion.f32 (W×H×2, rg32float: a -histmv variant's motion vectors)
//   noise N                noise.f32 (N×N×4 floats, rgba32float)
//   frames F               the chain runs F frames (default 1): pass i reads uniforms<i>.bin at
//                          frame 0 and uniforms<i>_<f>.bin at frame f; frame f's last output is
//                          written to out<f>.bin and texels<f>.bin (frame 0's also to out.bin, texels.bin)
//   pass FILE W H PPI [VERTEX]  a pass: its WGSL (a compute shader, or with VERTEX the fragment
//                          shader drawn with that vertex shader's fullscreen triangle), its
//                          output's size, pixels per invocation; uniforms<i>.bin its uniform
//                          bytes (i from 0); it reads the previous pass's output as ao_input
//   albedo BINDING         the pass above also reads albedo.f32 (the G-buffer's W×H×4 floats,
//                          rgba32float) at BINDING (a -mbg variant's last pass)
//   history READ WRITE     the pass above is a history pass: it reads the history at binding
//                          READ and writes the next at WRITE (two rgba16float textures of its
//                          output's size, cleared, swapped after every frame); WRITE -1: a
//                          fragment pass, which writes it as its second colour target
//   motion BINDING         the pass above reads motion.f32 at BINDING
// Bindings follow aogen/bindings.hpp's webgpu model; workgroups are the WGSL's @workgroup_size.
// Compute passes write rgba8unorm storage textures, fragment passes r8unorm render targets.
async function runChain() {
    process.env.EGL_PLATFORM ??= "surfaceless"; // no display: Mesa's EGL without a window system
    const webgpu = await load("webgpu");
    Object.assign(globalThis, webgpu.globals);
    gpu = webgpu.create(["backend=opengles"]);
    const adapter = await gpu.requestAdapter({ featureLevel: "compatibility" });
    if (!adapter) throw new Error("Dawn's OpenGL ES backend gave no WebGPU adapter");
    // Compatibility mode's default is 128 invocations per workgroup (core WebGPU's 256): ask for
    // what the adapter has, as an engine running a -wg16x16 variant must.
    const workgroupLimits = ["maxComputeInvocationsPerWorkgroup", "maxComputeWorkgroupSizeX", "maxComputeWorkgroupSizeY"];
    const device = await adapter.requestDevice({ requiredLimits: Object.fromEntries(workgroupLimits.map((k) => [k, adapter.limits[k]])) });
    const lines = readFileSync(join(dir, "chain.txt"), "utf8").split("\n").filter((l) => l.trim()).map((l) => l.trim().split(/\s+/));
    // A copy: a small file's Buffer is a view into Node's shared pool, at any offset.
    const floats = (name) => new Float32Array(new Uint8Array(readFileSync(join(dir, name))).buffer);
    const usage = GPUTextureUsage;
    const upload = (w, h, format, data, bpp) => {
        const t = device.createTexture({ size: [w, h], format, usage: usage.TEXTURE_BINDING | usage.COPY_DST });
        device.queue.writeTexture({ texture: t }, data, { bytesPerRow: w * bpp }, [w, h]);
        return t;
    };
    let depth, normals, albedo, motion, noise;
    let frames = 1;
    const passes = [];
    for (const l of lines) {
        if (l[0] === "gbuffer") {
            const w = +l[1], h = +l[2];
            depth = upload(w, h, "r32float", floats("depth.f32"), 4);
            if (existsSync(join(dir, "normals.f32"))) normals = upload(w, h, "rgba32float", floats("normals.f32"), 16);
            if (existsSync(join(dir, "albedo.f32"))) albedo = upload(w, h, "rgba32float", floats("albedo.f32"), 16);
            if (existsSync(join(dir, "motion.f32"))) motion = upload(w, h, "rg32float", floats("motion.f32"), 8);
        } else if (l[0] === "noise") {
            noise = upload(+l[1], +l[1], "rgba32float", floats("noise.f32"), 16);
        } else if (l[0] === "frames") {
            frames = +l[1];
        } else if (l[0] === "pass") {
            passes.push({ file: l[1], w: +l[2], h: +l[3], ppi: +l[4], vertex: l[5] });
        } else if (l[0] === "albedo") {
            passes[passes.length - 1].albedoBinding = +l[1];
        } else if (l[0] === "history") {
            passes[passes.length - 1].history = [+l[1], +l[2]];
        } else if (l[0] === "motion") {
            passes[passes.length - 1].motionBinding = +l[1];
        }
    }
    const sampler = device.createSampler({ addressModeU: "clamp-to-edge", addressModeV: "clamp-to-edge" });
    const text = (file) => readFileSync(join(dir, file), "utf8");
    device.pushErrorScope("validation");
    // Each pass's output, layout, pipeline and uniform buffer, made once for every frame.
    let previous;
    passes.forEach((p, i) => {
        const code = text(p.file);
        const fragment = p.vertex !== undefined;
        const visibility = fragment ? GPUShaderStage.FRAGMENT : GPUShaderStage.COMPUTE;
        const format = fragment ? "r8unorm" : "rgba8unorm";
        const entry = (binding, kind) => ({ binding, visibility, ...kind });
        const tex = { texture: { sampleType: "unfilterable-float" } }, smp = { sampler: { type: "non-filtering" } };
        const ubo = { buffer: { type: "uniform" } }, out = { storageTexture: { access: "write-only", format } };
        const ao = i === 0;
        // Bindings 0..4 as bindings.hpp's webgpu model lays them out; 5, the storage output, for compute.
        p.roles = ao ? [[0, ubo], [1, tex, depth], [2, smp, sampler], ...(normals ? [[3, tex, normals]] : []), [4, tex, noise]]
                     : [[0, ubo], [1, tex, depth], [2, smp, sampler], [3, tex, previous], [4, smp, sampler]];
        p.output = device.createTexture({
            size: [p.w, p.h], format,
            usage: (fragment ? usage.RENDER_ATTACHMENT : usage.STORAGE_BINDING) | usage.TEXTURE_BINDING | usage.COPY_SRC,
        });
        if (!fragment) p.roles.push([5, out, p.output]);
        if (p.albedoBinding !== undefined) p.roles.push([p.albedoBinding, tex, albedo]);
        if (p.motionBinding !== undefined) p.roles.push([p.motionBinding, tex, motion]);
        if (p.history) {
            // Two rgba16float images, cleared (0 frames held); frame f reads images[f % 2].
            const written = fragment ? usage.RENDER_ATTACHMENT : usage.STORAGE_BINDING;
            p.images = [0, 1].map(() => device.createTexture({ size: [p.w, p.h], format: "rgba16float", usage: written | usage.TEXTURE_BINDING }));
            p.roles.push([p.history[0], tex, null]);
            if (!fragment) p.roles.push([p.history[1], { storageTexture: { access: "write-only", format: "rgba16float" } }, null]);
        }
        p.layout = device.createBindGroupLayout({ entries: p.roles.map(([binding, kind]) => entry(binding, kind)) });
        const pipelineLayout = device.createPipelineLayout({ bindGroupLayouts: [p.layout] });
        const bytes = readFileSync(join(dir, `uniforms${i}.bin`));
        p.buffer = device.createBuffer({ size: Math.max(16, Math.ceil(bytes.length / 16) * 16), usage: GPUBufferUsage.UNIFORM | GPUBufferUsage.COPY_DST });
        if (fragment) {
            p.pipeline = device.createRenderPipeline({
                layout: pipelineLayout,
                vertex: { module: device.createShaderModule({ code: text(p.vertex) }), entryPoint: "main" },
                fragment: { module: device.createShaderModule({ code }), entryPoint: "main", targets: p.history ? [{ format }, { format: "rgba16float" }] : [{ format }] },
                primitive: { topology: "triangle-list" },
            });
        } else {
            p.pipeline = device.createComputePipeline({ layout: pipelineLayout, compute: { module: device.createShaderModule({ code }), entryPoint: "main" } });
            p.groupSize = /@workgroup_size\((\d+), (\d+)/.exec(code);
        }
        previous = p.output;
        p.texel = fragment ? 1 : 4;
    });
    const last = passes[passes.length - 1];
    const rowBytes = Math.ceil((last.w * last.texel) / 256) * 256;
    for (let f = 0; f < frames; ++f) {
        const encoder = device.createCommandEncoder();
        passes.forEach((p, i) => {
            device.queue.writeBuffer(p.buffer, 0, readFileSync(join(dir, f === 0 ? `uniforms${i}.bin` : `uniforms${i}_${f}.bin`)));
            const resource = (binding, r) => {
                if (binding === 0) return { buffer: p.buffer };
                if (p.history && binding === p.history[0]) return p.images[f % 2].createView();
                if (p.history && binding === p.history[1]) return p.images[(f + 1) % 2].createView(); // compute: a storage texture
                return r instanceof GPUSampler ? r : r.createView();
            };
            const group = device.createBindGroup({ layout: p.layout, entries: p.roles.map(([binding, , r]) => ({ binding, resource: resource(binding, r) })) });
            if (p.vertex !== undefined) {
                const target = (t) => ({ view: t.createView(), loadOp: "clear", clearValue: [0, 0, 0, 0], storeOp: "store" });
                // A history pass's second target: the history it writes this frame.
                const pass = encoder.beginRenderPass({ colorAttachments: p.history ? [target(p.output), target(p.images[(f + 1) % 2])] : [target(p.output)] });
                pass.setPipeline(p.pipeline);
                pass.setBindGroup(0, group);
                pass.setViewport(0, 0, p.w, p.h, 0, 1);
                pass.draw(3);
                pass.end();
            } else {
                const pass = encoder.beginComputePass();
                pass.setPipeline(p.pipeline);
                pass.setBindGroup(0, group);
                pass.dispatchWorkgroups(Math.ceil(p.w / p.ppi / +p.groupSize[1]), Math.ceil(p.h / p.ppi / +p.groupSize[2]));
                pass.end();
            }
        });
        const read = device.createBuffer({ size: rowBytes * last.h, usage: GPUBufferUsage.COPY_DST | GPUBufferUsage.MAP_READ });
        encoder.copyTextureToBuffer({ texture: last.output }, { buffer: read, bytesPerRow: rowBytes }, [last.w, last.h]);
        device.queue.submit([encoder.finish()]);
        const error = await device.popErrorScope(); // each frame's validation, before its results are read
        if (error) throw new Error(error.message.trim());
        device.pushErrorScope("validation");
        await read.mapAsync(GPUMapMode.READ);
        const texels = new Uint8Array(read.getMappedRange());
        const r = new Uint8Array(last.w * last.h);
        for (let y = 0; y < last.h; ++y) for (let x = 0; x < last.w; ++x) r[y * last.w + x] = texels[y * rowBytes + last.texel * x];
        const packed = new Uint8Array(last.w * last.h * last.texel);
        for (let y = 0; y < last.h; ++y) packed.set(texels.subarray(y * rowBytes, y * rowBytes + last.w * last.texel), y * last.w * last.texel);
        writeFileSync(join(dir, `out${f}.bin`), r);
        writeFileSync(join(dir, `texels${f}.bin`), packed);
        if (f === 0) writeFileSync(join(dir, "out.bin"), r), writeFileSync(join(dir, "texels.bin"), packed);
        read.unmap();
    }
    await device.popErrorScope();
    writeFileSync(join(dir, "device.txt"), `Dawn ${adapter.info.backendType || "opengles"}: ${adapter.info.description}`);
}

if (command === "versions") {
    naga = await load("naga-wasm");
    process.stdout.write(`naga ${naga.nagaVersion}\nnode ${process.versions.node}\n`);
} else if (command === "from-spirv" && dir) {
    await fromSpirv();
} else if (command === "tint" && dir) {
    await checkWithTint();
} else if (command === "to-spirv" && dir) {
    await toSpirv();
} else if (command === "run" && dir) {
    try {
        await runChain();
    } catch (e) {
        writeFileSync(join(dir, "run.error"), `Dawn could not run the chain: ${e.message}\n`);
    }
} else {
    usage();
}
process.exit(0); // Dawn keeps the event loop alive
