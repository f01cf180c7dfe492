// aogen/range.hpp — a setting's valid range, as a value the docs, checks and help all read.
//
// WHAT
//   int_range     an inclusive integer range lo..hi (a sample count, a slice count)
//   float_range   a range of finite floats, [lo, hi] or (lo, hi] (a radius, an exponent)
//   to_string(r)  the words error messages and help text use: "1..256", "> 0 and <= 1e+15"
//   require_in(subject, value, r)
//                 throws aogen::error unless `value` lies in `r`, worded as error.hpp's
//                 "<subject>: <value> <problem> (valid: <range>)"
//
// USAGE
//     #include <aogen/range.hpp>
//     static constexpr aogen::int_range samples_range{1, 256};
//     aogen::require_in("ssao samples", 300, samples_range);
//     // throws "ssao samples: 300 is out of range (valid: 1..256)"
//
// WHY
//   A range written once, as a constexpr value beside the field it bounds (params.hpp's
//   settings, variant.hpp's counts), is what validation, the command line's help and the
//   documentation all print, so they cannot disagree.
#pragma once

#include "error.hpp"

#include <cmath>
#include <string>
#include <string_view>

namespace aogen {

// An inclusive integer range lo..hi.
struct int_range {
    int lo;
    int hi;
    constexpr bool contains(int v) const { return v >= lo && v <= hi; }
};

// A range of finite floats: [lo, hi], or (lo, hi] when `lo_excluded`.
struct float_range {
    float lo;
    float hi;
    bool lo_excluded;
    bool contains(float v) const
    {
        if (!std::isfinite(v)) return false;
        return (lo_excluded ? v > lo : v >= lo) && v <= hi;
    }
};

inline std::string to_string(const int_range& r)
{
    return format_number(r.lo) + ".." + format_number(r.hi);
}
inline std::string to_string(const float_range& r)
{
    if (r.lo_excluded) return "> " + format_number(r.lo) + " and <= " + format_number(r.hi);
    return format_number(r.lo) + ".." + format_number(r.hi);
}

inline void require_in(std::string_view subject, int value, const int_range& r)
{
    require_range(subject, value, r.lo, r.hi);
}

// A finite float inside `r`, printing the float as a float ("0.1", not "0.10000000149011612").
inline void require_in(std::string_view subject, float value, const float_range& r)
{
    const std::string valid = "valid: " + to_string(r);
    if (!std::isfinite(value)) fail(subject, format_number(value) + " is not a finite number", valid);
    if (!r.contains(value)) fail(subject, format_number(value) + " is out of range", valid);
}

} // namespace aogen
