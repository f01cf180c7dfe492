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

#include "metrics.hpp"
#include "number_text.hpp"
#include "png.hpp"
#include "text.hpp"

#include <algorithm>
#include <cmath>

namespace aogen_report {

// `src` (w × h pixels of `channels` floats) scaled up by the integer `factor` to W × H,
// nearest, clamped at the far edges.
inline std::vector<float> upsample(const std::vector<float>& src, int w, int h, int factor, int W, int H, int channels = 1)
{
    if (factor < 1 || channels < 1 || src.size() != size_t(w) * h * channels || (W + factor - 1) / factor != w || (H + factor - 1) / factor != h)
        aogen::fail("upsample", std::to_string(w) + "x" + std::to_string(h) + " by " + std::to_string(factor) + " to " + std::to_string(W) + "x" +
                                    std::to_string(H),
                    "valid: w = ceil(W / factor) and h = ceil(H / factor)");
    std::vector<float> out(size_t(W) * H * channels);
    for (int y = 0; y < H; ++y)
        for (int x = 0; x < W; ++x)
            for (int c = 0; c < channels; ++c)
                out[(size_t(y) * W + x) * channels + c] = src[(size_t(y / factor) * w + x / factor) * channels + c];
    return out;
}

// Unit normals (3 floats per pixel) as 8-bit colours, n * 0.5 + 0.5 per channel (a normal
// map's look: +x red, +y green, +z blue); a zero or non-finite normal becomes (128, 128, 128).
inline uint8_t normal_byte(float x)
{
    return std::isfinite(x) ? uint8_t(std::lround((std::clamp(x, -1.0f, 1.0f) * 0.5f + 0.5f) * 255.0f)) : uint8_t(128);
}

inline std::vector<uint8_t> normal_bytes(const std::vector<float>& normals)
{
    std::vector<uint8_t> out(normals.size());
    for (size_t i = 0; i < normals.size(); ++i) out[i] = normal_byte(normals[i]);
    return out;
}

// normal_bytes read back: 3 floats per pixel in [-1, 1] (within 1/255 of what was written).
inline std::vector<float> normals_of_bytes(const std::vector<uint8_t>& bytes)
{
    std::vector<float> out(bytes.size());
    for (size_t i = 0; i < bytes.size(); ++i) out[i] = bytes[i] / 255.0f * 2.0f - 1.0f;
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

// A bent-normal row's label: "gtao-3x3-...-bn  bent normal  mean 7.2 deg".
inline std::string bent_strip_label(const std::string& name, double mean_degrees)
{
    return name + "  bent normal  mean " + detail::fixed(mean_degrees, 1, "n/a") + " deg";
}

// Rows of a label band over three panels: reference | variant | |variant − reference| of
// the AO (add_row), or of the bent normals (add_bent_normal_row: the normals as colours,
// normal_bytes' look, and the angle between them on the heat ramp, yellow at
// bent_heat_full_scale_degrees). Background pixels (not valid) are drawn in
// background_colour in every panel. The layout is the one described at the top of this header.
inline constexpr float bent_heat_full_scale_degrees = 30.0f;

class strip {
public:
    strip(int width, int height) : w_(width), h_(height), text_scale_(strip_text_scale(height)) {}

    // `label` is drawn as printable() ASCII; an empty one leaves the band empty.
    void add_row(const std::vector<float>& reference, const std::vector<float>& ao, const std::vector<uint8_t>& valid, std::string label = {})
    {
        require_size(reference.size(), 1), require_size(ao.size(), 1), require_size(valid.size(), 1);
        row k{{}, printable(label)};
        for (size_t i = 0; i < valid.size(); ++i) {
            const bool v = valid[i] != 0;
            k.panels[0].push_back(v ? grey(reference[i]) : background_colour);
            k.panels[1].push_back(v ? grey(ao[i]) : background_colour);
            k.panels[2].push_back(v ? heat(ao[i] - reference[i], heat_full_scale) : background_colour);
        }
        rows_.push_back(std::move(k));
    }

    // Bent normals, 3 floats per pixel in one space (unit, or zero where there is none).
    void add_bent_normal_row(const std::vector<float>& reference, const std::vector<float>& normals, const std::vector<uint8_t>& valid,
                             std::string label = {})
    {
        require_size(reference.size(), 3), require_size(normals.size(), 3), require_size(valid.size(), 1);
        row k{{}, printable(label)};
        for (size_t i = 0; i < valid.size(); ++i) {
            const bool v = valid[i] != 0;
            const float* t = &reference[3 * i];
            const float* n = &normals[3 * i];
            k.panels[0].push_back(v ? normal_colour(t) : background_colour);
            k.panels[1].push_back(v ? normal_colour(n) : background_colour);
            const double angle = angle_degrees(n, t); // NaN: no normal, drawn as 90 degrees
            k.panels[2].push_back(v ? heat(float(std::isnan(angle) ? 90.0 : angle), bent_heat_full_scale_degrees) : background_colour);
        }
        rows_.push_back(std::move(k));
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
        std::vector<rgb> panels[3]; // w_ × h_ colours each
        std::string label;
    };

    void require_size(size_t n, size_t per_pixel) const
    {
        const size_t pixels = size_t(w_) * h_;
        if (n != pixels * per_pixel)
            aogen::fail("image strip", "a row of " + std::to_string(n / per_pixel) + " pixels", "valid: " + std::to_string(pixels) + " pixels per image");
    }

    static rgb normal_colour(const float* n)
    {
        if (!(std::isfinite(n[0]) && std::isfinite(n[1]) && std::isfinite(n[2]))) return {255, 0, 255};
        return {normal_byte(n[0]), normal_byte(n[1]), normal_byte(n[2])};
    }

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
        for (int p = 0; p < 3; ++p)
            for (int y = 0; y < h_; ++y)
                for (int x = 0; x < w_; ++x) img.set(p * (w_ + strip_gap) + x, top + y, k.panels[p][size_t(y) * w_ + x]);
    }

    int w_, h_, text_scale_;
    std::vector<row> rows_;
};

} // namespace aogen_report
