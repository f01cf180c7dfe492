// aogen/depth_mips.hpp — the depth MIP chain a variant's prefilter pass builds: how many
// levels, how big each is, where each lies in the one image that holds them, and which level
// a tap reads.
//
// WHAT
//   A variant with depth_mips = N > 1 (variant.hpp; name token mipN) starts with a prefilter
//   pass (templates/prefilter.glsl) that reduces the depth buffer to levels 1 .. N - 1, each
//   half the size of the one before (rounded up), and the AO pass reads a tap's depth from the
//   level its distance from the pixel calls for: far taps read a coarse level, whose texels
//   lie close together in memory, where at full resolution they were scattered over the
//   screen and missed every cache (XeGTAO's depth MIP chain, Jimenez et al. 2016 §5).
//     level_size(w, h, L)      level L of a w × h depth buffer: ceil(w / 2^L) × ceil(h / 2^L)
//     level_origin(w, h, L)    where level L (>= 1) starts in the atlas
//     atlas_size(w, h, N)      the atlas: the one r32f image holding levels 1 .. N - 1
//     level_for(offset)        the level a tap `offset` full-resolution pixels away reads
//   Level 0 is the depth buffer itself: the AO pass reads it there, and the prefilter copies
//   nothing.
//
//   The atlas (levels 1 .. 4 of a 1920 × 1080 buffer: 960 × 540, 480 × 270, 240 × 135,
//   120 × 68):
//       +-----------------+--------+
//       |                 |   2    |
//       |        1        +----+---+
//       |                 | 3  |
//       |                 +--+-+
//       |                 |4 |
//       +-----------------+--+
//   level 1 at (0, 0), level L >= 2 at (width of level 1, the heights of levels 2 .. L - 1).
//
// WHAT A TEXEL HOLDS (templates/prefilter.glsl)
//   Raw depth, in the variant's convention, as the depth buffer: raw depth is affine in screen
//   space over a plane in every convention (depth.glsl's ao_depth_at), so the mean of a plane's
//   four texels is the plane's depth at their common centre, and the bilinear mix of four
//   level-L texels is the plane's depth under a tap exactly as at level 0 — what issue 11's
//   far floors need. Four texels that are not one plane (a silhouette, background among them)
//   give the one nearest the camera instead: a real surface point, never a point between two
//   surfaces that would read as an occluder.
//   Why 32-bit: a 16-bit float of raw depth has 11 significant bits, and standard depth puts
//   everything past a few near planes' distance into [0.99, 1), where a half cannot tell 1 m
//   from 100 m; 16 bits of view-space z would do, but z is not affine over a plane, and taps
//   on a far floor would read points above it as occluders again.
//
// WHICH LEVEL
//   level_for(offset) = clamp(floor(log2(offset) - level_offset), 0, N - 1): a tap reads a
//   level whose texels are about 1 / 2^level_offset of its distance apart (level_offset 3.3,
//   XeGTAO's DepthMIPSamplingOffset: texels a tenth of the distance), so the error a coarse
//   texel adds is a tenth of what the tap's own spacing already leaves out.
//
// USAGE
//     auto [aw, ah] = aogen::depth_mips::atlas_size(1920, 1080, 5);       // 1440 × 540
//     auto [x, y] = aogen::depth_mips::level_origin(1920, 1080, 3);     // 960, 270
#pragma once

#include "range.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

namespace aogen::depth_mips {

// The level counts a variant may take, level 0 (the depth buffer) included: 1 is no chain.
inline constexpr int_range levels_range{1, 5};

// log2 of the distance, in full-resolution pixels, below which a tap reads level 0 (WHICH LEVEL).
inline constexpr float level_offset = 3.3f;

// The prefilter's workgroup: 8 × 8 invocations, each reducing a 2 × 2 block of the depth
// buffer, so that one group holds a 16 × 16 block and reduces it to level 4 in shared memory.
inline constexpr int workgroup_side = 8;
inline constexpr int pixels_per_invocation = 2;

// Level `level` of a w × h depth buffer: each texel covers 2^level × 2^level pixels, the last
// row and column fewer; at least 1 × 1.
inline std::pair<int, int> level_size(int w, int h, int level)
{
    const int k = 1 << level;
    return {std::max(1, (w + k - 1) / k), std::max(1, (h + k - 1) / k)};
}

// Where level `level` >= 1 starts in the atlas (the picture above).
inline std::pair<int, int> level_origin(int w, int h, int level)
{
    if (level <= 1) return {0, 0};
    int y = 0;
    for (int k = 2; k < level; ++k) y += level_size(w, h, k).second;
    return {level_size(w, h, 1).first, y};
}

// The atlas holding levels 1 .. levels - 1 of a w × h depth buffer; 0 × 0 for one level.
inline std::pair<int, int> atlas_size(int w, int h, int levels)
{
    if (levels <= 1) return {0, 0};
    const auto [w1, h1] = level_size(w, h, 1);
    if (levels == 2) return {w1, h1};
    int column = 0;
    for (int k = 2; k < levels; ++k) column += level_size(w, h, k).second;
    return {w1 + level_size(w, h, 2).first, std::max(h1, column)};
}

// The level a tap `offset` full-resolution pixels from the pixel reads, of `levels`.
inline int level_for(float offset, int levels)
{
    const float l = std::floor(std::log2(std::max(offset, 1.0f)) - level_offset);
    return std::clamp(static_cast<int>(std::max(l, 0.0f)), 0, levels - 1);
}

} // namespace aogen::depth_mips
