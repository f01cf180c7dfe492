// aogen/techniques/descriptor.hpp — what a technique is to the library: one row of the table.
//
// WHAT
//   technique_desc   everything aogen does differently per AO technique, as one value: its
//                    AO pass's uniform block and bytes, its noise tile, its template files,
//                    #defines and constants, its temporal period and how it names its counts.
//                    Each technique fills one (techniques/ssao.hpp, gtao.hpp, vbao.hpp,
//                    sao.hpp) and techniques.hpp holds the table of them.
//   glsl_float, choice_define
//                    how a constant and a choice reach the templates as #defines
//
// USAGE
//     const aogen::technique_desc& t = aogen::technique_of(v.tech);  // techniques.hpp
//     t.block(v);           // the AO pass's uniform block
//     t.files(v);           // its template files between common/noise.glsl and the entry point
//
// ERRORS
//   The functions take a variant already validated (a plan's); pack validates the settings
//   it writes, as uniforms::pack_* do.
//
// WHY
//   Before the table, each of these was an `if (v.tech == …)` chain in its own file, and
//   three of them fell through to SSAO: a technique that missed one compiled and ran another
//   technique's block. A row is a struct of function pointers that must all be set:
//   techniques.hpp checks every row at compile time.
#pragma once

#include <aogen/error.hpp>
#include <aogen/layout.hpp>
#include <aogen/math.hpp>
#include <aogen/params.hpp>
#include <aogen/uniforms_common.hpp>
#include <aogen/variant.hpp>

#include <cstdint>
#include <string>
#include <vector>

namespace aogen {

// A float as a GLSL literal that reads back to the same float: the shortest round-trip
// digits, with ".0" added when they would otherwise read as an int.
inline std::string glsl_float(float value)
{
    std::string s = format_number(value);
    if (s.find_first_of(".en") == std::string::npos) s += ".0";
    return s;
}

// The #define of a choice: AO_<AXIS>_<VALUE>, the value upper-cased ("AO_OUTPUT_STRENGTH").
inline define choice_define(const char* axis, const char* value)
{
    std::string name = std::string("AO_") + axis + "_";
    for (const char* c = value; *c; ++c) name += static_cast<char>(*c >= 'a' && *c <= 'z' ? *c - 'a' + 'A' : *c);
    return {name, ""};
}

// The noise tile of a technique whose noise is a turn per pixel (GTAO, VBAO, SAO): 4 × 4
// rotations, whatever the settings say (ssao_params::noise_size is SSAO's alone).
inline int rotation_tile_size(const ao_settings&) { return 4; }

// One technique, as the library sees it (see WHAT). Every member is set.
struct technique_desc {
    technique id;
    // The AO pass's uniform block (uniforms.hpp's *_block), for `v`'s counts.
    layout::block_desc (*block)(const variant& v);
    // The block's bytes for settings `s`, into `block` (block(v) laid out: a plan's, computed
    // once): its params, the camera, the AO target's size, the frame's extras
    // (uniforms::pack_*). aogen::error on a setting out of range.
    std::vector<uint8_t> (*pack)(const variant& v, const ao_settings& s, const uniforms::camera& camera, vec2 target_size,
                                 const layout::struct_layout& block, const uniforms::extras& e);
    // The side of the noise tile the AO pass reads (SSAO's is a setting; the others' 4).
    int (*noise_size)(const ao_settings& s);
    // The AO pass's template files after common/noise.glsl, in order.
    std::vector<std::string> (*files)(const variant& v);
    // The AO pass's #defines after the technique, normals and fp16 ones: its counts and choices.
    std::vector<define> (*defines)(const variant& v);
    // The AO pass's constants from params.hpp, as (name, GLSL value).
    std::vector<define> (*constants)(const variant& v);
    // The angle, in turns, after which its samples repeat (temporal.hpp's frame rotation).
    double (*period_turns)(const variant& v);
    // What it computes per pixel, as selection.hpp lists it: "ssao: 16 samples".
    std::string (*counts_text)(const variant& v);
    // The taps one iteration of its AO pass's sample loop reads (the tap loop of
    // compile/loops.hpp): a slice step's two, one on each side; a sample's one.
    int taps_per_iteration;
};

} // namespace aogen
