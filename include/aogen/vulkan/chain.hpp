// aogen/vulkan/chain.hpp — runs one variant's chain (AO → blur passes) on a G-buffer.
//
// WHAT
//   chain compiles every pass of a variant into a pipeline once (passes.hpp: compute
//   pipelines, or fullscreen-triangle graphics pipelines for fragment variants); run()
//   uploads a G-buffer, the kernel and noise tile the params name and the std140 uniform
//   bytes of uniforms::pack_*, runs each pass in order — pass i writes its own AO image,
//   pass i + 1 samples it — and reads the last AO image back as floats, with each pass's
//   GPU time from timestamp queries around it. Compute and fragment variants share
//   everything but the pipelines and how a pass is recorded (a dispatch, or a draw into
//   a colour attachment), so both give the same AO for the same axes.
//
//   Inputs: depth as raw depth-buffer values in an R32_SFLOAT colour image (the default)
//   or a D32_SFLOAT depth image sampled through its depth aspect (run_options::depth;
//   shaders read .r either way and the AO is bit-identical; D32 holds only [0, 1], so
//   other values are an error there); normals as RGBA32F (xyz; ignored by
//   reconstructed-normal variants); the noise tile as RGBA32F.
//   Between passes and at the end, the AO is an R8_UNORM image of the AO target size:
//   the G-buffer's size, or ((w + 1) / 2, (h + 1) / 2) at half resolution (a storage
//   image for compute, a colour attachment for fragment). run_options::clear fills every
//   AO image before the passes; running with two clear values and comparing shows that
//   every pixel was written.
//
// USAGE
//     aogen::vulkan::context ctx({true});
//     aogen::variant v;                                   // ssao-s16-half-bilateral-...
//     aogen::vulkan::chain c(ctx, v);                     // any stage: compute or fragment
//     aogen::vulkan::gbuffer g{w, h, depth, normals};     // row-major, top row first
//     aogen::vulkan::chain_settings s;                    // params + camera
//     aogen::vulkan::chain_result r = c.run(g, s);        // r.ao (r.width × r.height), r.pass_ms
//     aogen::vulkan::run_options o;
//     o.depth = aogen::vulkan::depth_format::d32_sfloat;  // depth through a depth image
//     r = c.run(g, s, o);
//   See timing.hpp for the median of K runs.
//
// ERRORS
//   aogen::error: G-buffer sizes that do not match, depth outside [0, 1] for D32_SFLOAT, a
//   compile error, a fragment variant on a device without a graphics queue, a failing
//   Vulkan call.
#pragma once

#include "../kernel.hpp"
#include "../noise.hpp"
#include "../uniforms.hpp"
#include "device.hpp"
#include "passes.hpp"
#include "resources.hpp"

#include <algorithm>
#include <array>
#include <string>
#include <vector>

namespace aogen::vulkan {

struct gbuffer {
    int width = 0, height = 0;
    std::vector<float> depth;   // width × height raw depth values
    std::vector<float> normals; // width × height × 4 (xyz used); may be empty for reconstructed normals
};

struct chain_settings {
    ssao_params ssao;   // ssao.samples is taken from the variant
    gtao_params gtao;
    blur_params blur;
    uniforms::camera camera;
};

struct chain_result {
    int width = 0, height = 0;
    std::vector<float> ao;           // width × height, the last pass's output
    std::vector<std::string> passes; // "ao", "blur_x", ...
    std::vector<double> pass_ms;     // GPU time of each pass; empty without timestamps
};

// The image the depth buffer is uploaded to.
enum class depth_format {
    r32_sfloat, // a colour image of floats (any value, NaN included)
    d32_sfloat, // a depth image, as a renderer's depth buffer is (values in [0, 1])
};
inline constexpr std::array<enum_name<depth_format>, 2> depth_format_names{{
    {depth_format::r32_sfloat, "r32_sfloat"},
    {depth_format::d32_sfloat, "d32_sfloat"},
}};

struct run_options {
    float clear = 0.0f;                             // value every AO image holds before its pass writes it
    depth_format depth = depth_format::r32_sfloat;  // how the depth buffer reaches the shaders
};

// The AO target size of `v` for a G-buffer of w × h.
inline std::pair<int, int> target_size(const variant& v, int w, int h)
{
    return v.half_resolution ? std::pair<int, int>{(w + 1) / 2, (h + 1) / 2} : std::pair<int, int>{w, h};
}

class chain {
public:
    chain(context& ctx, const variant& v) : ctx_(ctx), v_(v), passes_(ctx, v) {}

    const variant& var() const { return v_; }

    chain_result run(const gbuffer& g, const chain_settings& s, const run_options& o = {})
    {
        check_inputs(g, o);
        const auto [TW, TH] = target_size(v_, g.width, g.height);
        resource_scope sc(ctx_);
        VkCommandBuffer cb = sc.begin_commands();
        const timestamps ts = make_timestamps(sc, cb);
        const inputs in = upload_inputs(sc, cb, g, s, o);
        const std::vector<image> outputs = make_outputs(sc, cb, TW, TH, o.clear);
        const std::vector<VkDescriptorSet> sets = write_sets(sc, s, in, outputs, vec2{float(TW), float(TH)});

        // Pass i writes outputs[i]; pass i + 1 samples it. Both of a pass's timestamps wait
        // for everything recorded before them (BOTTOM_OF_PIPE): a TOP_OF_PIPE start may be
        // written while the uploads or the previous pass still run, and a GPU then charges
        // that overlap to this pass. So the intervals follow one another and sum to the chain.
        const output_use use = passes_.output();
        for (size_t i = 0; i < passes_.size(); ++i) {
            if (i > 0)
                barrier(cb, outputs[i - 1], use.layout, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL, use.access, VK_ACCESS_SHADER_READ_BIT, use.stage,
                        passes_.reader_stage());
            if (ts.pool) vkCmdWriteTimestamp(cb, VK_PIPELINE_STAGE_BOTTOM_OF_PIPE_BIT, ts.pool, static_cast<uint32_t>(2 * i));
            passes_.record(sc, cb, i, sets[i], outputs[i], TW, TH);
            if (ts.pool) vkCmdWriteTimestamp(cb, VK_PIPELINE_STAGE_BOTTOM_OF_PIPE_BIT, ts.pool, static_cast<uint32_t>(2 * i + 1));
        }
        barrier(cb, outputs.back(), use.layout, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, use.access, VK_ACCESS_TRANSFER_READ_BIT, use.stage,
                VK_PIPELINE_STAGE_TRANSFER_BIT);
        const buffer readback = sc.read_back(cb, outputs.back(), TW, TH, 1);
        sc.submit(cb);

        chain_result out;
        out.width = TW;
        out.height = TH;
        out.ao.resize(static_cast<size_t>(TW) * TH);
        const auto* px = static_cast<const uint8_t*>(readback.mapped);
        for (size_t i = 0; i < out.ao.size(); ++i) out.ao[i] = px[i] / 255.0f;
        for (size_t i = 0; i < passes_.size(); ++i) out.passes.push_back(names::name_of(pass_kind_names, passes_[i].kind, "pass"));
        out.pass_ms = read_times(ts);
        return out;
    }

private:
    // The uploaded inputs every pass samples, and the samplers they are read through.
    struct inputs {
        image depth, normals, noise;
        VkSampler clamp = VK_NULL_HANDLE, repeat = VK_NULL_HANDLE;
        std::vector<vec4> kernel; // ssao only
        ssao_params ssao;         // the settings' with the variant's sample count
        int noise_size = 4;
    };
    struct timestamps {
        VkQueryPool pool = VK_NULL_HANDLE; // null without timestamps on this queue
        uint32_t count = 0;
    };

    void check_inputs(const gbuffer& g, const run_options& o) const
    {
        const int W = g.width, H = g.height;
        if (W < 1 || H < 1 || g.depth.size() != static_cast<size_t>(W) * H)
            throw error("vulkan chain: depth of " + std::to_string(g.depth.size()) + " values for " + std::to_string(W) + "x" +
                        std::to_string(H) + " (valid: width × height values, both >= 1)");
        if (v_.normals != normal_source::reconstructed && g.normals.size() != static_cast<size_t>(W) * H * 4)
            throw error("vulkan chain: normals of " + std::to_string(g.normals.size()) + " values (valid: width × height × 4)");
        names::require_listed(depth_format_names, o.depth, "vulkan chain depth format");
        // A copy into D32_SFLOAT of a value outside [0, 1] is undefined in Vulkan; say so instead.
        if (o.depth == depth_format::d32_sfloat)
            for (size_t i = 0; i < g.depth.size(); ++i)
                if (!(g.depth[i] >= 0.0f && g.depth[i] <= 1.0f))
                    throw error("vulkan chain: depth " + std::to_string(g.depth[i]) + " at pixel (" + std::to_string(i % W) + ", " +
                                std::to_string(i / W) + ") cannot be stored in D32_SFLOAT (valid: [0, 1], or depth_format::r32_sfloat)");
    }

    timestamps make_timestamps(resource_scope& sc, VkCommandBuffer cb) const
    {
        timestamps t;
        if (ctx_.timestamp_valid_bits() == 0) return t;
        VkDevice d = ctx_.device();
        t.count = static_cast<uint32_t>(passes_.size() * 2);
        VkQueryPoolCreateInfo qpi{VK_STRUCTURE_TYPE_QUERY_POOL_CREATE_INFO};
        qpi.queryType = VK_QUERY_TYPE_TIMESTAMP;
        qpi.queryCount = t.count;
        check(vkCreateQueryPool(d, &qpi, nullptr, &t.pool), "vkCreateQueryPool");
        sc.own(t.pool, vkDestroyQueryPool);
        vkCmdResetQueryPool(cb, t.pool, 0, t.count);
        return t;
    }

    // Milliseconds between each pass's pair of timestamps (after submit).
    std::vector<double> read_times(const timestamps& t) const
    {
        std::vector<double> ms;
        if (!t.pool) return ms;
        std::vector<uint64_t> ticks(t.count);
        check(vkGetQueryPoolResults(ctx_.device(), t.pool, 0, t.count, ticks.size() * 8, ticks.data(), 8,
                                    VK_QUERY_RESULT_64_BIT | VK_QUERY_RESULT_WAIT_BIT),
              "vkGetQueryPoolResults");
        const uint64_t mask = ctx_.timestamp_valid_bits() >= 64 ? ~0ull : (1ull << ctx_.timestamp_valid_bits()) - 1;
        for (size_t i = 0; i < passes_.size(); ++i)
            ms.push_back(double((ticks[2 * i + 1] - ticks[2 * i]) & mask) * ctx_.timestamp_period_ns() * 1e-6);
        return ms;
    }

    inputs upload_inputs(resource_scope& sc, VkCommandBuffer cb, const gbuffer& g, const chain_settings& s, const run_options& o) const
    {
        inputs in;
        in.ssao = s.ssao;
        in.ssao.samples = v_.ssao_samples;
        in.noise_size = v_.tech == technique::gtao ? 4 : in.ssao.noise_size;
        if (v_.tech == technique::ssao)
            in.kernel = kernel::generate(kernel::distribution_from_name(in.ssao.kernel), in.ssao.samples, in.ssao.kernel_seed);
        const std::vector<uint8_t> noise_bytes = noise::encode(noise::rotations(in.noise_size, in.ssao.noise_seed), noise::encoding::rgba32f);
        in.clamp = sc.make_sampler(VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE);
        in.repeat = sc.make_sampler(VK_SAMPLER_ADDRESS_MODE_REPEAT);
        const VkPipelineStageFlags readers = passes_.reader_stage();
        const VkFormat depth_vk = o.depth == depth_format::d32_sfloat ? VK_FORMAT_D32_SFLOAT : VK_FORMAT_R32_SFLOAT;
        in.depth = sc.upload(cb, g.width, g.height, depth_vk, g.depth.data(), g.depth.size() * 4, readers);
        if (v_.normals != normal_source::reconstructed)
            in.normals = sc.upload(cb, g.width, g.height, VK_FORMAT_R32G32B32A32_SFLOAT, g.normals.data(), g.normals.size() * 4, readers);
        in.noise = sc.upload(cb, in.noise_size, in.noise_size, VK_FORMAT_R32G32B32A32_SFLOAT, noise_bytes.data(), noise_bytes.size(), readers);
        return in;
    }

    // One AO image per pass, cleared to `clear`, in the layout its pass writes it in.
    std::vector<image> make_outputs(resource_scope& sc, VkCommandBuffer cb, int w, int h, float clear) const
    {
        const output_use use = passes_.output();
        std::vector<image> outputs;
        for (size_t i = 0; i < passes_.size(); ++i) {
            outputs.push_back(sc.make_image(w, h, ao_format,
                                            use.usage | VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT));
            resource_scope::clear(cb, outputs.back(), clear);
            barrier(cb, outputs.back(), VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, use.layout, VK_ACCESS_TRANSFER_WRITE_BIT, use.access,
                    VK_PIPELINE_STAGE_TRANSFER_BIT, use.stage);
        }
        return outputs;
    }

    // The std140 bytes of a pass's uniform block.
    std::vector<uint8_t> uniform_bytes(pass_kind pass, const chain_settings& s, const inputs& in, vec2 tsize) const
    {
        constexpr layout::rules rules = layout::rules::std140;
        if (pass != pass_kind::ao) return uniforms::pack_blur(s.blur, s.camera.proj, tsize, rules);
        if (v_.tech == technique::gtao) return uniforms::pack_gtao(s.gtao, s.camera, tsize, rules, in.noise_size);
        return uniforms::pack_ssao(in.ssao, s.camera, in.kernel, tsize, rules);
    }

    VkDescriptorPool make_descriptor_pool(resource_scope& sc) const
    {
        std::vector<VkDescriptorPoolSize> sizes;
        for (size_t i = 0; i < passes_.size(); ++i)
            for (const codegen::resource& r : passes_[i].resources) {
                const VkDescriptorType t = descriptor_type(r.kind);
                auto it = std::find_if(sizes.begin(), sizes.end(), [t](const VkDescriptorPoolSize& p) { return p.type == t; });
                if (it == sizes.end()) sizes.push_back({t, 1});
                else ++it->descriptorCount;
            }
        VkDescriptorPoolCreateInfo dpi{VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO};
        dpi.maxSets = static_cast<uint32_t>(passes_.size());
        dpi.poolSizeCount = static_cast<uint32_t>(sizes.size());
        dpi.pPoolSizes = sizes.data();
        VkDevice d = ctx_.device();
        VkDescriptorPool pool;
        check(vkCreateDescriptorPool(d, &dpi, nullptr, &pool), "vkCreateDescriptorPool");
        return sc.own(pool, vkDestroyDescriptorPool);
    }

    // The image (and sampler) a sampled resource of pass `i` reads.
    static VkDescriptorImageInfo sampled(const codegen::resource& r, size_t i, const inputs& in, const std::vector<image>& outputs)
    {
        const VkImageLayout read = VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL;
        if (r.name == "depth") return {in.clamp, in.depth.view, read};
        if (r.name == "normals") return {in.clamp, in.normals.view, read};
        if (r.name == "noise") return {in.repeat, in.noise.view, read};
        if (r.name == "ao_input" && i > 0) return {in.clamp, outputs[i - 1].view, read};
        throw error("vulkan chain: unknown sampled resource '" + r.name + "' (valid: depth, normals, noise, ao_input)");
    }

    // One descriptor set per pass, every binding of its resources written.
    std::vector<VkDescriptorSet> write_sets(resource_scope& sc, const chain_settings& s, const inputs& in, const std::vector<image>& outputs,
                                            vec2 tsize) const
    {
        VkDevice d = ctx_.device();
        const VkDescriptorPool pool = make_descriptor_pool(sc);
        std::vector<VkDescriptorSet> sets(passes_.size());
        for (size_t i = 0; i < passes_.size(); ++i) {
            const pass_pipeline& p = passes_[i];
            VkDescriptorSetAllocateInfo dai{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO};
            dai.descriptorPool = pool;
            dai.descriptorSetCount = 1;
            dai.pSetLayouts = &p.set_layout;
            check(vkAllocateDescriptorSets(d, &dai, &sets[i]), "vkAllocateDescriptorSets");
            // Sized up front: the writes point into these vectors.
            std::vector<VkDescriptorBufferInfo> bufs(p.resources.size());
            std::vector<VkDescriptorImageInfo> imgs(p.resources.size());
            std::vector<VkWriteDescriptorSet> writes;
            for (size_t k = 0; k < p.resources.size(); ++k) {
                const codegen::resource& r = p.resources[k];
                VkWriteDescriptorSet w{VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET};
                w.dstSet = sets[i];
                w.dstBinding = r.binding;
                w.descriptorCount = 1;
                w.descriptorType = descriptor_type(r.kind);
                if (r.kind == codegen::resource_kind::uniform_buffer) {
                    const std::vector<uint8_t> bytes = uniform_bytes(p.kind, s, in, tsize);
                    bufs[k] = {sc.make_buffer(bytes.data(), bytes.size(), VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT).handle, 0, bytes.size()};
                    w.pBufferInfo = &bufs[k];
                } else {
                    imgs[k] = r.kind == codegen::resource_kind::storage_image
                                  ? VkDescriptorImageInfo{VK_NULL_HANDLE, outputs[i].view, VK_IMAGE_LAYOUT_GENERAL}
                                  : sampled(r, i, in, outputs);
                    w.pImageInfo = &imgs[k];
                }
                writes.push_back(w);
            }
            vkUpdateDescriptorSets(d, static_cast<uint32_t>(writes.size()), writes.data(), 0, nullptr);
        }
        return sets;
    }

    context& ctx_;
    variant v_;
    pass_pipelines passes_;
};

} // namespace aogen::vulkan
