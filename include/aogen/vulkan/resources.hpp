// aogen/vulkan/resources.hpp — the buffers, images, samplers and commands the harness makes.
//
// WHAT
//   resource_scope owns what it creates (command pools, buffers, images, views, samplers,
//   framebuffers, descriptor pools, ...) and destroys it, in reverse order of creation,
//   once the queue is idle: a run that throws half-way leaks nothing. Memory follows a
//   frame loop's: everything the GPU reads or writes is DEVICE_LOCAL, host-visible memory
//   is only for staging uploads and for reading results back.
//     make_image          a 2D device-local image with its view; the view's aspect follows
//                         the format (DEPTH for D32_SFLOAT, COLOR otherwise)
//     make_device_buffer  a device-local buffer (storage, or filled by upload_buffer)
//     make_host_buffer    a host-visible, coherent, mapped buffer: staging and read-back only
//     upload              an image filled from host bytes through a staging buffer (into
//                         the depth aspect for a depth format), left in SHADER_READ_ONLY_OPTIMAL
//     upload_buffer       a device-local buffer filled from host bytes through a staging buffer
//     update_buffer       new bytes for such a buffer, the same way
//     clear               an image filled with one colour (vkCmdClearColorImage)
//     read_back           a copy of an image into a mapped buffer the host can read
//     make_sampler        a nearest-filtering sampler (clamped or repeating)
//     begin_commands / submit   one one-time command buffer, submitted and waited for
//   Staging buffers belong to the scope passed as `staging` (by default the same scope):
//   a long-lived scope uploads through a short-lived one, freed after the submit, so it
//   keeps no host copy of what it uploaded.
//   barrier() is the one image layout transition / memory dependency all of them use.
//
// USAGE
//     aogen::vulkan::resource_scope keep(ctx), staging(ctx);
//     VkCommandBuffer cb = staging.begin_commands();
//     image depth = keep.upload(cb, w, h, VK_FORMAT_D32_SFLOAT, bytes, size, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, staging);
//     ...
//     staging.submit(cb);                 // waits for the fence
//   // ~resource_scope: vkQueueWaitIdle, then every object destroyed
//
// ERRORS
//   aogen::error from check(): a failing Vulkan call; a format the device cannot sample.
#pragma once

#include "device.hpp"

#include <cstring>
#include <functional>
#include <string>
#include <vector>

namespace aogen::vulkan {

struct buffer {
    VkBuffer handle = VK_NULL_HANDLE;
    VkDeviceMemory memory = VK_NULL_HANDLE;
    void* mapped = nullptr; // host buffers only
};

struct image {
    VkImage handle = VK_NULL_HANDLE;
    VkImageView view = VK_NULL_HANDLE;
    VkImageAspectFlags aspect = VK_IMAGE_ASPECT_COLOR_BIT;
};

// The aspect an image of format `f` is read and copied through: the harness's only depth
// format is D32_SFLOAT (no stencil), every other format is a colour format.
inline VkImageAspectFlags aspect_of(VkFormat f)
{
    return f == VK_FORMAT_D32_SFLOAT ? VK_IMAGE_ASPECT_DEPTH_BIT : VK_IMAGE_ASPECT_COLOR_BIT;
}

// A layout transition of all of `img` (its aspect), with the memory dependency from
// (src access, src stage) to (dst access, dst stage).
inline void barrier(VkCommandBuffer cb, const image& img, VkImageLayout from, VkImageLayout to, VkAccessFlags src, VkAccessFlags dst,
                    VkPipelineStageFlags src_stage, VkPipelineStageFlags dst_stage)
{
    VkImageMemoryBarrier b{VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER};
    b.oldLayout = from;
    b.newLayout = to;
    b.srcAccessMask = src;
    b.dstAccessMask = dst;
    b.srcQueueFamilyIndex = b.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
    b.image = img.handle;
    b.subresourceRange = {img.aspect, 0, 1, 0, 1};
    vkCmdPipelineBarrier(cb, src_stage, dst_stage, 0, 0, nullptr, 0, nullptr, 1, &b);
}

// The memory dependency on all of buffer `b` from (src access, src stage) to (dst access, dst stage).
inline void buffer_barrier(VkCommandBuffer cb, const buffer& b, VkAccessFlags src, VkAccessFlags dst, VkPipelineStageFlags src_stage,
                           VkPipelineStageFlags dst_stage)
{
    VkBufferMemoryBarrier bb{VK_STRUCTURE_TYPE_BUFFER_MEMORY_BARRIER};
    bb.srcAccessMask = src;
    bb.dstAccessMask = dst;
    bb.srcQueueFamilyIndex = bb.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
    bb.buffer = b.handle;
    bb.size = VK_WHOLE_SIZE;
    vkCmdPipelineBarrier(cb, src_stage, dst_stage, 0, 0, nullptr, 1, &bb, 0, nullptr);
}

class resource_scope {
public:
    explicit resource_scope(context& c) : ctx_(c) {}
    ~resource_scope()
    {
        vkQueueWaitIdle(ctx_.queue()); // nothing is destroyed while the GPU may still use it
        for (auto it = undo_.rbegin(); it != undo_.rend(); ++it) (*it)();
    }
    resource_scope(const resource_scope&) = delete;
    resource_scope& operator=(const resource_scope&) = delete;

    context& ctx() const { return ctx_; }
    VkDevice device() const { return ctx_.device(); }

    // Runs `destroy` when the scope ends (after the queue is idle), before anything added earlier.
    void add(std::function<void()> destroy) { undo_.push_back(std::move(destroy)); }

    // `handle`, destroyed with `destroy` (vkDestroyBuffer, vkFreeMemory, ...: every
    // vkDestroy* of a device child takes (device, handle, allocator)) when the scope ends.
    template <class Handle, class Destroy>
    Handle own(Handle handle, Destroy destroy)
    {
        VkDevice d = device();
        add([d, handle, destroy] { destroy(d, handle, nullptr); });
        return handle;
    }

    // Device memory for `mr` with `properties`.
    VkDeviceMemory allocate(const VkMemoryRequirements& mr, VkMemoryPropertyFlags properties)
    {
        VkDevice d = device();
        VkMemoryAllocateInfo ai{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO};
        ai.allocationSize = mr.size;
        ai.memoryTypeIndex = ctx_.memory_type(mr.memoryTypeBits, properties);
        VkDeviceMemory m;
        check(vkAllocateMemory(d, &ai, nullptr, &m), "vkAllocateMemory");
        return own(m, vkFreeMemory);
    }

    // A host-visible, coherent buffer, mapped: for staging and read-back, never for what
    // a shader reads (on a discrete GPU every shader access would cross the bus).
    buffer make_host_buffer(size_t size, VkBufferUsageFlags usage)
    {
        buffer r = make_buffer(size, usage, VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT);
        check(vkMapMemory(device(), r.memory, 0, VK_WHOLE_SIZE, 0, &r.mapped), "vkMapMemory");
        return r;
    }

    // A mapped buffer holding a copy of `bytes`.
    buffer make_host_buffer(const void* bytes, size_t size, VkBufferUsageFlags usage)
    {
        const buffer b = make_host_buffer(size, usage);
        std::memcpy(b.mapped, bytes, size);
        return b;
    }

    // A device-local buffer, not mapped.
    buffer make_device_buffer(size_t size, VkBufferUsageFlags usage)
    {
        return make_buffer(size, usage, VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT);
    }

    // A device-local buffer holding `bytes`, copied from a staging buffer of `staging`, ready
    // for shader reads of stages `readers` (as a uniform or storage buffer).
    buffer upload_buffer(VkCommandBuffer cb, const void* bytes, size_t size, VkBufferUsageFlags usage, VkPipelineStageFlags readers,
                         resource_scope& staging)
    {
        const buffer r = make_device_buffer(size, usage | VK_BUFFER_USAGE_TRANSFER_DST_BIT);
        update_buffer(cb, r, bytes, size, readers, staging);
        return r;
    }

    // `size` bytes copied into the start of `target` (a buffer upload_buffer made) through a
    // staging buffer of `staging`, made visible to shader reads in `readers`. Whatever read
    // `target` before must have finished (a submission waited for).
    void update_buffer(VkCommandBuffer cb, const buffer& target, const void* bytes, size_t size, VkPipelineStageFlags readers,
                       resource_scope& staging)
    {
        const buffer source = staging.make_host_buffer(bytes, size, VK_BUFFER_USAGE_TRANSFER_SRC_BIT);
        const VkBufferCopy region{0, 0, size};
        vkCmdCopyBuffer(cb, source.handle, target.handle, 1, &region);
        buffer_barrier(cb, target, VK_ACCESS_TRANSFER_WRITE_BIT, VK_ACCESS_UNIFORM_READ_BIT | VK_ACCESS_SHADER_READ_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT,
                       readers);
    }

    image make_image(int w, int h, VkFormat f, VkImageUsageFlags usage)
    {
        require_format(f, usage);
        VkDevice d = device();
        image r;
        r.aspect = aspect_of(f);
        VkImageCreateInfo ii{VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO};
        ii.imageType = VK_IMAGE_TYPE_2D;
        ii.format = f;
        ii.extent = extent(w, h);
        ii.mipLevels = 1;
        ii.arrayLayers = 1;
        ii.samples = VK_SAMPLE_COUNT_1_BIT;
        ii.tiling = VK_IMAGE_TILING_OPTIMAL;
        ii.usage = usage;
        ii.initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;
        check(vkCreateImage(d, &ii, nullptr, &r.handle), "vkCreateImage");
        own(r.handle, vkDestroyImage);
        VkMemoryRequirements mr;
        vkGetImageMemoryRequirements(d, r.handle, &mr);
        VkDeviceMemory m = allocate(mr, VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT);
        check(vkBindImageMemory(d, r.handle, m, 0), "vkBindImageMemory");
        VkImageViewCreateInfo vi{VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO};
        vi.image = r.handle;
        vi.viewType = VK_IMAGE_VIEW_TYPE_2D;
        vi.format = f;
        vi.subresourceRange = {r.aspect, 0, 1, 0, 1};
        check(vkCreateImageView(d, &vi, nullptr, &r.view), "vkCreateImageView");
        own(r.view, vkDestroyImageView);
        return r;
    }

    // A sampled image holding `bytes` (tightly packed rows, top row first), in for shaders of `readers` (stage flags).
    // SHADER_READ_ONLY_OPTIMAL for shaders of `readers` (stage flags). The staging buffer
    // belongs to `staging`.
    image upload(VkCommandBuffer cb, int w, int h, VkFormat f, const void* bytes, size_t size, VkPipelineStageFlags readers,
                 resource_scope& staging)
    {
        const image r = make_image(w, h, f, VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT);
        update_image(cb, r, w, h, bytes, size, VK_IMAGE_LAYOUT_UNDEFINED, readers, staging);
        return r;
    }

    // `bytes` (w × h texels, tightly packed rows, top row first) copied over the whole of
    // `img` (made with TRANSFER_DST, now in layout `from`; UNDEFINED drops what it held)
    // through a staging buffer of `staging`, left in SHADER_READ_ONLY_OPTIMAL for shaders of
    // `readers`. Whatever used `img` before must have finished or be ordered by `cb`.
    void update_image(VkCommandBuffer cb, const image& img, int w, int h, const void* bytes, size_t size, VkImageLayout from,
                      VkPipelineStageFlags readers, resource_scope& staging)
    {
        const buffer source = staging.make_host_buffer(bytes, size, VK_BUFFER_USAGE_TRANSFER_SRC_BIT);
        barrier(cb, img, from, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_SHADER_WRITE_BIT, VK_ACCESS_TRANSFER_WRITE_BIT,
                VK_PIPELINE_STAGE_ALL_COMMANDS_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT);
        const VkBufferImageCopy c = copy_region(img, w, h);
        vkCmdCopyBufferToImage(cb, source.handle, img.handle, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &c);
        barrier(cb, img, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL, VK_ACCESS_TRANSFER_WRITE_BIT,
                VK_ACCESS_SHADER_READ_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT, readers);
    }

    // Fills colour image `img`, now in layout `from` (UNDEFINED for a new one), with `value`
    // in every channel once all earlier work is done, leaving it in TRANSFER_DST_OPTIMAL;
    // the caller's next barrier moves it on.
    static void clear(VkCommandBuffer cb, const image& img, float value, VkImageLayout from = VK_IMAGE_LAYOUT_UNDEFINED)
    {
        barrier(cb, img, from, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 0, VK_ACCESS_TRANSFER_WRITE_BIT, VK_PIPELINE_STAGE_ALL_COMMANDS_BIT,
                VK_PIPELINE_STAGE_TRANSFER_BIT);
        VkClearColorValue cc{};
        cc.float32[0] = cc.float32[1] = cc.float32[2] = cc.float32[3] = value;
        const VkImageSubresourceRange range{img.aspect, 0, 1, 0, 1};
        vkCmdClearColorImage(cb, img.handle, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, &cc, 1, &range);
    }

    // A buffer the host reads after submit(): `img` (w × h, `texel_bytes` per texel, in
    // TRANSFER_SRC_OPTIMAL) copied into it, made visible to the host.
    buffer read_back(VkCommandBuffer cb, const image& img, int w, int h, size_t texel_bytes)
    {
        const buffer r = make_host_buffer(static_cast<size_t>(w) * h * texel_bytes, VK_BUFFER_USAGE_TRANSFER_DST_BIT);
        const VkBufferImageCopy c = copy_region(img, w, h);
        vkCmdCopyImageToBuffer(cb, img.handle, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, r.handle, 1, &c);
        buffer_barrier(cb, r, VK_ACCESS_TRANSFER_WRITE_BIT, VK_ACCESS_HOST_READ_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_HOST_BIT);
        return r;
    }

    // Nearest filtering, no mipmaps: the passes read texels with texelFetch, except the
    // noise tile, which needs `repeat` to tile the screen.
    VkSampler make_sampler(VkSamplerAddressMode mode)
    {
        VkDevice d = device();
        VkSamplerCreateInfo sci{VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO};
        sci.magFilter = sci.minFilter = VK_FILTER_NEAREST;
        sci.mipmapMode = VK_SAMPLER_MIPMAP_MODE_NEAREST;
        sci.addressModeU = sci.addressModeV = sci.addressModeW = mode;
        VkSampler s;
        check(vkCreateSampler(d, &sci, nullptr, &s), "vkCreateSampler");
        return own(s, vkDestroySampler);
    }

    // A primary command buffer of a pool of its own, begun for one submission.
    VkCommandBuffer begin_commands()
    {
        VkDevice d = device();
        VkCommandPoolCreateInfo cpci{VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO};
        cpci.queueFamilyIndex = ctx_.queue_family();
        VkCommandPool pool;
        check(vkCreateCommandPool(d, &cpci, nullptr, &pool), "vkCreateCommandPool");
        own(pool, vkDestroyCommandPool);
        VkCommandBufferAllocateInfo cbi{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
        cbi.commandPool = pool;
        cbi.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
        cbi.commandBufferCount = 1;
        VkCommandBuffer cb;
        check(vkAllocateCommandBuffers(d, &cbi, &cb), "vkAllocateCommandBuffers");
        VkCommandBufferBeginInfo bbi{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
        bbi.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
        check(vkBeginCommandBuffer(cb, &bbi), "vkBeginCommandBuffer");
        return cb;
    }

    // Ends `cb`, submits it and waits until it has run.
    void submit(VkCommandBuffer cb)
    {
        VkDevice d = device();
        check(vkEndCommandBuffer(cb), "vkEndCommandBuffer");
        VkFenceCreateInfo fci{VK_STRUCTURE_TYPE_FENCE_CREATE_INFO};
        VkFence fence;
        check(vkCreateFence(d, &fci, nullptr, &fence), "vkCreateFence");
        own(fence, vkDestroyFence);
        VkSubmitInfo si{VK_STRUCTURE_TYPE_SUBMIT_INFO};
        si.commandBufferCount = 1;
        si.pCommandBuffers = &cb;
        check(vkQueueSubmit(ctx_.queue(), 1, &si, fence), "vkQueueSubmit");
        check(vkWaitForFences(d, 1, &fence, VK_TRUE, UINT64_MAX), "vkWaitForFences");
    }

private:
    buffer make_buffer(size_t size, VkBufferUsageFlags usage, VkMemoryPropertyFlags properties)
    {
        VkDevice d = device();
        buffer r;
        VkBufferCreateInfo bi{VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO};
        bi.size = size;
        bi.usage = usage;
        check(vkCreateBuffer(d, &bi, nullptr, &r.handle), "vkCreateBuffer");
        own(r.handle, vkDestroyBuffer);
        VkMemoryRequirements mr;
        vkGetBufferMemoryRequirements(d, r.handle, &mr);
        r.memory = allocate(mr, properties);
        check(vkBindBufferMemory(d, r.handle, r.memory, 0), "vkBindBufferMemory");
        return r;
    }

    static VkExtent3D extent(int w, int h) { return {static_cast<uint32_t>(w), static_cast<uint32_t>(h), 1}; }

    static VkBufferImageCopy copy_region(const image& img, int w, int h)
    {
        VkBufferImageCopy c{};
        c.imageSubresource = {img.aspect, 0, 0, 1};
        c.imageExtent = extent(w, h);
        return c;
    }

    // aogen::error unless the device supports `usage` of optimal-tiling images of `f`
    // (a depth format that cannot be sampled should say so, not fail in vkCreateImage).
    void require_format(VkFormat f, VkImageUsageFlags usage) const
    {
        VkFormatProperties fp;
        vkGetPhysicalDeviceFormatProperties(ctx_.physical_device(), f, &fp);
        const VkFormatFeatureFlags have = fp.optimalTilingFeatures;
        const bool ok = (!(usage & VK_IMAGE_USAGE_SAMPLED_BIT) || (have & VK_FORMAT_FEATURE_SAMPLED_IMAGE_BIT)) &&
                        (!(usage & VK_IMAGE_USAGE_STORAGE_BIT) || (have & VK_FORMAT_FEATURE_STORAGE_IMAGE_BIT)) &&
                        (!(usage & VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT) || (have & VK_FORMAT_FEATURE_COLOR_ATTACHMENT_BIT));
        if (!ok)
            throw error("vulkan: format " + std::to_string(static_cast<int>(f)) + " with usage " + std::to_string(usage) + " is not supported by " +
                        ctx_.device_name() + " (valid: a format the device samples / stores / renders to)");
    }

    context& ctx_;
    std::vector<std::function<void()>> undo_;
};

} // namespace aogen::vulkan
