// aogen/names.hpp — enum values <-> their names, from one table per enum.
//
// WHAT
//   Every enum in aogen that a command line, a JSON file or a manifest spells out has one
//   table of (value, name) pairs, a `constexpr std::array<aogen::enum_name<E>, N>`. The
//   functions in `aogen::names` read that table both ways and word their errors the same
//   way for every enum (error.hpp's "<subject>: <problem> (valid: ...)"):
//
//     names::name_of(table, value, subject)   value -> name; a value outside the table:
//                                              "<subject>: 7 is not a valid value (valid: a, b, c)"
//     names::value_of(table, name, subject)   name -> value; an unknown name:
//                                              "<subject>: 'x' is not a known name (valid: a, b, c)"
//     names::is_listed(table, value)          is the value in the table?
//     names::require_listed(table, value, subject)  throws the value error unless listed
//     names::fail_unlisted(table, value, subject)   throws the value error ([[noreturn]];
//                                              the end of an exhaustive switch)
//     names::list(table)                      "a, b, c", in table order
//     names::values(table)                    std::array<E, N> of the values, in table order
//     names::same_name(a, b)                  equal, taking '-' and '_' as the same character
//     names::distinct(table)                  no value and no name (up to '-'/'_') twice
//
//   Names are matched exactly (case matters), except that '-' and '_' are the same
//   character on both sides: "gbuffer-world" finds "gbuffer_world", and "wgsl_storage"
//   finds "wgsl-storage". name_of always returns the table's own spelling.
//
// USAGE
//     #include <aogen/names.hpp>
//
//     enum class fruit { blood_orange, kiwi };
//     inline constexpr std::array<aogen::enum_name<fruit>, 2> fruit_names{{
//         {fruit::blood_orange, "blood_orange"},
//         {fruit::kiwi, "kiwi"},
//     }};
//     static_assert(aogen::names::distinct(fruit_names));
//
//     inline const char* to_name(fruit f) { return aogen::names::name_of(fruit_names, f, "fruit"); }
//     inline fruit fruit_from_name(std::string_view s, std::string_view subject = "fruit")
//     {
//         return aogen::names::value_of(fruit_names, s, subject);
//     }
//
//     fruit_from_name("blood-orange");   // fruit::blood_orange
//     fruit_from_name("lemon", "--fruit");
//     // throws aogen::error "--fruit: 'lemon' is not a known name (valid: blood_orange, kiwi)"
//
// WHY
//   One table per enum keeps the names, the list in error messages and help text, and the
//   set of valid values from drifting apart; one set of functions keeps every header's
//   errors worded alike. The tables are constexpr, so `values()` and `distinct()` work in
//   constant expressions (static_assert, `inline constexpr` lists of all values).
#pragma once

#include "error.hpp"

#include <array>
#include <cstddef>
#include <string>
#include <string_view>
#include <type_traits>

namespace aogen {

// One row of an enum's name table.
template <class E>
struct enum_name {
    E value;
    const char* name;
};

namespace names {

// '-' and '_' are the same character in names.
constexpr char fold(char c) { return c == '-' ? '_' : c; }

// a == b, except that '-' and '_' match each other.
constexpr bool same_name(std::string_view a, std::string_view b)
{
    if (a.size() != b.size()) return false;
    for (std::size_t i = 0; i < a.size(); ++i)
        if (fold(a[i]) != fold(b[i])) return false;
    return true;
}

// The names in table order: "a, b, c".
template <class E, std::size_t N>
std::string list(const std::array<enum_name<E>, N>& table, std::string_view separator = ", ")
{
    std::string out;
    for (const auto& entry : table) {
        if (!out.empty()) out += separator;
        out += entry.name;
    }
    return out;
}

// The values in table order (for an `inline constexpr` list of all values).
template <class E, std::size_t N>
constexpr std::array<E, N> values(const std::array<enum_name<E>, N>& table)
{
    std::array<E, N> out{};
    for (std::size_t i = 0; i < N; ++i) out[i] = table[i].value;
    return out;
}

// True when no value and no name (up to '-'/'_') appears twice: check tables with
// static_assert(names::distinct(table)).
template <class E, std::size_t N>
constexpr bool distinct(const std::array<enum_name<E>, N>& table)
{
    for (std::size_t i = 0; i < N; ++i)
        for (std::size_t j = i + 1; j < N; ++j)
            if (table[i].value == table[j].value || same_name(table[i].name, table[j].name)) return false;
    return true;
}

template <class E, std::size_t N>
constexpr bool is_listed(const std::array<enum_name<E>, N>& table, E value)
{
    for (const auto& entry : table)
        if (entry.value == value) return true;
    return false;
}

// Throws "<subject>: 7 is not a valid value (valid: a, b, c)" for `value`, listed or not.
template <class E, std::size_t N>
[[noreturn]] void fail_unlisted(const std::array<enum_name<E>, N>& table, E value, std::string_view subject)
{
    const auto number = static_cast<long long>(static_cast<std::underlying_type_t<E>>(value));
    fail(subject, format_number(number) + " is not a valid value", "valid: " + list(table));
}

// Throws the same error unless `value` is in the table.
template <class E, std::size_t N>
void require_listed(const std::array<enum_name<E>, N>& table, E value, std::string_view subject)
{
    if (!is_listed(table, value)) fail_unlisted(table, value, subject);
}

// The table's name of `value`; a value outside the table throws aogen::error.
template <class E, std::size_t N>
const char* name_of(const std::array<enum_name<E>, N>& table, E value, std::string_view subject)
{
    for (const auto& entry : table)
        if (entry.value == value) return entry.name;
    fail_unlisted(table, value, subject);
}

// The value named `name` ('-' and '_' alike); an unknown name throws
// "<subject>: '<name>' is not a known name (valid: a, b, c)".
template <class E, std::size_t N>
E value_of(const std::array<enum_name<E>, N>& table, std::string_view name, std::string_view subject)
{
    for (const auto& entry : table)
        if (same_name(name, entry.name)) return entry.value;
    fail(subject, quote(name) + " is not a known name", "valid: " + list(table));
}

} // namespace names
} // namespace aogen
