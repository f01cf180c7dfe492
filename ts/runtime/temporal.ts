// ---- temporal.ts: each frame's turn of the noise and move of the slice steps (aogen/temporal.hpp)
// Frame 0 is the still frame: no turn, no move. Frame f turns the noise by offsetTurns(f) of
// the variant's period (a whole turn for SSAO and SAO, half a slice's for GTAO and VBAO) and
// moves GTAO's and VBAO's inner steps by stepOffset(f) of a step.

/** The frame sequences (temporal.hpp's sequence_names); van_der_corput is measured best. */
export const frameSequences = ["van_der_corput", "golden_ratio", "white"] as const;
export type FrameSequence = (typeof frameSequences)[number];

/** Frame `frame`'s offset in [0, 1) of a period. */
function offsetTurns(sequence: FrameSequence, frame: number): number {
    if (frame === 0) return 0;
    switch (sequence) {
    case "van_der_corput": return reverseBits(frame) * 2 ** -32;
    case "golden_ratio": return (Math.imul(frame, 0x9e3779b9) >>> 0) * 2 ** -32;
    case "white": return new Pcg32(BigInt(frame), randomStream.frames).nextFloat();
    }
}

/** Frame `frame`'s offset of the slice techniques' inner steps, in [0, 1) of a step. */
export function stepOffset(sequence: FrameSequence, frame: number): number {
    requireFrame(sequence, frame);
    if (frame === 0) return 0;
    switch (sequence) {
    case "van_der_corput": { // Sobol's second dimension
        let x = 0, direction = 0x80000000;
        for (let bits = frame; bits !== 0; bits >>>= 1, direction = (direction ^ (direction >>> 1)) >>> 0)
            if (bits & 1) x = (x ^ direction) >>> 0;
        return (x >>> 8) * 2 ** -24;
    }
    case "golden_ratio": return ((Math.imul(frame, 0x91e10da6) >>> 0) >>> 8) * 2 ** -24;
    case "white": {
        const rng = new Pcg32(BigInt(frame), randomStream.frames);
        rng.nextFloat(); // the frame's turn (offsetTurns)
        return rng.nextFloat();
    }
    }
}

/** (cos, sin) of frame `frame`'s turn of the noise, for a variant whose period is `periodTurns`. */
export function frameRotation(periodTurns: number, sequence: FrameSequence, frame: number): [number, number] {
    requireFrame(sequence, frame);
    const r = cosSinTurns(offsetTurns(sequence, frame) * periodTurns);
    return [toFloat(r.c), toFloat(r.s)];
}

function requireFrame(sequence: string, frame: number): void {
    if (!(frameSequences as readonly string[]).includes(sequence))
        throw new AogenError("frame sequence", `'${sequence}' is not a known name`, `valid: ${frameSequences.join(", ")}`);
    requireInteger("frame", frame, 0, 0xffffffff);
}
