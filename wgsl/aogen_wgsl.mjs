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
//   node aogen_wgsl.mjs versions         the versions of naga and of this script's Node.js
//
// Exit status: 0 when every file was handled (each with its output or its .error), 2 for a
// usage error, 3 when a tool cannot be loaded (its message on stderr).
import { readdirSync, readFileSync, writeFileSync } from "node:fs";
import { join } from "node:path";

const [command, dir] = process.argv.slice(2);

function usage() {
    process.stderr.write("usage: node aogen_wgsl.mjs from-spirv DIR | tint DIR | to-spirv DIR | versions\n");
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

if (command === "versions") {
    naga = await load("naga-wasm");
    process.stdout.write(`naga ${naga.nagaVersion}\nnode ${process.versions.node}\n`);
} else if (command === "from-spirv" && dir) {
    await fromSpirv();
} else if (command === "tint" && dir) {
    await checkWithTint();
} else if (command === "to-spirv" && dir) {
    await toSpirv();
} else {
    usage();
}
process.exit(0); // Dawn keeps the event loop alive
