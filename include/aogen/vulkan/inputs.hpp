// aogen/vulkan/inputs.hpp — what a chain reads: a G-buffer (on the host, and uploaded once
// into device-local images) and the per-chain inputs (uniform bytes per pass, noise tile).
//
// WHAT
//   gbuffer       the G-buffer on the host: raw depth values, RGBA32F normals and albedo,
//                 row-major, top row first.
//   gpu_gbuffer   that G-buffer uploaded into device-local images, once: depth as an
//                 R32_SFLOAT colour image (any float, NaN included) or a D32_SFLOAT depth
//                 image sampled through its depth aspect (values in [0, 1] only); normals
//                 and albedo as R32G32B32A32_SFLOAT, motion vectors as R32G32_SFLOAT, when
//                 the host G-buffer has them. Many bound chains
//                 (bound_chain.hpp) may read one gpu_gbuffer: the report uploads each
//                 scene's G-buffer once for every variant it runs.
//   chain_inputs  the bytes a chain's passes read besides the G-buffer: each pass's uniform
//                 block (std140, in pass order) and the noise tile as RGBA32F texels. Made by
//                 a plan's inputs(settings, w, h) (codegen/plan.hpp) — or by hand, for a caller
//                 that packs its own uniforms (a test planting a NaN does).
//
// USAGE
//     aogen::vulkan::gbuffer g{w, h, depth, normals};
//     aogen::vulkan::gpu_gbuffer uploaded(ctx, g);                          // R32_SFLOAT depth
//     aogen::vulkan::gpu_gbuffer as_d32(ctx, g, aogen::vulkan::depth_format::d32_sfloat);
//
// ERRORS
//   aogen::error: sizes that do not match (naming them), depth outside [0, 1] for
//   D32_SFLOAT (naming the pixel), a failing Vulkan call.
#pragma once

#include <aogen/chain_inputs.hpp>
#include <aogen/names.hpp>
#include "resources.hpp"

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace aogen::vulkan {

// The G-buffer and a chain's other inputs are aogen/chain_inputs.hpp's (no Vulkan in them:
// the GL runner reads the same).
using aogen::chain_inputs;
using aogen::gbuffer;

// The image the depth buffer is uploaded to.
enum class depth_format {
    r32_sfloat, // a colour image of floats (any value, NaN included)
    d32_sfloat, // a depth image, as a renderer's depth buffer is (values in [0, 1])
};
inline constexpr std::array<enum_name<depth_format>, 2> depth_format_names{{
    {depth_format::r32_sfloat, "r32_sfloat"},
    {depth_format::d32_sfloat, "d32_sfloat"},
}};


class gpu_gbuffer {
public:
    gpu_gbuffer(context& ctx, const gbuffer& g, depth_format format = depth_format::r32_sfloat)
        : scope_(ctx), width_(g.width), height_(g.height), format_(format)
    {
        check_host(g, format);
        resource_scope staging(ctx);
        VkCommandBuffer cb = staging.begin_commands();
        // Every stage that samples: compute passes, and fragment passes where the queue draws.
        VkPipelineStageFlags readers = VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT;
        if (ctx.graphics()) readers |= VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT;
        const VkFormat depth_vk = format == depth_format::d32_sfloat ? VK_FORMAT_D32_SFLOAT : VK_FORMAT_R32_SFLOAT;
        depth_ = scope_.upload(cb, g.width, g.height, depth_vk, g.depth.data(), g.depth.size() * 4, readers, staging);
        if (!g.normals.empty()) {
            normals_ = scope_.upload(cb, g.width, g.height, VK_FORMAT_R32G32B32A32_SFLOAT, g.normals.data(), g.normals.size() * 4, readers, staging);
            has_normals_ = true;
        }
        if (!g.albedo.empty()) {
            albedo_ = scope_.upload(cb, g.width, g.height, VK_FORMAT_R32G32B32A32_SFLOAT, g.albedo.data(), g.albedo.size() * 4, readers, staging);
            has_albedo_ = true;
        }
        if (!g.motion.empty()) {
            motion_ = scope_.upload(cb, g.width, g.height, VK_FORMAT_R32G32_SFLOAT, g.motion.data(), g.motion.size() * 4, readers, staging);
            has_motion_ = true;
        }
        staging.submit(cb);
    }

    int width() const { return width_; }
    int height() const { return height_; }
    depth_format format() const { return format_; }
    const image& depth() const { return depth_; }
    bool has_normals() const { return has_normals_; }
    const image& normals() const { return normals_; }
    bool has_albedo() const { return has_albedo_; }
    const image& albedo() const { return albedo_; }
    bool has_motion() const { return has_motion_; }
    const image& motion() const { return motion_; }

private:
    static void check_host(const gbuffer& g, depth_format format)
    {
        const int W = g.width, H = g.height;
        const size_t pixels = static_cast<size_t>(W < 0 ? 0 : W) * static_cast<size_t>(H < 0 ? 0 : H);
        if (W < 1 || H < 1 || g.depth.size() != pixels)
            throw error("vulkan gbuffer: depth of " + std::to_string(g.depth.size()) + " values for " + std::to_string(W) + "x" +
                        std::to_string(H) + " (valid: width × height values, both >= 1)");
        if (!g.normals.empty() && g.normals.size() != pixels * 4)
            throw error("vulkan gbuffer: normals of " + std::to_string(g.normals.size()) + " values (valid: width × height × 4, or none)");
        if (!g.albedo.empty() && g.albedo.size() != pixels * 4)
            throw error("vulkan gbuffer: albedo of " + std::to_string(g.albedo.size()) + " values (valid: width × height × 4, or none)");
        if (!g.motion.empty() && g.motion.size() != pixels * 2)
            throw error("vulkan gbuffer: motion vectors of " + std::to_string(g.motion.size()) + " values (valid: width × height × 2, or none)");
        names::require_listed(depth_format_names, format, "vulkan gbuffer depth format");
        // A copy into D32_SFLOAT of a value outside [0, 1] is undefined in Vulkan; say so instead.
        if (format == depth_format::d32_sfloat)
            for (size_t i = 0; i < g.depth.size(); ++i)
                if (!(g.depth[i] >= 0.0f && g.depth[i] <= 1.0f))
                    throw error("vulkan gbuffer: depth " + std::to_string(g.depth[i]) + " at pixel (" + std::to_string(i % W) + ", " +
                                std::to_string(i / W) + ") cannot be stored in D32_SFLOAT (valid: [0, 1], or depth_format::r32_sfloat)");
    }

    resource_scope scope_;
    int width_, height_;
    depth_format format_;
    image depth_, normals_, albedo_, motion_;
    bool has_normals_ = false, has_albedo_ = false, has_motion_ = false;
};

} // namespace aogen::vulkan
