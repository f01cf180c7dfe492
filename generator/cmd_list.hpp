// generator/cmd_list.hpp — `aogen list`: the variant axes and their valid values.
#pragma once

#include <aogen/matrix.hpp>
#include <aogen/quality.hpp>

#include <CLI/CLI.hpp>

#include <algorithm>
#include <iostream>
#include <string>
#include <vector>

namespace aogen::cli {

struct list_command {
    bool variants = false;

    void add_to(CLI::App& app)
    {
        CLI::App* sub = app.add_subcommand("list", "Print the variant axes and their valid values");
        sub->add_flag("--variants", variants, "Print the names of the default matrix's variants instead");
        sub->callback([this] { run(); });
    }

    void run() const
    {
        if (variants) {
            for (const variant& v : default_matrix()) std::cout << to_name(v) << "\n";
            return;
        }
        struct row {
            std::string axis, values, in_name;
        };
        const std::vector<row> rows{
            {"technique", names::list(technique_names), "ssao | gtao | vbao | sao"},
            {"ssao samples, sao taps", "1..256 (matrix: ssao 8, 16, 32, 64, sao 8, 16, 32; default 16)", "s<N>"},
            {"gtao, vbao slices x steps", "1..16 x 1..16 (default 2 x 3)", "<slices>x<steps>"},
            {"resolution", "half, full", "half | full"},
            {"blur", names::list(blur_mode_names), "bilateral | box | noblur"},
            {"bilateral depth", names::list(bilateral_depth_names) + " (default linear)", "-rawdepth for seed_raw"},
            {"normals", names::list(normal_source_names), "gbufworld | gbufview | recon"},
            {"depth", names::list(depth_convention_names), "std | rev | revinf"},
            {"projection", names::list(projection_kind_names), "persp | ortho"},
            {"stage", names::list(pipeline_stage_names), "cs | fs"},
            {"point-cloud fallback", "off, on (ssao only)", "-pc"},
            {"range check", names::list(ssao_range_check_names) + " (ssao only)", "-rc004 for seed004"},
            {"output", names::list(ssao_output_names) + " (ssao only)", "-powint"},
            {"precision", "fp32, fp16 (16-bit AO-pass arithmetic, not sao; spv, hlsl, msl targets)", "-fp16"},
            {"decisions", names::list(ssao_decisions_names) + " (ssao only)", "-step"},
            {"upsample", names::list(upsample_mode_names) + " (half resolution)", "-nearest"},
            {"depth mips", "1..5 levels (compute; default 1, none)", "-mip<N>"},
            {"deinterleaved", "off, on (compute)", "-deint"},
            {"bent normals", "off, on (gtao, vbao; compute)", "-bn"},
            {"multi-bounce", names::list(multi_bounce_mode_names) + " (gbuffer: each pixel's albedo from the G-buffer)", "-mb | -mbg"},
            {"workgroup", "1..32 x 1..32, at most 1024 (compute; default 8x8)", "-wg<X>x<Y>"},
        };
        size_t axis_width = 4, values_width = 6;
        for (const row& r : rows) axis_width = std::max(axis_width, r.axis.size()), values_width = std::max(values_width, r.values.size());
        auto print = [&](const std::string& a, const std::string& b, const std::string& c) {
            std::cout << a << std::string(axis_width + 2 - a.size(), ' ') << b << std::string(values_width + 2 - b.size(), ' ') << c << "\n";
        };
        print("axis", "values", "in a variant name");
        for (const row& r : rows) print(r.axis, r.values, r.in_name);
        std::cout << "\ndefault variant: " << to_name(variant{}) << "\n";
        std::cout << "\nGTAO and VBAO quality presets (XeGTAO's levels; slices x steps):";
        for (const quality_preset& p : quality_presets) std::cout << " " << p.name << " " << p.slices << "x" << p.steps;
        std::cout << "\n";
    }
};

} // namespace aogen::cli
