// aogen/vulkan/bound_chain.hpp — a chain's passes bound once to their inputs, then
// dispatched as often as wanted.
//
// WHAT
//   bound_chain takes compiled passes (pass_pipelines: a variant's, or the report's
//   fetch-floor kernels), an uploaded G-buffer (gpu_gbuffer, shared with other chains) and
//   the chain's own inputs (chain_inputs: uniform bytes per pass, noise tile), and makes,
//   once, everything a frame loop keeps: device-local uniform buffers and noise image, one
//   output image per pass (R8_UNORM, or R8G8B8A8_UNORM for rgba8 passes: passes.hpp) (pass i writes output i, pass i + 1 samples it), the
//   framebuffers of fragment passes, one descriptor set per pass. Then:
//     record(cb, timestamps)  records the whole chain -- one frame -- into a command buffer,
//                             as many times as the caller likes (timing.hpp records it
//                             hundreds of times back to back); with a query pool, one
//                             timestamp before the first pass and one after each pass;
//     next_frame()            a history chain's next frame: its two history images swap;
//     run_once(clear)         fills every output with `clear`, runs the chain once and reads
//                             back the last output as floats, with each pass's GPU time —
//                             and, for passes built with codegen::options::diagnostics, what
//                             their raw images held (diagnostics.hpp's raw_counts per pass).
//   Outputs rest in SHADER_READ_ONLY_OPTIMAL between passes and chains: each pass moves its
//   output to the layout it writes in (GENERAL for compute, COLOR_ATTACHMENT_OPTIMAL for
//   fragment) and back, so record() can follow itself or any other chain. Every record()
//   starts with a full execution barrier, so its passes never overlap the work recorded
//   before it and a pass's time is its own, not shared with its neighbour's.
//   The AO target size is the plan's (pass_pipelines::plan().target_size of the G-buffer's
//   size); every pass's output has that size but the upsample pass's, which has the
//   G-buffer's, and the prefilter's, the r32f atlas of the depth MIP chain
//   (aogen/depth_mips.hpp) the AO pass reads.
//
// USAGE
//     const aogen::codegen::plan plan = aogen::codegen::make_plan(v);
//     aogen::vulkan::pass_pipelines passes(ctx, plan, aogen::codegen::generate(plan));
//     aogen::vulkan::gpu_gbuffer g(ctx, host_gbuffer);
//     aogen::vulkan::bound_chain b(ctx, passes, g, plan.inputs(settings, g.width(), g.height()));
//     aogen::vulkan::chain_result r = b.run_once();         // r.ao, r.pass_ms, r.raw
//     // timing.hpp: time_chains(ctx, {&b, &other}, options)
//
// ERRORS
//   aogen::error: a pass reading normals the G-buffer does not have, uniform bytes for the
//   wrong number of passes, an unknown resource name, a failing Vulkan call.
#pragma once

#include <aogen/bent_normals.hpp>
#include <aogen/half.hpp>
#include "diagnostics.hpp"
#include "inputs.hpp"
#include "passes.hpp"

#include <algorithm>
#include <cstring>
#include <memory>
#include <string>
#include <vector>

namespace aogen::vulkan {

struct chain_result {
    int width = 0, height = 0;
    std::vector<float> ao;           // width × height, the last pass's output
    std::vector<float> bent_normal;  // a -bn chain's: 3 per pixel, view space, unit or 0 (none: bent_normals.hpp); else empty
    std::vector<std::string> passes; // "ao", "blur_x", ...
    std::vector<double> pass_ms;     // GPU time of each pass; empty without timestamps
    std::vector<raw_counts> raw;     // per pass, for diagnostic passes; empty otherwise
};

// Where record() writes its timestamps: pool, from query `first` on (queries() of them).
struct timestamp_slots {
    VkQueryPool pool = VK_NULL_HANDLE;
    uint32_t first = 0;
};

// The results of every query of `pool` [0, count), waited for.
inline std::vector<uint64_t> read_queries(const context& ctx, VkQueryPool pool, uint32_t count)
{
    std::vector<uint64_t> ticks(count);
    check(vkGetQueryPoolResults(ctx.device(), pool, 0, count, ticks.size() * 8, ticks.data(), 8, VK_QUERY_RESULT_64_BIT | VK_QUERY_RESULT_WAIT_BIT),
          "vkGetQueryPoolResults");
    return ticks;
}

class bound_chain {
public:
    // `in`: the bytes the passes read (passes.plan().inputs(settings, g's size), or bytes
    // made from them). `counter` counts the raw images of diagnostic passes (one is made on
    // first use if null).
    bound_chain(context& ctx, const pass_pipelines& passes, const gpu_gbuffer& g, const chain_inputs& in, const raw_counter* counter = nullptr)
        : ctx_(ctx), passes_(passes), scope_(ctx), counter_(counter)
    {
        depth_size_ = {g.width(), g.height()};
        const auto [target_width, target_height] = passes.plan().target_size(g.width(), g.height());
        for (size_t i = 0; i < passes.size(); ++i) sizes_.push_back(output_size_of(passes[i].kind, target_width, target_height));
        if (in.uniforms.size() != passes.size())
            throw error("vulkan bound chain: uniform bytes for " + std::to_string(in.uniforms.size()) + " passes given to " + passes.name() +
                        " (valid: one block per pass, " + std::to_string(passes.size()) + ")");
        for (size_t i = 0; i < passes.size(); ++i) {
            has_raw_ = has_raw_ || declares_raw(i);
            if (passes[i].kind == pass_kind::history) history_pass_ = i;
        }
        resource_scope staging(ctx);
        VkCommandBuffer cb = staging.begin_commands();
        upload_inputs(cb, in, staging);
        make_outputs(cb);
        staging.submit(cb);
        write_sets(g);
    }
    bound_chain(const bound_chain&) = delete;
    bound_chain& operator=(const bound_chain&) = delete;

    const pass_pipelines& passes() const { return passes_; }
    // The size of the chain's output: the last pass's.
    int width() const { return sizes_.back().first; }
    int height() const { return sizes_.back().second; }
    // Timestamps one record() writes: one before the first pass, one after each.
    uint32_t queries() const { return static_cast<uint32_t>(passes_.size() + 1); }

    // Records every pass in order (see the header comment for barriers and layouts).
    void record(VkCommandBuffer cb, timestamp_slots ts = {}) const
    {
        // Nothing recorded before overlaps this chain, and nothing of it overlaps what follows.
        vkCmdPipelineBarrier(cb, VK_PIPELINE_STAGE_ALL_COMMANDS_BIT, VK_PIPELINE_STAGE_ALL_COMMANDS_BIT, 0, 0, nullptr, 0, nullptr, 0, nullptr);
        const output_use use = passes_.output();
        const VkPipelineStageFlags readers = passes_.reader_stage() | VK_PIPELINE_STAGE_TRANSFER_BIT;
        // Both timestamps of a pass at BOTTOM_OF_PIPE: written once everything before has
        // finished, so the intervals follow one another and sum to the chain.
        if (ts.pool) vkCmdWriteTimestamp(cb, VK_PIPELINE_STAGE_BOTTOM_OF_PIPE_BIT, ts.pool, ts.first);
        for (size_t i = 0; i < passes_.size(); ++i) {
            const image& out = outputs_[i];
            barrier(cb, out, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL, use.layout, 0, use.access, readers, use.stage);
            if (has_raw_) raw_barrier(cb, raws_[i]);
            const bool history = i == history_pass_;
            if (history) history_write_barrier(cb, true);
            const auto [w, h] = dispatch_size(i);
            passes_.record(cb, i, history && parity_ ? history_set_ : sets_[i], history && parity_ ? history_framebuffer_ : framebuffers_[i], w, h);
            barrier(cb, out, use.layout, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL, use.access, VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_TRANSFER_READ_BIT,
                    use.stage, readers);
            if (history) history_write_barrier(cb, false);
            if (ts.pool) vkCmdWriteTimestamp(cb, VK_PIPELINE_STAGE_BOTTOM_OF_PIPE_BIT, ts.pool, ts.first + static_cast<uint32_t>(i + 1));
        }
    }

    // The next frame: the history the last frame wrote becomes the one record() reads (a
    // history chain's two images swap; nothing else changes). run_once() calls it after its
    // frame; a caller's own frame loop calls it after submitting each record(). The timing
    // loops record one frame over and over without it: each iteration that frame again.
    void next_frame()
    {
        if (history_pass_ != no_pass) parity_ ^= 1;
    }

    // Does the chain keep a history (a -hist or -histmv variant)?
    bool has_history() const { return history_pass_ != no_pass; }

    // The history the next record() reads -- the one the last wrote -- as 4 floats per AO
    // target texel (.r AO, .g log2 view depth, .b frames held; history.glsl).
    std::vector<float> read_history() const
    {
        require_history("read_history");
        const auto [w, h] = sizes_[history_pass_];
        resource_scope sc(ctx_);
        VkCommandBuffer cb = sc.begin_commands();
        const image& img = history_[parity_];
        barrier(cb, img, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, VK_ACCESS_SHADER_READ_BIT,
                VK_ACCESS_TRANSFER_READ_BIT, passes_.reader_stage(), VK_PIPELINE_STAGE_TRANSFER_BIT);
        const buffer host = sc.read_back(cb, img, w, h, 8);
        barrier(cb, img, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL, VK_ACCESS_TRANSFER_READ_BIT,
                VK_ACCESS_SHADER_READ_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT, passes_.reader_stage());
        sc.submit(cb);
        std::vector<float> out(static_cast<size_t>(w) * h * 4);
        const auto* halves = static_cast<const uint16_t*>(host.mapped);
        for (size_t k = 0; k < out.size(); ++k) out[k] = half_to_float(halves[k]);
        return out;
    }

    // Replaces the history the next record() reads by `rgba` (4 floats per texel, rounded
    // to 16 bits): an engine's own history, or a test's planted values. It must have the AO
    // target's size: another is refused by name.
    void load_history(int w, int h, const std::vector<float>& rgba)
    {
        require_history("load_history");
        const auto [tw, th] = sizes_[history_pass_];
        if (w != tw || h != th || rgba.size() != static_cast<size_t>(w < 0 ? 0 : w) * static_cast<size_t>(h < 0 ? 0 : h) * 4)
            fail("history", std::to_string(w) + "x" + std::to_string(h) + " with " + std::to_string(rgba.size()) + " values is not the AO target of " +
                                passes_.name() + " for a " + std::to_string(depth_size_.first) + "x" + std::to_string(depth_size_.second) + " G-buffer",
                 "valid: " + std::to_string(tw) + "x" + std::to_string(th) + ", 4 values per texel");
        std::vector<uint16_t> halves(rgba.size());
        for (size_t k = 0; k < rgba.size(); ++k) halves[k] = float_to_half(rgba[k]);
        resource_scope staging(ctx_);
        VkCommandBuffer cb = staging.begin_commands();
        scope_.update_image(cb, history_[parity_], w, h, halves.data(), halves.size() * 2, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL,
                            passes_.reader_stage(), staging);
        staging.submit(cb);
    }

    // New uniform bytes for every pass, the same sizes (another frame of the same settings:
    // plan.inputs with another chain_settings::frame); the noise tile, the G-buffer and the
    // outputs stay as bound. A frame loop runs one binding frame after frame this way.
    void set_uniforms(const chain_inputs& in)
    {
        bool same = in.uniforms.size() == uniforms_.size();
        for (size_t i = 0; same && i < uniforms_.size(); ++i) same = in.uniforms[i].size() == uniforms_[i].second;
        if (!same) throw error("vulkan bound chain: new uniform bytes for " + passes_.name() + " of other sizes (valid: one block per pass, as bound)");
        resource_scope staging(ctx_);
        VkCommandBuffer cb = staging.begin_commands();
        for (size_t i = 0; i < uniforms_.size(); ++i)
            scope_.update_buffer(cb, uniforms_[i].first, in.uniforms[i].data(), in.uniforms[i].size(), passes_.reader_stage(), staging);
        staging.submit(cb);
    }

    // Another G-buffer of the same size for the frames to come (a frame loop's next frame:
    // another view, other motion vectors); uniforms, noise, outputs and history stay. Every
    // set is written anew, so nothing recorded before may still be running: run_once() and
    // the timing loops wait for their work.
    void set_gbuffer(const gpu_gbuffer& g)
    {
        if (g.width() != depth_size_.first || g.height() != depth_size_.second)
            fail("vulkan bound chain G-buffer", std::to_string(g.width()) + "x" + std::to_string(g.height()) + " for " + passes_.name() + " bound to " +
                                                    std::to_string(depth_size_.first) + "x" + std::to_string(depth_size_.second),
                 "valid: the size it was bound with (bind the chain anew for another size)");
        write_sets(g);
    }

    // Every output filled with `clear`, the chain run once -- one frame: next_frame() after
    // it --, the last output read back.
    chain_result run_once(float clear = 0.0f)
    {
        resource_scope sc(ctx_);
        VkCommandBuffer cb = sc.begin_commands();
        for (const image& out : outputs_) clear_output(cb, out, clear, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL);
        const VkQueryPool pool = make_query_pool(sc, cb);
        record(cb, {pool, 0});
        const size_t last = outputs_.size() - 1;
        const buffer ao = record_read_back(sc, cb, last);
        const buffer counts = has_raw_ ? count_raw(sc, cb) : buffer{};
        sc.submit(cb);
        next_frame();

        chain_result out;
        out.width = width(), out.height = height();
        out.ao = decode_output(last, ao);
        if (passes_.bent_normals()) out.bent_normal = bent_normals_of(last, ao);
        for (size_t i = 0; i < passes_.size(); ++i) out.passes.push_back(names::name_of(pass_kind_names, passes_[i].kind, "pass"));
        if (pool) out.pass_ms = pass_ms(read_queries(ctx_, pool, queries()), 0);
        if (has_raw_)
            for (size_t i = 0; i < passes_.size(); ++i)
                out.raw.push_back(raw_counter::decode(static_cast<const uint8_t*>(counts.mapped) + count_stride() * i));
        return out;
    }

    // The output pass `i` holds now (after run_once), as floats: the AO of an r8/rgba8 image
    // (its first channel, / 255), or the r32f values of the prefilter's depth MIP atlas.
    // width × height of that pass's output (output_size(i)).
    std::vector<float> read_output(size_t i) const
    {
        if (i >= outputs_.size())
            throw error("vulkan bound chain: no pass " + std::to_string(i) + " in " + passes_.name() + " (valid: 0.." + std::to_string(outputs_.size() - 1) + ")");
        resource_scope sc(ctx_);
        VkCommandBuffer cb = sc.begin_commands();
        const buffer host = record_read_back(sc, cb, i);
        sc.submit(cb);
        return decode_output(i, host);
    }

    // The size of pass `i`'s output image.
    std::pair<int, int> output_size(size_t i) const { return sizes_.at(i); }

    // The GPU time of each pass, in ms, from the ticks record() wrote at `ticks[first...]`.
    std::vector<double> pass_ms(const std::vector<uint64_t>& ticks, size_t first) const
    {
        const uint64_t mask = ctx_.timestamp_valid_bits() >= 64 ? ~0ull : (1ull << ctx_.timestamp_valid_bits()) - 1;
        std::vector<double> ms;
        for (size_t i = 0; i < passes_.size(); ++i)
            ms.push_back(double((ticks[first + i + 1] - ticks[first + i]) & mask) * ctx_.timestamp_period_ns() * 1e-6);
        return ms;
    }

private:
    static constexpr size_t no_pass = ~size_t(0);

    void require_history(const char* what) const
    {
        if (history_pass_ == no_pass)
            fail("vulkan bound chain " + std::string(what), passes_.name() + " has no history pass", "valid: a -hist or -histmv variant");
    }

    // The history the history pass writes this frame, moved to the layout the pass writes in
    // (GENERAL for compute, COLOR_ATTACHMENT_OPTIMAL for fragment: passes.hpp's output())
    // before the pass (`before`) and back to SHADER_READ_ONLY_OPTIMAL after it; the one it
    // reads stays there.
    void history_write_barrier(VkCommandBuffer cb, bool before) const
    {
        const image& written = history_[parity_ ^ 1];
        const output_use use = passes_.output();
        const VkPipelineStageFlags readers = passes_.reader_stage() | VK_PIPELINE_STAGE_TRANSFER_BIT;
        const VkAccessFlags reads = VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_TRANSFER_READ_BIT;
        if (before)
            barrier(cb, written, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL, use.layout, reads, use.access, readers, use.stage);
        else
            barrier(cb, written, use.layout, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL, use.access, reads, use.stage, readers);
    }

    // Records the copy of output `i` into a host buffer, leaving the image where it was
    // (SHADER_READ_ONLY_OPTIMAL); the buffer holds its texels once `cb` is submitted.
    buffer record_read_back(resource_scope& sc, VkCommandBuffer cb, size_t i) const
    {
        const auto [w, h] = sizes_[i];
        const image& img = outputs_[i];
        barrier(cb, img, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, VK_ACCESS_SHADER_READ_BIT,
                VK_ACCESS_TRANSFER_READ_BIT, passes_.reader_stage(), VK_PIPELINE_STAGE_TRANSFER_BIT);
        const buffer host = sc.read_back(cb, img, w, h, texel_bytes(passes_[i].output_format));
        barrier(cb, img, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL, VK_ACCESS_TRANSFER_READ_BIT,
                VK_ACCESS_SHADER_READ_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT, passes_.reader_stage());
        return host;
    }

    // Output `i`'s texels, read back into `host`, as floats: an r32f texel as it is, the
    // first channel of an r8/rgba8 one / 255.
    std::vector<float> decode_output(size_t i, const buffer& host) const
    {
        const auto [w, h] = sizes_[i];
        const VkFormat format = passes_[i].output_format;
        const size_t texel = texel_bytes(format);
        std::vector<float> out(static_cast<size_t>(w) * h);
        const auto* bytes = static_cast<const uint8_t*>(host.mapped);
        for (size_t k = 0; k < out.size(); ++k) {
            if (format == VK_FORMAT_R32_SFLOAT) std::memcpy(&out[k], bytes + texel * k, 4);
            else out[k] = bytes[k * texel] / 255.0f;
        }
        return out;
    }

    // Output `i`'s bent normals (a -bn chain: .gba of rgba8, aogen/bent_normals.hpp), decoded.
    std::vector<float> bent_normals_of(size_t i, const buffer& host) const
    {
        if (passes_[i].output_format != VK_FORMAT_R8G8B8A8_UNORM)
            throw error("vulkan bound chain: " + passes_.name() + " writes bent normals to a format not read back here (valid: rgba8)");
        const auto [w, h] = sizes_[i];
        return aogen::decode_bent_normals(static_cast<const uint8_t*>(host.mapped), static_cast<size_t>(w) * h);
    }

    // The size of a pass's output image: the screen's for the upsample, the atlas of the
    // depth MIP chain for the prefilter — made for the most levels a variant may have, which
    // holds every shorter chain at the same places (aogen/depth_mips.hpp) — the target's
    // otherwise.
    std::pair<int, int> output_size_of(pass_kind pass, int target_width, int target_height) const
    {
        const auto [w, h] = depth_size_;
        if (pass == pass_kind::upsample) return {w, h};
        if (pass == pass_kind::prefilter) return depth_mips::atlas_size(w, h, depth_mips::levels_range.hi);
        return {target_width, target_height};
    }

    // The size pass `i` is dispatched over: its output's, but the prefilter's, which covers
    // the depth buffer it reduces and writes the smaller atlas around it.
    std::pair<int, int> dispatch_size(size_t i) const { return passes_[i].kind == pass_kind::prefilter ? depth_size_ : sizes_[i]; }

    bool declares_raw(size_t i) const
    {
        for (const codegen::resource& r : passes_[i].resources)
            if (r.role == resource_role::raw) return true;
        return false;
    }

    void upload_inputs(VkCommandBuffer cb, const chain_inputs& in, resource_scope& staging)
    {
        const VkPipelineStageFlags readers = passes_.reader_stage();
        for (const std::vector<uint8_t>& bytes : in.uniforms)
            uniforms_.push_back({scope_.upload_buffer(cb, bytes.data(), bytes.size(), VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT, readers, staging), bytes.size()});
        noise_ = scope_.upload(cb, in.noise_size, in.noise_size, VK_FORMAT_R32G32B32A32_SFLOAT, in.noise.data(), in.noise.size(), readers, staging);
        clamp_ = scope_.make_sampler(VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE);
        repeat_ = scope_.make_sampler(VK_SAMPLER_ADDRESS_MODE_REPEAT);
    }

    // One output per pass, cleared to 0 and left in SHADER_READ_ONLY_OPTIMAL; one raw image
    // per pass (GENERAL) for diagnostic passes.
    void make_outputs(VkCommandBuffer cb)
    {
        const output_use use = passes_.output();
        const VkImageUsageFlags usage = use.usage | VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT;
        // The history's two images (the engine's, in a renderer), cleared: 0 frames held.
        if (history_pass_ != no_pass) {
            const auto [w, h] = sizes_[history_pass_];
            for (image& img : history_) {
                img = scope_.make_image(w, h, image_format_of(codegen::history_format), usage);
                clear_output(cb, img, 0.0f, VK_IMAGE_LAYOUT_UNDEFINED);
            }
        }
        for (size_t i = 0; i < passes_.size(); ++i) {
            const auto [w, h] = sizes_[i];
            outputs_.push_back(scope_.make_image(w, h, passes_[i].output_format, usage));
            clear_output(cb, outputs_.back(), 0.0f, VK_IMAGE_LAYOUT_UNDEFINED);
            // A fragment history pass writes the history image of its parity: a framebuffer each.
            const bool history = i == history_pass_;
            framebuffers_.push_back(passes_.make_framebuffer(scope_, i, outputs_.back(), w, h, history ? &history_[1] : nullptr));
            if (history) history_framebuffer_ = passes_.make_framebuffer(scope_, i, outputs_.back(), w, h, &history_[0]);
            if (!has_raw_) continue;
            raws_.push_back(scope_.make_image(w, h, VK_FORMAT_R32_SFLOAT, VK_IMAGE_USAGE_STORAGE_BIT));
            barrier(cb, raws_.back(), VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_GENERAL, 0, VK_ACCESS_SHADER_WRITE_BIT,
                    VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT, passes_.reader_stage());
        }
    }

    // `img` (in `from`) filled with `value` and left in SHADER_READ_ONLY_OPTIMAL.
    void clear_output(VkCommandBuffer cb, const image& img, float value, VkImageLayout from) const
    {
        resource_scope::clear(cb, img, value, from);
        barrier(cb, img, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL, VK_ACCESS_TRANSFER_WRITE_BIT,
                VK_ACCESS_SHADER_READ_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT, passes_.reader_stage());
    }

    // The raw image a pass is about to write: finished with by whatever read or wrote it before.
    void raw_barrier(VkCommandBuffer cb, const image& raw) const
    {
        barrier(cb, raw, VK_IMAGE_LAYOUT_GENERAL, VK_IMAGE_LAYOUT_GENERAL, VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_SHADER_WRITE_BIT,
                VK_ACCESS_SHADER_WRITE_BIT, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT | passes_.reader_stage(), passes_.reader_stage());
    }

    VkQueryPool make_query_pool(resource_scope& sc, VkCommandBuffer cb) const
    {
        if (ctx_.timestamp_valid_bits() == 0) return VK_NULL_HANDLE;
        VkQueryPoolCreateInfo qpi{VK_STRUCTURE_TYPE_QUERY_POOL_CREATE_INFO};
        qpi.queryType = VK_QUERY_TYPE_TIMESTAMP;
        qpi.queryCount = queries();
        VkQueryPool pool;
        check(vkCreateQueryPool(ctx_.device(), &qpi, nullptr, &pool), "vkCreateQueryPool");
        sc.own(pool, vkDestroyQueryPool);
        vkCmdResetQueryPool(cb, pool, 0, queries());
        return pool;
    }

    // Bytes between two passes' counts: raw_counts_bytes, rounded up to the device's
    // alignment of storage-buffer descriptor offsets.
    size_t count_stride() const
    {
        const size_t a = static_cast<size_t>(ctx_.storage_buffer_alignment());
        return (raw_counts_bytes + a - 1) / a * a;
    }

    // Records the raw-value counts of every pass into a host buffer (after the passes).
    buffer count_raw(resource_scope& sc, VkCommandBuffer cb) const
    {
        if (!counter_) own_counter_ = std::make_unique<raw_counter>(ctx_), counter_ = own_counter_.get();
        const size_t stride = count_stride(), bytes = stride * passes_.size();
        const buffer counts = sc.make_device_buffer(bytes, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT |
                                                               VK_BUFFER_USAGE_TRANSFER_SRC_BIT);
        vkCmdFillBuffer(cb, counts.handle, 0, bytes, 0);
        buffer_barrier(cb, counts, VK_ACCESS_TRANSFER_WRITE_BIT, VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_SHADER_WRITE_BIT,
                       VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT);
        VkDescriptorPool pool = make_descriptor_pool(sc, {{VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, uint32_t(passes_.size())},
                                                          {VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, uint32_t(passes_.size())}},
                                                     uint32_t(passes_.size()));
        for (size_t i = 0; i < passes_.size(); ++i) {
            if (!declares_raw(i)) continue; // nothing written (the prefilter): its counts stay 0
            barrier(cb, raws_[i], VK_IMAGE_LAYOUT_GENERAL, VK_IMAGE_LAYOUT_GENERAL, VK_ACCESS_SHADER_WRITE_BIT, VK_ACCESS_SHADER_READ_BIT,
                    passes_.reader_stage(), VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT);
            counter_->record(cb, counter_->make_set(pool, raws_[i], counts, stride * i), sizes_[i].first, sizes_[i].second);
        }
        buffer_barrier(cb, counts, VK_ACCESS_SHADER_WRITE_BIT, VK_ACCESS_TRANSFER_READ_BIT, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT,
                       VK_PIPELINE_STAGE_TRANSFER_BIT);
        const buffer host = sc.make_host_buffer(bytes, VK_BUFFER_USAGE_TRANSFER_DST_BIT);
        const VkBufferCopy region{0, 0, bytes};
        vkCmdCopyBuffer(cb, counts.handle, host.handle, 1, &region);
        buffer_barrier(cb, host, VK_ACCESS_TRANSFER_WRITE_BIT, VK_ACCESS_HOST_READ_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_HOST_BIT);
        return host;
    }

    VkDescriptorPool make_descriptor_pool(resource_scope& sc, const std::vector<VkDescriptorPoolSize>& sizes, uint32_t max_sets) const
    {
        VkDescriptorPoolCreateInfo dpi{VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO};
        dpi.maxSets = max_sets;
        dpi.poolSizeCount = static_cast<uint32_t>(sizes.size());
        dpi.pPoolSizes = sizes.data();
        VkDescriptorPool pool;
        check(vkCreateDescriptorPool(ctx_.device(), &dpi, nullptr, &pool), "vkCreateDescriptorPool");
        return sc.own(pool, vkDestroyDescriptorPool);
    }

    // The pool for every pass's set: one descriptor per resource, by type.
    VkDescriptorPool make_pass_pool()
    {
        std::vector<VkDescriptorPoolSize> sizes;
        for (size_t i = 0; i < passes_.size(); ++i)
            for (int copy = 0; copy < (i == history_pass_ ? 2 : 1); ++copy) // the history pass: a set per history image read
                for (const codegen::resource& r : passes_[i].resources) {
                    const VkDescriptorType t = descriptor_type(r.kind);
                    auto it = std::find_if(sizes.begin(), sizes.end(), [t](const VkDescriptorPoolSize& p) { return p.type == t; });
                    if (it == sizes.end()) sizes.push_back({t, 1});
                    else ++it->descriptorCount;
                }
        return make_descriptor_pool(scope_, sizes, static_cast<uint32_t>(passes_.size() + (history_pass_ == no_pass ? 0 : 1)));
    }

    // The image and sampler a texture role of pass `i` reads.
    VkDescriptorImageInfo sampled(const codegen::resource& r, size_t i, const gpu_gbuffer& g, int parity) const
    {
        const VkImageLayout read = VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL;
        switch (r.role) {
        case resource_role::depth: return {clamp_, g.depth().view, read};
        case resource_role::normals:
            if (!g.has_normals())
                throw error("vulkan bound chain: " + passes_.name() + " reads normals, and the G-buffer has none (valid: a G-buffer with "
                            "width × height × 4 normals, or a reconstructed-normal variant)");
            return {clamp_, g.normals().view, read};
        case resource_role::gbuffer_albedo:
            if (!g.has_albedo())
                throw error("vulkan bound chain: " + passes_.name() + " reads the albedo G-buffer (-mbg), and the G-buffer has none (valid: a "
                            "G-buffer with width × height × 4 albedo values, e.g. with_uniform_albedo, or -mb's one albedo)");
            return {clamp_, g.albedo().view, read};
        case resource_role::noise: return {repeat_, noise_.view, read};
        case resource_role::history: return {clamp_, history_[parity].view, read};
        case resource_role::motion:
            if (!g.has_motion())
                throw error("vulkan bound chain: " + passes_.name() + " reads motion vectors (-histmv), and the G-buffer has none (valid: a "
                            "G-buffer with width × height × 2 motion values, or a -hist variant, which reprojects by the camera)");
            return {clamp_, g.motion().view, read};
        case resource_role::ao_input:
            if (i > 0) return {clamp_, outputs_[i - 1].view, read};
            break;
        case resource_role::depth_mips:
            for (size_t k = 0; k < i; ++k)
                if (passes_[k].kind == pass_kind::prefilter) return {clamp_, outputs_[k].view, read};
            break;
        default: break;
        }
        throw error("vulkan bound chain: unknown sampled resource '" + r.name +
                    "' (valid: depth, normals, noise, ao_input, depth_mips after a prefilter, albedo, history, motion)");
    }

    // A storage image of pass `i`: its output, or its raw values.
    VkDescriptorImageInfo stored(const codegen::resource& r, size_t i, int parity) const
    {
        if (r.role == resource_role::output) return {VK_NULL_HANDLE, outputs_[i].view, VK_IMAGE_LAYOUT_GENERAL};
        if (r.role == resource_role::raw) return {VK_NULL_HANDLE, raws_[i].view, VK_IMAGE_LAYOUT_GENERAL};
        if (r.role == resource_role::history_output) return {VK_NULL_HANDLE, history_[parity ^ 1].view, VK_IMAGE_LAYOUT_GENERAL};
        throw error("vulkan bound chain: unknown storage image '" + r.name + "' (valid: output, raw, history_output)");
    }

    // What descriptor `r` of pass `i` points at: WebGPU's separate textures and samplers
    // (binding_model::webgpu) take one half each of the combined descriptor.
    // `parity`: which history image a history pass reads (it writes the other).
    VkDescriptorImageInfo image_info(const codegen::resource& r, size_t i, const gpu_gbuffer& g, int parity) const
    {
        VkDescriptorImageInfo info = r.kind == codegen::resource_kind::storage_image ? stored(r, i, parity) : sampled(r, i, g, parity);
        if (r.kind == codegen::resource_kind::sampled_image) info.sampler = VK_NULL_HANDLE;
        if (r.kind == codegen::resource_kind::sampler) info.imageView = VK_NULL_HANDLE, info.imageLayout = VK_IMAGE_LAYOUT_UNDEFINED;
        return info;
    }

    // One descriptor set per pass, every binding of its resources written; the history pass
    // has two, one reading each history image (record() takes them by turns).
    void write_sets(const gpu_gbuffer& g)
    {
        if (sets_.empty()) {
            const VkDescriptorPool pool = make_pass_pool();
            for (size_t i = 0; i < passes_.size(); ++i) sets_.push_back(allocate_set(pool, i));
            if (history_pass_ != no_pass) history_set_ = allocate_set(pool, history_pass_);
        }
        for (size_t i = 0; i < passes_.size(); ++i) write_set(sets_[i], i, g, 0);
        if (history_pass_ != no_pass) write_set(history_set_, history_pass_, g, 1);
    }

    VkDescriptorSet allocate_set(VkDescriptorPool pool, size_t i) const
    {
        VkDescriptorSetAllocateInfo dai{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO};
        dai.descriptorPool = pool;
        dai.descriptorSetCount = 1;
        dai.pSetLayouts = &passes_[i].set_layout;
        VkDescriptorSet set;
        check(vkAllocateDescriptorSets(ctx_.device(), &dai, &set), "vkAllocateDescriptorSets");
        return set;
    }

    // Every binding of pass i's resources, in `set`.
    void write_set(VkDescriptorSet set, size_t i, const gpu_gbuffer& g, int parity) const
    {
        VkDevice d = ctx_.device();
        const pass_pipeline& p = passes_[i];
        // Sized up front: the writes point into these vectors.
        std::vector<VkDescriptorBufferInfo> bufs(p.resources.size());
        std::vector<VkDescriptorImageInfo> imgs(p.resources.size());
        std::vector<VkWriteDescriptorSet> writes;
        for (size_t k = 0; k < p.resources.size(); ++k) {
            const codegen::resource& r = p.resources[k];
            VkWriteDescriptorSet w{VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET};
            w.dstSet = set;
            w.dstBinding = r.binding;
            w.descriptorCount = 1;
            w.descriptorType = descriptor_type(r.kind);
            if (r.kind == codegen::resource_kind::uniform_buffer) {
                bufs[k] = {uniforms_[i].first.handle, 0, uniforms_[i].second};
                w.pBufferInfo = &bufs[k];
            } else {
                imgs[k] = image_info(r, i, g, parity);
                w.pImageInfo = &imgs[k];
            }
            writes.push_back(w);
        }
        vkUpdateDescriptorSets(d, static_cast<uint32_t>(writes.size()), writes.data(), 0, nullptr);
    }

    context& ctx_;
    const pass_pipelines& passes_;
    resource_scope scope_;
    std::pair<int, int> depth_size_;         // the G-buffer's
    std::vector<std::pair<int, int>> sizes_; // per pass: its output's width, height
    bool has_raw_ = false;
    std::vector<std::pair<buffer, size_t>> uniforms_; // per pass: buffer, size
    image noise_;
    VkSampler clamp_ = VK_NULL_HANDLE, repeat_ = VK_NULL_HANDLE;
    std::vector<image> outputs_, raws_;
    std::vector<VkFramebuffer> framebuffers_;
    std::vector<VkDescriptorSet> sets_;
    size_t history_pass_ = no_pass;  // the history pass's index, if the chain has one
    image history_[2];               // its two history images: it reads history_[parity_], writes the other
    VkDescriptorSet history_set_ = VK_NULL_HANDLE; // its set for parity 1 (sets_ holds parity 0's)
    VkFramebuffer history_framebuffer_ = VK_NULL_HANDLE; // a fragment history pass's for parity 1 (framebuffers_ holds parity 0's)
    int parity_ = 0;                 // which history record() reads: flipped by next_frame()
    mutable const raw_counter* counter_;
    mutable std::unique_ptr<raw_counter> own_counter_; // when no counter was given, made on the first count
};

} // namespace aogen::vulkan
