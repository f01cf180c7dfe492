// aogen_report/svg_plot.hpp — the error-against-time plot as SVG, drawn here in C++: no
// plotting library, no Python.
//
//     std::vector<aogen_report::plot_point> points = ...;      // one per variant
//     std::string svg = aogen_report::error_time_svg(points, "aogen: … H200, 18 scenes");
//
// Two panels side by side, default parameters and calibrated error — and a third, the error
// after N frames of a temporal accumulation, when the report averaged more than one — each
// a scatter of error (RMSE, linear, from 0) against GPU time (log axis). Each variant is one marker:
// its shape and colour say the technique (SSAO circle, GTAO triangle, VBAO square, SAO
// diamond), filled for compute variants, hollow for fragment ones; a thin bar behind it
// spans the time's p10–p90. The Pareto front (no other variant is both at least as fast
// and at least as accurate) is a black step line, and its points are labelled with the
// variant's short name only where the label collides with no other label, no marker and
// no edge — a crowded front keeps its points unlabelled rather than unreadable.
//
// Every marker is an element of class "point" with data-variant (the index the caller
// gave), data-panel ("default" | "calibrated" | "accumulated") and tabindex 0, and holds a <title> with
// the variant's name, time and error: a standalone SVG (report.md shows it) names its
// points on hover, and the report page (page.hpp) puts its own tooltip in their place.
// Colours and fonts are attributes, not a style sheet, so the file draws alike on its own
// and inside the page. Coordinates are written with one decimal: same points, same bytes.
#pragma once

#include "html_text.hpp"
#include "number_text.hpp"
#include "report_techniques.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <map>
#include <sstream>
#include <string>
#include <vector>

namespace aogen_report {

struct plot_point {
    size_t variant = 0;            // the caller's index, written as data-variant
    std::string name;              // the full variant name (hover)
    std::string label;             // its short name (Pareto labels)
    std::string technique, stage;  // "ssao" | "gtao" | "vbao" | "sao"; "compute" | "fragment"
    double ms = NAN, ms_p10 = NAN, ms_p90 = NAN;
    double error = NAN, error_calibrated = NAN, error_accumulated = NAN;
    bool pareto = false, pareto_calibrated = false, pareto_accumulated = false;
    double error_motion = NAN; // the report in motion's error (motion_time_svg)
    bool pareto_motion = false;
};

// Which error a panel plots: the single frame's at default parameters, calibrated, the
// mean of the report's frames, or the error in motion.
enum class plot_error { plain, calibrated, accumulated, motion };

// The short name a label shows: the tokens that tell the default matrix apart
// ("gtao-2x2-half-denoise-gbufworld-std-persp-cs" → "gtao-2x2-half-denoise").
inline std::string plot_label(const std::string& name)
{
    size_t at = 0;
    for (int dashes = 0; dashes < 4; ++dashes) {
        at = name.find('-', at + (dashes > 0));
        if (at == std::string::npos) return name;
    }
    return name.substr(0, at);
}

namespace detail {

// The plot's geometry, in SVG pixels.
inline constexpr double plot_panel_width = 620, plot_panel_height = 430;
inline constexpr double plot_left = 64, plot_right = 16, plot_top = 34, plot_bottom = 48; // margins inside a panel
inline constexpr double plot_title_height = 26, plot_legend_height = 30;
inline constexpr double plot_marker_radius = 4.5;
inline constexpr double plot_label_font = 10;          // px, monospace
inline constexpr double plot_label_char_width = 6.02;  // a monospace glyph's advance at that size (0.6 em, DejaVu Sans Mono)

// A technique's marker: its row's (report_techniques.hpp), grey circles for a name no row has.
inline technique_style style_of(const std::string& technique)
{
    const report_technique* t = report_technique_named(technique);
    return t ? t->style : technique_style{"#555555", "circle"};
}

inline std::string num(double x) { return fixed(x, 1); }

// The path of a marker of `shape` centred at (x, y).
inline std::string marker_path(const std::string& shape, double x, double y)
{
    const double r = plot_marker_radius;
    std::ostringstream d;
    if (shape == "triangle")
        d << "M" << num(x) << " " << num(y - 1.2 * r) << "L" << num(x + 1.1 * r) << " " << num(y + 0.8 * r) << "L" << num(x - 1.1 * r) << " "
          << num(y + 0.8 * r) << "Z";
    else if (shape == "square")
        d << "M" << num(x - 0.9 * r) << " " << num(y - 0.9 * r) << "h" << num(1.8 * r) << "v" << num(1.8 * r) << "h" << num(-1.8 * r) << "Z";
    else if (shape == "diamond")
        d << "M" << num(x) << " " << num(y - 1.2 * r) << "L" << num(x + 1.2 * r) << " " << num(y) << "L" << num(x) << " " << num(y + 1.2 * r)
          << "L" << num(x - 1.2 * r) << " " << num(y) << "Z";
    else // a circle as two arcs
        d << "M" << num(x - r) << " " << num(y) << "a" << num(r) << " " << num(r) << " 0 1 0 " << num(2 * r) << " 0a" << num(r) << " "
          << num(r) << " 0 1 0 " << num(-2 * r) << " 0Z";
    return d.str();
}

// 1, 2 and 5 times the powers of ten in [lo, hi]: the log axis's ticks.
inline std::vector<double> log_ticks(double lo, double hi)
{
    std::vector<double> ticks;
    for (int e = int(std::floor(std::log10(lo))); e <= int(std::ceil(std::log10(hi))); ++e)
        for (double m : {1.0, 2.0, 5.0}) {
            const double t = m * std::pow(10.0, e);
            if (t >= lo * (1 - 1e-9) && t <= hi * (1 + 1e-9)) ticks.push_back(t);
        }
    return ticks;
}

// A tick's text: as many decimals as it needs (0.005, 0.02, 0.5, 2, 50).
inline std::string tick_text(double t)
{
    for (int digits = 0; digits < 8; ++digits)
        if (std::fabs(std::round(t * std::pow(10.0, digits)) - t * std::pow(10.0, digits)) < 1e-6) return fixed(t, digits);
    return fixed(t, 8);
}

// A step of 1, 2, 2.5 or 5 times a power of ten giving at most 8 intervals up to `top`.
inline double linear_step(double top)
{
    const double base = std::pow(10.0, std::floor(std::log10(top / 8)));
    for (double m : {1.0, 2.0, 2.5, 5.0, 10.0})
        if (top / (m * base) <= 8) return m * base;
    return 10 * base;
}

struct box {
    double x0, y0, x1, y1;
    bool overlaps(const box& o) const { return x0 < o.x1 && o.x0 < x1 && y0 < o.y1 && o.y0 < y1; }
};

// One panel at horizontal offset `left` of the whole image.
class plot_panel {
public:
    plot_panel(const std::vector<plot_point>& points, plot_error kind, double left, double top)
        : points_(points), kind_(kind), left_(left), top_(top)
    {
        double lo = INFINITY, hi = 0, worst = 0;
        for (const plot_point& p : points_)
            if (shown(p)) {
                lo = std::min({lo, p.ms, std::isfinite(p.ms_p10) ? p.ms_p10 : p.ms});
                hi = std::max({hi, p.ms, std::isfinite(p.ms_p90) ? p.ms_p90 : p.ms});
                worst = std::max(worst, error(p));
            }
        if (!(hi > 0)) lo = 0.01, hi = 1, worst = 0.1; // nothing to show: an empty panel with axes
        // Room for a marker at either end, and at least a factor of 10 of time.
        lo /= 1.3, hi *= 1.3;
        if (hi / lo < 10) {
            const double widen = std::sqrt(10 / (hi / lo));
            lo /= widen, hi *= widen;
        }
        log_lo_ = std::log10(lo), log_hi_ = std::log10(hi);
        step_ = linear_step(std::max(worst, 1e-6) * 1.08);
        top_error_ = std::ceil(std::max(worst, 1e-6) * 1.08 / step_) * step_;
    }

    double error(const plot_point& p) const
    {
        switch (kind_) {
        case plot_error::calibrated: return p.error_calibrated;
        case plot_error::accumulated: return p.error_accumulated;
        case plot_error::motion: return p.error_motion;
        case plot_error::plain: break;
        }
        return p.error;
    }
    bool pareto(const plot_point& p) const
    {
        switch (kind_) {
        case plot_error::calibrated: return p.pareto_calibrated;
        case plot_error::accumulated: return p.pareto_accumulated;
        case plot_error::motion: return p.pareto_motion;
        case plot_error::plain: break;
        }
        return p.pareto;
    }
    const char* panel_name() const
    {
        switch (kind_) {
        case plot_error::calibrated: return "calibrated";
        case plot_error::accumulated: return "accumulated";
        case plot_error::motion: return "motion";
        case plot_error::plain: break;
        }
        return "default";
    }
    bool shown(const plot_point& p) const { return std::isfinite(p.ms) && p.ms > 0 && std::isfinite(error(p)); }

    // Pixel coordinates of a time and an error.
    double x(double ms) const { return x0() + (std::log10(ms) - log_lo_) / (log_hi_ - log_lo_) * (x1() - x0()); }
    double y(double e) const { return y1() - e / top_error_ * (y1() - y0()); }

    void draw(std::ostream& svg, const std::string& title) const
    {
        svg << "<g class=\"panel\" data-panel=\"" << panel_name() << "\">\n";
        svg << "<text x=\"" << num(left_ + plot_panel_width / 2) << "\" y=\"" << num(top_ + 18) << "\" text-anchor=\"middle\" font-size=\"13\">"
            << html_escape(title) << "</text>\n";
        draw_axes(svg);
        draw_front(svg);
        draw_points(svg);
        draw_labels(svg);
        svg << "</g>\n";
    }

private:
    double x0() const { return left_ + plot_left; }
    double x1() const { return left_ + plot_panel_width - plot_right; }
    double y0() const { return top_ + plot_top; }
    double y1() const { return top_ + plot_panel_height - plot_bottom; }

    void draw_axes(std::ostream& svg) const
    {
        svg << "<rect x=\"" << num(x0()) << "\" y=\"" << num(y0()) << "\" width=\"" << num(x1() - x0()) << "\" height=\"" << num(y1() - y0())
            << "\" fill=\"#ffffff\" stroke=\"#888888\"/>\n";
        for (double t : log_ticks(std::pow(10.0, log_lo_), std::pow(10.0, log_hi_))) {
            svg << "<line x1=\"" << num(x(t)) << "\" x2=\"" << num(x(t)) << "\" y1=\"" << num(y0()) << "\" y2=\"" << num(y1())
                << "\" stroke=\"#e4e4e4\"/>";
            svg << "<text x=\"" << num(x(t)) << "\" y=\"" << num(y1() + 15) << "\" text-anchor=\"middle\" font-size=\"10\">" << tick_text(t) << "</text>\n";
        }
        for (double e = 0; e <= top_error_ * (1 + 1e-9); e += step_) {
            svg << "<line x1=\"" << num(x0()) << "\" x2=\"" << num(x1()) << "\" y1=\"" << num(y(e)) << "\" y2=\"" << num(y(e))
                << "\" stroke=\"#e4e4e4\"/>";
            svg << "<text x=\"" << num(x0() - 5) << "\" y=\"" << num(y(e) + 3.5) << "\" text-anchor=\"end\" font-size=\"10\">" << tick_text(e) << "</text>\n";
        }
        svg << "<text x=\"" << num((x0() + x1()) / 2) << "\" y=\"" << num(y1() + 36) << "\" text-anchor=\"middle\" font-size=\"11\">"
            << "GPU time per frame, ms (median over scenes, log scale)</text>\n";
        svg << "<text transform=\"translate(" << num(left_ + 16) << " " << num((y0() + y1()) / 2) << ") rotate(-90)\" text-anchor=\"middle\" font-size=\"11\">"
            << "RMSE against ray-traced AO (mean over scenes)</text>\n";
    }

    std::vector<const plot_point*> front() const
    {
        std::vector<const plot_point*> f;
        for (const plot_point& p : points_)
            if (shown(p) && pareto(p)) f.push_back(&p);
        std::sort(f.begin(), f.end(), [&](const plot_point* a, const plot_point* b) {
            return a->ms != b->ms ? a->ms < b->ms : error(*a) != error(*b) ? error(*a) < error(*b) : a->variant < b->variant;
        });
        return f;
    }

    // The front as a step line: along each point's error to the next point's time, then down.
    void draw_front(std::ostream& svg) const
    {
        const std::vector<const plot_point*> f = front();
        if (f.empty()) return;
        svg << "<path class=\"front\" fill=\"none\" stroke=\"#000000\" stroke-width=\"1.2\" d=\"M" << num(x(f[0]->ms)) << " " << num(y(error(*f[0])));
        for (size_t i = 1; i < f.size(); ++i) svg << "H" << num(x(f[i]->ms)) << "V" << num(y(error(*f[i])));
        svg << "\"/>\n";
    }

    void draw_points(std::ostream& svg) const
    {
        for (const plot_point& p : points_) // the spreads first, under every marker
            if (shown(p) && std::isfinite(p.ms_p10) && std::isfinite(p.ms_p90) && p.ms_p10 > 0)
                svg << "<line class=\"spread\" x1=\"" << num(x(p.ms_p10)) << "\" x2=\"" << num(x(p.ms_p90)) << "\" y1=\"" << num(y(error(p)))
                    << "\" y2=\"" << num(y(error(p))) << "\" stroke=\"" << style_of(p.technique).colour << "\" stroke-opacity=\"0.45\"/>\n";
        for (const plot_point& p : points_) {
            if (!shown(p)) continue;
            const technique_style s = style_of(p.technique);
            const bool filled = p.stage != "fragment";
            svg << "<path class=\"point\" data-variant=\"" << p.variant << "\" data-panel=\"" << panel_name()
                << "\" tabindex=\"0\" d=\"" << marker_path(s.shape, x(p.ms), y(error(p))) << "\" fill=\"" << (filled ? s.colour : "#ffffff")
                << "\" fill-opacity=\"" << (filled ? "0.8" : "1") << "\" stroke=\"" << s.colour << "\" stroke-width=\"1.3\"><title>"
                << html_escape(p.name) << ": " << fixed(p.ms, 3) << " ms, RMSE " << fixed(error(p), 4) << "</title></path>\n";
        }
    }

    // The front's labels, fastest first, each at the first of six places around its point
    // that stays inside the panel and clear of every marker and every label placed so far.
    void draw_labels(std::ostream& svg) const
    {
        std::vector<box> taken;
        const double r = plot_marker_radius + 1;
        for (const plot_point& p : points_)
            if (shown(p)) taken.push_back({x(p.ms) - r, y(error(p)) - r, x(p.ms) + r, y(error(p)) + r});
        const box inside{x0() + 2, y0() + 2, x1() - 2, y1() - 2};
        for (const plot_point* p : front()) {
            const double px = x(p->ms), py = y(error(*p)), w = p->label.size() * plot_label_char_width, h = plot_label_font;
            const double gap = plot_marker_radius + 3;
            const double places[6][2] = {{px + gap, py - gap}, {px + gap, py + gap + h}, {px - gap - w, py - gap},
                                         {px - gap - w, py + gap + h}, {px - w / 2, py - gap - 2}, {px - w / 2, py + gap + h + 2}};
            for (const auto& at : places) { // (x, baseline)
                const box b{at[0], at[1] - h, at[0] + w, at[1] + 2};
                const bool clear = b.x0 >= inside.x0 && b.x1 <= inside.x1 && b.y0 >= inside.y0 && b.y1 <= inside.y1 &&
                                   std::none_of(taken.begin(), taken.end(), [&](const box& t) { return t.overlaps(b); });
                if (!clear) continue;
                taken.push_back(b);
                svg << "<text class=\"label\" data-variant=\"" << p->variant << "\" x=\"" << num(at[0]) << "\" y=\"" << num(at[1])
                    << "\" font-family=\"DejaVu Sans Mono, monospace\" font-size=\"" << num(plot_label_font) << "\">" << html_escape(p->label) << "</text>\n";
                break;
            }
        }
    }

    const std::vector<plot_point>& points_;
    plot_error kind_;
    double left_, top_;
    double log_lo_ = -2, log_hi_ = 0, step_ = 0.02, top_error_ = 0.1;
};

// The legend: a marker per technique (filled compute, hollow fragment), the front's line.
inline void draw_legend(std::ostream& svg, const std::vector<plot_point>& points, double top)
{
    std::vector<std::string> techniques;
    for (const report_technique& row : report_technique_table) {
        const std::string t = aogen::to_name(row.id);
        if (std::any_of(points.begin(), points.end(), [&](const plot_point& p) { return p.technique == t; })) techniques.push_back(t);
    }
    double x = plot_left;
    const double y = top + plot_legend_height / 2;
    for (const std::string& t : techniques) {
        const technique_style s = style_of(t);
        svg << "<path d=\"" << marker_path(s.shape, x, y) << "\" fill=\"" << s.colour << "\" fill-opacity=\"0.8\" stroke=\"" << s.colour << "\"/>";
        svg << "<path d=\"" << marker_path(s.shape, x + 14, y) << "\" fill=\"#ffffff\" stroke=\"" << s.colour << "\"/>";
        std::string upper = t;
        std::transform(upper.begin(), upper.end(), upper.begin(), [](unsigned char c) { return char(std::toupper(c)); });
        svg << "<text x=\"" << num(x + 24) << "\" y=\"" << num(y + 4) << "\" font-size=\"11\">" << upper << "</text>\n";
        x += 90;
    }
    svg << "<text x=\"" << num(x) << "\" y=\"" << num(y + 4) << "\" font-size=\"11\">filled: compute, hollow: fragment; bar: p10–p90 of the time</text>";
    x += 380;
    svg << "<path d=\"M" << num(x) << " " << num(y) << "h24\" stroke=\"#000000\" stroke-width=\"1.2\"/><text x=\"" << num(x + 30) << "\" y=\""
        << num(y + 4) << "\" font-size=\"11\">Pareto front (labelled where room)</text>\n";
}

// A plot's <svg> element of class `cls` (width × height), its background and `title` over it.
inline void open_plot(std::ostream& svg, const char* cls, double width, double height, const std::string& title)
{
    svg << "<svg xmlns=\"http://www.w3.org/2000/svg\" class=\"" << cls << "\" width=\"" << num(width) << "\" height=\"" << num(height)
        << "\" viewBox=\"0 0 " << num(width) << " " << num(height) << "\" font-family=\"DejaVu Sans, Arial, sans-serif\" role=\"img\" aria-label=\""
        << html_escape(title) << "\">\n";
    svg << "<rect width=\"100%\" height=\"100%\" fill=\"#fafafa\"/>\n";
    svg << "<text x=\"" << num(width / 2) << "\" y=\"18\" text-anchor=\"middle\" font-size=\"14\" font-weight=\"bold\">" << html_escape(title) << "</text>\n";
}

} // namespace detail

// The whole plot: `title` over the panels, the legend under them. With `frames` > 1 a third
// panel plots the error after that many frames (plot_point::error_accumulated).
inline std::string error_time_svg(const std::vector<plot_point>& points, const std::string& title, int frames = 1)
{
    const int panels = frames > 1 ? 3 : 2;
    const double width = panels * detail::plot_panel_width, height = detail::plot_title_height + detail::plot_panel_height + detail::plot_legend_height;
    std::ostringstream svg;
    detail::open_plot(svg, "error-time-plot", width, height, title);
    detail::plot_panel(points, plot_error::plain, 0, detail::plot_title_height).draw(svg, "Default parameters");
    detail::plot_panel(points, plot_error::calibrated, detail::plot_panel_width, detail::plot_title_height)
        .draw(svg, "Calibrated (ao^p, p fitted on the other scenes)");
    if (panels == 3)
        detail::plot_panel(points, plot_error::accumulated, 2 * detail::plot_panel_width, detail::plot_title_height)
            .draw(svg, "After " + std::to_string(frames) + " frames (their plain mean, still camera)");
    detail::draw_legend(svg, points, detail::plot_title_height + detail::plot_panel_height);
    svg << "</svg>\n";
    return svg.str();
}

// The report in motion's plot: one panel of each motion variant's error in motion (mean over
// its scenes, plot_point::error_motion) against its time per frame, its Pareto front
// (pareto_motion) drawn as error_time_svg draws one.
inline std::string motion_time_svg(const std::vector<plot_point>& points, const std::string& title)
{
    const double width = detail::plot_panel_width, height = detail::plot_title_height + detail::plot_panel_height + detail::plot_legend_height;
    std::ostringstream svg;
    detail::open_plot(svg, "motion-time-plot", width, height, title);
    detail::plot_panel(points, plot_error::motion, 0, detail::plot_title_height).draw(svg, "In motion (each scored frame against its own truth)");
    detail::draw_legend(svg, points, detail::plot_title_height + detail::plot_panel_height);
    svg << "</svg>\n";
    return svg.str();
}

} // namespace aogen_report
