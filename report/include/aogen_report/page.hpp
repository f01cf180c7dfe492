// aogen_report/page.hpp — report.html: the report as one self-contained page.
//
//     std::string html = aogen_report::report_page(data, meta);
//
// One file with nothing to fetch: the style sheet and script of page_assets.hpp, the
// error-against-time plot as inline SVG (svg_plot.hpp), and every variant's AO on every
// scene as PNG data: URIs. In order:
//   - the header facts and how to read them (report_sections.hpp: the same words as
//     report.md);
//   - the plot: default and calibrated error against time, a marker per variant, named on
//     hover or focus;
//   - the variants table, sortable by every column and filtered by technique,
//     resolution, blur and stage; selecting a row (or a marker) shows its strips, per
//     scene reference | variant | |error| with the variant's numbers on that scene;
//   - the scenes, the feature saving and what did not run.
// The page's numbers and images travel as JSON in <script type="application/json"
// id="aogen-data">, with every "<" written as \u003c so that no text — a scene named
// "</script>" — can end the element; everything else a user wrote is HTML-escaped.
//
// Images: the reference once per scene (8-bit grey, alpha 0 where no pixel is scored),
// and each run's AO as read back (8-bit grey at the target's resolution; the script shows
// a half-resolution one at full size by nearest upsampling, as the strips do). The page
// draws the error panel from the two, so each image is stored once.
#pragma once

#include "html_text.hpp"
#include "page_assets.hpp"
#include "png.hpp"
#include "report_sections.hpp"
#include "svg_plot.hpp"
#include "text_table.hpp"

#include <aogen/axes.hpp>

#include <nlohmann/json.hpp>

#include <sstream>

namespace aogen_report {

// The plot's points: one per variant, in the report's order (data-variant = index).
inline std::vector<plot_point> plot_points(const report_data& d)
{
    std::vector<plot_point> points;
    for (size_t i = 0; i < d.variants.size(); ++i) {
        const variant_record& v = d.variants[i];
        points.push_back({i, v.name, plot_label(v.name), aogen::to_name(v.v.tech), aogen::to_name(v.v.stage), v.ms, v.ms_p10, v.ms_p90, v.rmse,
                          v.rmse_calibrated, v.pareto, v.pareto_calibrated});
    }
    return points;
}

// The plot's title: what was measured, on what.
inline std::string plot_title(const report_data& d)
{
    return "aogen: AO error against run time — " + d.device + ", " + std::to_string(d.scenes.size()) + " scenes, " +
           std::to_string(d.grid * d.grid) + " reference rays per pixel";
}

namespace detail {

// A PNG data: URI.
inline std::string png_uri(const std::string& png) { return "data:image/png;base64," + base64(png); }

// The scene's reference as grey + alpha: alpha 255 where a pixel is scored, 0 elsewhere.
inline std::string reference_png(const reference& r)
{
    std::vector<uint8_t> pixels(size_t(r.width) * r.height * 2, 0);
    for (size_t i = 0; i < r.valid.size(); ++i)
        if (r.valid[i]) pixels[2 * i] = grey(r.ao[i])[0], pixels[2 * i + 1] = 255;
    return encode_png(r.width, r.height, 2, pixels);
}

// The median over the scenes of each pass's median time.
inline std::vector<double> pass_medians(const variant_record& v)
{
    std::vector<double> out;
    for (size_t k = 0; k < v.passes.size(); ++k) {
        std::vector<double> per_scene;
        for (const run_record& r : v.runs)
            if (r.ran() && k < r.pass_ms.size() && std::isfinite(r.pass_ms[k].median)) per_scene.push_back(r.pass_ms[k].median);
        out.push_back(per_scene.empty() ? NAN : aogen::vulkan::spread_of(per_scene).median);
    }
    return out;
}

// What the script reads: numbers per variant and scene, and the images.
inline std::string page_data(const report_data& d)
{
    nlohmann::json j;
    j["scenes"] = nlohmann::json::array();
    j["images"]["reference"] = nlohmann::json::array();
    for (const scene_record& s : d.scenes) {
        j["scenes"].push_back({{"name", s.scene.name}, {"width", s.truth.width}, {"height", s.truth.height}});
        j["images"]["reference"].push_back(png_uri(reference_png(s.truth)));
    }
    j["variants"] = nlohmann::json::array();
    j["images"]["ao"] = nlohmann::json::array();
    for (const variant_record& v : d.variants) {
        nlohmann::json runs = nlohmann::json::array(), images = nlohmann::json::array();
        for (const run_record& r : v.runs) {
            if (!r.ran()) {
                runs.push_back({{"skipped", r.skipped}});
                images.push_back(nullptr);
                continue;
            }
            runs.push_back({{"ms", number(r.ms.median)}, {"rmse", number(r.plain.rmse)}, {"rmse_calibrated", number(r.calibrated.rmse)},
                            {"power", number(r.power)}, {"factor", r.ao.factor}});
            images.push_back(png_uri(encode_png(r.ao.width, r.ao.height, 1, r.ao.unorm)));
        }
        nlohmann::json pass_ms = nlohmann::json::array();
        for (double ms : pass_medians(v)) pass_ms.push_back(number(ms));
        j["variants"].push_back({{"name", v.name}, {"ms", number(v.ms)}, {"ms_p10", number(v.ms_p10)}, {"ms_p90", number(v.ms_p90)},
                                 {"floor_ratio", number(v.floor_ratio)}, {"rmse", number(v.rmse)}, {"rmse_calibrated", number(v.rmse_calibrated)},
                                 {"passes", v.passes}, {"pass_ms", pass_ms}, {"runs", runs}});
        j["images"]["ao"].push_back(images);
    }
    std::string text = j.dump();
    std::string safe; // no "<" at all: nothing inside can close the <script> element
    safe.reserve(text.size());
    for (char c : text) safe += c == '<' ? std::string("\\u003c") : std::string(1, c);
    return safe;
}

// A sortable header cell: `type` "number" or "text".
inline std::string sort_header(const std::string& title, const char* type, bool numeric_column)
{
    return std::string("<th") + (numeric_column ? " class=\"num\"" : "") + " data-type=\"" + type + "\"><button type=\"button\">" +
           html_escape(title) + "</button></th>";
}

// A cell sorted by `value` ("" when missing) that shows `text`.
inline std::string value_cell(double value, const std::string& text, int sort_digits = 9)
{
    return "<td class=\"num\" data-value=\"" + (std::isfinite(value) ? fixed(value, sort_digits) : "") + "\">" + html_escape(text) + "</td>";
}
inline std::string text_cell(const std::string& text, const char* cls = nullptr)
{
    return std::string("<td") + (cls ? std::string(" class=\"") + cls + "\"" : "") + " data-value=\"" + html_escape(text) + "\">" +
           html_escape(text) + "</td>";
}

// The variants table and the filters over it.
inline void write_variant_table(std::ostream& html, const report_data& d)
{
    struct axis {
        const char* key; const char* title;
        std::string (*of)(const aogen::variant&);
    };
    static const axis axes[] = {
        {"technique", "technique", [](const aogen::variant& v) { return std::string(aogen::to_name(v.tech)); }},
        {"resolution", "resolution", [](const aogen::variant& v) { return std::string(v.half_resolution ? "half" : "full"); }},
        {"blur", "blur", [](const aogen::variant& v) { return std::string(aogen::to_name(v.blur)); }},
        {"stage", "stage", [](const aogen::variant& v) { return std::string(aogen::to_name(v.stage)); }},
    };
    html << "<form id=\"filters\" onsubmit=\"return false\">\n";
    for (const axis& a : axes) {
        std::vector<std::string> values;
        for (const variant_record& v : d.variants)
            if (std::find(values.begin(), values.end(), a.of(v.v)) == values.end()) values.push_back(a.of(v.v));
        std::sort(values.begin(), values.end());
        html << "<label>" << a.title << " <select name=\"" << a.key << "\"><option value=\"\">all</option>";
        for (const std::string& value : values) html << "<option>" << html_escape(value) << "</option>";
        html << "</select></label>\n";
    }
    html << "<span id=\"shown\"></span></form>\n";

    html << "<div class=\"table-scroll\"><table id=\"variant-table\">\n<thead><tr>" << sort_header("variant", "text", false);
    for (const axis& a : axes) html << sort_header(a.title, "text", false);
    for (const char* title : {"ms", "p10", "p90", "× floor", "× BW", "RMSE default", "★", "RMSE calibrated", "★ cal.", "AO instructions"})
        html << sort_header(title, "number", true);
    html << sort_header("raw NaN/Inf", "text", true) << "</tr></thead>\n<tbody>\n";
    for (size_t i : by_time(d.variants)) {
        const variant_record& v = d.variants[i];
        html << "<tr data-variant=\"" << i << "\"";
        for (const axis& a : axes) html << " data-" << a.key << "=\"" << html_escape(a.of(v.v)) << "\"";
        html << ">" << text_cell(v.name, "name");
        for (const axis& a : axes) html << text_cell(a.of(v.v));
        html << value_cell(v.ms, fixed(v.ms, 3)) << value_cell(v.ms_p10, fixed(v.ms_p10, 3)) << value_cell(v.ms_p90, fixed(v.ms_p90, 3))
             << value_cell(v.floor_ratio, fixed(v.floor_ratio, 2)) << value_cell(v.bandwidth_ratio, fixed(v.bandwidth_ratio, 2))
             << value_cell(v.rmse, fixed(v.rmse, 4)) << value_cell(v.pareto, v.pareto ? "★" : "", 0)
             << value_cell(v.rmse_calibrated, fixed(v.rmse_calibrated, 4)) << value_cell(v.pareto_calibrated, v.pareto_calibrated ? "★" : "", 0)
             << value_cell(v.ao_instructions, std::to_string(v.ao_instructions), 0) << text_cell(raw_non_finite(v.raw, v.raw_measured), "num")
             << "</tr>\n";
    }
    html << "</tbody>\n</table></div>\n";
}

} // namespace detail

inline std::string report_page(const report_data& d, const report_meta& meta)
{
    std::ostringstream html;
    html << "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n"
         << "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n"
         << "<title>aogen report: AO error against run time — " << html_escape(d.device) << "</title>\n"
         << "<style>" << page_style << "</style>\n</head>\n<body>\n";
    html << "<header>\n<h1>aogen report: AO error against run time</h1>\n";
    if (!meta.complete) html << "<p>" << html_from_markdown(partial_notice(d)) << "</p>\n";
    html << html_list(measurement_facts(d, meta), "class=\"facts\"") << "<p class=\"how\">" << html_from_markdown(how_to_read()) << "</p>\n</header>\n";

    html << "<section id=\"plot\">\n<h2>Error against time</h2>\n"
         << "<p>Every marker is a variant: hover or focus it for its numbers, click it for its images.</p>\n"
         << error_time_svg(plot_points(d), plot_title(d)) << "</section>\n<div id=\"tooltip\" role=\"tooltip\" hidden></div>\n";

    html << "<section id=\"variants\">\n<h2>Variants</h2>\n<p>Click a column's title to sort by it (again: the other way round); "
            "pick a technique, resolution, blur or stage to filter; click a row for its images on every scene.</p>\n";
    detail::write_variant_table(html, d);
    html << "</section>\n";

    html << "<section id=\"strips\">\n<h2>Images</h2>\n<p id=\"strips-for\">Select a variant (a row or a marker) to see, per scene, "
            "reference | variant (default parameters) | |variant − reference| (black 0, yellow ≥ "
         << detail::fixed(heat_full_scale, 2) << "; background in blue-grey).</p>\n<div id=\"strip-rows\"></div>\n</section>\n";

    html << "<section id=\"scenes\">\n<h2>Scenes</h2>\n<p>" << html_from_markdown(scenes_about()) << "</p>\n"
         << html_table(scenes_table(d, nullptr)) << "<p>" << html_from_markdown(noise_against_best(d)) << "</p>\n</section>\n";
    html << "<section id=\"feature-saving\">\n<h2>Leaving features out</h2>\n";
    if (d.savings.empty()) html << "<p>No SSAO variant without the point-cloud fallback, or no mesh-only scene: nothing to compare.</p>\n";
    else
        html << "<p>" << html_from_markdown(feature_saving_about()) << "</p>\n"
             << html_table(feature_saving_table(d)) << "<p>" << html_from_markdown(feature_saving_left_out(d)) << "</p>\n";
    html << "</section>\n";
    const std::vector<std::string> not_run = not_run_lines(d);
    if (!not_run.empty()) html << "<section id=\"not-run\">\n<h2>Not run</h2>\n" << html_list(not_run) << "</section>\n";
    html << "<script type=\"application/json\" id=\"aogen-data\">" << detail::page_data(d) << "</script>\n"
         << "<script>" << page_script << "</script>\n</body>\n</html>\n";
    return html.str();
}

} // namespace aogen_report
