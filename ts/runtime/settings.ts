// ---- settings.ts: the run-time settings, their defaults and ranges (aogen/params.hpp) --------
// The tables themselves (settingTables, defaultSettings, the Settings interfaces) are generated
// from params.hpp's by `aogen generate --targets ts`, below the runtime; here is what reads them.

/** One float setting as params.hpp's float_setting: its range and its words for an error. */
interface FloatSetting {
    readonly name: string;
    readonly lo: number; // as the shortest text of its float: Math.fround gives the float back
    readonly hi: number;
    readonly loExcluded: boolean;
    readonly valid: string; // "> 0 and <= 1e+15", as C++'s to_string(range)
}

/** `value` as C++'s format_number(float) would print it: the shortest text that reads back as that float. */
function formatFloat(value: number): string {
    if (Number.isNaN(value)) return "nan";
    if (!Number.isFinite(value)) return value > 0 ? "inf" : "-inf";
    for (let digits = 1; digits < 9; ++digits) {
        const text = value.toPrecision(digits);
        if (Math.fround(Number(text)) === value) return String(Number(text));
    }
    return String(value);
}

/** An integer in lo..hi, or an AogenError worded as C++'s require_range. */
function requireInteger(subject: string, value: number, lo: number, hi: number): void {
    if (!Number.isInteger(value) || value < lo || value > hi)
        throw new AogenError(subject, `${typeof value === "number" ? formatFloat(value) : String(value)} is out of range`, `valid: ${lo}..${hi}`);
}

/** `value` (a number) rounded to the float the GPU reads, or an AogenError naming `subject` and the range. */
function floatIn(subject: string, value: unknown, s: FloatSetting): number {
    if (typeof value !== "number") throw new AogenError(subject, `${String(value)} is not a number`, `valid: ${s.valid}`);
    const v = Math.fround(value);
    if (!Number.isFinite(v)) throw new AogenError(subject, `${formatFloat(v)} is not a finite number`, `valid: ${s.valid}`);
    const lo = Math.fround(s.lo), hi = Math.fround(s.hi); // the float ends C++ compares with
    if (!(s.loExcluded ? v > lo : v >= lo) || v > hi) throw new AogenError(subject, `${formatFloat(v)} is out of range`, `valid: ${s.valid}`);
    return v;
}

/** `value`, one of `names`, or an AogenError naming `subject` and them. */
function nameIn<T extends string>(subject: string, value: unknown, names: readonly T[]): T {
    if (typeof value === "string" && (names as readonly string[]).includes(value)) return value as T;
    throw new AogenError(subject, `'${String(value)}' is not a known name`, `valid: ${names.join(", ")}`);
}

/** The keys of `given` that `known` lacks, refused by name. */
function requireKnownKeys(subject: string, given: object, known: readonly string[]): void {
    for (const key of Object.keys(given))
        if (!known.includes(key)) throw new AogenError(`${subject}.${key}`, "is not a setting", `valid: ${known.join(", ")}`);
}

/** Any subset of the settings: the rest are aogen's defaults (defaultSettings()). */
export type SettingsInput = {
    readonly [G in keyof Settings]?: G extends "history"
        ? Partial<Omit<HistorySettings, "motion">> & { readonly motion?: Partial<MotionConvention> }
        : Partial<Settings[G]>;
};

/**
 * `input` over aogen's defaults, every float rounded to the float the GPU reads and checked as
 * params.hpp's validate() checks it: an AogenError names the first setting out of range
 * ("ssao.radius: -1 is out of range (valid: > 0 and <= 1e+15)") or not known.
 */
export function resolveSettings(input: SettingsInput = {}): Settings {
    const out = defaultSettings();
    requireKnownKeys("settings", input, Object.keys(out));
    for (const group of Object.keys(out) as (keyof Settings)[]) {
        const given: { [key: string]: unknown } = input[group] ?? {};
        const target = out[group] as unknown as { [key: string]: unknown };
        requireKnownKeys(group, given, Object.keys(target));
        for (const [key, value] of Object.entries(given)) if (value !== undefined && key !== "motion") target[key] = value;
        for (const f of floatSettings[group]) target[f.name] = floatIn(`${group}.${f.name}`, target[f.name], f);
    }
    const ssao = out.ssao;
    if (typeof ssao.kernel !== "string" || !new RegExp(`^[a-z0-9_]{${kernelNameLength[0]},${kernelNameLength[1]}}$`).test(ssao.kernel))
        throw new AogenError("ssao.kernel", `'${String(ssao.kernel)}' is not a kernel name`,
            `valid: ${kernelNameLength[0]}..${kernelNameLength[1]} characters of a-z, 0-9 and _, e.g. crytek`);
    requireInteger("ssao.kernel_seed", ssao.kernel_seed, 0, 0xffffffff);
    requireInteger("ssao.noise_size", ssao.noise_size, noiseSizeRange[0], noiseSizeRange[1]);
    requireInteger("ssao.noise_seed", ssao.noise_seed, 0, 0xffffffff);
    const h = out.history;
    h.clamp = nameIn("history.clamp", h.clamp, historyClamps);
    const motion = input.history?.motion ?? {};
    requireKnownKeys("history.motion", motion, Object.keys(h.motion));
    h.motion = {
        units: nameIn("history.motion.units", motion.units ?? h.motion.units, motionUnits),
        direction: nameIn("history.motion.direction", motion.direction ?? h.motion.direction, motionDirections),
        y: nameIn("history.motion.y", motion.y ?? h.motion.y, motionYs),
    };
    return out;
}
