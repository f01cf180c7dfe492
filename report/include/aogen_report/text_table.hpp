// aogen_report/text_table.hpp — a table (or a list) written once and shown twice: as
// Markdown in report.md and as HTML in report.html.
//
//     aogen_report::text_table t{{"scene", "valid pixels"}, "lr", {}};
//     t.rows.push_back({"crease", "57600"});
//     md << aogen_report::markdown_table(t);
//     html << aogen_report::html_table(t);
//     html << aogen_report::html_list({"Device: **H200**", "Command: `aogen_report`"});
//
// Cells hold the report's Markdown (`code`, **strong**, *emphasis*): html_table turns those
// marks into HTML and escapes everything else (html_text.hpp), so a cell made from a
// user's scene name is shown as text.
#pragma once

#include "html_text.hpp"

#include <aogen/error.hpp>

#include <sstream>
#include <string>
#include <vector>

namespace aogen_report {

struct text_table {
    std::vector<std::string> head;              // column titles
    std::string align;                          // per column: 'l'eft, 'r'ight, 'c'entre
    std::vector<std::vector<std::string>> rows; // one cell per column
};

namespace detail {

inline void require_shape(const text_table& t)
{
    bool ok = t.align.size() == t.head.size();
    for (const auto& row : t.rows) ok = ok && row.size() == t.head.size();
    if (!ok) aogen::fail("text table", "rows or alignments of another width than its " + std::to_string(t.head.size()) + " columns", "valid: one cell and one alignment per column");
}

} // namespace detail

inline std::string markdown_table(const text_table& t)
{
    detail::require_shape(t);
    std::ostringstream md;
    md << "|";
    for (const std::string& h : t.head) md << " " << h << " |";
    md << "\n|";
    for (char a : t.align) md << (a == 'r' ? "---:|" : a == 'c' ? ":-:|" : "---|");
    md << "\n";
    for (const auto& row : t.rows) {
        md << "|";
        for (const std::string& cell : row) md << " " << cell << " |";
        md << "\n";
    }
    return md.str();
}

// `attributes` go into the <table> tag as they are (the caller's own text, never a user's).
inline std::string html_table(const text_table& t, const std::string& attributes = "")
{
    detail::require_shape(t);
    const auto align = [&](size_t c) { return t.align[c] == 'r' ? " class=\"num\"" : t.align[c] == 'c' ? " class=\"mid\"" : ""; };
    std::ostringstream html;
    html << "<table" << (attributes.empty() ? "" : " " + attributes) << ">\n<thead><tr>";
    for (size_t c = 0; c < t.head.size(); ++c) html << "<th" << align(c) << ">" << html_from_markdown(t.head[c]) << "</th>";
    html << "</tr></thead>\n<tbody>\n";
    for (const auto& row : t.rows) {
        html << "<tr>";
        for (size_t c = 0; c < row.size(); ++c) html << "<td" << align(c) << ">" << html_from_markdown(row[c]) << "</td>";
        html << "</tr>\n";
    }
    html << "</tbody>\n</table>\n";
    return html.str();
}

// Lines of the report's Markdown as an HTML list (`attributes` as html_table's).
inline std::string html_list(const std::vector<std::string>& lines, const std::string& attributes = "")
{
    std::string html = "<ul" + (attributes.empty() ? "" : " " + attributes) + ">\n";
    for (const std::string& line : lines) html += "<li>" + html_from_markdown(line) + "</li>\n";
    return html + "</ul>\n";
}

} // namespace aogen_report
