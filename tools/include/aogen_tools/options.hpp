// aogen_tools/options.hpp — command-line option checks that word their errors as aogen does.
//
// CLI11 converts option text itself and says "Could not convert: --count = abc", with no
// valid range; and it wraps a negative number into an unsigned one without a word
// (--seed -1 became 2^64 − 1). These validators look at the text first, so each bad value
// is one line naming the option, the value and what is valid:
//     --count: 'abc' is not an integer (valid: 1..256)
//     --seed: '-1' is out of range (valid: 0..18446744073709551615)
//     --name: '1abc' is not an identifier (valid: letters, digits and _, ...)
//     --out: is empty (valid: a path)
// usage: sub->add_option("--count", count)->check(aogen::tools::integer_in(1, 256));
//        sub->add_option("--name", name)->check(aogen::tools::declaration_name());
// Shared by the `aogen` command line and aogen_report.
#pragma once

#include <aogen/error.hpp>
#include <aogen/layout.hpp>

#include <CLI/CLI.hpp>

#include <charconv>
#include <cmath>
#include <cstdint>
#include <new>
#include <regex>
#include <string>

namespace aogen::tools {

namespace detail {

// The validator's text, or "" when it accepts: the message part after "<option>: ".
template <class Check>
CLI::Validator validator(Check check, std::string description)
{
    return CLI::Validator(
        [check](std::string& text) -> std::string {
            try {
                check(text);
                return "";
            } catch (const error& e) {
                return e.what();
            }
        },
        std::move(description));
}

// "problem (valid)", the form CLI11 prefixes with the option's name ("--count: ...").
[[noreturn]] inline void reject(const std::string& problem, const std::string& valid)
{
    throw error(problem + " (" + valid + ")");
}

} // namespace detail

// A decimal integer in [lo, hi] (an optional '-', then digits only).
inline CLI::Validator integer_in(long long lo, unsigned long long hi)
{
    const std::string valid = "valid: " + std::to_string(lo) + ".." + std::to_string(hi);
    return detail::validator(
        [lo, hi, valid](const std::string& text) {
            const bool negative = !text.empty() && text[0] == '-';
            const std::string digits = negative ? text.substr(1) : text;
            if (digits.empty() || digits.find_first_not_of("0123456789") != std::string::npos) detail::reject(quote(text) + " is not an integer", valid);
            unsigned long long magnitude = 0;
            const auto parsed = std::from_chars(digits.data(), digits.data() + digits.size(), magnitude);
            const bool overflow = parsed.ec == std::errc::result_out_of_range;
            // -magnitude >= lo, i.e. magnitude <= -lo, computed without overflowing at LLONG_MIN.
            const bool in_range = !overflow && (negative ? lo < 0 && magnitude <= static_cast<unsigned long long>(-(lo + 1)) + 1
                                                         : magnitude <= hi && (lo <= 0 || magnitude >= static_cast<unsigned long long>(lo)));
            if (!in_range) detail::reject(quote(text) + " is out of range", valid);
        },
        "INT in " + std::to_string(lo) + ".." + std::to_string(hi));
}

// A finite decimal number in [lo, hi] ("0.5", "1e3"; no "nan", "inf" or trailing text).
inline CLI::Validator number_in(double lo, double hi)
{
    const std::string valid = "valid: " + format_number(lo) + ".." + format_number(hi);
    return detail::validator(
        [lo, hi, valid](const std::string& text) {
            double x = 0;
            const auto parsed = std::from_chars(text.data(), text.data() + text.size(), x);
            if (text.empty() || parsed.ptr != text.data() + text.size() || parsed.ec == std::errc::invalid_argument)
                detail::reject(quote(text) + " is not a number", valid);
            if (parsed.ec == std::errc::result_out_of_range || !std::isfinite(x) || x < lo || x > hi)
                detail::reject(quote(text) + " is out of range", valid);
        },
        "NUMBER in " + format_number(lo) + ".." + format_number(hi));
}

// Any text but the empty one.
inline CLI::Validator not_empty(const std::string& what)
{
    return detail::validator(
        [what](const std::string& text) {
            if (text.empty()) detail::reject("is empty", "valid: " + what);
        },
        "");
}

// A name a declaration can use (aogen/layout.hpp's rules: an identifier of at most 1024
// characters that is no keyword of a target language).
inline CLI::Validator declaration_name()
{
    return detail::validator(
        [](const std::string& text) {
            const std::string problem = layout::detail::name_problem(text);
            if (!problem.empty()) throw error(problem);
        },
        "IDENTIFIER");
}

// One line for a CLI11 parse error, in aogen's form: CLI11's own messages ("--rules is
// required", "The following argument was not expected: --frob") say what is wrong but not
// what is valid, so the line adds the option's help text, or the command's options.
inline std::string parse_error_line(const CLI::App& app, const CLI::ParseError& e, const std::string& program)
{
    std::string what = printable(e.what(), 200);
    if (what.find("(valid:") != std::string::npos) return what; // one of ours
    // CLI11 says an option given without its value as "--count: 1 required INT:INT in
    // 1..256 missing", in its own type names; the user wrote an option and nothing after it.
    static const std::regex missing_value("^(-[^ :]+): [0-9]+ required .* missing$");
    std::smatch m;
    if (std::regex_match(what, m, missing_value)) what = m[1].str() + ": is given without a value";
    const CLI::App* command = &app;
    for (const CLI::App* sub : app.get_subcommands()) command = sub; // the one being parsed
    for (const CLI::Option* o : command->get_options()) {
        const std::string name = o->get_name(); // "--rules", or a positional's name
        if (!name.empty() && name[0] == '-' && what.find(name) != std::string::npos && !o->get_description().empty())
            return what + " (valid: " + name + " is: " + printable(o->get_description(), 160) + ")";
    }
    // The options, as many as keep the line short; --help has them all.
    std::string options;
    for (const CLI::Option* o : command->get_options()) {
        const std::string name = o->get_name();
        if (name.empty() || name[0] != '-' || name == "--help") continue;
        if (options.size() + name.size() > 120) {
            options += ", ...";
            break;
        }
        options += (options.empty() ? "" : ", ") + name;
    }
    const std::string full = command == &app ? program : program + " " + command->get_name();
    return what + " (valid: the options of " + full + ": " + options + "; " + full + " --help)";
}

// One line for any exception that ends a program, in aogen's form: an aogen::error as it
// is; anything else — a C++ library's own exception, which names no input — said to be
// aogen's fault rather than the user's, with the library's words kept for the report.
inline std::string exception_line(const std::exception& e)
{
    if (dynamic_cast<const aogen::error*>(&e)) return e.what();
    if (dynamic_cast<const std::bad_alloc*>(&e)) return "memory: ran out (valid: a smaller input, or a machine with more memory)";
    return "internal error: a library failed (" + printable(e.what(), 160) +
           ") (valid: any input should give an aogen error instead; please report this with the command line)";
}

} // namespace aogen::tools
