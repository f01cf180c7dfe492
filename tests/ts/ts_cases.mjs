// tests/ts/ts_cases.mjs — runs the cases ts_module_test.cpp writes through the generated TypeScript
// module (compiled by tsc), and writes what the module computed, for the C++ test to compare with
// aogen's own bytes.
//
//   node ts_cases.mjs MODULE.js CASES.json RESULTS.json
//
// CASES.json: {"inputs": [{variant, camera, previousCamera?, settings, frame, frameSequence,
// resetHistory, width, height}], "kernels": [{distribution, count, seed}], "noise": [{size, seed}],
// "spirals": [count], "frames": [{sequence, frame, periodTurns}], "errors": [{variant, settings,
// width, height}], "fma": [[a, b, c]]}. RESULTS.json: the same lists, each bytes as hex (uniforms per pass, then the
// noise tile; frames: rotation cos, sin and step offset as float32; fma: the double) or, for errors, the message.
import { readFileSync, writeFileSync } from "node:fs";
import { pathToFileURL } from "node:url";

const [modulePath, casesPath, resultsPath] = process.argv.slice(2);
const aogen = await import(pathToFileURL(modulePath).href);
const cases = JSON.parse(readFileSync(casesPath, "utf8"));

const hex = (buffer) => Buffer.from(buffer instanceof ArrayBuffer ? buffer : buffer.buffer, buffer.byteOffset ?? 0, buffer.byteLength).toString("hex");
const floats = (values) => hex(new Float32Array(values));
const thrown = (f) => {
    try {
        f();
        return "no error";
    } catch (e) {
        return `${e.name}: ${e.message}`;
    }
};

const results = {
    inputs: cases.inputs.map((c) => {
        const r = aogen.chainInputs(c.variant, c, c.width, c.height);
        return { uniforms: r.uniforms.map(hex), noiseSize: r.noiseSize, noise: hex(r.noise) };
    }),
    kernels: cases.kernels.map((k) => hex(aogen.makeKernel(k.distribution, k.count, k.seed))),
    noise: cases.noise.map((n) => hex(aogen.float32Bytes(aogen.noiseRotations(n.size, n.seed)))),
    spirals: cases.spirals.map((n) => hex(aogen.spiralTaps(n))),
    frames: cases.frames.map((f) => floats([...aogen.frameRotation(f.periodTurns, f.sequence, f.frame), aogen.stepOffset(f.sequence, f.frame)])),
    errors: cases.errors.map((c) => thrown(() => aogen.chainInputs(c.variant, c, c.width, c.height))),
    fma: (cases.fma ?? []).map(([a, b, c]) => hex(new Float64Array([aogen.fma(a, b, c)]))),
};
writeFileSync(resultsPath, JSON.stringify(results));
