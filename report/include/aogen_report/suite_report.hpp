// aogen_report/suite_report.hpp — the stability suite's report.md and results.json.
//
//     std::string md = aogen_report::suite_markdown(d, command);
//     std::string json = aogen_report::suite_json(d, command);
//
// report.md: how to read it; the cases (what each stresses, its criterion, the run closest
// to its limit and the figure that decided it); a table of
// variants × cases, ✓ or ✗ per cell, numbered columns so it fits; then every failure with
// the figure that decided it, and what could not run. results.json: every run's numbers:
//   {"aogen_report": 2, "suite": "stability", "device", "command", "rays_per_pixel",
//    "failures", "cases": [{name, about, source, truth_noise_rms,
//      criterion: {error_ratio, error_slack, max_excess, compare_depth, depth_max, depth_mean,
//                  compare_error, fault_reach, twin_pixel_max, compare_scales, scale_max},
//      runs: [{variant, skipped | {pass, decided_by, rmse, twin_rmse, error_limit,
//              raw: {nan, inf, below_zero, above_one, max_excess},
//              background_pixels, background_not_one, depth_max, depth_mean,
//              twin_pixel_max, changed_reach (with faults), scale_max, scale_worst (with compare_scales)}}]}]}
#pragma once

#include "number_text.hpp"
#include "suite.hpp"
#include "text_table.hpp"

#include <nlohmann/json.hpp>

#include <map>
#include <sstream>

namespace aogen_report {

inline std::string suite_json(const suite_data& d, const std::string& command)
{
    nlohmann::json j;
    j["aogen_report"] = 2;
    j["suite"] = "stability";
    j["device"] = d.device;
    j["command"] = command;
    j["rays_per_pixel"] = d.grid * d.grid;
    j["failures"] = d.failures();
    j["cases"] = nlohmann::json::array();
    for (const suite_case_record& c : d.cases) {
        const stability_criterion& k = c.c.criterion;
        nlohmann::json runs = nlohmann::json::array();
        for (const suite_run& r : c.runs) {
            nlohmann::json e{{"variant", r.variant}};
            if (!r.ran()) e["skipped"] = r.skipped;
            else {
                e["pass"] = r.pass;
                e["decided_by"] = r.decided_by;
                e["rmse"] = r.rmse, e["twin_rmse"] = r.twin_rmse, e["error_limit"] = r.error_limit;
                e["raw"] = {{"nan", r.raw.nan}, {"inf", r.raw.inf}, {"below_zero", r.raw.below_zero}, {"above_one", r.raw.above_one},
                            {"max_excess", r.raw.max_excess}};
                e["background_pixels"] = r.background_pixels, e["background_not_one"] = r.background_not_one;
                e["depth_max"] = r.depth_max, e["depth_mean"] = r.depth_mean;
            }
            if (!c.c.faults.empty()) e["twin_pixel_max"] = r.twin_pixel_max, e["changed_reach"] = r.changed_reach;
            if (k.compare_scales) e["scale_max"] = r.scale_max, e["scale_worst"] = r.scale_worst;
            runs.push_back(e);
        }
        j["cases"].push_back({{"name", c.c.name},
                              {"about", c.c.about},
                              {"source", c.c.source},
                              {"truth_noise_rms", c.truth_noise},
                              {"criterion", {{"error_ratio", k.error_ratio}, {"error_slack", k.error_slack}, {"max_excess", k.max_excess},
                                             {"compare_depth", k.compare_depth}, {"depth_max", k.depth_max}, {"depth_mean", k.depth_mean},
                                             {"compare_error", k.compare_error}, {"fault_reach", k.fault_reach}, {"twin_pixel_max", k.twin_pixel_max},
                                             {"compare_scales", k.compare_scales}, {"scale_max", k.scale_max}}},
                              {"runs", runs}});
    }
    return j.dump(2) + "\n";
}

// How it was run, one Markdown line per fact.
inline std::vector<std::string> suite_facts(const suite_data& d, const std::string& command)
{
    size_t runs = 0;
    for (const suite_case_record& c : d.cases)
        for (const suite_run& r : c.runs) runs += r.ran();
    return {"Device: **" + d.device + "**",
            std::to_string(d.cases.size()) + " cases × " + std::to_string(d.variants.size()) + " variants: " + std::to_string(runs) + " runs, **" +
                std::to_string(d.failures()) + " failed**",
            "Reference: Embree, " + std::to_string(d.grid * d.grid) + " rays per pixel", "Command: `" + command + "`"};
}

inline std::string suite_how_to_read()
{
    return "**How to read it.** Each case is a scene at an extreme and its benign twin (aogen_report/stability.hpp). A run passes "
           "when no pass computed a NaN or an infinity (raw values, before the guard that keeps them from the output), no raw value "
           "lies outside [0, 1] by more than rounding, every background pixel (and every planted fault) is exactly 1, the depth "
           "conventions agree where the case compares them, a faulted scene matches its twin pixel by pixel away from its faults, "
           "a scaled scene matches the scene pixel by pixel, and the RMSE against the ray-traced reference is at most the case's "
           "ratio times the same variant's RMSE on the twin plus a slack. Each variant runs in the projection of the case's camera.";
}

// The cases: what each stresses, its criterion, the run closest to its limit.
inline text_table suite_cases_table(const suite_data& d)
{
    using detail::fixed;
    text_table t{{"#", "case", "stresses", "criterion", "reference noise", "closest to its limit"}, "rlllrl", {}};
    for (size_t i = 0; i < d.cases.size(); ++i) {
        const stability_criterion& k = d.cases[i].c.criterion;
        const suite_run* closest = nullptr;
        for (const suite_run& r : d.cases[i].runs)
            if (r.ran() && r.error_limit > 0 && (!closest || r.rmse / r.error_limit > closest->rmse / closest->error_limit)) closest = &r;
        const std::string error = k.compare_error ? "RMSE ≤ " + fixed(k.error_ratio, 2) + " × twin + " + fixed(k.error_slack, 3) : "";
        const std::string depth = k.compare_depth ? "depth Δ ≤ " + fixed(k.depth_max, 4) : "";
        const std::string pixels = d.cases[i].c.faults.empty() ? "" : "twin Δ ≤ " + fixed(k.twin_pixel_max * 255, 1) + "/255 beyond " +
                                                                       fixed(k.fault_reach, 0) + " px of a fault";
        const std::string scales = k.compare_scales ? "× 10⁻⁶ … 10⁶ Δ ≤ " + fixed(k.scale_max * 255, 1) + "/255" : "";
        std::string criterion;
        for (const std::string& part : {error, depth, pixels, scales})
            if (!part.empty()) criterion += (criterion.empty() ? "" : "; ") + part;
        t.rows.push_back({std::to_string(i + 1), d.cases[i].c.name, d.cases[i].c.about, criterion, fixed(d.cases[i].truth_noise, 4),
                          closest ? "`" + closest->variant + "`: " + closest->decided_by : "–"});
    }
    return t;
}

// Every failed run with the figure that decided it.
inline std::vector<std::string> suite_failure_lines(const suite_data& d)
{
    std::vector<std::string> lines;
    for (const suite_case_record& c : d.cases)
        for (const suite_run& r : c.runs)
            if (r.ran() && !r.pass) lines.push_back("**" + c.c.name + "**, `" + r.variant + "`: " + r.decided_by);
    return lines;
}

// The runs that could not happen, one line per case and reason.
inline std::vector<std::string> suite_not_run_lines(const suite_data& d)
{
    std::map<std::string, size_t> skipped;
    for (const suite_case_record& c : d.cases)
        for (const suite_run& r : c.runs)
            if (!r.ran()) ++skipped[c.c.name + ": " + r.skipped];
    std::vector<std::string> lines;
    for (const auto& [why, n] : skipped) lines.push_back(why + " (" + std::to_string(n) + (n == 1 ? " variant" : " variants") + ")");
    return lines;
}

inline std::string suite_markdown(const suite_data& d, const std::string& command)
{
    std::ostringstream md;
    md << "# aogen stability suite\n\n";
    for (const std::string& fact : suite_facts(d, command)) md << "- " << fact << "\n";
    md << "\n" << suite_how_to_read() << " The same report as a page: [report.html](report.html).\n\n";
    md << "## Cases\n\nEach case's run closest to its error limit, with the figure that decided it (every run's is in "
          "results.json).\n\n" << markdown_table(suite_cases_table(d));

    md << "\n## Variants × cases\n\n✓ passed, ✗ failed, – could not run (columns: the cases' numbers above).\n\n| variant |";
    for (size_t i = 0; i < d.cases.size(); ++i) md << " " << i + 1 << " |";
    md << " failed |\n|---|";
    for (size_t i = 0; i < d.cases.size(); ++i) md << ":-:|";
    md << "---:|\n";
    for (size_t v = 0; v < d.variants.size(); ++v) {
        size_t failed = 0;
        md << "| `" << d.variants[v] << "` |";
        for (const suite_case_record& c : d.cases) {
            const suite_run& r = c.runs[v];
            md << " " << (!r.ran() ? "–" : r.pass ? "✓" : "✗") << " |";
            failed += r.ran() && !r.pass;
        }
        md << " " << failed << " |\n";
    }

    md << "\n## Failures\n\n";
    const std::vector<std::string> failures = suite_failure_lines(d);
    if (failures.empty()) md << "None.\n";
    for (const std::string& line : failures) md << "- " << line << "\n";
    const std::vector<std::string> not_run = suite_not_run_lines(d);
    if (!not_run.empty()) {
        md << "\n## Not run\n\n";
        for (const std::string& line : not_run) md << "- " << line << "\n";
    }
    return md.str();
}

} // namespace aogen_report
