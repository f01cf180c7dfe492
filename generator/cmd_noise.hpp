// generator/cmd_noise.hpp — `aogen noise`: a noise tile of rotation vectors, encoded.
//
//   aogen noise --size 4 --seed 2 --encoding rgba8_unorm --format bin --out noise.bin
#pragma once

#include "format.hpp"
#include <aogen_tools/files.hpp>
#include <aogen_tools/options.hpp>

#include <aogen/noise.hpp>

#include <CLI/CLI.hpp>

namespace aogen::cli {

using namespace tools; // the readers and writers the command line shares with the report (tools/)

struct noise_command {
    int size = 4;
    uint64_t seed = 2;
    std::string pattern = "random";
    std::string encoding = "rgba8_unorm";
    std::string format = "json";
    std::string name = "aogen_noise";
    std::string out;

    void add_to(CLI::App& app)
    {
        CLI::App* sub = app.add_subcommand("noise", "Generate an N x N tile of rotation vectors (cos, sin, 0, 1)");
        sub->add_option("--size", size, "Tile side in texels, 1..64")->capture_default_str()->check(integer_in(1, 64));
        sub->add_option("--seed", seed, "Seed; the same seed gives the same bytes")->capture_default_str()->check(integer_in(0, UINT64_MAX));
        sub->add_option("--pattern", pattern, "random (the seeds') or r2 (stratified angles)")->capture_default_str();
        sub->add_option("--encoding", encoding, "rgba32f, rgba16f, rg16f, rgba8_unorm, rgba8_snorm")->capture_default_str();
        sub->add_option("--format", format, "json, cpp or bin (the encoded texels)")->capture_default_str();
        sub->add_option("--name", name, "Array name in cpp output")->capture_default_str()->check(declaration_name());
        sub->add_option("--out", out, "Write to this file instead of standard output")->check(not_empty("a file path, or - for standard output"));
        sub->callback([this] { run(); });
    }

    void run() const
    {
        const noise::encoding enc = noise::encoding_from_name(encoding);
        const noise::tile tile = noise::generate(noise::pattern_from_name(pattern), size, seed);
        const std::vector<uint8_t> bytes = noise::encode(tile, enc);
        if (format == "bin") return emit(out, std::string(bytes.begin(), bytes.end()));
        if (format == "json") {
            std::string text = "{\n\"pattern\": \"" + pattern + "\",\n\"size\": " + std::to_string(size) +
                               ",\n\"seed\": " + std::to_string(seed) + ",\n\"encoding\": \"" + encoding +
                               "\",\n\"vulkan_format\": \"" + std::string(noise::vulkan_format_name(enc)) +
                               "\",\n\"texels\": " + vec4_array(name, tile.texels, text_language::json) +
                               ",\n\"bytes\": [\n" + byte_list(bytes) + "\n]\n}\n";
            return emit(out, text);
        }
        if (format == "cpp") {
            std::string text = "// aogen noise --size " + std::to_string(size) + " --seed " + std::to_string(seed) +
                                " --pattern " + pattern + " --encoding " + encoding + "\n// " +
                                std::to_string(size) + " x " + std::to_string(size) + " texels, " +
                                std::string(noise::vulkan_format_name(enc)) + "\n#include <cstdint>\n" +
                                "static const std::uint8_t " + name + "[" + std::to_string(bytes.size()) + "] = {\n" +
                                byte_list(bytes) + "\n};\n";
            return emit(out, text);
        }
        fail("--format", quote(format) + " is not a noise format", "valid: json, cpp, bin");
    }
};

} // namespace aogen::cli
