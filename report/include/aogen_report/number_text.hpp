// aogen_report/number_text.hpp — numbers written for people, with a fixed number of
// decimals: the report's tables (markdown.hpp) and its strip labels (images.hpp).
//
//     aogen_report::detail::fixed(0.05, 3)          // "0.050"
//     aogen_report::detail::fixed(NAN, 3)           // "–": a variant that did not run
//     aogen_report::detail::fixed(NAN, 3, "n/a")    // "n/a": where the text must be ASCII
//
// printf's "%.*f" in the C locale (the report never sets another), so the same number
// gives the same text everywhere.
#pragma once

#include <cmath>
#include <cstdio>
#include <string>

namespace aogen_report::detail {

// `x` with `digits` decimals; `missing` when it is NaN or infinite.
inline std::string fixed(double x, int digits, const char* missing = "–")
{
    if (!std::isfinite(x)) return missing;
    char buffer[64];
    std::snprintf(buffer, sizeof buffer, "%.*f", digits, x);
    return buffer;
}

} // namespace aogen_report::detail
