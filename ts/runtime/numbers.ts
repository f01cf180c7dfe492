// ---- numbers.ts: float32 rounding, an exact fused multiply-add, and aogen's error -----------
// aogen's C++ computes the bytes an AO pass uploads in float and double arithmetic whose every
// rounding is IEEE 754's; JavaScript's numbers are doubles, so a double operation here rounds
// as C++'s does, and a float one is the double operation rounded once more by Math.fround
// (exact for + - * / and sqrt: a double holds more than twice a float's 24 bits). What C++
// rounds once and JavaScript cannot -- std::fma -- is computed exactly below (fma).

/** aogen's error: `subject: problem (valid: ...)`, the words the C++ library uses. */
export class AogenError extends Error {
    constructor(subject: string, problem: string, valid: string) {
        super(`${subject}: ${problem} (${valid})`);
        this.name = "AogenError";
    }
}

/** The float nearest `x`, with -0 made +0 (C++'s `float(x) + 0.0f`: a zero has one bit pattern). */
function toFloat(x: number): number {
    return Math.fround(x) + 0;
}

const doubleBits = new DataView(new ArrayBuffer(8));

/** Finite, non-zero `x` as m * 2^e exactly (m an integer, its sign x's). */
function decompose(x: number): { m: bigint; e: number } {
    doubleBits.setFloat64(0, x);
    const hi = doubleBits.getUint32(0), lo = doubleBits.getUint32(4);
    const biased = (hi >>> 20) & 0x7ff;
    let m = (BigInt(hi & 0xfffff) << 32n) | BigInt(lo);
    if (biased !== 0) m |= 1n << 52n;
    const e = (biased === 0 ? 1 : biased) - 1075;
    return { m: hi >>> 31 ? -m : m, e };
}

/** The double nearest n * 2^e (ties to even); n is an exact integer. */
function roundToDouble(n: bigint, e: number): number {
    const negative = n < 0n;
    let a = negative ? -n : n;
    const bits = a.toString(2).length;
    if (bits > 53) {
        const shift = bits - 53;
        const half = 1n << BigInt(shift - 1);
        const rest = a & ((1n << BigInt(shift)) - 1n);
        a >>= BigInt(shift);
        if (rest > half || (rest === half && (a & 1n) === 1n)) a += 1n;
        e += shift;
    }
    // a < 2^54 is exact as a number; scaling by a power of two is exact for normal results.
    const r = Number(a) * 2 ** e;
    return negative ? -r : r;
}

/**
 * a * b + c rounded once, as C++'s std::fma (JavaScript has no fused multiply-add): the exact
 * product and sum as integers times a power of two, rounded to the nearest double. For the
 * finite arguments aogen's polynomials give it (cosSinTurns); exported for aogen's tests, which
 * hold it to C++'s.
 */
export function fma(a: number, b: number, c: number): number {
    if (a === 0 || b === 0 || c === 0) return a * b + c; // one rounding at most already
    const x = decompose(a), y = decompose(b), z = decompose(c);
    const pe = x.e + y.e;
    const e = Math.min(pe, z.e);
    const sum = ((x.m * y.m) << BigInt(pe - e)) + (z.m << BigInt(z.e - e));
    if (sum === 0n) return 0; // an exact zero sum is +0 when rounding to nearest
    return roundToDouble(sum, e);
}
