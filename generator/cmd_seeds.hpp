// generator/cmd_seeds.hpp — `aogen seeds`: the data of the seeds' own configurations.
//
//   aogen seeds --out out/seeds
//
// For each preset of presets.hpp (Taos SSAO, Taos GTAO, Unique Engine SSAO, the
// point-cloud viewer's ssao.wgsl) it writes, under DIR/<preset>/:
//   params.json                    the preset's variant axes and settings
//   kernel.json, kernel.rgba32f.bin            the hemisphere kernel (SSAO presets)
//   noise.<encoding>.bin, noise.json           the 4×4 rotation tile, every encoding
//   uniforms.<rules>.bin / .json               the pass's uniform block bytes and layout
//   uniforms.glsl .hlsl .metal .wgsl .<rules>.hpp   its declaration in each language
// and DIR/manifest.json listing every file with its size. All files are built in memory
// first and written only when everything succeeded; unchanged files are not rewritten.
#pragma once

#include "format.hpp"
#include <aogen_tools/files.hpp>
#include <aogen_tools/options.hpp>
#include "struct_json.hpp"

#include <aogen/declare.hpp>
#include <aogen/kernel.hpp>
#include <aogen/noise.hpp>
#include <aogen/presets.hpp>
#include <aogen/uniforms.hpp>

#include <CLI/CLI.hpp>

#include <algorithm>
#include <iostream>
#include <map>

namespace aogen::cli {

using namespace tools; // the readers and writers the command line shares with the report (tools/)

// The example camera the uniform bytes are packed with: 1920×1080, 60° vertical field
// of view (tan 30° written out, so no libm call enters the bytes), near 0.1, far 100,
// standard depth, at the world origin looking down −z.
struct example_camera {
    static constexpr float tan_half_fov_y = 0.57735026918962576f;
    static constexpr float width = 1920, height = 1080, near = 0.1f, far = 100.0f;
    static uniforms::camera get() { return {mat4{}, perspective(tan_half_fov_y, width / height, near, far)}; }
    static vec2 target(bool half_resolution)
    {
        return half_resolution ? vec2{width / 2, height / 2} : vec2{width, height};
    }
};

// Each rule set with the declaration language that expresses it and a file suffix.
struct rules_output {
    layout::rules rules;
    layout::language language;
    const char* declaration_file;
};

inline const rules_output uniform_outputs[] = {
    {layout::rules::std140, layout::language::glsl, "uniforms.glsl"},
    {layout::rules::std430, layout::language::cpp, "uniforms.std430.hpp"},
    {layout::rules::hlsl_cbuffer, layout::language::hlsl, "uniforms.hlsl"},
    {layout::rules::msl, layout::language::msl, "uniforms.metal"},
    {layout::rules::wgsl_uniform, layout::language::wgsl, "uniforms.wgsl"},
};

class seeds_artifacts {
public:
    std::map<std::string, std::string> files; // path relative to DIR → bytes

    void add(const std::string& path, std::string bytes) { files[path] = std::move(bytes); }

    // The data of preset `p`: an SSAO or a GTAO one (the seeds have no VBAO).
    void add_preset(const preset& p)
    {
        validate(p);
        if (p.variant.tech == technique::ssao) add_ssao(p);
        else if (p.variant.tech == technique::gtao) add_gtao(p);
        else fail("seeds", std::string(p.name) + " is a " + to_name(p.variant.tech) + " preset", "valid: ssao, gtao");
    }

    std::string manifest() const
    {
        nlohmann::ordered_json j;
        j["camera"] = {{"width", example_camera::width}, {"height", example_camera::height},
                       {"tan_half_fov_y", json_float(example_camera::tan_half_fov_y)}, {"near", json_float(example_camera::near)},
                       {"far", json_float(example_camera::far)}, {"depth", "standard"}};
        nlohmann::ordered_json list = nlohmann::ordered_json::array();
        for (const auto& [path, bytes] : files) list.push_back({{"path", path}, {"bytes", bytes.size()}});
        j["files"] = list;
        return j.dump(2) + "\n";
    }

private:
    void add_ssao(const preset& p)
    {
        const ssao_params& s = p.settings.ssao;
        const std::string dir = std::string(p.name) + "/";
        const auto samples = kernel::generate(kernel::distribution_from_name(s.kernel), p.variant.samples,
                                              s.kernel_seed, kernel::scale_law::crytek);
        add(dir + "params.json", ssao_json(p).dump(2) + "\n");
        add(dir + "kernel.json", vec4_array("kernel", samples, text_language::json));
        add(dir + "kernel.rgba32f.bin", vec4_bytes(samples));
        add_noise(dir, s.noise_size, s.noise_seed);
        const bool seed004_block = p.variant.point_cloud_fallback; // the viewer keeps its own block
        for (const rules_output& o : uniform_outputs) {
            const layout::block_desc block = seed004_block ? uniforms::pointcloud_block() : uniforms::ssao_block(p.variant.samples);
            const std::vector<uint8_t> bytes =
                seed004_block ? uniforms::pack_pointcloud(s, example_camera::get().proj, o.rules)
                              : uniforms::pack_ssao(s, example_camera::get(), samples,
                                                    example_camera::target(p.variant.half_resolution), o.rules);
            add_uniforms(dir, block, o, bytes);
        }
    }

    void add_gtao(const preset& p)
    {
        const gtao_params& g = p.settings.gtao;
        const std::string dir = std::string(p.name) + "/";
        nlohmann::ordered_json j;
        j["name"] = p.name;
        j["gtao"] = {{"radius", json_float(g.radius)}, {"thickness_bias", json_float(g.thickness_bias)}, {"strength", json_float(g.strength)},
                     {"falloff_range", json_float(g.falloff_range)}, {"thin_occluder", json_float(g.thin_occluder)},
                     {"slices", p.variant.slices}, {"steps", p.variant.steps}, {"half_resolution", p.variant.half_resolution},
                     {"normals", to_name(p.variant.normals)}};
        j["blur"] = blur_json(p);
        add(dir + "params.json", j.dump(2) + "\n");
        add_noise(dir, noise::default_size, 2);
        for (const rules_output& o : uniform_outputs)
            add_uniforms(dir, uniforms::gtao_block(), o,
                         uniforms::pack_gtao(g, example_camera::get(), example_camera::target(p.variant.half_resolution), o.rules));
    }

    void add_noise(const std::string& dir, int size, uint64_t seed)
    {
        const noise::tile tile = noise::rotations(size, seed);
        add(dir + "noise.json", vec4_array("noise", tile.texels, text_language::json));
        for (noise::encoding e : {noise::encoding::rgba32f, noise::encoding::rgba16f, noise::encoding::rg16f,
                                  noise::encoding::rgba8_unorm, noise::encoding::rgba8_snorm}) {
            const std::vector<uint8_t> bytes = noise::encode(tile, e);
            add(dir + "noise." + std::string(noise::to_name(e)) + ".bin", std::string(bytes.begin(), bytes.end()));
        }
    }

    void add_uniforms(const std::string& dir, const layout::block_desc& block, const rules_output& o,
                      const std::vector<uint8_t>& bytes)
    {
        const layout::struct_layout l = layout::compute(block, o.rules);
        const std::string rules = layout::to_name(o.rules);
        add(dir + "uniforms." + rules + ".bin", std::string(bytes.begin(), bytes.end()));
        add(dir + "uniforms." + rules + ".json", layout_to_json(l).dump(2) + "\n");
        add(dir + o.declaration_file, layout::declare(l, o.language));
    }

    // The blur's axes (the variant's) and constants (the settings').
    static nlohmann::ordered_json blur_json(const preset& p)
    {
        const blur_params& b = p.settings.blur;
        return {{"mode", to_name(p.variant.blur)}, {"depth", to_name(p.variant.blur_depth)}, {"raw_depth_k", json_float(b.raw_depth_k)},
                {"linear_sharpness", json_float(b.linear_sharpness)}};
    }

    // The SSAO axes and settings, interleaved in the order the files have always had.
    static nlohmann::ordered_json ssao_json(const preset& p)
    {
        const ssao_params& s = p.settings.ssao;
        const variant& v = p.variant;
        nlohmann::ordered_json j;
        j["name"] = p.name;
        j["ssao"] = {{"samples", v.samples}, {"radius", json_float(s.radius)}, {"bias", json_float(s.bias)}, {"output", to_name(v.output)},
                     {"strength", json_float(s.strength)}, {"power", json_float(s.power)}, {"intensity", json_float(s.intensity)},
                     {"range_check", to_name(v.range_check)}, {"kernel", s.kernel}, {"kernel_seed", s.kernel_seed},
                     {"noise_size", s.noise_size}, {"noise_seed", s.noise_seed},
                     {"half_resolution", v.half_resolution}, {"normals", to_name(v.normals)},
                     {"point_cloud_fallback", v.point_cloud_fallback}};
        j["blur"] = blur_json(p);
        return j;
    }
};

struct seeds_command {
    std::string out = "out/seeds";

    void add_to(CLI::App& app)
    {
        CLI::App* sub = app.add_subcommand("seeds", "Write the kernels, noise tiles and uniform blocks of the seeds' presets");
        sub->add_option("--out", out, "Output directory")->capture_default_str()->check(not_empty("a directory path"));
        sub->callback([this] { run(); });
    }

    void run() const
    {
        require_writable_folder(out, "--out");
        seeds_artifacts a;
        for (const preset& p : presets::seeds()) a.add_preset(p);
        a.add("manifest.json", a.manifest());
        // Every file or none: what was written is said once all of it is in place.
        file_set set(out);
        for (const auto& [path, bytes] : a.files) set.add(path, bytes);
        const std::vector<std::string> changed = set.commit();
        const size_t written = changed.size();
        for (const auto& [path, bytes] : a.files) {
            const bool was_written = std::binary_search(changed.begin(), changed.end(), path);
            std::cout << (was_written ? "wrote     " : "unchanged ") << out << "/" << path << " (" << bytes.size() << " bytes)\n";
        }
        std::cout << a.files.size() << " files in " << out << " (" << written << " written, "
                  << a.files.size() - written << " unchanged)\n";
    }
};

} // namespace aogen::cli
