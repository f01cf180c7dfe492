// ---- tiles.ts: the noise tile and SAO's spiral (aogen/noise.hpp, aogen/spiral.hpp) ----------

/**
 * The noise tile of `size` x `size` rotations (1..64; ssao_params.noise_size, 4 for GTAO, VBAO
 * and SAO) for `seed` (ssao_params.noise_seed), as noise::rotations: texel (x, y) at
 * 4 (y size + x), (cos t, sin t, 0, 1) with t uniform, drawn as a point of the unit disk.
 * Upload it as rgba32float (noiseBytes).
 */
export function noiseRotations(size: number, seed: number): Float32Array {
    requireInteger("noise size", size, 1, 64);
    requireInteger("noise seed", seed, 0, 0xffffffff);
    const rng = new Pcg32(BigInt(seed), randomStream.noiseRandom);
    const out = new Float32Array(4 * size * size);
    for (let i = 0; i < size * size; ++i) {
        const p = drawInUnitDisk(rng);
        const norm = Math.sqrt(p.norm2);
        out.set([toFloat(p.x / norm), toFloat(p.y / norm), 0, 1], 4 * i);
    }
    return out;
}

/** `texels` as little-endian float32 bytes: an rgba32float texture's (noise::encoding::rgba32f). */
export function float32Bytes(texels: Float32Array): ArrayBuffer {
    const bytes = new ArrayBuffer(4 * texels.length);
    const view = new DataView(bytes);
    texels.forEach((t, i) => view.setFloat32(4 * i, t, true));
    return bytes;
}

/**
 * SAO's `count` spiral taps (1..256), as spiral::taps: tap i at (cos, sin) of i golden-angle
 * turns, its radius share alpha = (i + 1/2) / count, as (cos, sin, alpha, 0).
 */
export function spiralTaps(count: number): Float32Array {
    requireInteger("spiral taps", count, 1, 256);
    const golden = (3 - Math.sqrt(5)) / 2;
    const out = new Float32Array(4 * count);
    for (let i = 0; i < count; ++i) {
        const turns = i * golden;
        const cs = cosSinTurns(turns - Math.floor(turns));
        out.set([toFloat(cs.c), toFloat(cs.s), Math.fround((2 * i + 1) / (2 * count)), 0], 4 * i);
    }
    return out;
}
