// aogen_report/arguments.hpp — command-line values the report's programs share (aogen_report,
// aogen_tune): comma-separated lists, sizes, ray counts, and scene lists.
//
//     comma_list("a,,b")             // {"a", "b"}
//     parse_size("320x180", w, h);   // aogen::error naming --size unless each is 8..4096
//     grid_for_rays(4096);           // 64; aogen::error naming --rays unless grid² with an even grid of 32..256
//     load_scenes("crease,my.json"); // built-in names or scene files; "" every built-in scene
#pragma once

#include <aogen/variant.hpp>
#include <aogen_scenes/scene.hpp>

#include <string>
#include <vector>

namespace aogen_report {

inline std::vector<std::string> comma_list(const std::string& text)
{
    std::vector<std::string> out;
    for (const std::string& item : aogen::detail::split(text, ','))
        if (!item.empty()) out.push_back(item);
    return out;
}

inline bool ends_with(const std::string& s, const std::string& suffix)
{
    return s.size() >= suffix.size() && s.compare(s.size() - suffix.size(), suffix.size(), suffix) == 0;
}

inline void parse_size(const std::string& text, int& width, int& height)
{
    const std::vector<std::string> parts = aogen::detail::split(text, 'x');
    const auto number = [&](const std::string& s) {
        if (s.empty() || s.size() > 5 || s.find_first_not_of("0123456789") != std::string::npos) return -1;
        return std::stoi(s);
    };
    width = parts.size() == 2 ? number(parts[0]) : -1;
    height = parts.size() == 2 ? number(parts[1]) : -1;
    if (width < 8 || height < 8 || width > 4096 || height > 4096)
        aogen::fail("--size", aogen::quote(text) + " is not a size", "valid: WIDTHxHEIGHT, each 8..4096, e.g. 320x180");
}

// Rays per pixel = grid², grid even (stratum pairs) and >= 32: at least 1024 rays.
inline int grid_for_rays(int rays)
{
    for (int g = 32; g <= 256; g += 2)
        if (g * g == rays) return g;
    aogen::fail("--rays", std::to_string(rays) + " is not a valid ray count", "valid: the square of an even number from 32 to 256: 1024, 1156, ..., 4096, ..., 65536");
}

// Built-in names or scene JSON files; empty: every built-in scene.
inline std::vector<aogen::scenes::scene> load_scenes(const std::string& list)
{
    std::vector<aogen::scenes::scene> out;
    const std::vector<std::string> items = list.empty() ? aogen::scenes::builtin_scene_names() : comma_list(list);
    for (const std::string& item : items) out.push_back(ends_with(item, ".json") ? aogen::scenes::load_scene(item) : aogen::scenes::builtin_scene(item));
    return out;
}

} // namespace aogen_report
