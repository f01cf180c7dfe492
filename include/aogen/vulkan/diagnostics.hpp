// aogen/vulkan/diagnostics.hpp — counting what a pass computed before its guard.
//
// WHAT
//   A pass built with codegen::options::diagnostics stores its raw value — what ao_pass()
//   returned, before ao_finalize() turned NaN into 1 and clamped to [0, 1] — into an r32f
//   image (entry_*.glsl). The shipped output can never show a NaN, so a check of numerical
//   stability has to look there. raw_counter is the compute kernel that reads such an image
//   and counts, per image:
//     nan          NaN values (exponent all ones, mantissa not zero)
//     inf          +infinity or -infinity
//     below_zero   finite values < 0
//     above_one    finite values > 1
//     max_excess   how far the farthest of those lies outside [0, 1] (0 when none): a
//                  count of values 1.0000001 from a blur's rounding reads differently from
//                  one of values 3
//   The tests are on the bits, as ao_is_finite's are: a driver compiling with fast-math may
//   assume isnan() false. bound_chain (bound_chain.hpp) runs it after a diagnostic chain's
//   passes, one dispatch per raw image, and reads the counts back.
//
// USAGE
//     aogen::vulkan::raw_counter counter(ctx);
//     aogen::codegen::options o;
//     o.diagnostics = true;
//     aogen::vulkan::chain c(ctx, aogen::codegen::make_plan(v, o));
//     aogen::vulkan::chain_result r = c.run(g, s);    // r.raw[pass].nan, .inf, ...
//
// ERRORS
//   aogen::error: a failing compile or Vulkan call.
#pragma once

#include <aogen/codegen.hpp>

#include "resources.hpp"
#include "spirv_cache.hpp"

#include <algorithm>
#include <cstdint>
#include <cstring>

namespace aogen::vulkan {

// What one raw image held.
struct raw_counts {
    uint64_t nan = 0, inf = 0, below_zero = 0, above_one = 0;
    float max_excess = 0; // the largest distance outside [0, 1] of a finite value
    uint64_t non_finite() const { return nan + inf; }
    uint64_t out_of_range() const { return below_zero + above_one; }
    raw_counts& operator+=(const raw_counts& o)
    {
        nan += o.nan, inf += o.inf, below_zero += o.below_zero, above_one += o.above_one;
        max_excess = std::max(max_excess, o.max_excess);
        return *this;
    }
};

// The counts as the kernel leaves them in its storage buffer: five uints per image (the
// last the bits of max_excess: for floats >= 0 the bits order as the values do, so the
// kernel keeps the largest with atomicMax).
inline constexpr size_t raw_counts_words = 5;
inline constexpr size_t raw_counts_bytes = raw_counts_words * sizeof(uint32_t);

class raw_counter {
public:
    static constexpr int workgroup = 8;

    explicit raw_counter(context& ctx, spirv_cache* cache = nullptr) : ctx_(ctx)
    {
        spirv_cache own;
        const std::vector<uint32_t>& words = (cache ? *cache : own).get(source());
        try {
            build(words);
        } catch (...) {
            destroy();
            throw;
        }
    }
    ~raw_counter() { destroy(); }
    raw_counter(const raw_counter&) = delete;
    raw_counter& operator=(const raw_counter&) = delete;

    VkDescriptorSetLayout set_layout() const { return set_layout_; }

    // A descriptor set of `pool` reading `raw` (in GENERAL) and counting into `counts` at
    // byte `offset` (raw_counts_bytes of it).
    VkDescriptorSet make_set(VkDescriptorPool pool, const image& raw, const buffer& counts, VkDeviceSize offset) const
    {
        VkDescriptorSetAllocateInfo dai{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO};
        dai.descriptorPool = pool;
        dai.descriptorSetCount = 1;
        dai.pSetLayouts = &set_layout_;
        VkDescriptorSet set;
        check(vkAllocateDescriptorSets(ctx_.device(), &dai, &set), "vkAllocateDescriptorSets");
        const VkDescriptorImageInfo ii{VK_NULL_HANDLE, raw.view, VK_IMAGE_LAYOUT_GENERAL};
        const VkDescriptorBufferInfo bi{counts.handle, offset, raw_counts_bytes};
        VkWriteDescriptorSet w[2] = {{VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET}, {VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET}};
        w[0].dstSet = w[1].dstSet = set;
        w[0].dstBinding = 0, w[1].dstBinding = 1;
        w[0].descriptorCount = w[1].descriptorCount = 1;
        w[0].descriptorType = VK_DESCRIPTOR_TYPE_STORAGE_IMAGE;
        w[0].pImageInfo = &ii;
        w[1].descriptorType = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
        w[1].pBufferInfo = &bi;
        vkUpdateDescriptorSets(ctx_.device(), 2, w, 0, nullptr);
        return set;
    }

    // Records the count of one w × h raw image (its counts zeroed beforehand by the caller).
    void record(VkCommandBuffer cb, VkDescriptorSet set, int w, int h) const
    {
        vkCmdBindPipeline(cb, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline_);
        vkCmdBindDescriptorSets(cb, VK_PIPELINE_BIND_POINT_COMPUTE, layout_, 0, 1, &set, 0, nullptr);
        vkCmdDispatch(cb, static_cast<uint32_t>((w + workgroup - 1) / workgroup), static_cast<uint32_t>((h + workgroup - 1) / workgroup), 1);
    }

    // The counts as read back from the kernel's raw_counts_words uints at `bytes`.
    static raw_counts decode(const uint8_t* bytes)
    {
        uint32_t words[raw_counts_words];
        std::memcpy(words, bytes, sizeof words);
        raw_counts r{words[0], words[1], words[2], words[3]};
        std::memcpy(&r.max_excess, &words[4], sizeof(float));
        return r;
    }

private:
    static codegen::shader_source source()
    {
        codegen::shader_source s;
        s.stage = shader_stage::compute;
        s.name = "aogen raw-value counter";
        s.glsl = R"glsl(#version 450
// One invocation per texel of a pass's raw-value image: classify it by its bits.
layout(local_size_x = 8, local_size_y = 8, local_size_z = 1) in;
layout(set = 0, binding = 0, r32f) uniform readonly image2D u_raw;
layout(set = 0, binding = 1, std430) buffer Counts {
    uint nan_count;
    uint inf_count;
    uint below_zero;
    uint above_one;
    uint max_excess_bits;
} counts;

void main()
{
    ivec2 p = ivec2(gl_GlobalInvocationID.xy);
    ivec2 size = imageSize(u_raw);
    if (p.x >= size.x || p.y >= size.y) return;
    float v = imageLoad(u_raw, p).r;
    uint bits = floatBitsToUint(v);
    bool special = (bits & 0x7f800000u) == 0x7f800000u; // exponent all ones: NaN or infinity
    if (special && (bits & 0x007fffffu) != 0u) atomicAdd(counts.nan_count, 1u);
    else if (special) atomicAdd(counts.inf_count, 1u);
    else if (v < 0.0 || v > 1.0) {
        if (v < 0.0) atomicAdd(counts.below_zero, 1u);
        else atomicAdd(counts.above_one, 1u);
        atomicMax(counts.max_excess_bits, floatBitsToUint(v < 0.0 ? -v : v - 1.0));
    }
}
)glsl";
        return s;
    }

    void build(const std::vector<uint32_t>& words)
    {
        VkDevice d = ctx_.device();
        const VkDescriptorSetLayoutBinding bindings[2] = {
            {0, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, 1, VK_SHADER_STAGE_COMPUTE_BIT, nullptr},
            {1, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1, VK_SHADER_STAGE_COMPUTE_BIT, nullptr},
        };
        VkDescriptorSetLayoutCreateInfo dli{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO};
        dli.bindingCount = 2;
        dli.pBindings = bindings;
        check(vkCreateDescriptorSetLayout(d, &dli, nullptr, &set_layout_), "vkCreateDescriptorSetLayout");
        VkPipelineLayoutCreateInfo pli{VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO};
        pli.setLayoutCount = 1;
        pli.pSetLayouts = &set_layout_;
        check(vkCreatePipelineLayout(d, &pli, nullptr, &layout_), "vkCreatePipelineLayout");
        VkShaderModuleCreateInfo smi{VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO};
        smi.codeSize = words.size() * 4;
        smi.pCode = words.data();
        check(vkCreateShaderModule(d, &smi, nullptr, &module_), "vkCreateShaderModule");
        VkComputePipelineCreateInfo cpi{VK_STRUCTURE_TYPE_COMPUTE_PIPELINE_CREATE_INFO};
        cpi.stage = {VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO};
        cpi.stage.stage = VK_SHADER_STAGE_COMPUTE_BIT;
        cpi.stage.module = module_;
        cpi.stage.pName = "main";
        cpi.layout = layout_;
        check(vkCreateComputePipelines(d, VK_NULL_HANDLE, 1, &cpi, nullptr, &pipeline_), "vkCreateComputePipelines");
    }

    void destroy()
    {
        VkDevice d = ctx_.device();
        if (pipeline_) vkDestroyPipeline(d, pipeline_, nullptr);
        if (module_) vkDestroyShaderModule(d, module_, nullptr);
        if (layout_) vkDestroyPipelineLayout(d, layout_, nullptr);
        if (set_layout_) vkDestroyDescriptorSetLayout(d, set_layout_, nullptr);
        pipeline_ = VK_NULL_HANDLE, module_ = VK_NULL_HANDLE, layout_ = VK_NULL_HANDLE, set_layout_ = VK_NULL_HANDLE;
    }

    context& ctx_;
    VkDescriptorSetLayout set_layout_ = VK_NULL_HANDLE;
    VkPipelineLayout layout_ = VK_NULL_HANDLE;
    VkShaderModule module_ = VK_NULL_HANDLE;
    VkPipeline pipeline_ = VK_NULL_HANDLE;
};

} // namespace aogen::vulkan
