// generator/cmd_kernel.hpp — `aogen kernel`: a hemisphere sample kernel in any format.
//
//   aogen kernel --kind crytek --count 16 --seed 1 --format glsl
#pragma once

#include "format.hpp"
#include <aogen_tools/files.hpp>
#include <aogen_tools/options.hpp>

#include <aogen/kernel.hpp>

#include <CLI/CLI.hpp>

namespace aogen::cli {

using namespace tools; // the readers and writers the command line shares with the report (tools/)

struct kernel_command {
    std::string kind = "crytek";
    std::string scale = "crytek";
    int count = 16;
    uint64_t seed = 1;
    std::string format = "json";
    std::string name = "aogen_kernel";
    std::string out;

    void add_to(CLI::App& app)
    {
        CLI::App* sub = app.add_subcommand("kernel", "Generate a hemisphere sample kernel (vec4: xyz, w = 0)");
        sub->add_option("--kind", kind, "Distribution: crytek, cosine, hammersley")->capture_default_str();
        sub->add_option("--scale", scale, "Length law: crytek (0.1 + 0.9 (i/N)^2) or none")->capture_default_str();
        sub->add_option("--count", count, "Samples, 1..256")->capture_default_str()->check(integer_in(1, 256));
        sub->add_option("--seed", seed, "Seed; the same seed gives the same bytes")->capture_default_str()->check(integer_in(0, UINT64_MAX));
        sub->add_option("--format", format, "json, cpp, glsl, wgsl or bin (RGBA32F bytes)")->capture_default_str();
        sub->add_option("--name", name, "Constant name in cpp/glsl/wgsl output")->capture_default_str()->check(declaration_name());
        sub->add_option("--out", out, "Write to this file instead of standard output")->check(not_empty("a file path, or - for standard output"));
        sub->callback([this] { run(); });
    }

    void run() const
    {
        const auto samples = kernel::generate(kernel::distribution_from_name(kind), count, seed,
                                              kernel::scale_law_from_name(scale));
        if (format == "bin") return emit(out, vec4_bytes(samples));
        if (format == "json") {
            std::string text = "{\n\"kind\": \"" + kind + "\",\n\"scale\": \"" + scale + "\",\n\"count\": " +
                               std::to_string(count) + ",\n\"seed\": " + std::to_string(seed) +
                               ",\n\"samples\": " + vec4_array(name, samples, text_language::json) + "}\n";
            return emit(out, text);
        }
        const std::string header = "// aogen kernel --kind " + kind + " --scale " + scale + " --count " +
                                   std::to_string(count) + " --seed " + std::to_string(seed) + "\n";
        if (format == "cpp") return emit(out, header + vec4_array(name, samples, text_language::cpp));
        if (format == "glsl") return emit(out, header + vec4_array(name, samples, text_language::glsl));
        if (format == "wgsl") return emit(out, header + vec4_array(name, samples, text_language::wgsl));
        fail("--format", quote(format) + " is not a kernel format", "valid: json, cpp, glsl, wgsl, bin");
    }
};

} // namespace aogen::cli
