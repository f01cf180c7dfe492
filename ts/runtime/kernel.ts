// ---- kernel.ts: SSAO's hemisphere kernels (aogen/kernel.hpp) --------------------------------
// N samples in the unit hemisphere (z >= 0) as (x, y, z, 0), scaled by Crytek's law
// 0.1 + 0.9 (i/N)^2 (kernel::scale_law::crytek, the default), by distribution:
//   crytek      a uniform direction, times a random length (seed 000's kernel)
//   cosine      cosine-weighted: a point of the unit disk lifted onto the hemisphere
//   hammersley  the Hammersley set, cosine-weighted; a seed of 0 is the unrotated set

/** The kernel distributions (kernel.hpp's distribution_names). */
export const kernelDistributions = ["crytek", "cosine", "hammersley"] as const;
export type KernelDistribution = (typeof kernelDistributions)[number];

/** Crytek's scale of sample i of n: (n^2 + 9 i^2) / (10 n^2) = 0.1 + 0.9 (i/n)^2, as a float. */
function crytekFactor(index: number, count: number): number {
    const n2 = count * count, i2 = index * index;
    return Math.fround(Math.fround(n2 + 9 * i2) / Math.fround(10 * n2));
}

function scaledSample(out: Float32Array, i: number, x: number, y: number, z: number, length: number): void {
    out[4 * i] = toFloat(x * length);
    out[4 * i + 1] = toFloat(y * length);
    out[4 * i + 2] = toFloat(z * length);
    out[4 * i + 3] = 0;
}

function crytekKernel(count: number, seed: number): Float32Array {
    const rng = new Pcg32(BigInt(seed), randomStream.kernelCrytek);
    const out = new Float32Array(4 * count);
    for (let i = 0; i < count; ++i) {
        let x: number, y: number, z: number, norm2: number;
        do { // a point of the half box [-1, 1)^2 x [0, 1), not the origin
            x = drawSignedFixed(rng);
            y = drawSignedFixed(rng);
            z = rng.nextU24();
            norm2 = x * x + y * y + z * z; // < 3 * 2^48: exact
        } while (norm2 === 0);
        const randomLength = rng.nextFloat(); // drawn after the direction
        const norm = Math.sqrt(norm2);
        const length = randomLength * crytekFactor(i, count);
        scaledSample(out, i, x / norm, y / norm, z / norm, length);
    }
    return out;
}

function cosineKernel(count: number, seed: number): Float32Array {
    const rng = new Pcg32(BigInt(seed), randomStream.kernelCosine);
    const out = new Float32Array(4 * count);
    for (let i = 0; i < count; ++i) {
        const p = drawInUnitDisk(rng);
        const z = Math.sqrt(2 ** 48 - p.norm2) * 2 ** -24;
        scaledSample(out, i, p.x * 2 ** -24, p.y * 2 ** -24, z, crytekFactor(i, count));
    }
    return out;
}

function reverseBits(v: number): number {
    v = ((v >>> 1) & 0x55555555) | ((v & 0x55555555) << 1);
    v = ((v >>> 2) & 0x33333333) | ((v & 0x33333333) << 2);
    v = ((v >>> 4) & 0x0f0f0f0f) | ((v & 0x0f0f0f0f) << 4);
    v = ((v >>> 8) & 0x00ff00ff) | ((v & 0x00ff00ff) << 8);
    return ((v >>> 16) | (v << 16)) >>> 0;
}

function hammersleyKernel(count: number, seed: number): Float32Array {
    let offsetA = 0, offsetB = 0;
    if (seed !== 0) {
        const rng = new Pcg32(BigInt(seed), randomStream.kernelHammersley);
        offsetA = rng.nextU32();
        offsetB = rng.nextU32();
    }
    const out = new Float32Array(4 * count);
    for (let i = 0; i < count; ++i) {
        const a = (Number((BigInt(i) << 32n) / BigInt(count)) + offsetA) >>> 0;
        const b = (reverseBits(i) + offsetB) >>> 0;
        const radius = Math.sqrt(b) * 2 ** -16;
        const z = Math.sqrt(2 ** 32 - b) * 2 ** -16;
        const angle = cosSinTurns(a * 2 ** -32);
        scaledSample(out, i, radius * angle.c, radius * angle.s, z, crytekFactor(i, count));
    }
    return out;
}

/**
 * The kernel of `count` samples (1..256) of `distribution` for `seed` (an unsigned 32-bit
 * integer: ssao_params.kernel_seed), as vec4s: the bytes kernel::generate writes. Throws an
 * AogenError naming a distribution, count or seed that is not valid.
 */
export function makeKernel(distribution: string, count: number, seed: number): Float32Array {
    requireInteger("kernel count", count, 1, 256);
    requireInteger("kernel seed", seed, 0, 0xffffffff);
    switch (distribution) {
    case "crytek": return crytekKernel(count, seed);
    case "cosine": return cosineKernel(count, seed);
    case "hammersley": return hammersleyKernel(count, seed);
    }
    throw new AogenError("kernel distribution", `'${distribution}' is not a known name`, `valid: ${kernelDistributions.join(", ")}`);
}
