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

// One axis as `aogen list` prints it: its name, its valid values, how a variant name writes it.
struct list_row {
    std::string axis, values, in_name;
};

// The rows of `aogen list`, each read from the tables that define the axis (axes.hpp's names,
// variant.hpp's name tokens, ranges and defaults), never written out by hand: a value added to
// a table appears here, and tests/core/test_list.cpp parses every token shown.
inline std::vector<list_row> axis_rows()
{
    using aogen::detail::extra_tokens;
    const variant d;
    auto range = [](const int_range& r) { return to_string(r); };
    auto extra = [](size_t i) { return "-" + std::string(extra_tokens[i]); };
    return {
        {"technique", names::list(technique_names), names::list(technique_names, " | ")},
        {"ssao samples, sao taps", range(variant::samples_range) + " (default " + std::to_string(d.samples) + ")", "s<N>"},
        {"gtao, vbao slices x steps", range(variant::slices_range) + " x " + range(variant::steps_range) + " (default " +
                                          std::to_string(d.slices) + " x " + std::to_string(d.steps) + ")", "<slices>x<steps>"},
        {"resolution", "half, full", "half | full"},
        {"blur", names::list(blur_mode_names), names::list(aogen::detail::blur_tokens, " | ")},
        {"bilateral depth", names::list(bilateral_depth_names) + " (default " + to_name(d.blur_depth) + ")", extra(0) + " for seed_raw"},
        {"normals", names::list(normal_source_names), names::list(aogen::detail::normal_tokens, " | ")},
        {"depth", names::list(depth_convention_names), names::list(aogen::detail::depth_tokens, " | ")},
        {"projection", names::list(projection_kind_names), names::list(aogen::detail::projection_tokens, " | ")},
        {"stage", names::list(pipeline_stage_names), names::list(aogen::detail::stage_tokens, " | ")},
        {"point-cloud fallback", "off, on (ssao only)", extra(1)},
        {"range check", names::list(ssao_range_check_names) + " (ssao only)", extra(2) + " for seed004"},
        {"output", names::list(ssao_output_names) + " (ssao only)", extra(3)},
        {"decisions", names::list(ssao_decisions_names) + " (ssao only)", extra(4)},
        {"precision", "fp32, fp16 (16-bit AO-pass arithmetic, not sao; spv, hlsl, msl targets)", extra(5)},
        {"upsample", names::list(upsample_mode_names) + " (half resolution)", extra(6)},
        {"depth mips", range(variant::depth_mips_range) + " levels (compute; default " + std::to_string(d.depth_mips) + ", none)", extra(7)},
        {"deinterleaved", "off, on (compute)", extra(8)},
        {"bent normals", "off, on (gtao, vbao; compute)", extra(9)},
        {"multi-bounce", names::list(multi_bounce_mode_names) + " (gbuffer: each pixel's albedo from the G-buffer)", extra(10) + " | " + extra(11)},
        {"history", names::list(history_mode_names) + " (not with bent normals)", extra(12) + " | " + extra(13)},
        {"workgroup", range(variant::workgroup_side_range) + " x " + range(variant::workgroup_side_range) + ", at most " +
                          std::to_string(variant::max_workgroup_invocations) + " (compute; default " + std::to_string(d.workgroup_x) + "x" +
                          std::to_string(d.workgroup_y) + ")", extra(14)},
    };
}

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
        const std::vector<list_row> rows = axis_rows();
        size_t axis_width = 4, values_width = 6;
        for (const list_row& r : rows) axis_width = std::max(axis_width, r.axis.size()), values_width = std::max(values_width, r.values.size());
        auto print = [&](const std::string& a, const std::string& b, const std::string& c) {
            std::cout << a << std::string(axis_width + 2 - a.size(), ' ') << b << std::string(values_width + 2 - b.size(), ' ') << c << "\n";
        };
        print("axis", "values", "in a variant name");
        for (const list_row& r : rows) print(r.axis, r.values, r.in_name);
        std::cout << "\ndefault variant: " << to_name(variant{}) << "\n";
        std::cout << "\nGTAO and VBAO quality presets (XeGTAO's levels; slices x steps):";
        for (const quality_preset& p : quality_presets) std::cout << " " << p.name << " " << p.slices << "x" << p.steps;
        std::cout << "\n";
    }
};

} // namespace aogen::cli
