// ---- random.ts: aogen's random numbers, bit for bit (aogen/random.hpp) ----------------------
// PCG32 (O'Neill 2014) seeded through SplitMix64, one stream per purpose; 64-bit state in
// bigint. Points are drawn in 24-bit fixed point and accepted by exact integer tests, so the
// same seed gives the same points in C++ and here.

const mask64 = (1n << 64n) - 1n;

function splitmix64(x: bigint): bigint {
    x = (x + 0x9e3779b97f4a7c15n) & mask64;
    x = ((x ^ (x >> 30n)) * 0xbf58476d1ce4e5b9n) & mask64;
    x = ((x ^ (x >> 27n)) * 0x94d049bb133111ebn) & mask64;
    return x ^ (x >> 31n);
}

/** Each purpose's PCG32 stream (random.hpp's random::stream). */
const randomStream = {
    kernelCrytek: 0x6b65726e656c3031n, // "kernel01"
    kernelCosine: 0x6b65726e656c3032n, // "kernel02"
    kernelHammersley: 0x6b65726e656c3033n, // "kernel03"
    noiseRandom: 0x6e6f697365303031n, // "noise001"
    frames: 0x6672616d65733031n, // "frames01": temporal.hpp's white sequence
} as const;

class Pcg32 {
    private state = 0n;
    private readonly increment: bigint;

    /** random::seeded(seed, stream): the seed through SplitMix64, then PCG32's seeding. */
    constructor(seed: bigint, stream: bigint) {
        this.increment = ((stream << 1n) | 1n) & mask64;
        this.step();
        this.state = (this.state + splitmix64(seed & mask64)) & mask64;
        this.step();
    }

    nextU32(): number {
        const old = this.state;
        this.step();
        const xorshifted = Number((((old >> 18n) ^ old) >> 27n) & 0xffffffffn);
        const rotation = Number(old >> 59n);
        return ((xorshifted >>> rotation) | (xorshifted << ((32 - rotation) & 31))) >>> 0;
    }

    nextU24(): number {
        return this.nextU32() >>> 8;
    }

    /** In [0, 1): 24 random bits times 2^-24, exact in a float. */
    nextFloat(): number {
        return this.nextU24() * 2 ** -24;
    }

    private step(): void {
        this.state = (this.state * 6364136223846793005n + this.increment) & mask64;
    }
}

const fixedOne = 2 ** 24;

/** A signed 24-bit fixed-point coordinate in [-1, 1): 2 u - 2^24. */
function drawSignedFixed(rng: Pcg32): number {
    return 2 * rng.nextU24() - fixedOne;
}

/** A point strictly inside the unit disk, never its centre (x, y in 2^-24; norm2 = x^2 + y^2, exact). */
function drawInUnitDisk(rng: Pcg32): { x: number; y: number; norm2: number } {
    for (;;) {
        const x = drawSignedFixed(rng);
        const y = drawSignedFixed(rng);
        const norm2 = x * x + y * y; // < 2^49: exact
        if (norm2 > 0 && norm2 < 2 ** 48) return { x, y, norm2 };
    }
}

/**
 * cos and sin of `turns` whole turns, as random.hpp's cos_sin_turns: reduced to the nearest
 * quarter turn exactly, then Taylor polynomials to a^18 by fused multiply-adds (no libm, whose
 * last bit differs between C libraries and JavaScript engines).
 */
function cosSinTurns(turns: number): { c: number; s: number } {
    const quarters = turns * 4;
    const nearest = Math.floor(quarters + 0.5);
    const remainder = quarters - nearest;
    const a = remainder * 1.5707963267948966192;
    const a2 = a * a;
    const f = [1, 1]; // f[k] = 1 / k!
    for (let k = 2; k <= 18; ++k) f.push(f[k - 1]! / k);
    let sinPoly = f[17]!;
    for (const k of [15, 13, 11, 9, 7, 5, 3]) sinPoly = fma(sinPoly, a2, k % 4 === 3 ? -f[k]! : f[k]!);
    const sinA = fma(sinPoly, a2 * a, a);
    let cosPoly = f[18]!;
    for (const k of [16, 14, 12, 10, 8, 6, 4, 2]) cosPoly = fma(cosPoly, a2, k % 4 === 0 ? -f[k]! : f[k]!);
    const cosA = fma(-cosPoly, a2, 1);
    const quarter = nearest - 4 * Math.floor(nearest * 0.25);
    if (quarter === 0) return { c: cosA, s: sinA };
    if (quarter === 1) return { c: -sinA, s: cosA };
    if (quarter === 2) return { c: -cosA, s: -sinA };
    return { c: sinA, s: -cosA };
}
