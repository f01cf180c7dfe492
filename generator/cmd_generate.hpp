// generator/cmd_generate.hpp — `aogen generate`: shader variants for every target.
//
//   aogen generate --out DIR                                  the default matrix
//   aogen generate --out DIR ssao-s16-half-bilateral-gbufworld-std-persp-cs ...
//   aogen generate --out DIR --variants spec.json --scene scene.json --targets spv,hlsl60
//
// For every variant (after scene selection when --scene is given) and every shader of
// its passes, it writes DIR/<variant>/<pass>.<comp|vert|frag>.<target extension>, then
//   DIR/manifest.json       bindings, uniform layouts, features and what was left out
//   DIR/aogen_variants.hpp  SPIR-V as uint32_t arrays, the uniform structs (C++, with
//                           static_asserts), binding constants
//   DIR/ts/                 with --targets wgsl,ts: the variants as one TypeScript module for a
//                           WebGPU engine (aogen.ts, package.json, tsconfig.json; ts_module.hpp)
// All of it is built in memory first; files are written only when everything compiled,
// each to a temporary name and renamed, and a file whose bytes would not change is not
// rewritten. Identical sources (variants sharing an AO pass) are compiled once. ESSL
// compute passes write an rgba8 image (ESSL 3.10 has no r8); every other target r8.
#pragma once

#include <aogen_tools/files.hpp>
#include <aogen_tools/options.hpp>
#include "struct_json.hpp"
#include "ts_module.hpp"
#include <aogen_tools/variant_spec.hpp>

#include <aogen/codegen.hpp>
#include <aogen/compile.hpp>
#include <aogen/declare.hpp>
#include <aogen/emitted.hpp>
#include <aogen/matrix.hpp>
#include <aogen/quality.hpp>
#include <aogen/selection.hpp>

#include <CLI/CLI.hpp>

#include <iostream>
#include <map>

namespace aogen::cli {

using namespace tools; // the readers and writers the command line shares with the report (tools/)

// A C++ identifier from a variant or pass name: '-' and '.' become '_'.
inline std::string identifier(std::string s)
{
    for (char& c : s)
        if (c == '-' || c == '.') c = '_';
    return s;
}

inline std::string spirv_array(const std::string& name, const std::vector<uint32_t>& words)
{
    static const char digits[] = "0123456789abcdef";
    std::string out = "inline constexpr std::uint32_t " + name + "[" + std::to_string(words.size()) + "] = {";
    for (size_t i = 0; i < words.size(); ++i) {
        out += i % 8 == 0 ? "\n    " : " ";
        std::string hex = "0x00000000";
        for (int d = 0; d < 8; ++d) hex[9 - d] = digits[(words[i] >> (4 * d)) & 15];
        out += hex + ",";
    }
    return out + "\n};\n";
}

// How aogen's own tests check a target's text for `v` (targets.hpp's verification): its row's,
// or its row's for fp16 variants.
inline const char* verification(compile::target t, const variant& v)
{
    const compile::target_info& row = compile::info(t);
    return compile::to_name(v.fp16 ? row.checked_fp16 : row.checked);
}

// What an engine must keep for a history variant (-hist, -histmv): the two history images,
// their format and size, which binding reads and which writes, what a frame, a cut and a
// resize do (docs/bindings.md says the same).
inline nlohmann::ordered_json history_entry(const variant& v)
{
    const auto at = [](resource_role r) { return binding_of(pass_family::history, r, binding_model::vulkan); };
    const auto at_webgpu = [](resource_role r) { return binding_of(pass_family::history, r, binding_model::webgpu); };
    nlohmann::ordered_json h;
    h["format"] = codegen::history_format;
    h["channels"] = ".r AO, .g log2 of the view depth, .b frames held (0: none)";
    h["size"] = "the AO target's: the screen's, or half of it rounded up at half resolution";
    h["read"] = {{"name", "u_history"}, {"binding", at(resource_role::history)}, {"wgsl_binding", at_webgpu(resource_role::history)}};
    const bool fragment = v.stage == pipeline_stage::fragment;
    if (fragment) // two colour attachments: the AO at location 0, the history at 1
        h["written"] = {{"name", "o_history"}, {"colour_attachment", 1}};
    else
        h["written"] = {{"name", "u_history_output"}, {"binding", at(resource_role::history_output)}, {"wgsl_binding", at_webgpu(resource_role::history_output)}};
    if (v.history == history_mode::motion_vectors)
        h["motion_vectors"] = {{"name", "u_motion"}, {"binding", at(resource_role::motion)}, {"wgsl_binding", at_webgpu(resource_role::motion)},
                               {"convention", "history_params::motion (default: NDC, current minus previous, y up)"}};
    h["each_frame"] = fragment ? "bind the image written last frame as u_history and render the history pass into the AO image (attachment 0) and the other (attachment 1), run the chain, swap the two"
                               : "bind the image written last frame as u_history and the other as u_history_output, run the chain, swap the two";
    h["first_frame_and_resize"] = "two new images cleared to 0 (a cleared history holds no frame: the pass writes this frame alone)";
    h["camera_cut"] = "HistoryUniforms.reset = 1 (chain_settings::reset_history) for one frame: the output is the chain's without the pass, bit for bit";
    return h;
}

class variant_generator {
public:
    std::vector<compile::target> targets;
    bool typescript = false; // --targets ...,ts: the TypeScript module (ts_module.hpp), from the WGSL
    std::map<std::string, std::string> files; // path relative to DIR → bytes
    nlohmann::ordered_json manifest = {{"variants", nlohmann::ordered_json::array()}};
    std::string header;

    bool targets_include(compile::target t) const { return std::find(targets.begin(), targets.end(), t) != targets.end(); }

    // Adds the planned variant `p` (made once by make_plan; each target's sources come from
    // plan_for(p, target), which plans nothing again).
    void add(const codegen::plan& p, const feature_list& features)
    {
        const variant& v = p.variant();
        const std::string name = p.name();
        const std::string ns = identifier(name);
        nlohmann::ordered_json entry;
        entry["name"] = name;
        entry["hash"] = hash(v);
        entry["technique"] = names::name_of(technique_names, v.tech, "technique");
        entry["stage"] = names::name_of(pipeline_stage_names, v.stage, "stage");
        if (const std::string q = quality_name_of(v); !q.empty()) entry["quality"] = q; // aogen/quality.hpp
        entry["features"] = features.compiled;
        nlohmann::ordered_json left = nlohmann::ordered_json::array();
        for (const left_out_feature& f : features.left_out) left.push_back({{"feature", f.feature}, {"why", f.why}});
        entry["left_out"] = left;
        nlohmann::ordered_json verified;
        for (compile::target t : targets) verified[compile::to_name(t)] = verification(t, v);
        entry["verification"] = verified;
        if (has_history_pass(v)) entry["history"] = history_entry(v);

        std::string ns_body;
        std::vector<std::string> declared_structs;
        nlohmann::ordered_json passes = nlohmann::ordered_json::array();
        const std::vector<codegen::shader_source> sources = codegen::generate(p);
        const std::vector<codegen::shader_source> essl_sources =
            wants(compile::target::essl) ? codegen::generate(plan_for(p, compile::target::essl)) : std::vector<codegen::shader_source>{};
        const std::vector<codegen::shader_source> wgsl_sources =
            wants(compile::target::wgsl) ? codegen::generate(plan_for(p, compile::target::wgsl)) : std::vector<codegen::shader_source>{};
        for (size_t i = 0; i < sources.size(); ++i) {
            const codegen::shader_source& s = sources[i];
            const codegen::shader_plan& planned = p.shaders()[i];
            const shader_stage stage = s.stage;
            const compile::compiled& c = compiled_once(s.glsl, stage, s.name, other_targets());
            const compile::compiled* essl = wants(compile::target::essl)
                                                ? &compiled_once(essl_sources[i].glsl, stage, s.name, {compile::target::essl})
                                                : nullptr;
            const std::string base = name + "/" + names::name_of(pass_kind_names, s.pass, "pass") + "." +
                                     file_extension(s.stage);
            nlohmann::ordered_json pass;
            pass["pass"] = names::name_of(pass_kind_names, s.pass, "pass");
            pass["stage"] = to_name(stage);
            nlohmann::ordered_json outputs;
            for (compile::target t : targets) {
                const std::string path = base + "." + compile::info(t).extension;
                outputs[compile::to_name(t)] = path;
                if (t == compile::target::spv) files[path] = spirv_bytes(c.spirv);
                else if (t == compile::target::essl) files[path] = essl->text.at(t);
                else if (t == compile::target::wgsl) files[path] = wgsl_.at(wgsl_sources[i].glsl).text;
                else files[path] = c.text.at(t);
            }
            pass["outputs"] = outputs;
            pass["entry"] = c.refl.entry_points.at(compile::target::spv);
            nlohmann::ordered_json entries;
            for (const auto& [t, e] : c.refl.entry_points) entries[compile::to_name(t)] = e;
            if (essl) entries[compile::to_name(compile::target::essl)] = essl->refl.entry_points.at(compile::target::essl);
            const translated_wgsl* wgsl = wants(compile::target::wgsl) ? &wgsl_.at(wgsl_sources[i].glsl) : nullptr;
            if (wgsl) entries[compile::to_name(compile::target::wgsl)] = wgsl->refl.entry_points.at(compile::target::spv);
            pass["entry_points"] = entries;
            pass["bindings"] = bindings_json(c.refl);
            if (wgsl) pass["wgsl_bindings"] = bindings_json(wgsl->refl); // bind group 0, as naga reads the WGSL
            if (stage == shader_stage::compute) {
                pass["workgroup_size"] = {c.refl.workgroup_size[0], c.refl.workgroup_size[1], c.refl.workgroup_size[2]};
                // Dispatch ceil(output size / pixels_per_invocation / workgroup size) groups.
                pass["pixels_per_invocation"] = pixels_per_invocation(s.pass, pipeline_stage::compute);
            }
            const std::string pass_id = identifier(pass["pass"].get<std::string>() + "_" + file_extension(s.stage));
            ns_body += "// pass " + pass["pass"].get<std::string>() + ", " + to_name(stage) + " shader\n";
            ns_body += spirv_array(pass_id + "_spv", c.spirv);
            for (const compile::descriptor_binding& b : c.refl.bindings)
                ns_body += "inline constexpr std::uint32_t " + pass_id + "_binding_" + identifier(b.instance.empty() ? b.name : b.instance) +
                           " = " + std::to_string(b.binding) + ";\n";
            if (wgsl)
                for (const compile::descriptor_binding& b : wgsl->refl.bindings)
                    ns_body += "inline constexpr std::uint32_t " + pass_id + "_wgsl_binding_" +
                               identifier(b.instance.empty() ? b.name : b.instance) + " = " + std::to_string(b.binding) + ";\n";
            for (const codegen::resource& r : s.resources) {
                if (r.kind != codegen::resource_kind::uniform_buffer) continue;
                const layout::struct_layout& l = planned.layout; // std140, laid out by the plan
                const compile::buffer_block* block = compile::find_block(c.refl, l.name);
                if (!block) fail(s.name, "its SPIR-V has no uniform block " + l.name, "valid: the block codegen declared");
                compile::check_layout(*block, l); // the core layout engine against SPIR-V's own offsets
                if (wgsl) {
                    // The same bytes under WGSL's rules: aogen's layout against naga's, read from
                    // the SPIR-V naga makes of the WGSL it wrote.
                    const std::optional<compile::buffer_block> naga_block = compile::find_struct_block(wgsl->refl, l.name);
                    if (!naga_block) fail(s.name, "its WGSL has no uniform struct " + l.name, "valid: the block codegen declared");
                    compile::check_layout(*naga_block, layout::compute(planned.block, layout::rules::wgsl_uniform));
                }
                pass["uniforms"] = layout_to_json(l);
                if (std::find(declared_structs.begin(), declared_structs.end(), l.name) == declared_structs.end()) {
                    declared_structs.push_back(l.name);
                    layout::declaration_options o;
                    o.cpp_prelude = false;
                    ns_body += layout::declare(l, layout::language::cpp, o);
                }
            }
            pass["spirv_words"] = c.refl.spirv_words;
            pass["spirv_instructions"] = c.refl.spirv_instructions;
            passes.push_back(pass);
        }
        // The variant's own figures are its AO shader's (the first compute or fragment pass).
        for (const auto& p : passes)
            if (p["pass"] == "ao" && p["stage"] != "vertex") {
                entry["entry"] = p["entry"];
                entry["outputs"] = p["outputs"];
                entry["bindings"] = p["bindings"];
                entry["uniforms"] = p["uniforms"];
                entry["spirv_instructions"] = p["spirv_instructions"];
            }
        entry["passes"] = passes;
        manifest["variants"].push_back(entry);
        if (typescript) {
            std::vector<std::string> texts;
            for (const codegen::shader_source& s : wgsl_sources) texts.push_back(wgsl_.at(s.glsl).text);
            ts_module_.add(plan_for(p, compile::target::wgsl), texts);
        }
        header += "namespace " + ns + " {\ninline constexpr const char name[] = \"" + name + "\";\n" + ns_body +
                  "} // namespace " + ns + "\n\n";
    }

    // The TypeScript module's files (DIR/ts/), when asked for.
    std::map<std::string, std::string> typescript_files() const { return typescript ? ts_module_.files() : std::map<std::string, std::string>{}; }

    std::string header_text() const
    {
        return "// aogen_variants.hpp — generated by `aogen generate`; do not edit.\n"
               "// Per variant (namespace aogen_variants::<variant name with '_'>): the SPIR-V of each\n"
               "// pass, its binding numbers and the uniform structs as the shader declares them.\n"
               "#pragma once\n" +
               std::string(layout::detail::cpp_prelude()) + "\nnamespace aogen_variants {\n\n" + header +
               "} // namespace aogen_variants\n";
    }

    // Translates every WebGPU-model source of `variants` to WGSL in one batch (a Node.js
    // process costs a quarter of a second): naga writes it, naga and Tint validate it, and
    // naga's SPIR-V of it is reflected for the manifest's wgsl_bindings and the layout check.
    void prepare_wgsl(const std::vector<codegen::plan>& plans)
    {
        if (!wants(compile::target::wgsl)) return;
        std::vector<codegen::shader_source> unique; // by GLSL text (their names are the first variant's)
        std::vector<std::vector<uint32_t>> spirv;
        for (const codegen::plan& p : plans)
            for (const codegen::shader_source& s : codegen::generate(plan_for(p, compile::target::wgsl))) {
                if (std::any_of(unique.begin(), unique.end(), [&](const codegen::shader_source& u) { return u.glsl == s.glsl; })) continue;
                unique.push_back(s);
                spirv.push_back(compiled_once(s.glsl, s.stage, s.name, {compile::target::spv}).spirv);
            }
        if (unique.empty()) return;
        const std::vector<std::string> texts = wgsl_texts(unique, spirv); // an fp16 variant is refused by name, with the reason
        std::vector<wgsl::wgsl_job> back;
        for (size_t i = 0; i < unique.size(); ++i) back.push_back({unique[i].name, unique[i].stage, texts[i]});
        const std::vector<std::vector<uint32_t>> naga_spirv = wgsl::to_spirv(back);
        for (size_t i = 0; i < unique.size(); ++i)
            wgsl_[unique[i].glsl] = {texts[i], compile::reflect(naga_spirv[i], unique[i].stage, unique[i].name + " (naga's SPIR-V of its WGSL)")};
    }

private:
    std::map<std::pair<std::string, std::vector<compile::target>>, compile::compiled> cache_; // by GLSL source text and targets
    struct translated_wgsl {
        std::string text;
        compile::reflection refl; // of naga's SPIR-V of the text
    };
    std::map<std::string, translated_wgsl> wgsl_; // by WebGPU-model GLSL source
    ts::module ts_module_;

    bool wants(compile::target t) const { return targets_include(t); }

    std::vector<compile::target> other_targets() const
    {
        std::vector<compile::target> out;
        for (compile::target t : targets) // made from the ordinary GLSL (options_for's default options)
            if (!compile::info(t).four_channel_output && !compile::info(t).separate_samplers) out.push_back(t);
        return out;
    }

    const compile::compiled& compiled_once(const std::string& glsl, shader_stage stage, const std::string& name,
                                           const std::vector<compile::target>& for_targets)
    {
        // By the targets too: prepare_wgsl compiles a WebGPU-model source for SPIR-V alone, and
        // where that source is the ordinary one, add() then needs its other targets' texts.
        const auto key = std::make_pair(glsl, for_targets);
        auto found = cache_.find(key);
        if (found != cache_.end()) return found->second;
        return cache_.emplace(key, compile::compile(glsl, stage, name, for_targets)).first->second;
    }

    static std::string spirv_bytes(const std::vector<uint32_t>& words)
    {
        std::string bytes;
        for (uint32_t w : words)
            for (int i = 0; i < 4; ++i) bytes.push_back(static_cast<char>(w >> (8 * i)));
        return bytes;
    }

    static nlohmann::ordered_json bindings_json(const compile::reflection& refl)
    {
        nlohmann::ordered_json out = nlohmann::ordered_json::array();
        for (const compile::descriptor_binding& b : refl.bindings) {
            nlohmann::ordered_json j;
            j["set"] = b.set;
            j["binding"] = b.binding;
            j["kind"] = compile::to_name(b.kind);
            j["name"] = b.instance.empty() ? b.name : b.instance;
            j["type"] = b.type;
            if (!b.image_format.empty()) j["format"] = b.image_format;
            out.push_back(j);
        }
        return out;
    }
};

struct generate_command {
    std::string spec;
    std::string scene;
    std::string out;
    std::string targets = compile::default_generate_targets(); // wgsl on request: it needs Node.js
    std::vector<std::string> variant_names;
    bool quiet = false;

    void add_to(CLI::App& app)
    {
        CLI::App* sub = app.add_subcommand("generate", "Generate shader variants for every target, a manifest and a C++ header");
        sub->add_option("--variants", spec, "A variant spec (JSON: \"variants\" names and/or \"matrices\")")->check(not_empty("a variant spec file"));
        sub->add_option("--scene", scene, "What the renderer has and needs (JSON); selects each variant's features")->check(not_empty("a scene file"));
        sub->add_option("--targets", targets,
                        "Comma-separated: " + compile::target_list() + ", and ts with wgsl (the TypeScript module; wgsl needs Node.js: scripts/install-deps.sh)")
            ->capture_default_str();
        sub->add_option("--out", out, "Output directory")->required()->check(not_empty("a directory path"));
        sub->add_flag("--quiet", quiet, "No progress on stderr");
        sub->add_option("NAME", variant_names, "Variant names (see aogen list); none and no --variants: the default matrix");
        sub->callback([this] { run(); });
    }

    void run() const
    {
        require_writable_folder(out, "--out"); // before minutes of compiling, not after
        variant_generator g;
        const auto is_target = [](const std::string& t) {
            const auto& names = compile::target_names;
            return std::any_of(names.begin(), names.end(), [&](const auto& n) { return names::same_name(t, n.name); });
        };
        for (const std::string& t : split_list(targets))
            if (t == "ts") g.typescript = true;
            else if (is_target(t)) g.targets.push_back(compile::target_from_name(t, "--targets"));
            else fail("--targets", quote(t) + " is not a known name", "valid: " + compile::target_list() + ", ts with wgsl");
        if (g.targets.empty()) fail("--targets", "is empty", "valid: " + compile::target_list() + ", ts with wgsl");
        if (g.typescript && !g.targets_include(compile::target::wgsl))
            fail("--targets", "ts without wgsl", "valid: ts with wgsl, e.g. --targets wgsl,ts: the TypeScript module holds the WGSL");
        std::vector<variant> variants;
        for (const std::string& n : variant_names) append_unique(variants, variant_from_name(n));
        if (!spec.empty())
            for (const variant& v : variants_from_json(json_reader(json_reader::parse(read_file(spec), spec), spec)))
                append_unique(variants, v);
        if (variant_names.empty() && spec.empty()) variants = default_matrix();

        std::optional<scene_needs> needs;
        if (!scene.empty()) needs = scene_from_json(json_reader(json_reader::parse(read_file(scene), scene), scene));
        std::vector<selection> selected;
        for (const variant& v : variants) {
            selection s = needs ? select(v, *needs) : selection{v, features(v)};
            bool duplicate = false;
            for (const selection& existing : selected) duplicate = duplicate || existing.v == s.v;
            if (!duplicate) selected.push_back(s);
        }
        std::vector<codegen::plan> plans; // each variant planned once: every target's sources come from its plan
        for (const selection& s : selected) plans.push_back(codegen::make_plan(s.v));
        g.prepare_wgsl(plans);
        for (size_t i = 0; i < selected.size(); ++i) {
            if (!quiet) std::cerr << "aogen: [" << i + 1 << "/" << selected.size() << "] " << plans[i].name() << "\n";
            g.add(plans[i], selected[i].features);
        }
        g.files["manifest.json"] = g.manifest.dump(2) + "\n";
        g.files["aogen_variants.hpp"] = g.header_text();
        for (const auto& [path, text] : g.typescript_files()) g.files[path] = text;
        file_set set(out);
        for (const auto& [path, bytes] : g.files) set.add(path, bytes);
        const size_t written = set.commit().size();
        if (!quiet)
            std::cerr << "aogen: " << selected.size() << " variants, " << g.files.size() << " files in " << out << " ("
                      << written << " written, " << g.files.size() - written << " unchanged)\n";
    }

    static std::vector<std::string> split_list(const std::string& s)
    {
        std::vector<std::string> parts;
        std::string part;
        for (char c : s + ",") {
            if (c != ',') part += c;
            else if (!part.empty()) parts.push_back(part), part.clear();
        }
        return parts;
    }
};

} // namespace aogen::cli
