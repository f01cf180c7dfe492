// aogen_report/images.hpp — AO images for people: full resolution, grey levels, an error
// heat map, and the report's strips (reference | variant | |error|, one labelled row per
// variant).
//
//     std::vector<float> full = aogen_report::upsample(ao, w, h, 2, W, H);   // half → full
//     aogen_report::strip s(W, H);
//     s.add_row(reference, full, valid, aogen_report::strip_label(name, ms, rmse));
//     std::string png = aogen_report::encode_png(s.image());
//
// Half-resolution AO is compared and shown at full resolution by nearest upsampling
// (full-res pixel x reads half-res pixel x / 2): what a composite pass reads without a
// bilateral upsample.
//
// A strip's layout, for W × H panels and text at s = strip_text_scale(H) pixels per font unit:
//   - each row is a label band of band_height = (glyph_height + 2 · strip_label_margin) · s
//     pixels (dark text on a light band, a margin of strip_label_margin · s around it), then
//     the three panels, strip_gap apart; rows are strip_gap apart; an empty label leaves its
//     band empty, so every row has the same height;
//   - width = max(3W + 2 · strip_gap, widest label's text_width + 2 · strip_label_margin · s):
//     a label wider than the panels widens the strip (it is never wrapped or cut), and the
//     panels stay at the left;
//   - height = rows · (band_height + H) + (rows − 1) · strip_gap (one row when there is none).
#pragma once

#include "number_text.hpp"
#include "png.hpp"
#include "text.hpp"

#include <algorithm>
#include <cmath>

namespace aogen_report {

// `src` (w × h) scaled up by the integer `factor` to W × H, clamped at the far edges.
inline std::vector<float> upsample(const std::vector<float>& src, int w, int h, int factor, int W, int H)
{
    if (factor < 1 || src.size() != size_t(w) * h || (W + factor - 1) / factor != w || (H + factor - 1) / factor != h)
        aogen::fail("upsample", std::to_string(w) + "x" + std::to_string(h) + " by " + std::to_string(factor) + " to " + std::to_string(W) + "x" +
                                    std::to_string(H),
                    "valid: w = ceil(W / factor) and h = ceil(H / factor)");
    std::vector<float> out(size_t(W) * H);
    for (int y = 0; y < H; ++y)
        for (int x = 0; x < W; ++x) out[size_t(y) * W + x] = src[size_t(y / factor) * w + x / factor];
    return out;
}

// AO in [0, 1] as a grey level; NaN and ±inf are magenta, so they cannot hide.
inline rgb grey(float ao)
{
    if (!std::isfinite(ao)) return {255, 0, 255};
    const auto g = uint8_t(std::lround(std::clamp(ao, 0.0f, 1.0f) * 255.0f));
    return {g, g, g};
}

// |error| on a black → purple → orange → yellow ramp reaching yellow at `full_scale`.
inline rgb heat(float error, float full_scale)
{
    if (!std::isfinite(error)) return {255, 0, 255};
    static const float stops[4][3] = {{0, 0, 0}, {120, 28, 160}, {240, 110, 30}, {255, 250, 160}};
    const float t = std::clamp(std::fabs(error) / full_scale, 0.0f, 1.0f) * 3.0f;
    const int i = std::min(int(t), 2);
    const float f = t - i;
    rgb c;
    for (int k = 0; k < 3; ++k) c[k] = uint8_t(std::lround(stops[i][k] + f * (stops[i + 1][k] - stops[i][k])));
    return c;
}

inline constexpr float heat_full_scale = 0.5f; // |error| shown at full brightness
inline constexpr rgb background_colour{40, 60, 90};
inline constexpr rgb label_band_colour{235, 235, 235};
inline constexpr rgb label_text_colour{0, 0, 0};
inline constexpr int strip_gap = 2;
inline constexpr int strip_label_margin = 2; // font units around a label's text

// Pixels per font unit for panels `panel_height` tall: 1 (the font's own size, legible
// from the smallest panels up) below 160 rows, 2 at 320×180, 7 at 1920×1080, so the text
// (glyph_height · scale pixels) grows with the panels: a tenth of a 180-row panel, a
// seventeenth of a 1080-row one.
inline int strip_text_scale(int panel_height) { return 1 + panel_height / 160; }

// A strip row's label: "gtao-2x3-half-box-gbufworld-std-persp-cs  0.050 ms  RMSE 0.0761";
// "n/a" for a time or an error that is not finite (ASCII, as the label font needs).
inline std::string strip_label(const std::string& name, double ms, double rmse)
{
    return name + "  " + detail::fixed(ms, 3, "n/a") + " ms  RMSE " + detail::fixed(rmse, 4, "n/a");
}

// Rows of a label band over three panels: reference | variant | |variant − reference|.
// Background pixels (not valid) are drawn in background_colour in every panel. The layout
// is the one described at the top of this header.
class strip {
public:
    strip(int width, int height) : w_(width), h_(height), text_scale_(strip_text_scale(height)) {}

    // `label` is drawn as printable() ASCII; an empty one leaves the band empty.
    void add_row(const std::vector<float>& reference, const std::vector<float>& ao, const std::vector<uint8_t>& valid, std::string label = {})
    {
        const size_t n = size_t(w_) * h_;
        if (reference.size() != n || ao.size() != n || valid.size() != n)
            aogen::fail("image strip", "a row of " + std::to_string(ao.size()) + " pixels", "valid: " + std::to_string(n) + " pixels per image");
        rows_.push_back({reference, ao, valid, printable(label)});
    }

    int text_scale() const { return text_scale_; }
    int band_height() const { return (glyph_height + 2 * strip_label_margin) * text_scale_; }

    rgb_image image() const
    {
        const int rows = std::max<int>(1, int(rows_.size()));
        rgb_image img(width(), rows * (band_height() + h_) + (rows - 1) * strip_gap, {255, 255, 255});
        for (size_t r = 0; r < rows_.size(); ++r) {
            const int top = int(r) * (band_height() + h_ + strip_gap);
            draw_label(img, rows_[r].label, top);
            draw_panels(img, rows_[r], top + band_height());
        }
        return img;
    }

private:
    struct row {
        std::vector<float> reference, ao;
        std::vector<uint8_t> valid;
        std::string label;
    };

    int margin() const { return strip_label_margin * text_scale_; }

    int width() const
    {
        int w = 3 * w_ + 2 * strip_gap;
        for (const row& k : rows_)
            if (!k.label.empty()) w = std::max(w, text_width(k.label, text_scale_) + 2 * margin());
        return w;
    }

    // The band across the whole strip, with the label at its margin.
    void draw_label(rgb_image& img, const std::string& label, int top) const
    {
        for (int y = top; y < top + band_height(); ++y)
            for (int x = 0; x < img.width; ++x) img.set(x, y, label_band_colour);
        draw_text(img, margin(), top + margin(), label, label_text_colour, text_scale_);
    }

    void draw_panels(rgb_image& img, const row& k, int top) const
    {
        for (int y = 0; y < h_; ++y)
            for (int x = 0; x < w_; ++x) {
                const size_t i = size_t(y) * w_ + x;
                const bool v = k.valid[i] != 0;
                img.set(x, top + y, v ? grey(k.reference[i]) : background_colour);
                img.set(w_ + strip_gap + x, top + y, v ? grey(k.ao[i]) : background_colour);
                img.set(2 * (w_ + strip_gap) + x, top + y, v ? heat(k.ao[i] - k.reference[i], heat_full_scale) : background_colour);
            }
    }

    int w_, h_, text_scale_;
    std::vector<row> rows_;
};

} // namespace aogen_report
