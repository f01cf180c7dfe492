// aogen_report/page.hpp — report.html: the report as one self-contained page.
//
//     std::string html = aogen_report::report_page(data, meta);
//     aogen_report::page_images images;               // a run's sets after every scene: one cache
//     std::string again = aogen_report::report_page(data, meta, &images);
//
// One file with nothing to fetch: the style sheet and script of page_assets.hpp, the
// error-against-time plot as inline SVG (svg_plot.hpp), and every variant's AO on every
// scene as PNG data: URIs. In order:
//   - the header facts and how to read them (report_sections.hpp: the same words as
//     report.md);
//   - the plot: default, calibrated and (with more than one frame) accumulated error against
//     time, a marker per variant, named on hover or focus;
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
// draws the error panel from the two, so each image is stored once. A scene wider than
// page_image_max_width is shown box-filtered down by a whole factor (display_grid).
#pragma once

#include "html_text.hpp"
#include "page_assets.hpp"
#include "png.hpp"
#include "report_sections.hpp"
#include "svg_plot.hpp"
#include "text_table.hpp"

#include <aogen/axes.hpp>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <map>
#include <sstream>
#include <utility>

namespace aogen_report {

// The plot's points: one per variant, in the report's order (data-variant = index).
inline std::vector<plot_point> plot_points(const report_data& d)
{
    std::vector<plot_point> points;
    for (size_t i = 0; i < d.variants.size(); ++i) {
        const variant_record& v = d.variants[i];
        points.push_back({i, v.name, plot_label(v.name), aogen::to_name(v.v.tech), aogen::to_name(v.v.stage), v.ms, v.ms_p10, v.ms_p90, v.rmse,
                          v.rmse_calibrated, v.rmse_accumulated, v.pareto, v.pareto_calibrated, v.pareto_accumulated});
    }
    return points;
}

// The plot in motion's points: one per variant run in motion, in the order first run, its
// error in motion the mean over its scenes and its time the median of its scenes' (NaN
// where none was timed); the Pareto front among them. data-variant is that order.
inline std::vector<plot_point> motion_plot_points(const report_data& d)
{
    std::vector<plot_point> points;
    std::vector<std::vector<double>> times;
    std::vector<size_t> scenes;
    for (const motion_record& r : d.motion) {
        size_t i = 0;
        while (i < points.size() && points[i].name != r.variant) ++i;
        if (i == points.size()) {
            const aogen::variant v = aogen::variant_from_name(r.variant);
            plot_point p;
            p.variant = i, p.name = r.variant, p.label = plot_label(r.variant), p.technique = aogen::to_name(v.tech), p.stage = aogen::to_name(v.stage);
            p.error_motion = 0;
            points.push_back(p), times.emplace_back(), scenes.push_back(0);
        }
        points[i].error_motion += r.error, scenes[i] += 1;
        if (std::isfinite(r.ms)) times[i].push_back(r.ms);
    }
    for (size_t i = 0; i < points.size(); ++i) {
        points[i].error_motion /= double(scenes[i]);
        std::vector<double>& t = times[i];
        std::sort(t.begin(), t.end());
        if (!t.empty()) points[i].ms = t.size() % 2 ? t[t.size() / 2] : 0.5 * (t[t.size() / 2 - 1] + t[t.size() / 2]);
    }
    for (plot_point& p : points) {
        p.pareto_motion = std::isfinite(p.ms);
        for (const plot_point& q : points)
            if (&q != &p && std::isfinite(q.ms) && q.ms <= p.ms && q.error_motion <= p.error_motion && (q.ms < p.ms || q.error_motion < p.error_motion))
                p.pareto_motion = false;
    }
    return points;
}

// The plot in motion's title.
inline std::string motion_plot_title(const report_data& d)
{
    const motion_options& o = d.motion_settings;
    return "aogen in motion: error over frames " + std::to_string(o.first_scored) + "–" + std::to_string(o.frames - 1) + " against run time — " + d.device;
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

// The page shows every image at most page_image_max_width pixels wide: a larger scene's
// images are box-filtered down by a whole factor (1920 × 1080 → 480 × 270), so a 1080p
// report's page stays tens of megabytes, not hundreds. The numbers are always the
// full-resolution ones.
inline constexpr int page_image_max_width = 480;

struct display_grid {
    int factor = 1;          // screen pixels per displayed pixel, along each axis
    int width = 0, height = 0; // the displayed size
    display_grid(int screen_width, int screen_height)
        : factor((screen_width + page_image_max_width - 1) / page_image_max_width),
          width((screen_width + factor - 1) / factor), height((screen_height + factor - 1) / factor)
    {
    }
};

// Per displayed pixel, the mean of `values` (screen-sized) over its block's valid pixels,
// as a grey level; `valid_out` (when given) 1 where the block has any.
inline std::vector<uint8_t> block_means(const std::vector<float>& values, const std::vector<uint8_t>& valid, int screen_width,
                                        const display_grid& g, std::vector<uint8_t>* valid_out = nullptr)
{
    const int screen_height = int(values.size()) / screen_width;
    std::vector<uint8_t> grey_levels(size_t(g.width) * g.height, 255);
    if (valid_out) valid_out->assign(grey_levels.size(), 0);
    for (int y = 0; y < g.height; ++y)
        for (int x = 0; x < g.width; ++x) {
            double sum = 0;
            int count = 0;
            for (int sy = y * g.factor; sy < std::min(screen_height, (y + 1) * g.factor); ++sy)
                for (int sx = x * g.factor; sx < std::min(screen_width, (x + 1) * g.factor); ++sx)
                    if (valid[size_t(sy) * screen_width + sx]) sum += values[size_t(sy) * screen_width + sx], ++count;
            if (count == 0) continue;
            grey_levels[size_t(y) * g.width + x] = grey(float(sum / count))[0];
            if (valid_out) (*valid_out)[size_t(y) * g.width + x] = 1;
        }
    return grey_levels;
}

// The scene's reference as displayed, grey + alpha: alpha 255 where a pixel is scored, 0 elsewhere.
inline std::string reference_png(const reference& r, const display_grid& g)
{
    std::vector<uint8_t> valid;
    const std::vector<uint8_t> levels = block_means(r.ao, r.valid, r.width, g, &valid);
    std::vector<uint8_t> pixels(levels.size() * 2);
    for (size_t i = 0; i < levels.size(); ++i) pixels[2 * i] = valid[i] ? levels[i] : 0, pixels[2 * i + 1] = valid[i] ? 255 : 0;
    return encode_png(g.width, g.height, 2, pixels);
}

// A run's AO as displayed, and the factor the page upsamples it by: as read back when the
// scene is shown at full size (a half-resolution target ×2, by nearest upsampling), else
// the block means of its full-resolution image over the reference's valid pixels.
inline std::pair<std::string, int> ao_png(const ao_readback& ao, const reference& r, const display_grid& g)
{
    if (g.factor == 1) return {encode_png(ao.width, ao.height, 1, ao.unorm), ao.factor};
    return {encode_png(g.width, g.height, 1, block_means(ao.full(r.width, r.height), r.valid, r.width, g)), 1};
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

} // namespace detail

// The page's images as data: URIs, each encoded once: a scene's reference, and a run's AO
// with the factor the page upsamples it by. Neither changes once its scene is scored, so the
// report's program keeps one across the sets it writes after every scene: each image is
// encoded once, not once per set (the sets' writing grew with the square of the scenes).
// By scene index and (variant index, scene index): for one report's data only.
class page_images {
public:
    const std::string& reference_of(const scene_record& s, size_t scene, const detail::display_grid& g)
    {
        auto found = references_.find(scene);
        if (found == references_.end()) found = references_.emplace(scene, detail::png_uri(detail::reference_png(s.truth, g))).first;
        return found->second;
    }
    const std::pair<std::string, int>& ao_of(const run_record& r, const reference& truth, size_t variant, size_t scene, const detail::display_grid& g)
    {
        const auto key = std::make_pair(variant, scene);
        auto found = ao_.find(key);
        if (found == ao_.end()) {
            const auto [png, factor] = detail::ao_png(r.ao, truth, g);
            found = ao_.emplace(key, std::make_pair(detail::png_uri(png), factor)).first;
        }
        return found->second;
    }

private:
    std::map<size_t, std::string> references_;
    std::map<std::pair<size_t, size_t>, std::pair<std::string, int>> ao_;
};

namespace detail {

// What the script reads: numbers per variant and scene, and the images (from `images`).
inline std::string page_data(const report_data& d, page_images& images_of)
{
    nlohmann::json j;
    j["frames"] = d.frames;
    j["scenes"] = nlohmann::json::array();
    j["images"]["reference"] = nlohmann::json::array();
    std::vector<display_grid> grids; // per scene
    for (size_t i = 0; i < d.scenes.size(); ++i) {
        const scene_record& s = d.scenes[i];
        const display_grid& g = grids.emplace_back(s.truth.width, s.truth.height);
        j["scenes"].push_back({{"name", s.scene.name}, {"width", g.width}, {"height", g.height}});
        j["images"]["reference"].push_back(images_of.reference_of(s, i, g));
    }
    j["variants"] = nlohmann::json::array();
    j["images"]["ao"] = nlohmann::json::array();
    for (size_t vi = 0; vi < d.variants.size(); ++vi) {
        const variant_record& v = d.variants[vi];
        nlohmann::json runs = nlohmann::json::array(), images = nlohmann::json::array();
        for (size_t s = 0; s < v.runs.size(); ++s) {
            const run_record& r = v.runs[s];
            if (!r.ran()) {
                runs.push_back({{"skipped", r.skipped}});
                images.push_back(nullptr);
                continue;
            }
            const auto& [uri, factor] = images_of.ao_of(r, d.scenes[s].truth, vi, s, grids[s]);
            runs.push_back({{"ms", number(r.ms.median)}, {"rmse", number(r.plain.rmse)}, {"rmse_calibrated", number(r.calibrated.rmse)},
                            {"rmse_accumulated", number(r.accumulated.rmse)}, {"bent_degrees", number(r.bent.mean_degrees)},
                            {"power", number(r.power)}, {"factor", factor}});
            images.push_back(uri);
        }
        nlohmann::json pass_ms = nlohmann::json::array();
        for (double ms : pass_medians(v)) pass_ms.push_back(number(ms));
        j["variants"].push_back({{"name", v.name}, {"ms", number(v.ms)}, {"ms_p10", number(v.ms_p10)}, {"ms_p90", number(v.ms_p90)},
                                 {"floor_ratio", number(v.floor_ratio)}, {"rmse", number(v.rmse)}, {"rmse_calibrated", number(v.rmse_calibrated)},
                                 {"rmse_accumulated", number(v.rmse_accumulated)}, {"bent_degrees", number(v.bent_degrees)},
                                 {"passes", v.passes}, {"pass_ms", pass_ms}, {"runs", runs}});
        j["images"]["ao"].push_back(images);
    }
    std::string text = j.dump();
    std::string safe; // no "<" at all: nothing inside can close the <script> element
    safe.reserve(text.size());
    for (char c : text)
        if (c == '<') safe += "\\u003c";
        else safe += c;
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
    for (const char* title : {"ms", "p10", "p90", "× floor", "× BW", "RMSE default", "★", "RMSE calibrated", "★ cal."})
        html << sort_header(title, "number", true);
    html << sort_header("RMSE after " + std::to_string(d.frames) + " frames", "number", true) << sort_header("★ frames", "number", true)
         << sort_header("bent normal °", "number", true) << sort_header("AO instructions", "number", true)
         << sort_header("per tap", "number", true);
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
             << value_cell(v.rmse_accumulated, fixed(v.rmse_accumulated, 4)) << value_cell(v.pareto_accumulated, v.pareto_accumulated ? "★" : "", 0)
             << value_cell(v.bent_degrees, fixed(v.bent_degrees, 1, ""))
             << value_cell(v.ao_instructions, std::to_string(v.ao_instructions), 0)
             << value_cell(v.ao_tap_instructions, fixed(v.ao_tap_instructions, 1), 0) << text_cell(raw_non_finite(v.raw, v.raw_measured), "num")
             << "</tr>\n";
    }
    html << "</tbody>\n</table></div>\n";
}

} // namespace detail

// `images`: the encoded images of earlier sets of the same report, kept and added to (the
// program's, across its sets); none: encoded here.
inline std::string report_page(const report_data& d, const report_meta& meta, page_images* images = nullptr)
{
    page_images own;
    std::ostringstream html;
    html << "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n"
         << "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n"
         << "<title>aogen report: AO error against run time — " << html_escape(d.device) << "</title>\n"
         << "<style>" << page_style << "</style>\n</head>\n<body>\n";
    html << "<header>\n<h1>aogen report: AO error against run time</h1>\n";
    if (!meta.complete) html << "<p>" << html_from_markdown(partial_notice(d)) << "</p>\n";
    html << html_list(measurement_facts(d, meta), "class=\"facts\"") << "<p class=\"how\">" << html_from_markdown(how_to_read(d.frames)) << "</p>\n</header>\n";

    html << "<section id=\"plot\">\n<h2>Error against time</h2>\n"
         << "<p>Every marker is a variant: hover or focus it for its numbers, click it for its images.</p>\n"
         << error_time_svg(plot_points(d), plot_title(d), d.frames) << "</section>\n<div id=\"tooltip\" role=\"tooltip\" hidden></div>\n";

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
    if (!d.motion.empty())
        html << "<section id=\"motion\">\n<h2>In motion</h2>\n<p>" << html_from_markdown(motion_about(d)) << "</p>\n<figure id=\"motion-plot\">"
             << motion_time_svg(motion_plot_points(d), motion_plot_title(d)) << "</figure>\n" << html_table(motion_table(d))
             << html_table(motion_scenes_table(d)) << "</section>\n";
    const std::vector<std::string> not_run = not_run_lines(d);
    if (!not_run.empty()) html << "<section id=\"not-run\">\n<h2>Not run</h2>\n" << html_list(not_run) << "</section>\n";
    html << "<script type=\"application/json\" id=\"aogen-data\">" << detail::page_data(d, images ? *images : own) << "</script>\n"
         << "<script>" << page_script << "</script>\n</body>\n</html>\n";
    return html.str();
}

} // namespace aogen_report
