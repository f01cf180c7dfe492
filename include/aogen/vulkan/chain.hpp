// aogen/vulkan/chain.hpp — runs one compute variant's chain (AO → blur passes) on a G-buffer.
//
// WHAT
//   chain compiles every pass of a compute variant (codegen::generate → compile → SPIR-V)
//   into a pipeline once; run() uploads a G-buffer, the kernel and noise tile the params
//   name and the std140 uniform bytes of uniforms::pack_*, dispatches each pass with the
//   variant's workgroup size, and reads the AO back as floats, with each pass's GPU time
//   from timestamp queries.
//
//   Inputs: depth as an R32_SFLOAT sampled image (raw depth-buffer values), normals as
//   RGBA32F (xyz; ignored by reconstructed-normal variants), the noise tile as RGBA32F.
//   Between passes and at the end, the AO is an R8_UNORM storage image of the AO target
//   size: the G-buffer's size, or ((w + 1) / 2, (h + 1) / 2) at half resolution.
//   run_options::clear fills every AO image before the passes; running with two clear
//   values and comparing shows that every pixel was written.
//
// USAGE
//     aogen::vulkan::context ctx({true});
//     aogen::variant v;                                   // ssao-s16-half-bilateral-...
//     aogen::vulkan::chain c(ctx, v);
//     aogen::vulkan::gbuffer g{w, h, depth, normals};     // row-major, top row first
//     aogen::vulkan::chain_settings s;                    // params + camera
//     aogen::vulkan::chain_result r = c.run(g, s);        // r.ao (r.width × r.height), r.pass_ms
//   See timing.hpp for the median of K runs.
//
// ERRORS
//   aogen::error: a fragment variant, G-buffer sizes that do not match, a compile error,
//   a failing Vulkan call.
#pragma once

#include "../codegen.hpp"
#include "../compile.hpp"
#include "../kernel.hpp"
#include "../noise.hpp"
#include "../uniforms.hpp"
#include "device.hpp"

#include <cstring>
#include <functional>
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

struct run_options {
    float clear = 0.0f; // value every AO image holds before its pass writes it
};

// The AO target size of `v` for a G-buffer of w × h.
inline std::pair<int, int> target_size(const variant& v, int w, int h)
{
    return v.half_resolution ? std::pair<int, int>{(w + 1) / 2, (h + 1) / 2} : std::pair<int, int>{w, h};
}

class chain {
public:
    chain(context& ctx, const variant& v) : ctx_(ctx), v_(v)
    {
        if (v.stage != pipeline_stage::compute) throw error("vulkan chain: variant " + to_name(v) + " is not a compute variant (valid: stage compute)");
        VkDevice d = ctx.device();
        try {
            for (const codegen::shader_source& s : codegen::generate(v)) {
                pass p;
                p.kind = s.pass;
                p.resources = s.resources;
                compile::compiled c = compile::compile(s.glsl, s.stage, s.name, {compile::target::spv});
                VkShaderModuleCreateInfo smi{VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO};
                smi.codeSize = c.spirv.size() * 4;
                smi.pCode = c.spirv.data();
                check(vkCreateShaderModule(d, &smi, nullptr, &p.module), "vkCreateShaderModule");
                passes_.push_back(p);
                pass& q = passes_.back();
                std::vector<VkDescriptorSetLayoutBinding> lb;
                for (const codegen::resource& r : s.resources) lb.push_back({r.binding, descriptor_type(r.kind), 1, VK_SHADER_STAGE_COMPUTE_BIT, nullptr});
                VkDescriptorSetLayoutCreateInfo dli{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO};
                dli.bindingCount = static_cast<uint32_t>(lb.size());
                dli.pBindings = lb.data();
                check(vkCreateDescriptorSetLayout(d, &dli, nullptr, &q.set_layout), "vkCreateDescriptorSetLayout");
                VkPipelineLayoutCreateInfo pli{VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO};
                pli.setLayoutCount = 1;
                pli.pSetLayouts = &q.set_layout;
                check(vkCreatePipelineLayout(d, &pli, nullptr, &q.layout), "vkCreatePipelineLayout");
                VkComputePipelineCreateInfo cpi{VK_STRUCTURE_TYPE_COMPUTE_PIPELINE_CREATE_INFO};
                cpi.stage = {VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO};
                cpi.stage.stage = VK_SHADER_STAGE_COMPUTE_BIT;
                cpi.stage.module = q.module;
                cpi.stage.pName = "main";
                cpi.layout = q.layout;
                check(vkCreateComputePipelines(d, VK_NULL_HANDLE, 1, &cpi, nullptr, &q.pipeline), "vkCreateComputePipelines");
            }
        } catch (...) {
            destroy();
            throw;
        }
    }
    ~chain() { destroy(); }
    chain(const chain&) = delete;
    chain& operator=(const chain&) = delete;

    const variant& var() const { return v_; }

    chain_result run(const gbuffer& g, const chain_settings& s, const run_options& o = {})
    {
        const int W = g.width, H = g.height;
        if (W < 1 || H < 1 || g.depth.size() != static_cast<size_t>(W) * H)
            throw error("vulkan chain: depth of " + std::to_string(g.depth.size()) + " values for " + std::to_string(W) + "x" +
                        std::to_string(H) + " (valid: width × height values, both >= 1)");
        const bool need_normals = v_.normals != normal_source::reconstructed;
        if (need_normals && g.normals.size() != static_cast<size_t>(W) * H * 4)
            throw error("vulkan chain: normals of " + std::to_string(g.normals.size()) + " values (valid: width × height × 4)");
        const auto [TW, TH] = target_size(v_, W, H);
        const vec2 tsize{float(TW), float(TH)};
        scope sc(ctx_);
        VkDevice d = ctx_.device();

        // Uniform bytes and data.
        ssao_params sp = s.ssao;
        sp.samples = v_.ssao_samples;
        const int noise_size = v_.tech == technique::gtao ? 4 : sp.noise_size;
        const std::vector<uint8_t> noise_bytes = noise::encode(noise::rotations(noise_size, sp.noise_seed), noise::encoding::rgba32f);

        VkCommandPoolCreateInfo cpci{VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO};
        cpci.queueFamilyIndex = ctx_.queue_family();
        VkCommandPool pool;
        check(vkCreateCommandPool(d, &cpci, nullptr, &pool), "vkCreateCommandPool");
        sc.add([d, pool] { vkDestroyCommandPool(d, pool, nullptr); });
        VkCommandBufferAllocateInfo cbi{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
        cbi.commandPool = pool;
        cbi.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
        cbi.commandBufferCount = 1;
        VkCommandBuffer cb;
        check(vkAllocateCommandBuffers(d, &cbi, &cb), "vkAllocateCommandBuffers");
        VkCommandBufferBeginInfo bbi{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
        bbi.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
        check(vkBeginCommandBuffer(cb, &bbi), "vkBeginCommandBuffer");

        const bool timed = ctx_.timestamp_valid_bits() > 0;
        const uint32_t query_count = static_cast<uint32_t>(passes_.size() * 2);
        VkQueryPool queries = VK_NULL_HANDLE;
        if (timed) {
            VkQueryPoolCreateInfo qpi{VK_STRUCTURE_TYPE_QUERY_POOL_CREATE_INFO};
            qpi.queryType = VK_QUERY_TYPE_TIMESTAMP;
            qpi.queryCount = query_count;
            check(vkCreateQueryPool(d, &qpi, nullptr, &queries), "vkCreateQueryPool");
            sc.add([d, queries] { vkDestroyQueryPool(d, queries, nullptr); });
            vkCmdResetQueryPool(cb, queries, 0, query_count);
        }

        VkSamplerCreateInfo sci{VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO};
        sci.magFilter = sci.minFilter = VK_FILTER_NEAREST;
        sci.mipmapMode = VK_SAMPLER_MIPMAP_MODE_NEAREST;
        sci.addressModeU = sci.addressModeV = sci.addressModeW = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE;
        VkSampler sampler;
        check(vkCreateSampler(d, &sci, nullptr, &sampler), "vkCreateSampler");
        sc.add([d, sampler] { vkDestroySampler(d, sampler, nullptr); });
        VkSamplerCreateInfo nci = sci;
        nci.addressModeU = nci.addressModeV = nci.addressModeW = VK_SAMPLER_ADDRESS_MODE_REPEAT;
        VkSampler repeat;
        check(vkCreateSampler(d, &nci, nullptr, &repeat), "vkCreateSampler");
        sc.add([d, repeat] { vkDestroySampler(d, repeat, nullptr); });

        const image depth = upload(sc, cb, W, H, VK_FORMAT_R32_SFLOAT, g.depth.data(), g.depth.size() * 4);
        image normals{};
        if (need_normals) normals = upload(sc, cb, W, H, VK_FORMAT_R32G32B32A32_SFLOAT, g.normals.data(), g.normals.size() * 4);
        const image noise_image = upload(sc, cb, noise_size, noise_size, VK_FORMAT_R32G32B32A32_SFLOAT, noise_bytes.data(), noise_bytes.size());

        // One R8 AO image per pass, cleared to o.clear, in GENERAL for storage writes.
        std::vector<image> outputs;
        for (size_t i = 0; i < passes_.size(); ++i) {
            outputs.push_back(make_image(sc, TW, TH, VK_FORMAT_R8_UNORM,
                                         VK_IMAGE_USAGE_STORAGE_BIT | VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT |
                                             VK_IMAGE_USAGE_TRANSFER_DST_BIT));
            barrier(cb, outputs.back().handle, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 0, VK_ACCESS_TRANSFER_WRITE_BIT,
                    VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT);
            VkClearColorValue cc{};
            cc.float32[0] = o.clear;
            VkImageSubresourceRange range{VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
            vkCmdClearColorImage(cb, outputs.back().handle, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, &cc, 1, &range);
            barrier(cb, outputs.back().handle, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, VK_IMAGE_LAYOUT_GENERAL, VK_ACCESS_TRANSFER_WRITE_BIT,
                    VK_ACCESS_SHADER_WRITE_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT);
        }

        // Descriptors.
        VkDescriptorPoolSize ps[3] = {{VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, 8},
                                      {VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 16},
                                      {VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, 8}};
        VkDescriptorPoolCreateInfo dpi{VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO};
        dpi.maxSets = static_cast<uint32_t>(passes_.size());
        dpi.poolSizeCount = 3;
        dpi.pPoolSizes = ps;
        VkDescriptorPool dpool;
        check(vkCreateDescriptorPool(d, &dpi, nullptr, &dpool), "vkCreateDescriptorPool");
        sc.add([d, dpool] { vkDestroyDescriptorPool(d, dpool, nullptr); });

        std::vector<VkDescriptorSet> sets(passes_.size());
        for (size_t i = 0; i < passes_.size(); ++i) {
            const pass& p = passes_[i];
            VkDescriptorSetAllocateInfo dai{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO};
            dai.descriptorPool = dpool;
            dai.descriptorSetCount = 1;
            dai.pSetLayouts = &p.set_layout;
            check(vkAllocateDescriptorSets(d, &dai, &sets[i]), "vkAllocateDescriptorSets");
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
                    std::vector<uint8_t> bytes;
                    if (p.kind != pass_kind::ao) bytes = uniforms::pack_blur(s.blur, s.camera.proj, tsize, layout::rules::std140);
                    else if (v_.tech == technique::gtao) bytes = uniforms::pack_gtao(s.gtao, s.camera, tsize, layout::rules::std140, noise_size);
                    else bytes = uniforms::pack_ssao(sp, s.camera, kernel::generate(kernel::distribution_from_name(sp.kernel), sp.samples, sp.kernel_seed),
                                                     tsize, layout::rules::std140);
                    const buffer b = make_buffer(sc, bytes.size(), VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT);
                    std::memcpy(b.mapped, bytes.data(), bytes.size());
                    bufs[k] = {b.handle, 0, bytes.size()};
                    w.pBufferInfo = &bufs[k];
                } else if (r.kind == codegen::resource_kind::storage_image) {
                    imgs[k] = {VK_NULL_HANDLE, outputs[i].view, VK_IMAGE_LAYOUT_GENERAL};
                    w.pImageInfo = &imgs[k];
                } else {
                    VkImageView view = VK_NULL_HANDLE;
                    VkSampler smp = sampler;
                    if (r.name == "depth") view = depth.view;
                    else if (r.name == "normals") view = normals.view;
                    else if (r.name == "noise") view = noise_image.view, smp = repeat;
                    else if (r.name == "ao_input" && i > 0) view = outputs[i - 1].view;
                    else throw error("vulkan chain: unknown sampled resource '" + r.name + "' (valid: depth, normals, noise, ao_input)");
                    imgs[k] = {smp, view, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL};
                    w.pImageInfo = &imgs[k];
                }
                writes.push_back(w);
            }
            vkUpdateDescriptorSets(d, static_cast<uint32_t>(writes.size()), writes.data(), 0, nullptr);
        }

        // Dispatches: pass i writes outputs[i]; pass i + 1 samples it.
        const uint32_t gx = static_cast<uint32_t>((TW + v_.workgroup_x - 1) / v_.workgroup_x);
        const uint32_t gy = static_cast<uint32_t>((TH + v_.workgroup_y - 1) / v_.workgroup_y);
        for (size_t i = 0; i < passes_.size(); ++i) {
            if (i > 0)
                barrier(cb, outputs[i - 1].handle, VK_IMAGE_LAYOUT_GENERAL, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL, VK_ACCESS_SHADER_WRITE_BIT,
                        VK_ACCESS_SHADER_READ_BIT, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT);
            vkCmdBindPipeline(cb, VK_PIPELINE_BIND_POINT_COMPUTE, passes_[i].pipeline);
            vkCmdBindDescriptorSets(cb, VK_PIPELINE_BIND_POINT_COMPUTE, passes_[i].layout, 0, 1, &sets[i], 0, nullptr);
            if (timed) vkCmdWriteTimestamp(cb, VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT, queries, static_cast<uint32_t>(2 * i));
            vkCmdDispatch(cb, gx, gy, 1);
            if (timed) vkCmdWriteTimestamp(cb, VK_PIPELINE_STAGE_BOTTOM_OF_PIPE_BIT, queries, static_cast<uint32_t>(2 * i + 1));
        }
        const image& last = outputs.back();
        barrier(cb, last.handle, VK_IMAGE_LAYOUT_GENERAL, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, VK_ACCESS_SHADER_WRITE_BIT, VK_ACCESS_TRANSFER_READ_BIT,
                VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT);
        const buffer readback = make_buffer(sc, static_cast<size_t>(TW) * TH, VK_BUFFER_USAGE_TRANSFER_DST_BIT);
        VkBufferImageCopy copy{};
        copy.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
        copy.imageExtent = {static_cast<uint32_t>(TW), static_cast<uint32_t>(TH), 1};
        vkCmdCopyImageToBuffer(cb, last.handle, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, readback.handle, 1, &copy);
        VkBufferMemoryBarrier hb{VK_STRUCTURE_TYPE_BUFFER_MEMORY_BARRIER};
        hb.srcAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
        hb.dstAccessMask = VK_ACCESS_HOST_READ_BIT;
        hb.srcQueueFamilyIndex = hb.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
        hb.buffer = readback.handle;
        hb.size = VK_WHOLE_SIZE;
        vkCmdPipelineBarrier(cb, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_HOST_BIT, 0, 0, nullptr, 1, &hb, 0, nullptr);
        check(vkEndCommandBuffer(cb), "vkEndCommandBuffer");

        VkFenceCreateInfo fci{VK_STRUCTURE_TYPE_FENCE_CREATE_INFO};
        VkFence fence;
        check(vkCreateFence(d, &fci, nullptr, &fence), "vkCreateFence");
        sc.add([d, fence] { vkDestroyFence(d, fence, nullptr); });
        VkSubmitInfo si{VK_STRUCTURE_TYPE_SUBMIT_INFO};
        si.commandBufferCount = 1;
        si.pCommandBuffers = &cb;
        check(vkQueueSubmit(ctx_.queue(), 1, &si, fence), "vkQueueSubmit");
        check(vkWaitForFences(d, 1, &fence, VK_TRUE, UINT64_MAX), "vkWaitForFences");

        chain_result out;
        out.width = TW;
        out.height = TH;
        out.ao.resize(static_cast<size_t>(TW) * TH);
        const auto* px = static_cast<const uint8_t*>(readback.mapped);
        for (size_t i = 0; i < out.ao.size(); ++i) out.ao[i] = px[i] / 255.0f;
        for (const pass& p : passes_) out.passes.push_back(names::name_of(pass_kind_names, p.kind, "pass"));
        if (timed) {
            std::vector<uint64_t> ticks(query_count);
            check(vkGetQueryPoolResults(d, queries, 0, query_count, ticks.size() * 8, ticks.data(), 8,
                                        VK_QUERY_RESULT_64_BIT | VK_QUERY_RESULT_WAIT_BIT),
                  "vkGetQueryPoolResults");
            const uint64_t mask = ctx_.timestamp_valid_bits() >= 64 ? ~0ull : (1ull << ctx_.timestamp_valid_bits()) - 1;
            for (size_t i = 0; i < passes_.size(); ++i)
                out.pass_ms.push_back(double((ticks[2 * i + 1] - ticks[2 * i]) & mask) * ctx_.timestamp_period_ns() * 1e-6);
        }
        return out;
    }

private:
    struct pass {
        pass_kind kind = pass_kind::ao;
        std::vector<codegen::resource> resources;
        VkShaderModule module = VK_NULL_HANDLE;
        VkDescriptorSetLayout set_layout = VK_NULL_HANDLE;
        VkPipelineLayout layout = VK_NULL_HANDLE;
        VkPipeline pipeline = VK_NULL_HANDLE;
    };
    struct image {
        VkImage handle = VK_NULL_HANDLE;
        VkImageView view = VK_NULL_HANDLE;
    };
    struct buffer {
        VkBuffer handle = VK_NULL_HANDLE;
        void* mapped = nullptr;
    };
    // Everything one run creates, destroyed in reverse order (after the queue is idle).
    struct scope {
        explicit scope(context& c) : ctx(c) {}
        ~scope()
        {
            vkQueueWaitIdle(ctx.queue());
            for (auto it = undo.rbegin(); it != undo.rend(); ++it) (*it)();
        }
        void add(std::function<void()> f) { undo.push_back(std::move(f)); }
        context& ctx;
        std::vector<std::function<void()>> undo;
    };

    static VkDescriptorType descriptor_type(codegen::resource_kind k)
    {
        switch (k) {
        case codegen::resource_kind::uniform_buffer: return VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER;
        case codegen::resource_kind::combined_image_sampler: return VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER;
        case codegen::resource_kind::storage_image: return VK_DESCRIPTOR_TYPE_STORAGE_IMAGE;
        }
        throw error("vulkan chain: unknown resource kind");
    }

    static void barrier(VkCommandBuffer cb, VkImage img, VkImageLayout from, VkImageLayout to, VkAccessFlags src, VkAccessFlags dst,
                        VkPipelineStageFlags src_stage, VkPipelineStageFlags dst_stage)
    {
        VkImageMemoryBarrier b{VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER};
        b.oldLayout = from;
        b.newLayout = to;
        b.srcAccessMask = src;
        b.dstAccessMask = dst;
        b.srcQueueFamilyIndex = b.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
        b.image = img;
        b.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
        vkCmdPipelineBarrier(cb, src_stage, dst_stage, 0, 0, nullptr, 0, nullptr, 1, &b);
    }

    // Device memory for `mr` with `properties`, freed when `sc` ends.
    VkDeviceMemory allocate(scope& sc, const VkMemoryRequirements& mr, VkMemoryPropertyFlags properties)
    {
        VkDevice d = ctx_.device();
        VkMemoryAllocateInfo ai{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO};
        ai.allocationSize = mr.size;
        ai.memoryTypeIndex = ctx_.memory_type(mr.memoryTypeBits, properties);
        VkDeviceMemory m;
        check(vkAllocateMemory(d, &ai, nullptr, &m), "vkAllocateMemory");
        sc.add([d, m] { vkFreeMemory(d, m, nullptr); });
        return m;
    }

    buffer make_buffer(scope& sc, size_t size, VkBufferUsageFlags usage)
    {
        VkDevice d = ctx_.device();
        buffer r;
        VkBufferCreateInfo bi{VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO};
        bi.size = size;
        bi.usage = usage;
        check(vkCreateBuffer(d, &bi, nullptr, &r.handle), "vkCreateBuffer");
        VkBuffer h = r.handle;
        sc.add([d, h] { vkDestroyBuffer(d, h, nullptr); });
        VkMemoryRequirements mr;
        vkGetBufferMemoryRequirements(d, r.handle, &mr);
        VkDeviceMemory m = allocate(sc, mr, VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT);
        check(vkBindBufferMemory(d, r.handle, m, 0), "vkBindBufferMemory");
        check(vkMapMemory(d, m, 0, VK_WHOLE_SIZE, 0, &r.mapped), "vkMapMemory");
        return r;
    }

    image make_image(scope& sc, int w, int h, VkFormat f, VkImageUsageFlags usage)
    {
        VkDevice d = ctx_.device();
        image r;
        VkImageCreateInfo ii{VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO};
        ii.imageType = VK_IMAGE_TYPE_2D;
        ii.format = f;
        ii.extent = {static_cast<uint32_t>(w), static_cast<uint32_t>(h), 1};
        ii.mipLevels = 1;
        ii.arrayLayers = 1;
        ii.samples = VK_SAMPLE_COUNT_1_BIT;
        ii.tiling = VK_IMAGE_TILING_OPTIMAL;
        ii.usage = usage;
        ii.initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;
        check(vkCreateImage(d, &ii, nullptr, &r.handle), "vkCreateImage");
        VkImage h2 = r.handle;
        sc.add([d, h2] { vkDestroyImage(d, h2, nullptr); });
        VkMemoryRequirements mr;
        vkGetImageMemoryRequirements(d, r.handle, &mr);
        VkDeviceMemory m = allocate(sc, mr, 0);
        check(vkBindImageMemory(d, r.handle, m, 0), "vkBindImageMemory");
        VkImageViewCreateInfo vi{VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO};
        vi.image = r.handle;
        vi.viewType = VK_IMAGE_VIEW_TYPE_2D;
        vi.format = f;
        vi.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
        check(vkCreateImageView(d, &vi, nullptr, &r.view), "vkCreateImageView");
        VkImageView v = r.view;
        sc.add([d, v] { vkDestroyImageView(d, v, nullptr); });
        return r;
    }

    // A sampled image holding `bytes`, in SHADER_READ_ONLY_OPTIMAL for the compute passes.
    image upload(scope& sc, VkCommandBuffer cb, int w, int h, VkFormat f, const void* bytes, size_t size)
    {
        image r = make_image(sc, w, h, f, VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT);
        const buffer staging = make_buffer(sc, size, VK_BUFFER_USAGE_TRANSFER_SRC_BIT);
        std::memcpy(staging.mapped, bytes, size);
        barrier(cb, r.handle, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 0, VK_ACCESS_TRANSFER_WRITE_BIT,
                VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT);
        VkBufferImageCopy c{};
        c.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
        c.imageExtent = {static_cast<uint32_t>(w), static_cast<uint32_t>(h), 1};
        vkCmdCopyBufferToImage(cb, staging.handle, r.handle, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &c);
        barrier(cb, r.handle, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL, VK_ACCESS_TRANSFER_WRITE_BIT,
                VK_ACCESS_SHADER_READ_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT);
        return r;
    }

    void destroy()
    {
        VkDevice d = ctx_.device();
        for (pass& p : passes_) {
            if (p.pipeline) vkDestroyPipeline(d, p.pipeline, nullptr);
            if (p.layout) vkDestroyPipelineLayout(d, p.layout, nullptr);
            if (p.set_layout) vkDestroyDescriptorSetLayout(d, p.set_layout, nullptr);
            if (p.module) vkDestroyShaderModule(d, p.module, nullptr);
        }
        passes_.clear();
    }

    context& ctx_;
    variant v_;
    std::vector<pass> passes_;
};

} // namespace aogen::vulkan
