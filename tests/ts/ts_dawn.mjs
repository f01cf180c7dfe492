// tests/ts/ts_dawn.mjs — a variant's chain made and recorded by the generated TypeScript module's
// AoChain on Dawn (npm webgpu: its OpenGL ES backend on Mesa's llvmpipe, as aogen_wgsl.mjs runs
// WGSL), every uniform byte and the noise tile computed by the module too: nothing of the chain
// comes from C++ but the G-buffer.
//
//   node ts_dawn.mjs MODULE.js WEBGPU_DIR DIR...
//
// For each DIR (one Dawn device runs them all, in order): DIR/chain.json: {variant, width, height,
// frames: [ChainSettings, ...]}; DIR/depth.f32 (width x height floats, r32float), and where the
// variant reads them normals.f32 (x4, rgba32float), albedo.f32 (x4) and motion.f32 (x2,
// rg32float). Writes DIR/out<f>.bin, frame f's output, one byte a pixel (.r), and
// DIR/texels<f>.bin, its texels packed (4 bytes for rgba8unorm, 1 for r8unorm).
import { readFileSync, writeFileSync, existsSync } from "node:fs";
import { join } from "node:path";
import { pathToFileURL } from "node:url";

const [modulePath, webgpuDir, ...dirs] = process.argv.slice(2);
const aogen = await import(pathToFileURL(modulePath).href);
process.env.EGL_PLATFORM ??= "surfaceless";
const webgpu = await import(pathToFileURL(join(webgpuDir, "node_modules/webgpu/index.js")).href);
Object.assign(globalThis, webgpu.globals);
const gpu = webgpu.create(["backend=opengles"]);
const adapter = await gpu.requestAdapter({ featureLevel: "compatibility" });
if (!adapter) throw new Error("Dawn's OpenGL ES backend gave no WebGPU adapter");
const limits = ["maxComputeInvocationsPerWorkgroup", "maxComputeWorkgroupSizeX", "maxComputeWorkgroupSizeY"];
const device = await adapter.requestDevice({ requiredLimits: Object.fromEntries(limits.map((k) => [k, adapter.limits[k]])) });
device.pushErrorScope("validation");

// One DIR: its chain made, its frames recorded and read back.
async function runChain(dir) {
    const chain = JSON.parse(readFileSync(join(dir, "chain.json"), "utf8"));
    const { width: w, height: h } = chain;
    const floats = (name) => new Float32Array(new Uint8Array(readFileSync(join(dir, name))).buffer);
    const upload = (name, format, bpp) => {
        if (!existsSync(join(dir, name))) return undefined;
        const t = device.createTexture({ size: [w, h], format, usage: GPUTextureUsage.TEXTURE_BINDING | GPUTextureUsage.COPY_DST });
        device.queue.writeTexture({ texture: t }, floats(name), { bytesPerRow: w * bpp }, [w, h]);
        return t;
    };
    const ao = aogen.AoChain.create(device, chain.variant, w, h);
    const [ow, oh] = ao.outputSize;
    const compute = ao.outputFormat === "rgba8unorm";
    const output = device.createTexture({
        size: [ow, oh], format: ao.outputFormat,
        usage: (compute ? GPUTextureUsage.STORAGE_BINDING : GPUTextureUsage.RENDER_ATTACHMENT) | GPUTextureUsage.COPY_SRC,
    });
    const textures = {
        depth: upload("depth.f32", "r32float", 4), normals: upload("normals.f32", "rgba32float", 16),
        albedo: upload("albedo.f32", "rgba32float", 16), motion: upload("motion.f32", "rg32float", 8), output,
    };
    // DIR/bad.json: each a member of the textures replaced ({"depth": "rgba8unorm"}: that format,
    // {"depth": [W, H]}: that size, {"normals": null}: missing); what record() threw, in order, to DIR/bad_out.json.
    if (existsSync(join(dir, "bad.json"))) {
        const said = JSON.parse(readFileSync(join(dir, "bad.json"), "utf8")).map((change) => {
            const t = { ...textures };
            for (const [key, v] of Object.entries(change)) {
                if (v === null) delete t[key];
                else t[key] = device.createTexture({ size: Array.isArray(v) ? v : [t[key].width, t[key].height], format: Array.isArray(v) ? t[key].format : v,
                    usage: GPUTextureUsage.TEXTURE_BINDING | GPUTextureUsage.STORAGE_BINDING });
            }
            ao.update(chain.frames[0]);
            try {
                ao.record(device.createCommandEncoder(), t);
                return "no error";
            } catch (e) {
                return `${e.name}: ${e.message}`;
            }
        });
        writeFileSync(join(dir, "bad_out.json"), JSON.stringify(said));
    }
    const texel = compute ? 4 : 1;
    const rowBytes = Math.ceil((ow * texel) / 256) * 256;
    for (let f = 0; f < chain.frames.length; ++f) {
        ao.update(chain.frames[f]);
        const encoder = device.createCommandEncoder();
        ao.record(encoder, textures);
        const read = device.createBuffer({ size: rowBytes * oh, usage: GPUBufferUsage.COPY_DST | GPUBufferUsage.MAP_READ });
        encoder.copyTextureToBuffer({ texture: output }, { buffer: read, bytesPerRow: rowBytes }, [ow, oh]);
        device.queue.submit([encoder.finish()]);
        const error = await device.popErrorScope();
        if (error) throw new Error(error.message.trim());
        device.pushErrorScope("validation");
        await read.mapAsync(GPUMapMode.READ);
        const bytes = new Uint8Array(read.getMappedRange());
        const r = new Uint8Array(ow * oh), packed = new Uint8Array(ow * oh * texel);
        for (let y = 0; y < oh; ++y) {
            packed.set(bytes.subarray(y * rowBytes, y * rowBytes + ow * texel), y * ow * texel);
            for (let x = 0; x < ow; ++x) r[y * ow + x] = bytes[y * rowBytes + texel * x];
        }
        writeFileSync(join(dir, `out${f}.bin`), r);
        writeFileSync(join(dir, `texels${f}.bin`), packed);
        read.unmap();
    }
    ao.destroy();
    for (const t of Object.values(textures)) t?.destroy();
}

for (const dir of dirs) await runChain(dir);
process.exit(0); // Dawn keeps the event loop alive
