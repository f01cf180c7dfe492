// aogen/vulkan/passes.hpp — a chain's passes as Vulkan pipelines, compute or fragment.
//
// WHAT
//   pass_pipelines compiles every pass of a chain (GLSL → compile::compile → SPIR-V, through
//   a spirv_cache when one is given) into a pipeline, with a descriptor set layout made from
//   the pass's codegen::resource list, and records a pass into a command buffer:
//     compute   one compute pipeline per pass; the output is a storage image (GENERAL);
//               record() dispatches ceil(w / workgroup_x) × ceil(h / workgroup_y) groups
//               (w and h divided by pixels_per_invocation first: the upsample's halves).
//     fragment  one graphics pipeline per pass: the fullscreen-triangle vertex shader
//               (compiled once: its text is the same in every pass) and the pass's
//               fragment shader, into one R8_UNORM colour attachment through a render
//               pass (Vulkan 1.1: no dynamic rendering) that loads and stores it -- two
//               for the history pass, the AO and its RGBA16F history (history.glsl);
//               make_framebuffer() makes the framebuffer of an output image once, and
//               record() sets the viewport and scissor to the target size and draws 3
//               vertices without vertex buffers.
//   The passes are a plan's (codegen::make_plan(v, options): options::diagnostics adds each
//   pass's raw-value image), built from codegen::generate(plan)'s sources or from texts of the
//   same shaders by another road, in the plan's order and with its resource names — a
//   target's round trip and the report's floor kernels are such lists.
//   output() says how the stage's passes use their output image (usage, layout, access,
//   pipeline stage) and reader_stage() where the passes sample their inputs, so the
//   caller's barriers are the same code for both stages.
//
// USAGE
//     const aogen::codegen::plan plan = aogen::codegen::make_plan(v);  // v.stage compute or fragment
//     aogen::vulkan::pass_pipelines p(ctx, plan, aogen::codegen::generate(plan));
//     for (size_t i = 0; i < p.size(); ++i) { ... p[i].resources, p[i].set_layout ... }
//     VkFramebuffer fb = p.make_framebuffer(scope, i, output_image, w, h); // null for compute
//     p.record(cb, i, set, fb, target_w, target_h);
//
// ERRORS
//   aogen::error: a compile error (naming the shader), a fragment variant on a queue
//   without graphics, raw diagnostics of fragment passes on a device whose fragment
//   shaders cannot store to images, a failing Vulkan call.
#pragma once

#include <aogen/codegen.hpp>
#include "resources.hpp"
#include "spirv_cache.hpp"

#include <string>
#include <vector>

namespace aogen::vulkan {

// The AO images between passes and at the end: one 8-bit unorm channel — or, for passes
// generated with codegen::options::output_format "rgba8" (WebGPU and OpenGL ES have no r8
// storage format), four, the AO in the first.
inline constexpr VkFormat ao_format = VK_FORMAT_R8_UNORM;

// The image format of a compute pass's output format qualifier; the harness reads back r8
// and rgba8 only.
inline VkFormat image_format_of(const std::string& qualifier)
{
    if (qualifier == "r8") return VK_FORMAT_R8_UNORM;
    if (qualifier == "rgba8") return VK_FORMAT_R8G8B8A8_UNORM;
    if (qualifier == "r32f") return VK_FORMAT_R32_SFLOAT; // the prefilter's depth MIP atlas
    if (qualifier == "rgba16f") return VK_FORMAT_R16G16B16A16_SFLOAT; // the history (codegen::history_format)
    throw error("vulkan: an output image in format " + qualifier + " (valid: r8, rgba8, r32f, rgba16f: the formats the harness reads back)");
}

// Bytes per texel of the formats image_format_of makes.
inline size_t texel_bytes(VkFormat f)
{
    if (f == VK_FORMAT_R8_UNORM) return 1;
    return f == VK_FORMAT_R16G16B16A16_SFLOAT ? 8 : 4;
}

struct pass_pipeline {
    pass_kind kind = pass_kind::ao;
    std::vector<codegen::resource> resources; // the compute or fragment shader's, by binding
    VkFormat output_format = ao_format;       // its output image's: the chain's, or the prefilter's r32f atlas
    VkDescriptorSetLayout set_layout = VK_NULL_HANDLE;
    VkPipelineLayout layout = VK_NULL_HANDLE;
    VkPipeline pipeline = VK_NULL_HANDLE;
};

// How a stage's passes write their output image.
struct output_use {
    VkImageUsageFlags usage;    // what the image must be created with, besides sampling and transfers
    VkImageLayout layout;       // the layout while the pass writes it
    VkAccessFlags access;       // the pass's accesses to it
    VkPipelineStageFlags stage; // the pipeline stage of those accesses
};

inline VkDescriptorType descriptor_type(codegen::resource_kind k)
{
    switch (k) {
    case codegen::resource_kind::uniform_buffer: return VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER;
    case codegen::resource_kind::combined_image_sampler: return VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER;
    case codegen::resource_kind::sampled_image: return VK_DESCRIPTOR_TYPE_SAMPLED_IMAGE;
    case codegen::resource_kind::sampler: return VK_DESCRIPTOR_TYPE_SAMPLER;
    case codegen::resource_kind::storage_image: return VK_DESCRIPTOR_TYPE_STORAGE_IMAGE;
    }
    throw error("vulkan: unknown resource kind");
}

class pass_pipelines {
public:
    // The passes of plan `p`, built from `sources`: codegen::generate(p)'s, or texts of the
    // same shaders by another road (a target's round trip, the report's floors) -- one per
    // shader of the plan, in its order, of the same pass and stage. `name` names them in
    // messages (empty: the plan's name). The plan gives each pass's workgroup, pixels per
    // invocation and sizes (plan(): what bound_chain binds).
    pass_pipelines(context& ctx, const codegen::plan& p, const std::vector<codegen::shader_source>& sources, spirv_cache* cache = nullptr,
                   std::string name = "")
        : ctx_(ctx), plan_(p), name_(name.empty() ? p.name() : std::move(name))
    {
        require_planned(sources);
        if (fragment() && !ctx.graphics())
            throw error("vulkan: " + name_ + " is a fragment chain, and the queue of " + ctx.device_name() +
                        " has no graphics (valid: stage compute on this device)");
        spirv_cache own_cache;
        try {
            build(sources, cache ? *cache : own_cache);
        } catch (...) {
            destroy();
            throw;
        }
    }
    ~pass_pipelines() { destroy(); }
    pass_pipelines(const pass_pipelines&) = delete;
    pass_pipelines& operator=(const pass_pipelines&) = delete;

    size_t size() const { return passes_.size(); }
    const pass_pipeline& operator[](size_t i) const { return passes_[i]; }
    bool fragment() const { return plan_.variant().stage == pipeline_stage::fragment; }
    const std::string& name() const { return name_; }
    const codegen::plan& plan() const { return plan_; }
    // Do the passes write a bent normal beside the AO (a -bn variant's: .gba of rgba8)?
    bool bent_normals() const { return plan_.variant().bent_normals; }

    // Where the passes read their inputs (uploads and the previous pass's output).
    VkPipelineStageFlags reader_stage() const
    {
        return fragment() ? VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT : VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT;
    }

    output_use output() const
    {
        if (fragment())
            // LOAD_OP_LOAD reads the attachment (the clear value shows wherever no fragment is written).
            return {VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
                    VK_ACCESS_COLOR_ATTACHMENT_READ_BIT | VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT, VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT};
        return {VK_IMAGE_USAGE_STORAGE_BIT, VK_IMAGE_LAYOUT_GENERAL, VK_ACCESS_SHADER_WRITE_BIT, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT};
    }

    // The framebuffer through which fragment pass `i` writes `target` (w × h), owned by `sc`
    // -- and, the history pass, `history` (its second attachment: the history it writes);
    // null for compute passes, which write their storage images directly.
    VkFramebuffer make_framebuffer(resource_scope& sc, size_t i, const image& target, int w, int h, const image* history = nullptr) const
    {
        if (!fragment()) return VK_NULL_HANDLE;
        const bool two = passes_[i].kind == pass_kind::history;
        if (two != (history != nullptr))
            throw error("vulkan: a framebuffer of " + name_ + "'s " + names::name_of(pass_kind_names, passes_[i].kind, "pass") + " pass " +
                        (two ? "without its history image" : "with a history image") + " (valid: the history pass writes two, the others one)");
        const VkImageView views[2] = {target.view, two ? history->view : VK_NULL_HANDLE};
        VkFramebufferCreateInfo fi{VK_STRUCTURE_TYPE_FRAMEBUFFER_CREATE_INFO};
        fi.renderPass = two ? history_render_pass_ : render_pass_;
        fi.attachmentCount = two ? 2 : 1;
        fi.pAttachments = views;
        fi.width = static_cast<uint32_t>(w);
        fi.height = static_cast<uint32_t>(h);
        fi.layers = 1;
        VkFramebuffer fb;
        check(vkCreateFramebuffer(ctx_.device(), &fi, nullptr, &fb), "vkCreateFramebuffer");
        return sc.own(fb, vkDestroyFramebuffer);
    }

    // Records pass `i` with `set` bound, writing its output (w × h, in output().layout;
    // `framebuffer` from make_framebuffer for fragment passes). For the prefilter, w × h is
    // the depth buffer's size, which it is dispatched over, not its atlas's.
    void record(VkCommandBuffer cb, size_t i, VkDescriptorSet set, VkFramebuffer framebuffer, int w, int h) const
    {
        const pass_pipeline& p = passes_[i];
        const VkPipelineBindPoint point = fragment() ? VK_PIPELINE_BIND_POINT_GRAPHICS : VK_PIPELINE_BIND_POINT_COMPUTE;
        if (fragment()) begin_render_pass(cb, p.kind == pass_kind::history ? history_render_pass_ : render_pass_, framebuffer, w, h);
        vkCmdBindPipeline(cb, point, p.pipeline);
        vkCmdBindDescriptorSets(cb, point, p.layout, 0, 1, &set, 0, nullptr);
        if (fragment()) {
            vkCmdDraw(cb, 3, 1, 0, 0); // the fullscreen triangle from gl_VertexIndex
            vkCmdEndRenderPass(cb);
        } else {
            const codegen::shader_plan& planned = plan_.pass_shader(i);
            const int k = planned.pixels_per_invocation;
            const auto [wx, wy] = planned.workgroup;
            vkCmdDispatch(cb, groups((w + k - 1) / k, wx), groups((h + k - 1) / k, wy), 1);
        }
    }

private:
    void require_planned(const std::vector<codegen::shader_source>& sources) const
    {
        const std::vector<codegen::shader_plan>& shaders = plan_.shaders();
        bool same = sources.size() == shaders.size();
        for (size_t i = 0; same && i < sources.size(); ++i) same = sources[i].pass == shaders[i].pass && sources[i].stage == shaders[i].stage;
        if (!same) fail("vulkan passes of " + name_, "were given sources of another plan", "valid: a source per shader of the plan, in its order");
    }

    static uint32_t groups(int size, int workgroup) { return static_cast<uint32_t>((size + workgroup - 1) / workgroup); }

    void build(const std::vector<codegen::shader_source>& sources, spirv_cache& cache)
    {
        if (fragment()) {
            render_pass_ = make_render_pass({ao_format});
            if (has_history_pass(plan_.variant())) history_render_pass_ = make_render_pass({ao_format, image_format_of(codegen::history_format)});
        }
        VkShaderModule vertex = VK_NULL_HANDLE;
        for (const codegen::shader_source& s : sources) {
            if (s.stage == shader_stage::vertex) {
                if (!vertex) vertex = make_module(cache.get(s));
                continue;
            }
            require_storage_in_fragment(s);
            VkFormat own = ao_format;
            for (const codegen::resource& r : s.resources)
                if (r.role == resource_role::output) {
                    own = image_format_of(r.format);
                    if (s.pass == pass_kind::prefilter) continue; // its atlas is no AO image
                    if (!has_ao_output_) output_format_ = own, has_ao_output_ = true;
                    else if (own != output_format_) throw error("vulkan: " + s.name + " writes " + r.format + ", another pass of " + name_ + " another format (valid: one output format per chain)");
                }
            passes_.push_back({s.pass, s.resources, own});
            pass_pipeline& p = passes_.back();
            make_layouts(p);
            if (fragment()) make_graphics(p, vertex, make_module(cache.get(s)));
            else make_compute(p, make_module(cache.get(s)));
        }
    }

    // A fragment shader that stores to an image (the raw values of diagnostic mode) needs
    // the device's fragmentStoresAndAtomics.
    void require_storage_in_fragment(const codegen::shader_source& s) const
    {
        if (s.stage != shader_stage::fragment || ctx_.fragment_stores()) return;
        for (const codegen::resource& r : s.resources)
            if (r.kind == codegen::resource_kind::storage_image)
                throw error("vulkan: " + s.name + " stores to image '" + r.name + "' from a fragment shader, which " + ctx_.device_name() +
                            " does not support (valid: a compute variant, or no raw diagnostics)");
    }

    // A module declaring the Float16 capability (an fp16 variant's AO pass) needs the
    // device's shaderFloat16.
    void require_float16(const std::vector<uint32_t>& spirv) const
    {
        if (ctx_.shader_float16()) return;
        const uint32_t op_capability = 17, float16 = 9; // SPIR-V's OpCapability and Capability Float16
        for (size_t i = 5; i < spirv.size();) { // after the header, instruction by instruction
            const uint32_t words = spirv[i] >> 16, opcode = spirv[i] & 0xffffu;
            if (opcode == op_capability && words == 2 && i + 1 < spirv.size() && spirv[i + 1] == float16)
                throw error("vulkan: " + name_ + " does 16-bit float arithmetic, which " + ctx_.device_name() +
                            " does not support (valid: a device with shaderFloat16, or the variant without -fp16)");
            if (words == 0) break;
            i += words;
        }
    }

    VkShaderModule make_module(const std::vector<uint32_t>& spirv)
    {
        require_float16(spirv);
        VkShaderModuleCreateInfo smi{VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO};
        smi.codeSize = spirv.size() * 4;
        smi.pCode = spirv.data();
        VkShaderModule m;
        check(vkCreateShaderModule(ctx_.device(), &smi, nullptr, &m), "vkCreateShaderModule");
        modules_.push_back(m);
        return m;
    }

    void make_layouts(pass_pipeline& p)
    {
        const VkShaderStageFlags visible = fragment() ? VK_SHADER_STAGE_FRAGMENT_BIT : VK_SHADER_STAGE_COMPUTE_BIT;
        std::vector<VkDescriptorSetLayoutBinding> lb;
        for (const codegen::resource& r : p.resources) lb.push_back({r.binding, descriptor_type(r.kind), 1, visible, nullptr});
        VkDescriptorSetLayoutCreateInfo dli{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO};
        dli.bindingCount = static_cast<uint32_t>(lb.size());
        dli.pBindings = lb.data();
        check(vkCreateDescriptorSetLayout(ctx_.device(), &dli, nullptr, &p.set_layout), "vkCreateDescriptorSetLayout");
        VkPipelineLayoutCreateInfo pli{VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO};
        pli.setLayoutCount = 1;
        pli.pSetLayouts = &p.set_layout;
        check(vkCreatePipelineLayout(ctx_.device(), &pli, nullptr, &p.layout), "vkCreatePipelineLayout");
    }

    static VkPipelineShaderStageCreateInfo stage_info(VkShaderStageFlagBits stage, VkShaderModule m)
    {
        VkPipelineShaderStageCreateInfo s{VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO};
        s.stage = stage;
        s.module = m;
        s.pName = "main";
        return s;
    }

    void make_compute(pass_pipeline& p, VkShaderModule m)
    {
        VkComputePipelineCreateInfo cpi{VK_STRUCTURE_TYPE_COMPUTE_PIPELINE_CREATE_INFO};
        cpi.stage = stage_info(VK_SHADER_STAGE_COMPUTE_BIT, m);
        cpi.layout = p.layout;
        check(vkCreateComputePipelines(ctx_.device(), VK_NULL_HANDLE, 1, &cpi, nullptr, &p.pipeline), "vkCreateComputePipelines");
    }

    // A colour attachment per format (the AO; the history pass's history second), each
    // loaded (the caller cleared it) and stored, in COLOR_ATTACHMENT_OPTIMAL before, during
    // and after the pass: the caller's barriers do every layout transition, as for compute.
    VkRenderPass make_render_pass(const std::vector<VkFormat>& formats) const
    {
        std::vector<VkAttachmentDescription> attachments;
        std::vector<VkAttachmentReference> refs;
        for (VkFormat f : formats) {
            VkAttachmentDescription a{};
            a.format = f;
            a.samples = VK_SAMPLE_COUNT_1_BIT;
            a.loadOp = VK_ATTACHMENT_LOAD_OP_LOAD;
            a.storeOp = VK_ATTACHMENT_STORE_OP_STORE;
            a.stencilLoadOp = VK_ATTACHMENT_LOAD_OP_DONT_CARE;
            a.stencilStoreOp = VK_ATTACHMENT_STORE_OP_DONT_CARE;
            a.initialLayout = a.finalLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
            refs.push_back({static_cast<uint32_t>(attachments.size()), VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL});
            attachments.push_back(a);
        }
        VkSubpassDescription sub{};
        sub.pipelineBindPoint = VK_PIPELINE_BIND_POINT_GRAPHICS;
        sub.colorAttachmentCount = static_cast<uint32_t>(refs.size());
        sub.pColorAttachments = refs.data();
        VkRenderPassCreateInfo rpi{VK_STRUCTURE_TYPE_RENDER_PASS_CREATE_INFO};
        rpi.attachmentCount = static_cast<uint32_t>(attachments.size());
        rpi.pAttachments = attachments.data();
        rpi.subpassCount = 1;
        rpi.pSubpasses = &sub;
        VkRenderPass rp;
        check(vkCreateRenderPass(ctx_.device(), &rpi, nullptr, &rp), "vkCreateRenderPass");
        return rp;
    }

    // Viewport and scissor are dynamic: the target size is known only when a G-buffer is run.
    void make_graphics(pass_pipeline& p, VkShaderModule vertex, VkShaderModule fragment_module)
    {
        const VkPipelineShaderStageCreateInfo stages[2] = {stage_info(VK_SHADER_STAGE_VERTEX_BIT, vertex),
                                                           stage_info(VK_SHADER_STAGE_FRAGMENT_BIT, fragment_module)};
        VkPipelineVertexInputStateCreateInfo vi{VK_STRUCTURE_TYPE_PIPELINE_VERTEX_INPUT_STATE_CREATE_INFO};
        VkPipelineInputAssemblyStateCreateInfo ia{VK_STRUCTURE_TYPE_PIPELINE_INPUT_ASSEMBLY_STATE_CREATE_INFO};
        ia.topology = VK_PRIMITIVE_TOPOLOGY_TRIANGLE_LIST;
        VkPipelineViewportStateCreateInfo vp{VK_STRUCTURE_TYPE_PIPELINE_VIEWPORT_STATE_CREATE_INFO};
        vp.viewportCount = vp.scissorCount = 1;
        VkPipelineRasterizationStateCreateInfo rs{VK_STRUCTURE_TYPE_PIPELINE_RASTERIZATION_STATE_CREATE_INFO};
        rs.polygonMode = VK_POLYGON_MODE_FILL;
        rs.cullMode = VK_CULL_MODE_NONE;
        rs.lineWidth = 1.0f;
        VkPipelineMultisampleStateCreateInfo ms{VK_STRUCTURE_TYPE_PIPELINE_MULTISAMPLE_STATE_CREATE_INFO};
        ms.rasterizationSamples = VK_SAMPLE_COUNT_1_BIT;
        const bool history = p.kind == pass_kind::history; // its history is colour attachment 1
        // R8_UNORM has only R; RGBA16F all four. Without the independentBlend feature every
        // attachment's state must be the same: all four bits, which R8 ignores past R.
        VkPipelineColorBlendAttachmentState att[2]{};
        att[0].colorWriteMask = att[1].colorWriteMask = history ? VK_COLOR_COMPONENT_R_BIT | VK_COLOR_COMPONENT_G_BIT | VK_COLOR_COMPONENT_B_BIT | VK_COLOR_COMPONENT_A_BIT
                                                                : VK_COLOR_COMPONENT_R_BIT;
        VkPipelineColorBlendStateCreateInfo cb{VK_STRUCTURE_TYPE_PIPELINE_COLOR_BLEND_STATE_CREATE_INFO};
        cb.attachmentCount = history ? 2 : 1;
        cb.pAttachments = att;
        const VkDynamicState dynamic[2] = {VK_DYNAMIC_STATE_VIEWPORT, VK_DYNAMIC_STATE_SCISSOR};
        VkPipelineDynamicStateCreateInfo ds{VK_STRUCTURE_TYPE_PIPELINE_DYNAMIC_STATE_CREATE_INFO};
        ds.dynamicStateCount = 2;
        ds.pDynamicStates = dynamic;
        VkGraphicsPipelineCreateInfo gpi{VK_STRUCTURE_TYPE_GRAPHICS_PIPELINE_CREATE_INFO};
        gpi.stageCount = 2;
        gpi.pStages = stages;
        gpi.pVertexInputState = &vi;
        gpi.pInputAssemblyState = &ia;
        gpi.pViewportState = &vp;
        gpi.pRasterizationState = &rs;
        gpi.pMultisampleState = &ms;
        gpi.pColorBlendState = &cb;
        gpi.pDynamicState = &ds;
        gpi.layout = p.layout;
        gpi.renderPass = history ? history_render_pass_ : render_pass_;
        check(vkCreateGraphicsPipelines(ctx_.device(), VK_NULL_HANDLE, 1, &gpi, nullptr, &p.pipeline), "vkCreateGraphicsPipelines");
    }

    // A framebuffer of `target` (destroyed with `sc`), the render pass begun on it and the
    // viewport and scissor set to all of it.
    void begin_render_pass(VkCommandBuffer cb, VkRenderPass render_pass, VkFramebuffer framebuffer, int w, int h) const
    {
        const VkExtent2D size{static_cast<uint32_t>(w), static_cast<uint32_t>(h)};
        VkRenderPassBeginInfo rbi{VK_STRUCTURE_TYPE_RENDER_PASS_BEGIN_INFO};
        rbi.renderPass = render_pass;
        rbi.framebuffer = framebuffer;
        rbi.renderArea = {{0, 0}, size};
        vkCmdBeginRenderPass(cb, &rbi, VK_SUBPASS_CONTENTS_INLINE);
        const VkViewport viewport{0.0f, 0.0f, float(w), float(h), 0.0f, 1.0f};
        const VkRect2D scissor{{0, 0}, size};
        vkCmdSetViewport(cb, 0, 1, &viewport);
        vkCmdSetScissor(cb, 0, 1, &scissor);
    }

    void destroy()
    {
        VkDevice d = ctx_.device();
        for (pass_pipeline& p : passes_) {
            if (p.pipeline) vkDestroyPipeline(d, p.pipeline, nullptr);
            if (p.layout) vkDestroyPipelineLayout(d, p.layout, nullptr);
            if (p.set_layout) vkDestroyDescriptorSetLayout(d, p.set_layout, nullptr);
        }
        passes_.clear();
        for (VkShaderModule m : modules_) vkDestroyShaderModule(d, m, nullptr);
        modules_.clear();
        for (VkRenderPass* rp : {&render_pass_, &history_render_pass_}) {
            if (*rp) vkDestroyRenderPass(d, *rp, nullptr);
            *rp = VK_NULL_HANDLE;
        }
    }

    context& ctx_;
    codegen::plan plan_;
    std::string name_;
    VkFormat output_format_ = ao_format;
    bool has_ao_output_ = false; // output_format_ is a pass's, not the default
    std::vector<pass_pipeline> passes_;
    std::vector<VkShaderModule> modules_; // every module, the shared vertex shader once
    VkRenderPass render_pass_ = VK_NULL_HANDLE;         // every fragment pass's but the history's: the AO
    VkRenderPass history_render_pass_ = VK_NULL_HANDLE; // the history pass's: the AO, then its history
};

} // namespace aogen::vulkan
