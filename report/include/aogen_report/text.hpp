// aogen_report/text.hpp — one line of text drawn into an rgb_image: the labels of the
// report's image strips, in Debian's stb_easy_font (libstb-dev).
//
//     std::string line = aogen_report::printable("naïve");        // "na?ve": ASCII only
//     int w = aogen_report::text_width(line, 2);                    // pixels, at 2 pixels per font unit
//     int h = aogen_report::text_height(2);
//     aogen_report::draw_text(img, x, y, line, {0, 0, 0}, 2);       // (x, y): top left
//
// HOW
//   stb_easy_font builds each glyph from segments one font unit thick and returns them as
//   quads: 4 vertices of 16 bytes each (x, y, z as floats, then 4 colour bytes; x to the
//   right, y down). The text is printed at the origin, so every corner lies on a whole font
//   unit, and each quad is an axis-aligned rectangle of font units: it is filled with
//   `scale` × `scale` pixels per unit. No antialiasing, so the same text gives the same
//   pixels every time.
//
//   The font has ASCII 32–126 only and indexes its tables by (character − 32) unchecked,
//   so every other byte must never reach it: printable() replaces each control character
//   and each UTF-8 encoded character (all of its bytes) by one '?'.
//
//   The header is a single file of static functions and tables (no IMPLEMENTATION macro):
//   each translation unit that includes this header gets its own copy.
#pragma once

#include "png.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <string_view>

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wunused-function"
#include <stb_easy_font.h>
#pragma GCC diagnostic pop

namespace aogen_report {

// Every glyph, descenders included, lies in font-unit rows 0–8 of its line.
inline constexpr int glyph_height = 9;

// `text` with what the font cannot draw replaced: one '?' per control character, DEL,
// invalid byte or UTF-8 character.
inline std::string printable(std::string_view text)
{
    std::string out;
    bool in_utf8_character = false; // the last byte was a non-ASCII one
    for (const char c : text) {
        const auto byte = static_cast<unsigned char>(c);
        const bool continuation = (byte & 0xC0) == 0x80; // 10xxxxxx: the rest of a UTF-8 character
        if (byte >= 32 && byte <= 126) out += c;
        else if (!(continuation && in_utf8_character)) out += '?';
        in_utf8_character = byte >= 0x80;
    }
    return out;
}

// The line's advance in pixels (its last glyph's trailing space included).
inline int text_width(std::string_view text, int scale)
{
    std::string line = printable(text);
    return stb_easy_font_width(line.data()) * scale;
}

inline int text_height(int scale) { return glyph_height * scale; }

namespace detail {

// The quads stb_easy_font emits for `line` (printable ASCII) printed at the origin.
inline std::vector<char> glyph_quads(std::string& line)
{
    // No glyph has more than 11 segments; one quad (64 bytes) per segment, so this buffer
    // never truncates.
    constexpr int bytes_per_quad = 64, most_quads_per_glyph = 11;
    std::vector<char> buffer(line.size() * most_quads_per_glyph * bytes_per_quad);
    const int quads = stb_easy_font_print(0, 0, line.data(), nullptr, buffer.data(), int(buffer.size()));
    buffer.resize(size_t(quads) * bytes_per_quad);
    return buffer;
}

} // namespace detail

// `text` in `colour`, its top left corner at pixel (x, y), `scale` pixels per font unit.
// Pixels outside the image are left out.
inline void draw_text(rgb_image& img, int x, int y, std::string_view text, rgb colour, int scale)
{
    std::string line = printable(text);
    const std::vector<char> quads = detail::glyph_quads(line);
    constexpr size_t vertex_bytes = 16;
    for (size_t q = 0; q < quads.size(); q += 4 * vertex_bytes) {
        // The quad's corners in font units: the extremes over its 4 vertices.
        float x0 = INFINITY, y0 = INFINITY, x1 = -INFINITY, y1 = -INFINITY;
        for (size_t v = q; v < q + 4 * vertex_bytes; v += vertex_bytes) {
            float vx, vy;
            std::memcpy(&vx, &quads[v], sizeof vx);
            std::memcpy(&vy, &quads[v + 4], sizeof vy);
            x0 = std::min(x0, vx), x1 = std::max(x1, vx), y0 = std::min(y0, vy), y1 = std::max(y1, vy);
        }
        const int left = std::max(0, x + int(std::lround(x0)) * scale), right = std::min(img.width, x + int(std::lround(x1)) * scale);
        const int top = std::max(0, y + int(std::lround(y0)) * scale), bottom = std::min(img.height, y + int(std::lround(y1)) * scale);
        for (int py = top; py < bottom; ++py)
            for (int px = left; px < right; ++px) img.set(px, py, colour);
    }
}

} // namespace aogen_report
