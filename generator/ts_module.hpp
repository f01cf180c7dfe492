// generator/ts_module.hpp — `aogen generate --targets wgsl,ts`: the variants as one TypeScript module.
//
// WHAT
//   A WebGPU engine written in TypeScript cannot include a C++ header. For the generated
//   variants, DIR/ts/ holds what such an engine needs, in its own language:
//     aogen.ts        one ES module: the runtime (ts/runtime/*.ts, embedded at build time:
//                     aogen's random numbers, kernels, noise tile, spiral, frame sequences and
//                     uniform packing, each bit for bit as the C++ headers compute them), then
//                     the data generated here -- the settings with their defaults and ranges
//                     (params.hpp's float_setting tables), and per variant its passes: WGSL,
//                     entry point, workgroup, pixels per invocation, the uniform block laid
//                     out under WGSL's rules, the bindings (bind group 0) -- and AoChain, which
//                     makes the pipelines and records the passes on a GPUDevice
//     package.json    an npm package a project can depend on by path (types: aogen.ts)
//     tsconfig.json   `tsc --strict`, as the tests compile it
//   module.add(plan, wgsl texts) collects a variant; module.files() gives the three files.
//
// ERRORS
//   None of its own: the variants were planned and their WGSL made and validated before.
//
// WHY
//   Here, beside cmd_generate.hpp, because the module is a file `aogen generate` writes, made
//   from what it already holds (plans, WGSL texts); the runtime is TypeScript written once in
//   ts/runtime/, not strings in C++.
#pragma once

#include <aogen/depth_mips.hpp>
#include <aogen/error.hpp>
#include <aogen/layout.hpp>
#include <aogen/params.hpp>
#include <aogen/plan.hpp>
#include <aogen/techniques.hpp>

#include <nlohmann/json.hpp>

#include <ts_runtime_embedded.hpp>

#ifndef AOGEN_VERSION
#error "generator/CMakeLists.txt defines AOGEN_VERSION (aogen's version) for the command line's headers"
#endif

#include <array>
#include <map>
#include <string>
#include <vector>

namespace aogen::cli::ts {

// A JSON string: a valid TypeScript string literal too.
inline std::string literal(const std::string& text) { return nlohmann::json(text).dump(); }

// One float setting's table row and its default, as settings.ts's FloatSetting reads them.
template <class P, std::size_t N>
std::string float_rows(const std::array<float_setting<P>, N>& table)
{
    std::string out = "[";
    for (const float_setting<P>& s : table)
        out += "\n        { name: " + literal(s.name) + ", lo: " + format_number(s.range.lo) + ", hi: " + format_number(s.range.hi) +
               ", loExcluded: " + (s.range.lo_excluded ? "true" : "false") + ", valid: " + literal(to_string(s.range)) + " },";
    return out + "\n    ]";
}

// The interface's members for `table`, each with its range and default (P{}'s).
template <class P, std::size_t N>
std::string float_members(const std::array<float_setting<P>, N>& table)
{
    const P defaults{};
    std::string out;
    for (const float_setting<P>& s : table)
        out += "    /** " + to_string(s.range) + "; default " + format_number(defaults.*s.field) + " (params.hpp) */\n    " + s.name + ": number;\n";
    return out;
}

template <class P, std::size_t N>
std::string float_defaults(const P& defaults, const std::array<float_setting<P>, N>& table)
{
    std::string out;
    for (const float_setting<P>& s : table) out += std::string(out.empty() ? "" : ", ") + s.name + ": " + format_number(defaults.*s.field);
    return out;
}

// A names table as a TypeScript tuple of string literals.
template <class Names>
std::string name_tuple(const Names& names)
{
    std::string out = "[";
    for (const auto& n : names) out += std::string(out.size() > 1 ? ", " : "") + literal(std::string(n.name));
    return out + "] as const";
}

// The settings section: interfaces, tables and defaults from params.hpp.
inline std::string settings_section()
{
    const ao_settings d{};
    std::string out = "// ---- generated from aogen/params.hpp: the settings, their defaults and ranges ----------------\n\n";
    out += "export const historyClamps = " + name_tuple(history_clamp_names) + ";\n";
    out += "export const motionUnits = " + name_tuple(motion_units_names) + ";\n";
    out += "export const motionDirections = " + name_tuple(motion_direction_names) + ";\n";
    out += "export const motionYs = " + name_tuple(motion_y_names) + ";\n";
    out += "const kernelNameLength = [" + std::to_string(ssao_params::kernel_name_length_range.lo) + ", " +
           std::to_string(ssao_params::kernel_name_length_range.hi) + "] as const;\n";
    out += "const noiseSizeRange = [" + std::to_string(ssao_params::noise_size_range.lo) + ", " + std::to_string(ssao_params::noise_size_range.hi) +
           "] as const;\n\n";
    out += "export interface SsaoSettings {\n" + float_members(ssao_float_settings) +
           "    /** the kernel's distribution: crytek, cosine or hammersley; default " + literal(d.ssao.kernel) + " */\n    kernel: string;\n" +
           "    /** the kernel's seed, an unsigned 32-bit integer; default " + std::to_string(d.ssao.kernel_seed) + " */\n    kernel_seed: number;\n" +
           "    /** the noise tile's side, " + to_string(ssao_params::noise_size_range) + "; default " + std::to_string(d.ssao.noise_size) +
           " */\n    noise_size: number;\n" + "    /** the noise tile's seed, an unsigned 32-bit integer; default " + std::to_string(d.ssao.noise_seed) +
           " */\n    noise_seed: number;\n}\n";
    out += "export interface GtaoSettings {\n" + float_members(gtao_float_settings) + "}\n";
    out += "export interface VbaoSettings {\n" + float_members(vbao_float_settings) + "}\n";
    out += "export interface SaoSettings {\n" + float_members(sao_float_settings) + "}\n";
    out += "export interface BlurSettings {\n" + float_members(blur_float_settings) + "}\n";
    out += "export interface FinalizeSettings {\n" + float_members(finalize_float_settings) + "}\n";
    out += "/** The renderer's motion vectors (a -histmv variant's): units, which way they point, which way y grows. */\n";
    out += "export interface MotionConvention {\n    units: (typeof motionUnits)[number];\n    direction: (typeof motionDirections)[number];\n"
           "    y: (typeof motionYs)[number];\n}\n";
    out += "export interface HistorySettings {\n" + float_members(history_float_settings) +
           "    /** how the history is clamped: none, range, min_max or variance; default " + literal(names::name_of(history_clamp_names, d.history.clamp, "clamp")) +
           " */\n    clamp: (typeof historyClamps)[number];\n    motion: MotionConvention;\n}\n";
    out += "/** Every pass's run-time settings (params.hpp's ao_settings): a variant reads its technique's, its blur's, finalize and history. */\n";
    out += "export interface Settings {\n    ssao: SsaoSettings;\n    gtao: GtaoSettings;\n    vbao: VbaoSettings;\n    sao: SaoSettings;\n"
           "    blur: BlurSettings;\n    finalize: FinalizeSettings;\n    history: HistorySettings;\n}\n\n";
    out += "const floatSettings: { readonly [G in keyof Settings]: readonly FloatSetting[] } = {\n";
    out += "    ssao: " + float_rows(ssao_float_settings) + ",\n    gtao: " + float_rows(gtao_float_settings) + ",\n    vbao: " +
           float_rows(vbao_float_settings) + ",\n    sao: " + float_rows(sao_float_settings) + ",\n    blur: " + float_rows(blur_float_settings) +
           ",\n    finalize: " + float_rows(finalize_float_settings) + ",\n    history: " + float_rows(history_float_settings) + ",\n};\n\n";
    const motion_convention& motion = d.history.motion;
    out += "/** aogen's defaults (params.hpp), a new object each call. */\nexport function defaultSettings(): Settings {\n    return {\n";
    out += "        ssao: { " + float_defaults(d.ssao, ssao_float_settings) + ", kernel: " + literal(d.ssao.kernel) + ", kernel_seed: " +
           std::to_string(d.ssao.kernel_seed) + ", noise_size: " + std::to_string(d.ssao.noise_size) + ", noise_seed: " + std::to_string(d.ssao.noise_seed) + " },\n";
    out += "        gtao: { " + float_defaults(d.gtao, gtao_float_settings) + " },\n";
    out += "        vbao: { " + float_defaults(d.vbao, vbao_float_settings) + " },\n";
    out += "        sao: { " + float_defaults(d.sao, sao_float_settings) + " },\n";
    out += "        blur: { " + float_defaults(d.blur, blur_float_settings) + " },\n";
    out += "        finalize: { " + float_defaults(d.finalize, finalize_float_settings) + " },\n";
    out += "        history: { " + float_defaults(d.history, history_float_settings) + ", clamp: " +
           literal(names::name_of(history_clamp_names, d.history.clamp, "clamp")) + ",\n            motion: { units: " +
           literal(names::name_of(motion_units_names, motion.units, "units")) + ", direction: " +
           literal(names::name_of(motion_direction_names, motion.direction, "direction")) + ", y: " +
           literal(names::name_of(motion_y_names, motion.y, "y")) + " } },\n";
    return out + "    };\n}\n";
}

// `l` as uniforms.ts's BlockLayout (a WGSL-rules layout: every member a scalar, vector,
// matrix or array of them).
inline std::string block_text(const layout::struct_layout& l)
{
    std::string out = "{ name: " + literal(l.name) + ", size: " + std::to_string(l.size) + ", members: [";
    for (const layout::member_layout& m : l.members) {
        const layout::value_type t = *m.value;
        const char* scalar = t.scalar == layout::scalar_type::float32 ? "f32" : t.scalar == layout::scalar_type::int32 ? "i32" : "u32";
        out += "\n        { name: " + literal(m.name) + ", offset: " + std::to_string(m.offset) + ", scalar: \"" + scalar +
               "\", columns: " + std::to_string(t.columns) + ", rows: " + std::to_string(t.rows) + ", elements: " +
               std::to_string(m.count.value_or(1)) + ", arrayStride: " + std::to_string(m.array_stride) + ", matrixStride: " +
               std::to_string(m.matrix_stride) + " },";
    }
    return out + "\n    ] }";
}

// A shader's resources as passes.ts's BindingInfo list (bind group 0).
inline std::string bindings_text(const std::vector<codegen::resource>& resources)
{
    std::string out = "[";
    for (const codegen::resource& r : resources)
        out += std::string(out.size() > 1 ? ", " : "") + "{ binding: " + std::to_string(r.binding) + ", role: " +
               literal(std::string(names::name_of(resource_role_names, r.role, "role"))) + ", kind: " +
               literal(std::string(names::name_of(codegen::resource_kind_names, r.kind, "kind"))) +
               (r.kind == codegen::resource_kind::storage_image ? ", format: " + literal(codegen::webgpu_format(r.format)) : "") + " }";
    return out + "]";
}

class module {
public:
    // Adds variant `p`, planned for the wgsl target (its webgpu binding model: plan_for(plan,
    // target::wgsl)); `wgsl` holds the WGSL of each of its shaders, in p.shaders()'s order.
    void add(const codegen::plan& p, const std::vector<std::string>& wgsl)
    {
        const variant& v = p.variant();
        std::string passes;
        std::string vertex; // a fragment pass's vertex shader comes first
        for (size_t i = 0; i < p.shaders().size(); ++i) {
            const codegen::shader_plan& s = p.shaders()[i];
            if (s.stage == shader_stage::vertex) {
                vertex = text_index(wgsl.at(i));
                continue;
            }
            const bool compute = s.stage == shader_stage::compute;
            const std::string block = block_index(layout::compute(s.block, layout::rules::wgsl_uniform));
            passes += "\n        { pass: " + literal(std::string(names::name_of(pass_kind_names, s.pass, "pass"))) + ", stage: \"" +
                      (compute ? "compute" : "fragment") + "\", wgsl: wgsl[" + text_index(wgsl.at(i)) + "]!" +
                      (compute ? "" : ", vertexWgsl: wgsl[" + vertex + "]!") + ", entryPoint: \"main\"" +
                      (compute ? ", workgroupSize: [" + std::to_string(s.workgroup.first) + ", " + std::to_string(s.workgroup.second) + ", 1]" : "") +
                      ", pixelsPerInvocation: " + std::to_string(s.pixels_per_invocation) +
                      ", screenSized: " + (s.pass == pass_kind::upsample ? "true" : "false") +
                      // the atlas the Vulkan harness makes too (vulkan/bound_chain.hpp): for the most levels
                      (s.pass == pass_kind::prefilter ? ", atlasLevels: " + std::to_string(depth_mips::levels_range.hi) : "") +
                      ", block: blocks[" + block + "]!" +
                      ",\n            bindings: " + bindings_text(s.resources) + " },";
        }
        const bool slices = has_slices(v.tech);
        variants_ += "    " + literal(p.name()) + ": {\n        name: " + literal(p.name()) + ", technique: " +
                     literal(std::string(names::name_of(technique_names, v.tech, "technique"))) + ", stage: \"" +
                     (v.stage == pipeline_stage::compute ? "compute" : "fragment") + "\", halfResolution: " + (v.half_resolution ? "true" : "false") +
                     ",\n        samples: " + std::to_string(slices ? 0 : v.samples) + ", slices: " + std::to_string(slices ? v.slices : 0) +
                     ", steps: " + std::to_string(slices ? v.steps : 0) + ", periodTurns: " + format_number(technique_of(v.tech).period_turns(v)) +
                     ",\n        passes: [" + passes + "\n        ],\n    },\n";
    }

    // DIR/ts/'s files, by path relative to DIR.
    std::map<std::string, std::string> files() const
    {
        std::string runtime;
        for (const auto& f : ts_runtime::templates) runtime += std::string(f.text) + "\n";
        std::string texts = "const wgsl: readonly string[] = [";
        for (const std::string& t : texts_) texts += "\n    " + literal(t) + ",";
        std::string blocks = "const blocks: readonly BlockLayout[] = [";
        for (const std::string& b : blocks_) blocks += "\n    " + b + ",";
        const std::string module_text = std::string(header) + runtime + settings_section() +
                                        "\n// ---- generated by `aogen generate`: the variants -----------------------------------------------\n\n" +
                                        texts + "\n];\n\n" + blocks + "\n];\n\n" +
                                        "/** The variants of this module, by aogen's canonical name. */\n"
                                        "export const variants: { readonly [name: string]: VariantInfo } = {\n" +
                                        variants_ + "};\n";
        return {{"ts/aogen.ts", module_text}, {"ts/package.json", package_json()}, {"ts/tsconfig.json", tsconfig_json}};
    }

private:
    std::vector<std::string> texts_;  // each WGSL text once
    std::vector<std::string> blocks_; // each block layout once
    std::string variants_;

    std::string text_index(const std::string& text) { return std::to_string(index_of(texts_, text)); }
    std::string block_index(const layout::struct_layout& l) { return std::to_string(index_of(blocks_, block_text(l))); }

    static size_t index_of(std::vector<std::string>& list, const std::string& item)
    {
        for (size_t i = 0; i < list.size(); ++i)
            if (list[i] == item) return i;
        list.push_back(item);
        return list.size() - 1;
    }

    static constexpr const char* header =
        "// aogen.ts -- generated by `aogen generate --targets wgsl,ts`; do not edit.\n"
        "// aogen's AO variants for a WebGPU engine in TypeScript: each variant's passes (WGSL, workgroup,\n"
        "// uniform layout), its settings with aogen's defaults and ranges, and the bytes its chain uploads\n"
        "// (chainInputs: every uniform block, the noise tile), computed bit for bit as aogen's C++ does.\n"
        "//     import { chainInputs, variants } from \"./aogen.js\";\n"
        "//     const inputs = chainInputs(\"ssao-s16-half-bilateral-gbufworld-std-persp-cs\", { camera, settings: { ssao: { radius: 0.8 } } }, 1920, 1080);\n"
        "//     // inputs.uniforms[i]: pass i's bytes for device.queue.writeBuffer; inputs.noise: the rgba32float noise tile\n"
        "// Bad input (a setting out of range, a variant this module does not hold) throws an AogenError naming it.\n\n";

    // The package's version is aogen's (CMake's project version), so a module says which aogen made it.
    static std::string package_json() { return std::string(package_json_head) + AOGEN_VERSION + package_json_tail; }
    static constexpr const char* package_json_head = R"({
  "name": "aogen-variants",
  "version": ")";
    static constexpr const char* package_json_tail = R"(",
  "description": "aogen's AO variants for WebGPU: WGSL, uniform layouts and packing, generated by `aogen generate --targets wgsl,ts`",
  "type": "module",
  "types": "./aogen.ts",
  "exports": { ".": "./aogen.ts" },
  "peerDependencies": { "@webgpu/types": ">=0.1.60" }
}
)";

    static constexpr const char* tsconfig_json = R"({
  "compilerOptions": {
    "target": "ES2022",
    "module": "ES2022",
    "moduleResolution": "bundler",
    "strict": true,
    "noUncheckedIndexedAccess": true,
    "declaration": true,
    "outDir": "dist",
    "types": ["@webgpu/types"]
  },
  "files": ["aogen.ts"]
}
)";
};

} // namespace aogen::cli::ts
