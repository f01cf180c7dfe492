// aogen_report/arguments.hpp — command-line values the report's programs share (aogen_report,
// aogen_tune): comma-separated lists, sizes, ray counts, and scene lists.
//
//     comma_list("a,,b")             // {"a", "b"}
//     parse_size("320x180", w, h);   // aogen::error naming --size unless each is 8..4096
//     grid_for_rays(4096);           // 64; aogen::error naming --rays unless grid² with an even grid of 32..256
//     load_scenes("crease,my.json"); // built-in names or scene files; "" every built-in scene but the motion-only ones
//     load_motion_scenes("");        // the scenes with a camera path (the report in motion)
//     parse_history("blend=0.05,clamp=range,range=0.1");   // history_params; aogen::error naming --history
#pragma once

#include <aogen/params.hpp>
#include <aogen/variant.hpp>
#include <aogen_scenes/scene.hpp>

#include <algorithm>
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

// The history pass's settings from "key=value,..." over the defaults: blend, clamp (none,
// range, min_max, variance), range, widening, gamma, depth_tolerance. Each value is checked
// by history_params' own ranges; an unknown key or a value that is no number is refused by
// name.
inline aogen::history_params parse_history(const std::string& text)
{
    aogen::history_params h;
    const std::string keys = "blend, clamp, range, widening, gamma, depth_tolerance";
    for (const std::string& item : comma_list(text)) {
        const size_t eq = item.find('=');
        const std::string key = item.substr(0, eq), value = eq == std::string::npos ? "" : item.substr(eq + 1);
        if (eq == std::string::npos || value.empty()) aogen::fail("--history", aogen::quote(item) + " is not key=value", "valid: " + keys + ", e.g. blend=0.1");
        if (key == "clamp") {
            h.clamp = aogen::names::value_of(aogen::history_clamp_names, value, "--history clamp");
            continue;
        }
        float* field = key == "blend" ? &h.blend : key == "range" ? &h.range : key == "widening" ? &h.min_max_widening
                     : key == "gamma" ? &h.variance_gamma : key == "depth_tolerance" ? &h.depth_tolerance : nullptr;
        if (!field) aogen::fail("--history", aogen::quote(key) + " is not a setting of the history pass", "valid: " + keys);
        size_t used = 0;
        try {
            *field = std::stof(value, &used);
        } catch (const std::exception&) {
            used = 0;
        }
        if (used != value.size()) aogen::fail("--history " + key, aogen::quote(value) + " is not a number", "valid: a decimal number");
    }
    aogen::validate(h, "--history");
    return h;
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
// Built-in scenes made for the report in motion (motion.hpp) alone: by default their frame 0 is
// not scored still -- rolling_sphere's floor, wall and sphere are crease's and
// sphere_on_plane's -- which keeps the default report within 1.25 × its time before the
// report in motion (BENCHMARKS.md § 2026-12-07 (session 7)). Named in --scenes, they are.
inline const std::vector<std::string>& motion_only_scenes()
{
    static const std::vector<std::string> names{"rolling_sphere"};
    return names;
}

// Built-in names or scene files, comma-separated; "": every built-in scene but the
// motion-only ones.
inline std::vector<aogen::scenes::scene> load_scenes(const std::string& list)
{
    std::vector<aogen::scenes::scene> out;
    std::vector<std::string> items = list.empty() ? aogen::scenes::builtin_scene_names() : comma_list(list);
    if (list.empty())
        for (const std::string& m : motion_only_scenes()) items.erase(std::remove(items.begin(), items.end(), m), items.end());
    for (const std::string& item : items) out.push_back(ends_with(item, ".json") ? aogen::scenes::load_scene(item) : aogen::scenes::builtin_scene(item));
    return out;
}

// The scenes the report runs in motion: of `list` (as load_scenes reads it), those with a
// camera path; "": every built-in scene with one, the motion-only ones included.
inline std::vector<aogen::scenes::scene> load_motion_scenes(const std::string& list)
{
    std::vector<aogen::scenes::scene> out;
    for (const std::string& item : list.empty() ? aogen::scenes::builtin_scene_names() : comma_list(list)) {
        aogen::scenes::scene s = ends_with(item, ".json") ? aogen::scenes::load_scene(item) : aogen::scenes::builtin_scene(item);
        if (aogen::scenes::frame_count(s) > 1) out.push_back(std::move(s));
    }
    return out;
}

} // namespace aogen_report
