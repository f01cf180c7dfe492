// aogen_report/html_text.hpp — text made safe for an HTML page or an SVG image, and
// the report's few Markdown marks turned into HTML.
//
//     aogen_report::html_escape("<script>")                // "&lt;script&gt;"
//     aogen_report::html_from_markdown("*Default*: `x`")  // "<em>Default</em>: <code>x</code>"
//     aogen_report::base64(png_bytes)                     // for a data: URI
//
// Every piece of user text the pages show (scene names, paths, the command) goes through
// html_escape, so a scene named "<script>" is shown as text and never run. The report's
// paragraphs are written once, in Markdown (report.md), and shown in the page through
// html_from_markdown, which knows exactly the marks they use: **strong**, *emphasis* and
// `code`; everything else is escaped.
#pragma once

#include <algorithm>
#include <cstdint>
#include <string>

namespace aogen_report {

// `text` with & < > " ' as character references: safe in element content and in quoted
// attribute values, of HTML and of SVG (XML) alike.
inline std::string html_escape(const std::string& text)
{
    std::string out;
    out.reserve(text.size());
    for (char c : text) switch (c) {
        case '&': out += "&amp;"; break;
        case '<': out += "&lt;"; break;
        case '>': out += "&gt;"; break;
        case '"': out += "&quot;"; break;
        case '\'': out += "&#39;"; break;
        default: out += c;
        }
    return out;
}

// A line of the report's Markdown as HTML: `code`, **strong** and *emphasis* (not nested
// inside code). As in CommonMark, a mark opens only before a non-space and closes only
// after one ("ao^p * 2" keeps its star); an unpaired mark is kept as the character it is.
inline std::string html_from_markdown(const std::string& markdown)
{
    const auto is_space = [&](size_t at) { return at >= markdown.size() || markdown[at] == ' '; };
    // The first closing `mark` after `from`: preceded by a non-space.
    const auto closing = [&](const std::string& mark, size_t from) {
        for (size_t at = markdown.find(mark, from); at != std::string::npos; at = markdown.find(mark, at + 1))
            if (!is_space(at - 1)) return at;
        return std::string::npos;
    };
    std::string out;
    size_t i = 0;
    while (i < markdown.size()) {
        const char c = markdown[i];
        const bool strong = markdown.compare(i, 2, "**") == 0;
        const std::string mark = c == '`' ? "`" : strong ? "**" : c == '*' ? "*" : "";
        const bool opens = !mark.empty() && (c == '`' || !is_space(i + mark.size()));
        const size_t end = opens ? (c == '`' ? markdown.find(mark, i + 1) : closing(mark, i + mark.size() + 1)) : std::string::npos;
        if (end == std::string::npos || end == i + mark.size()) {
            out += html_escape(std::string(1, c));
            ++i;
            continue;
        }
        const std::string inner = markdown.substr(i + mark.size(), end - i - mark.size());
        const char* tag = c == '`' ? "code" : strong ? "strong" : "em";
        out += std::string("<") + tag + ">" + (c == '`' ? html_escape(inner) : html_from_markdown(inner)) + "</" + tag + ">";
        i = end + mark.size();
    }
    return out;
}

// `bytes` in base64 (RFC 4648, padded), as a data: URI carries them.
inline std::string base64(const std::string& bytes)
{
    static const char digits[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string out;
    out.reserve((bytes.size() + 2) / 3 * 4);
    for (size_t i = 0; i < bytes.size(); i += 3) {
        const size_t n = std::min<size_t>(3, bytes.size() - i);
        uint32_t group = 0;
        for (size_t k = 0; k < 3; ++k) group = group << 8 | (k < n ? uint8_t(bytes[i + k]) : 0u);
        for (size_t k = 0; k < 4; ++k) out += k <= n ? digits[(group >> (18 - 6 * k)) & 63] : '=';
    }
    return out;
}

} // namespace aogen_report
