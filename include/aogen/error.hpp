// aogen/error.hpp — the one error mechanism of aogen.
//
// Every function in aogen that rejects its input throws aogen::error. The message
// always names three things: what was wrong (the parameter, field, member or file),
// the value that was given, and what would have been valid. For example:
//
//     kernel count: 0 is out of range (valid: 1..256)
//     ssao.radius: nan is not a finite number (valid: > 0)
//
// Callers that want a single line on stderr (the `aogen` command line) print
// `e.what()` and exit non-zero; nothing else is needed.
//
// Helpers here build those messages so that every header words them the same way:
//     aogen::fail("noise size", "3 is not a power of two", "valid: 1, 2, 4, ..., 64");
//     aogen::quote(user_text)    // "'ssao-s9000'": what the user wrote, safe to print
//     aogen::require_range("kernel count", n, 1, 256);
//     aogen::require_finite_range("ssao.radius", r, 0.0, 1e9);  // inclusive
#pragma once

#include <charconv>
#include <cmath>
#include <stdexcept>
#include <string>
#include <string_view>
#include <system_error>

namespace aogen {

// Thrown for every rejected input. `what()` is one line, ready to print.
class error : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// Shortest text that reads back to the same value ("0.1", "1e+09", "nan", "inf").
// std::to_chars gives the same digits on every conforming standard library, which
// keeps error messages and generated files identical across compilers.
inline std::string format_number(double value)
{
    if (std::isnan(value)) return "nan";
    if (std::isinf(value)) return value > 0 ? "inf" : "-inf";
    char buffer[64];
    auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
    return std::string(buffer, result.ptr);
}

inline std::string format_number(float value)
{
    if (std::isnan(value)) return "nan";
    if (std::isinf(value)) return value > 0 ? "inf" : "-inf";
    char buffer[64];
    auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
    return std::string(buffer, result.ptr);
}

inline std::string format_number(long long value) { return std::to_string(value); }
inline std::string format_number(unsigned long long value) { return std::to_string(value); }
inline std::string format_number(int value) { return std::to_string(value); }
inline std::string format_number(unsigned value) { return std::to_string(value); }
inline std::string format_number(long value) { return std::to_string(value); }
inline std::string format_number(unsigned long value) { return std::to_string(value); }

// What the user wrote, as an error message quotes it: in single quotes, every byte that
// is not printable ASCII written as \xNN (a control character in a name must not reach
// the terminal raw: "\x1b[31m" would colour it), and at most `limit` characters of the
// original kept — a longer text ends in "... (N bytes)", so an 18 kB name gives a short
// line. The one way aogen echoes user text.
inline std::string quote(std::string_view text, size_t limit = 80)
{
    static const char hex[] = "0123456789abcdef";
    std::string out = "'";
    const size_t kept = text.size() > limit ? limit : text.size();
    for (size_t i = 0; i < kept; ++i) {
        const auto c = static_cast<unsigned char>(text[i]);
        if (c >= 0x20 && c < 0x7f && c != '\\') out += char(c);
        else if (c == '\\') out += "\\\\";
        else out.append("\\x").append(1, hex[c >> 4]).append(1, hex[c & 15]);
    }
    out += "'";
    if (kept < text.size()) out += "... (" + std::to_string(text.size()) + " bytes)";
    return out;
}

// A name or path as the subject of a message: as it is, but every byte that is not
// printable ASCII written as \xNN and at most `limit` characters kept (a longer one ends
// in "... (N bytes)"). No quotes: a file name or a member path reads best bare.
inline std::string printable(std::string_view text, size_t limit = 120)
{
    static const char hex[] = "0123456789abcdef";
    std::string out;
    const size_t kept = text.size() > limit ? limit : text.size();
    for (size_t i = 0; i < kept; ++i) {
        const auto c = static_cast<unsigned char>(text[i]);
        if (c >= 0x20 && c < 0x7f) out += char(c);
        else out.append("\\x").append(1, hex[c >> 4]).append(1, hex[c & 15]);
    }
    if (kept < text.size()) out += "... (" + std::to_string(text.size()) + " bytes)";
    return out;
}

// "<subject>: <problem> (<valid>)". `valid` should start with "valid:" or say what to do.
[[noreturn]] inline void fail(std::string_view subject, std::string_view problem,
                              std::string_view valid)
{
    std::string message;
    message.append(subject).append(": ").append(problem);
    if (!valid.empty()) message.append(" (").append(valid).append(")");
    throw error(message);
}

// Integers and other exactly comparable values in [lo, hi].
template <class T>
void require_range(std::string_view subject, T value, T lo, T hi)
{
    if (value < lo || value > hi)
        fail(subject, format_number(value) + " is out of range",
             "valid: " + format_number(lo) + ".." + format_number(hi));
}

// A finite floating-point value in [lo, hi]. NaN and infinities are named as such.
inline void require_finite_range(std::string_view subject, double value, double lo, double hi)
{
    std::string valid = "valid: " + format_number(lo) + ".." + format_number(hi);
    if (!std::isfinite(value)) fail(subject, format_number(value) + " is not a finite number", valid);
    if (value < lo || value > hi) fail(subject, format_number(value) + " is out of range", valid);
}

// A finite floating-point value strictly greater than lo and at most hi.
inline void require_finite_above(std::string_view subject, double value, double lo, double hi)
{
    std::string valid = "valid: > " + format_number(lo) + " and <= " + format_number(hi);
    if (!std::isfinite(value)) fail(subject, format_number(value) + " is not a finite number", valid);
    if (!(value > lo) || value > hi) fail(subject, format_number(value) + " is out of range", valid);
}

} // namespace aogen
