// aogen_report/images.hpp — AO images for people: full resolution, grey levels, an error
// heat map, and the report's strips (reference | variant | |error|, one row per variant).
//
//     std::vector<float> full = aogen_report::upsample(ao, w, h, 2, W, H);   // half → full
//     aogen_report::strip s(W, H);
//     s.add_row(reference, full, valid);                                     // one row
//     std::string png = aogen_report::encode_png(s.image());
//
// Half-resolution AO is compared and shown at full resolution by nearest upsampling
// (full-res pixel x reads half-res pixel x / 2): what a composite pass reads without a
// bilateral upsample.
#pragma once

#include "png.hpp"

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
inline constexpr int strip_gap = 2;

// Rows of three panels: reference | variant | |variant − reference|. Background pixels
// (not valid) are drawn in background_colour in every panel.
class strip {
public:
    strip(int width, int height) : w_(width), h_(height) {}

    void add_row(const std::vector<float>& reference, const std::vector<float>& ao, const std::vector<uint8_t>& valid)
    {
        const size_t n = size_t(w_) * h_;
        if (reference.size() != n || ao.size() != n || valid.size() != n)
            aogen::fail("image strip", "a row of " + std::to_string(ao.size()) + " pixels", "valid: " + std::to_string(n) + " pixels per image");
        rows_.push_back({reference, ao, valid});
    }

    rgb_image image() const
    {
        const int rows = std::max<int>(1, int(rows_.size()));
        rgb_image img(3 * w_ + 2 * strip_gap, rows * h_ + (rows - 1) * strip_gap, {255, 255, 255});
        for (size_t r = 0; r < rows_.size(); ++r) {
            const row& k = rows_[r];
            const int top = int(r) * (h_ + strip_gap);
            for (int y = 0; y < h_; ++y)
                for (int x = 0; x < w_; ++x) {
                    const size_t i = size_t(y) * w_ + x;
                    const bool v = k.valid[i] != 0;
                    img.set(x, top + y, v ? grey(k.reference[i]) : background_colour);
                    img.set(w_ + strip_gap + x, top + y, v ? grey(k.ao[i]) : background_colour);
                    img.set(2 * (w_ + strip_gap) + x, top + y, v ? heat(k.ao[i] - k.reference[i], heat_full_scale) : background_colour);
                }
        }
        return img;
    }

private:
    struct row {
        std::vector<float> reference, ao;
        std::vector<uint8_t> valid;
    };
    int w_, h_;
    std::vector<row> rows_;
};

} // namespace aogen_report
