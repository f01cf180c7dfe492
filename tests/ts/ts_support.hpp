// tests/ts/ts_support.hpp — what the TypeScript module's tests share: the module the command line
// generates for thirteen variants, compiled by the pinned tsc --strict (once, at build time; a
// mutant aimed at it makes its own); a process runner; the settings and cameras as the module
// reads them (JSON).
#pragma once

#include <aogen/chain_inputs.hpp>
#include <aogen/plan.hpp>
#include <aogen/wgsl.hpp>

#include "mutants/mutants.hpp"

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <sstream>

#ifndef AOGEN_TS_MODULE_DIR
#error "tests/CMakeLists.txt defines AOGEN_TS_TESTS_DIR (tests/ts) and AOGEN_TS_MODULE_DIR (the build's module)"
#endif

namespace aogen_test {

using namespace aogen;
using nlohmann::json;

// The variants the module is generated for: module_variants.txt's, one a line ('#' a comment).
inline const std::vector<std::string> module_variants = [] {
    std::vector<std::string> names;
    std::istringstream in(wgsl::detail::read_all(AOGEN_TS_TESTS_DIR "/module_variants.txt"));
    for (std::string line; std::getline(in, line);)
        if (!line.empty() && line[0] != '#') names.push_back(line);
    return names;
}();

// Runs `args` (args[0] a path): its exit status (-1: killed) and what it wrote to stdout and stderr.
inline std::pair<int, std::string> run_status(std::vector<std::string> args, const std::string& log)
{
    const int status = wgsl::detail::run_process(std::move(args), log, true);
    return {status, wgsl::detail::read_all(log)};
}

// run_status, and an aogen::error unless it exits 0.
inline std::string run(std::vector<std::string> args, const std::string& log)
{
    const std::string program = args.at(0);
    const auto [status, said] = run_status(std::move(args), log);
    if (status != 0) fail(program, "failed: " + said.substr(0, 2000), "valid: exit status 0");
    return said;
}

// Whether the active mutant is aimed at the module (and the build's, made without it, will not do).
inline bool mutant_in_module()
{
    const std::optional<mutant>& m = active_mutant();
    return m && m->kind == "emitted" && m->file == "ts:aogen.ts";
}

// A module compiled by tsc --strict -- the build's (tests/ts/build_module.cmake), or under a
// mutant aimed at it this process's own: the build's generated text, the mutant planted,
// compiled here -- and a scratch folder for this process's files.
struct compiled_module {
    wgsl::detail::scratch dir;
    // The scratch folder removes its files; its folders are removed here -- also when the
    // constructor throws (a member is destroyed then, the object is not).
    struct folders_removed {
        const wgsl::detail::scratch& dir;
        ~folders_removed()
        {
            if (std::getenv("AOGEN_WGSL_KEEP")) return;
            for (const auto& e : std::filesystem::directory_iterator(dir.path()))
                if (e.is_directory() && !e.is_symlink()) std::filesystem::remove_all(e.path());
        }
    } cleanup{dir};
    wgsl::tools tools = wgsl::find_tools();
    std::string root; // holds ts/
    std::string ts() const { return root + "/ts"; }
    std::string js() const { return ts() + "/dist/aogen.js"; }

    // The build's module in `built`.
    explicit compiled_module(const std::string& built) : root(mutant_in_module() ? dir.path() : built)
    {
        if (wgsl::detail::is_file(built + "/FAILED")) fail("ts test", wgsl::detail::read_all(built + "/FAILED"), "valid: scripts/install-deps.sh, then the build");
        if (!wgsl::detail::is_file(built + "/BUILT")) fail("ts test", "the build made no module in " + built, "valid: the build's ts module targets built");
        if (root == built) return;
        std::filesystem::create_directory(ts());
        for (const char* f : {"package.json", "tsconfig.json"}) std::filesystem::copy_file(built + "/ts/" + f, ts() + "/" + f);
        wgsl::detail::write_all(ts() + "/aogen.ts", aogen_test::emitted_under_test(wgsl::detail::read_all(built + "/ts/aogen.ts"), "ts:aogen.ts"));
        // The module's one dependency, @webgpu/types, where a project keeps it: its node_modules.
        std::filesystem::create_directory_symlink(tools.dir + "/node_modules", ts() + "/node_modules");
        run({tools.node, tools.dir + "/node_modules/typescript/bin/tsc", "-p", ts()}, dir.file("tsc.log"));
    }
    compiled_module(const compiled_module&) = delete;
    compiled_module& operator=(const compiled_module&) = delete;

    // ts_cases.mjs over `cases`: its results.
    json results(const json& cases) const
    {
        wgsl::detail::write_all(dir.file("cases.json"), cases.dump());
        run({tools.node, std::string(AOGEN_TS_TESTS_DIR) + "/ts_cases.mjs", js(), dir.file("cases.json"), dir.file("results.json")},
            dir.file("cases.log"));
        return json::parse(wgsl::detail::read_all(dir.file("results.json")));
    }
};

// The module of module_variants.
inline const compiled_module& the_module()
{
    static const compiled_module m(AOGEN_TS_MODULE_DIR);
    return m;
}

inline std::string hex(const uint8_t* bytes, size_t n)
{
    static const char digits[] = "0123456789abcdef";
    std::string out;
    for (size_t i = 0; i < n; ++i) out += digits[bytes[i] >> 4], out += digits[bytes[i] & 15];
    return out;
}
inline std::string hex(const std::vector<uint8_t>& b) { return hex(b.data(), b.size()); }
inline std::string hex(const std::vector<vec4>& v) { return hex(reinterpret_cast<const uint8_t*>(v.data()), v.size() * sizeof(vec4)); }

inline json matrix_json(const mat4& m)
{
    json a = json::array();
    for (int i = 0; i < 16; ++i) a.push_back(m[i / 4][i % 4]);
    return a;
}

inline json camera_json(const uniforms::camera& c) { return {{"worldToView", matrix_json(c.world_to_view)}, {"proj", matrix_json(c.proj)}}; }

template <class P, std::size_t N>
json floats_json(const P& p, const std::array<float_setting<P>, N>& table)
{
    json j = json::object();
    for (const float_setting<P>& s : table) j[s.name] = p.*s.field;
    return j;
}

// `s` as the module's SettingsInput: every setting, by params.hpp's names.
inline json settings_json(const ao_settings& s)
{
    json j;
    j["ssao"] = floats_json(s.ssao, ssao_float_settings);
    j["ssao"]["kernel"] = s.ssao.kernel, j["ssao"]["kernel_seed"] = s.ssao.kernel_seed;
    j["ssao"]["noise_size"] = s.ssao.noise_size, j["ssao"]["noise_seed"] = s.ssao.noise_seed;
    j["gtao"] = floats_json(s.gtao, gtao_float_settings);
    j["vbao"] = floats_json(s.vbao, vbao_float_settings);
    j["sao"] = floats_json(s.sao, sao_float_settings);
    j["blur"] = floats_json(s.blur, blur_float_settings);
    j["finalize"] = floats_json(s.finalize, finalize_float_settings);
    j["history"] = floats_json(s.history, history_float_settings);
    j["history"]["clamp"] = names::name_of(history_clamp_names, s.history.clamp, "clamp");
    j["history"]["motion"] = {{"units", names::name_of(motion_units_names, s.history.motion.units, "units")},
                              {"direction", names::name_of(motion_direction_names, s.history.motion.direction, "direction")},
                              {"y", names::name_of(motion_y_names, s.history.motion.y, "y")}};
    return j;
}

} // namespace aogen_test
