// `aogen list` (generator/cmd_list.hpp's axis_rows) against the variant-name parser: every
// token the list shows parses at its place in a name, and every value of every axis table
// and every extra has a token there. A row written by hand that drifts from the grammar
// (cmd_list.hpp once printed the blur tokens without `denoise`) fails here.
#include <aogen/axes.hpp>
#include <aogen/variant.hpp>

#include <catch2/catch.hpp>

#include "cmd_list.hpp"

#include <set>
#include <string>
#include <vector>

namespace unity_test_list {

using aogen::cli::axis_rows;
using aogen::cli::list_row;

const list_row& row_named(const std::vector<list_row>& rows, const std::string& axis)
{
    for (const list_row& r : rows)
        if (r.axis == axis) return r;
    FAIL("aogen list has no row " << axis); // throws: the line below is never reached
    return rows.front();
}

std::vector<std::string> tokens_of(const std::string& in_name)
{
    std::vector<std::string> out;
    size_t from = 0;
    for (size_t at; (at = in_name.find(" | ", from)) != std::string::npos; from = at + 3) out.push_back(in_name.substr(from, at - from));
    out.push_back(in_name.substr(from));
    return out;
}

// The default name with token `index` replaced (technique: with its count token too).
std::string name_with(size_t index, const std::string& token)
{
    std::vector<std::string> t = aogen::detail::split(aogen::to_name(aogen::variant{}), '-');
    t[index] = token;
    if (index == 0) t[1] = aogen::has_samples(aogen::technique_from_name(token)) ? "s16" : "2x3";
    std::string name;
    for (const std::string& s : t) name += (name.empty() ? "" : "-") + s;
    return name;
}

TEST_CASE("list: every fixed token aogen list shows parses at its place, one per value of the axis", "[list]")
{
    const std::vector<list_row> rows = axis_rows();
    struct place {
        const char* axis;
        size_t index, values;
    };
    for (const place& p : {place{"technique", 0, aogen::technique_names.size()}, place{"resolution", 2, 2},
                           place{"blur", 3, aogen::blur_mode_names.size()}, place{"normals", 4, aogen::normal_source_names.size()},
                           place{"depth", 5, aogen::depth_convention_names.size()},
                           place{"projection", 6, aogen::projection_kind_names.size()},
                           place{"stage", 7, aogen::pipeline_stage_names.size()}}) {
        INFO(p.axis);
        const std::vector<std::string> tokens = tokens_of(row_named(rows, p.axis).in_name);
        CHECK(tokens.size() == p.values);
        std::set<std::string> names;
        for (const std::string& t : tokens) {
            INFO(t);
            CHECK_NOTHROW(aogen::variant_from_name(name_with(p.index, t)));
            names.insert(aogen::to_name(aogen::variant_from_name(name_with(p.index, t))));
        }
        CHECK(names.size() == p.values); // each token a different variant
    }
}

TEST_CASE("list: every extra aogen list shows parses, and every extra of the grammar is shown", "[list]")
{
    std::set<std::string> shown;
    for (const list_row& r : axis_rows())
        for (const std::string& t : tokens_of(r.in_name))
            if (!t.empty() && t[0] == '-') shown.insert(t.substr(0, t.find(' ')));
    std::set<std::string> grammar;
    for (const char* t : aogen::detail::extra_tokens) grammar.insert("-" + std::string(t));
    CHECK(shown == grammar);
    for (std::string token : shown) {
        INFO(token);
        const size_t n = token.find("<N>");
        if (n != std::string::npos) token.replace(n, 3, "2");
        const size_t wg = token.find("<X>x<Y>");
        if (wg != std::string::npos) token.replace(wg, 7, "16x16");
        // The SSAO default takes every extra but bent normals, which GTAO takes.
        const std::string ssao = aogen::to_name(aogen::variant{}) + token, gtao = name_with(0, "gtao") + token;
        bool parsed = false;
        for (const std::string& name : {ssao, gtao}) {
            try {
                parsed = parsed || aogen::to_name(aogen::variant_from_name(name)) == name;
            } catch (const aogen::error&) {
            }
        }
        CHECK(parsed);
    }
}

} // namespace unity_test_list
