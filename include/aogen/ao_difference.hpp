// aogen/ao_difference.hpp — how far one AO image is from another, pixel by pixel: what
// "target X gives the SPIR-V's AO" means (issue 13).
//
// WHAT
//   difference_of(got, expected) compares two AO images of the same pixel count: the largest
//   per-pixel difference, how many pixels are bit-identical, and whether every pixel is within
//   one 8-bit step (1/255: the AO images the runners read back are k / 255). Images of
//   different sizes, and a NaN on either side, are as far apart as AO can be: 1.
//
// USAGE
//     aogen::ao_difference d = aogen::difference_of(gl_run.ao, spirv_run.ao);
//     if (!d.within_one_step()) ...;   // d.largest * 255 steps apart somewhere
//     bool exact = d.bit_identical();
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

namespace aogen {

struct ao_difference {
    float largest = 0;     // the largest |got − expected| over the pixels, AO units
    size_t identical = 0;  // pixels whose values are the same float
    size_t pixels = 0;     // pixels compared (0 when the sizes differ)

    bool bit_identical() const { return identical == pixels && largest == 0.0f; }
    // 1/255 and a float's rounding of k / 255 (the values are k / 255 read back as floats)
    bool within_one_step() const { return largest <= 1.0f / 255 + 1e-6f; }
};

inline ao_difference difference_of(const std::vector<float>& got, const std::vector<float>& expected)
{
    ao_difference d;
    if (got.size() != expected.size()) {
        d.largest = 1.0f;
        return d;
    }
    d.pixels = got.size();
    for (size_t i = 0; i < got.size(); ++i) {
        float step = std::fabs(got[i] - expected[i]);
        if (std::isnan(step)) step = 1.0f; // a NaN is as far from any AO as AO can be
        d.largest = std::max(d.largest, step);
        d.identical += step == 0.0f;
    }
    return d;
}

} // namespace aogen
