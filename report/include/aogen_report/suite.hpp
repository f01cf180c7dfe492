// aogen_report/suite.hpp — the stability suite: every variant on every stability case,
// judged by the case's criterion (stability.hpp).
//
// WHAT
//   run_suite(settings) runs, for each case and each variant:
//     1. the variant adapted to the case's camera (its projection axis set to the camera's:
//        an orthographic case runs the orthographic form of every variant), built in its
//        diagnostic form (raw values before the guard, counted per pass);
//     2. on the case's scene and on its twin: the G-buffer as the renderer stores it (with
//        the case's faults planted, and its noise rotation if it fixes one), one run, the AO
//        read back; the reference traced on the world G-buffer (grid² rays per pixel);
//     3. with criterion.compare_depth, the same in standard, reversed and reversed-infinite
//        depth, each compared pixel by pixel with standard depth; with compare_scales, the
//        same on the scene scaled by each of scale_factors(), compared pixel by pixel with
//        the scene's own;
//   and judges it: raw NaN/Inf, raw excess beyond [0, 1], background exactly 1, output in
//   [0, 1], a bent normal on every other pixel (-bn variants), RMSE against the twin's, the
//   depth differences. The first check that fails
//   decides ("NaN 3 in blur_x", "background 12 px not 1", "RMSE 0.21 > 1.5 × 0.06 + 0.03").
//   Variants a case cannot run (a normal-buffer variant where the renderer has none) are
//   listed, not judged. Pixels where a fault was planted are left out of the error (the
//   shader must give them AO 1, checked like the background).
//
// USAGE
//     aogen_report::suite_settings s;
//     for (const std::string& n : aogen_report::builtin_case_names()) s.cases.push_back(aogen_report::builtin_case(n));
//     s.variants = aogen_report::suite_variants();
//     aogen_report::suite_data d = aogen_report::run_suite(s);   // d.failures(), d.cases[i].runs[j]
#pragma once

#include "metrics.hpp"
#include "reference.hpp"
#include "scene_bench.hpp"
#include "settings.hpp"
#include "stability.hpp"

#include <aogen/matrix.hpp>

#include <array>
#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace aogen_report {

struct suite_settings {
    std::vector<stability_case> cases;
    std::vector<aogen::variant> variants;
    int grid = 32; // reference rays per pixel: grid²
    aogen::vulkan::device_options device;
    std::function<void(const std::string&)> progress = [](const std::string&) {};
    aogen::codegen::template_reader templates; // the shaders' templates: empty, the embedded ones (a test plants a mutant here)
};

// One variant on one case.
struct suite_run {
    std::string variant;             // as run (adapted to the case's camera)
    std::string skipped;             // why it did not run; "" when it ran
    bool pass = false;
    std::string decided_by;          // the first failing check, or what the error criterion read
    aogen::vulkan::raw_counts raw;   // the case's scene, every pass
    size_t background_pixels = 0, background_not_one = 0;
    size_t bent_pixels = 0, bent_missing = 0; // -bn variants: the other pixels, and those without a bent normal
    double rmse = 0, twin_rmse = 0, error_limit = 0;
    double depth_max = 0, depth_mean = 0; // compare_depth only
    double twin_pixel_max = 0;            // faults only: the largest difference from the twin beyond fault_reach
    double changed_reach = 0;             // faults only: the farthest pixel (from its fault) that differs by more than twin_pixel_max
    double scale_max = 0;                 // compare_scales only: the largest difference from the unscaled scene's AO
    double scale_worst = 1;               //   and the factor it was read at
    std::string history;                  // a history variant's own checks (history_failure): "" passed, else what failed
    bool ran() const { return skipped.empty(); }
};

struct suite_case_record {
    stability_case c;
    double truth_noise = 0;          // the case reference's RMS standard error
    std::vector<suite_run> runs;     // one per settings variant
};

struct suite_data {
    std::string device;
    int grid = 0;
    std::vector<std::string> variants; // the settings' variants, as given
    std::vector<suite_case_record> cases;
    size_t failures() const
    {
        size_t n = 0;
        for (const suite_case_record& c : cases)
            for (const suite_run& r : c.runs) n += r.ran() && !r.pass;
        return n;
    }
};

// The variants the suite runs by default: the default matrix, GTAO's one slice, one step,
// fp16 twins of each technique's default (16-bit arithmetic, where view depths past 65504
// and the other extremes would show first), and two history chains, compute by motion
// vectors and fragment by the camera (each also runs history_failure's checks).
inline std::vector<aogen::variant> suite_variants()
{
    std::vector<aogen::variant> v = aogen::default_matrix();
    for (const char* name : {"gtao-1x1-half-noblur-gbufworld-std-persp-cs", "gtao-1x1-full-noblur-gbufworld-std-persp-cs",
                             "ssao-s16-half-bilateral-gbufworld-std-persp-cs-fp16", "gtao-2x3-half-bilateral-gbufworld-std-persp-cs-fp16",
                             "gtao-2x2-half-denoise-gbufworld-std-persp-cs-fp16", "vbao-2x3-half-bilateral-gbufworld-std-persp-cs-fp16",
                             "gtao-1x4-half-noblur-gbufworld-std-persp-cs-histmv", "gtao-2x2-half-denoise-gbufworld-std-persp-fs-hist"})
        aogen::append_unique(v, aogen::variant_from_name(name));
    return v;
}

namespace detail {

// `v` in the form a camera of this projection runs.
inline aogen::variant adapted(aogen::variant v, const aogen::scenes::camera& c)
{
    v.projection = c.projection == aogen::scenes::projection_kind::orthographic ? aogen::projection_kind::orthographic
                                                                                 : aogen::projection_kind::perspective;
    return aogen::canonical(v);
}

// Diagnostic chains, compiled once per variant name for the whole suite. prepare() plans and
// generates the chains a suite will run and compiles all their shaders at once, on every
// core (spirv_cache::compile_all); get() then builds each chain's pipelines on first use.
class chain_cache {
public:
    chain_cache(aogen::vulkan::context& ctx, aogen::codegen::template_reader templates) : ctx_(ctx), templates_(std::move(templates)) {}

    void prepare(const std::vector<aogen::variant>& variants)
    {
        std::vector<aogen::codegen::shader_source> sources;
        for (const aogen::variant& v : variants) {
            const std::string name = aogen::to_name(v);
            if (chains_.count(name) || planned_.count(name)) continue;
            aogen::codegen::plan p = aogen::codegen::make_plan(v, options());
            const std::vector<aogen::codegen::shader_source> s = aogen::codegen::generate(p);
            sources.insert(sources.end(), s.begin(), s.end());
            planned_.emplace(name, std::move(p));
        }
        spirv_.compile_all(sources);
    }

    const aogen::vulkan::chain& get(const aogen::variant& v)
    {
        const std::string name = aogen::to_name(v);
        auto it = chains_.find(name);
        if (it != chains_.end()) return *it->second;
        auto planned = planned_.find(name);
        if (planned == planned_.end()) prepare({v}), planned = planned_.find(name);
        auto chain = std::make_unique<aogen::vulkan::chain>(ctx_, planned->second, &spirv_); // its SPIR-V compiled by prepare()
        planned_.erase(planned);
        return *chains_.emplace(name, std::move(chain)).first->second;
    }

private:
    aogen::codegen::options options() const
    {
        aogen::codegen::options o;
        o.diagnostics = true;
        o.templates = templates_;
        return o;
    }

    aogen::vulkan::context& ctx_;
    aogen::codegen::template_reader templates_;
    aogen::vulkan::spirv_cache spirv_;
    std::map<std::string, aogen::codegen::plan> planned_; // planned and compiled, not yet built
    std::map<std::string, std::unique_ptr<aogen::vulkan::chain>> chains_;
};

// Every chain the suite's cases will run (the variants adapted to each case's scene and twin,
// and to every depth convention where a case compares them), skipping what cannot run.
inline std::vector<aogen::variant> chains_needed(const suite_settings& settings)
{
    std::vector<aogen::variant> needed;
    for (const stability_case& c : settings.cases)
        for (const aogen::variant& base : settings.variants) {
            const aogen::variant v = adapted(base, c.scene.camera), vt = adapted(base, c.twin.camera);
            if (!cannot_run(v, c.scene).empty() || !cannot_run(vt, c.twin).empty()) continue;
            needed.push_back(v), needed.push_back(vt);
            if (!c.criterion.compare_depth) continue;
            for (aogen::depth_convention d : {aogen::depth_convention::reversed, aogen::depth_convention::reversed_infinite}) {
                aogen::variant vd = v;
                vd.depth = d;
                needed.push_back(vd);
            }
        }
    return needed;
}

// What one run read back: the chain's output and the screen-sized AO, and which output
// pixels the shader must leave at exactly 1 (background or a planted fault).
struct one_run {
    bench_run run;
    std::vector<uint8_t> must_be_one; // per output pixel
    std::vector<uint8_t> faulted;     // per full-resolution pixel
    int width = 0;                    // the full resolution's width
    const aogen::vulkan::chain_result& out() const { return run.out; }
};

inline one_run run_once(chain_cache& chains, const aogen::variant& v, scene_bench& bench, const bench_inputs& inputs)
{
    one_run r;
    r.run = bench.run(chains.get(v), default_settings(v, bench.scene()), inputs);
    // The G-buffer the run read: the cached one, or a faulted copy only where there are faults.
    std::optional<aogen::vulkan::gbuffer> faulted_copy;
    if (!inputs.faults.empty()) faulted_copy = scene_bench::with_faults(bench.gbuffer(v), inputs.faults);
    const aogen::vulkan::gbuffer& g = faulted_copy ? *faulted_copy : bench.gbuffer(v);
    r.width = g.width;
    r.faulted.assign(size_t(g.width) * g.height, 0);
    for (const gbuffer_fault& f : inputs.faults) r.faulted[fault_pixel(f, g.width, g.height)] = 1;
    // An output pixel reads full pixel (x·k, y·k), clamped (common/depth.glsl's ao_full_pixel).
    const int ow = r.out().width, oh = r.out().height, k = r.run.scale;
    // A zero normal gives AO 1 in the AO pass; a blur may still mix it with its neighbours.
    const bool ao_pass_only = passes(v).size() == 1;
    r.must_be_one.assign(size_t(ow) * oh, 0);
    for (int y = 0; y < oh; ++y)
        for (int x = 0; x < ow; ++x) {
            const size_t full = size_t(std::min(y * k, g.height - 1)) * g.width + std::min(x * k, g.width - 1);
            const bool faulted_depth = r.faulted[full] && !std::isfinite(g.depth[full]);
            const bool faulted_normal = r.faulted[full] && v.normals != aogen::normal_source::reconstructed && std::isfinite(g.depth[full]);
            r.must_be_one[size_t(y) * ow + x] = !bench.truth().hit[full] || faulted_depth || (faulted_normal && ao_pass_only);
        }
    return r;
}

// A history variant's own checks on a case's scene, a still camera, one binding (history.glsl):
// after two frames a NaN, an infinity and a negative infinity are planted in every 7th history
// texel, and the next frame must drop them (no raw NaN or infinity, a history written with no
// texel that is not finite, and its output and history those of the same frame with those
// texels holding no frame, bit for bit); a reset, and a camera turned 180 degrees
// since the last frame, must each give frame 0's output bit for bit (this frame alone); and a
// history of another size must be refused by name. "" when all hold, else the first that failed.
inline std::string history_failure(chain_cache& chains, const aogen::variant& v, scene_bench& bench)
{
    const aogen::vulkan::chain& c = chains.get(v);
    aogen::vulkan::chain_settings s = default_settings(v, bench.scene());
    const std::unique_ptr<aogen::vulkan::bound_chain> b = bench.bind(c, s);
    const auto frame = [&](uint32_t f, bool reset, const std::optional<aogen::uniforms::camera>& previous) {
        s.frame = f, s.reset_history = reset, s.previous_camera = previous;
        b->set_uniforms(c.plan().inputs(s, bench.width(), bench.height()));
        return b->run_once();
    };
    const aogen::vulkan::chain_result first = b->run_once();
    frame(1, false, std::nullopt);
    // Every 7th texel planted, and the same texels instead holding no frame (all 0): the pass
    // must drop a texel that is not finite exactly as one that holds nothing.
    std::vector<float> planted = b->read_history(), emptied = planted;
    const float inf = std::numeric_limits<float>::infinity();
    for (size_t t = 0; 4 * t < planted.size(); t += 7) { // t % 3 takes 0, 1, 2 in turn
        float* texel = &planted[4 * t];
        if (t % 3 == 0) texel[0] = std::nanf(""); // the AO
        if (t % 3 == 1) texel[0] = inf;
        if (t % 3 == 2) texel[1] = -inf;          // the depth code
        std::fill_n(&emptied[4 * t], 4, 0.0f);
    }
    const auto [tw, th] = c.plan().target_size(bench.width(), bench.height());
    b->load_history(tw, th, planted);
    const aogen::vulkan::chain_result after = frame(2, false, std::nullopt);
    const std::vector<float> written = b->read_history();
    b->load_history(tw, th, emptied);
    const aogen::vulkan::chain_result after_empty = frame(2, false, std::nullopt);
    for (const aogen::vulkan::raw_counts& k : after.raw)
        if (k.nan || k.inf) return "history: a planted NaN or infinity reached a pass's raw values";
    for (float h : written)
        if (!std::isfinite(h)) return "history: a planted NaN or infinity outlived its frame";
    if (after.ao != after_empty.ao || written != b->read_history())
        return "history: a planted NaN or infinity was not dropped as a texel that holds no frame";
    if (frame(0, true, std::nullopt).ao != first.ao) return "history: a reset is not frame 0's output bit for bit";
    aogen::uniforms::camera turned = s.camera;
    aogen::mat4 half_turn; // 180 degrees about the view's y axis
    half_turn.columns[0] = {-1, 0, 0, 0}, half_turn.columns[2] = {0, 0, -1, 0};
    turned.world_to_view = half_turn * s.camera.world_to_view;
    if (frame(0, false, turned).ao != first.ao) return "history: after a turn of 180 degrees the output is not this frame's alone";
    try {
        b->load_history(tw + 1, th, std::vector<float>(size_t(tw + 1) * th * 4, 0.0f));
        return "history: a history of another size was taken";
    } catch (const aogen::error& e) {
        if (std::string(e.what()).find("history") == std::string::npos) return "history: another size refused without naming the history";
    }
    return "";
}

// The reference's valid pixels without the faulted ones (the shader answers 1 there by design).
inline std::vector<uint8_t> scored_pixels(const reference& truth, const std::vector<uint8_t>& faulted)
{
    std::vector<uint8_t> valid = truth.valid;
    for (size_t i = 0; i < valid.size(); ++i) valid[i] = valid[i] && !faulted[i];
    return valid;
}

// The twin's pixels its error is taken over: every valid one, or those in the case's window.
inline std::vector<uint8_t> twin_scored_pixels(const stability_case& c, const reference& twin)
{
    std::vector<uint8_t> valid = twin.valid;
    if (!c.twin_window) return valid;
    const auto [x0, y0] = *c.twin_window;
    for (int y = 0; y < twin.height; ++y)
        for (int x = 0; x < twin.width; ++x) {
            const bool inside = x >= x0 && y >= y0 && x < x0 + c.scene.camera.width && y < y0 + c.scene.camera.height;
            valid[size_t(y) * twin.width + x] &= uint8_t(inside);
        }
    return valid;
}

inline std::string fixed_text(double x, int digits)
{
    char b[64];
    std::snprintf(b, sizeof b, "%.*f", digits, x);
    return b;
}

// The faulted run `a` against its unfaulted twin `b` (the same scene), output pixel by output
// pixel: the largest difference beyond the case's fault_reach (in full-resolution pixels from
// the nearest fault), and how far from its fault the farthest clearly changed pixel lies.
inline void compare_with_twin(suite_run& r, const one_run& a, const one_run& b, const stability_case& c)
{
    if (a.out().ao.size() != b.out().ao.size())
        aogen::fail("stability case " + c.name, "its faults' twin differs in size", "valid: faults with the twin the same scene");
    const int W = a.width;
    const int k = a.run.scale;
    std::vector<std::array<int, 2>> faults;
    for (size_t i = 0; i < a.faulted.size(); ++i)
        if (a.faulted[i]) faults.push_back({int(i % W), int(i / W)});
    for (int y = 0; y < a.out().height; ++y)
        for (int x = 0; x < a.out().width; ++x) {
            double nearest = 1e30;
            for (const auto& f : faults) nearest = std::min(nearest, std::hypot(double(x * k - f[0]), double(y * k - f[1])));
            const size_t i = size_t(y) * a.out().width + x;
            const double diff = std::fabs(double(a.out().ao[i]) - b.out().ao[i]);
            if (diff > c.criterion.twin_pixel_max) r.changed_reach = std::max(r.changed_reach, nearest);
            if (nearest > c.criterion.fault_reach) r.twin_pixel_max = std::max(r.twin_pixel_max, diff);
        }
}

// Judges `r` by the case's criterion; the first failing check decides.
inline void judge(suite_run& r, const stability_criterion& k, const std::vector<std::string>& pass_names,
                  const std::vector<aogen::vulkan::raw_counts>& per_pass)
{
    for (size_t i = 0; i < per_pass.size(); ++i) {
        const aogen::vulkan::raw_counts& c = per_pass[i];
        if (c.nan || c.inf) {
            r.decided_by = "raw NaN " + std::to_string(c.nan) + ", Inf " + std::to_string(c.inf) + " in " + pass_names[i];
            return;
        }
        if (c.out_of_range() && c.max_excess > k.max_excess) {
            char b[128];
            std::snprintf(b, sizeof b, "raw %llu values outside [0, 1] (by up to %.3g) in %s", static_cast<unsigned long long>(c.out_of_range()),
                          double(c.max_excess), pass_names[i].c_str());
            r.decided_by = b;
            return;
        }
    }
    if (!r.history.empty()) {
        r.decided_by = r.history;
        return;
    }
    if (r.background_not_one) {
        r.decided_by = std::to_string(r.background_not_one) + " of " + std::to_string(r.background_pixels) + " background/fault pixels not exactly 1";
        return;
    }
    if (r.bent_missing) {
        r.decided_by = std::to_string(r.bent_missing) + " of " + std::to_string(r.bent_pixels) + " surface pixels without a bent normal";
        return;
    }
    if (k.compare_depth && (r.depth_max > k.depth_max || r.depth_mean > k.depth_mean)) {
        r.decided_by = "depth conventions differ by up to " + fixed_text(r.depth_max, 4) + " (mean " + fixed_text(r.depth_mean, 5) + ")";
        return;
    }
    if (r.twin_pixel_max > k.twin_pixel_max) {
        r.decided_by = "a pixel " + fixed_text(r.changed_reach, 1) + " px from its fault differs from the twin by " +
                       fixed_text(r.twin_pixel_max * 255, 1) + "/255 (beyond " + fixed_text(k.fault_reach, 1) + " px, at most " +
                       fixed_text(k.twin_pixel_max * 255, 1) + "/255)";
        return;
    }
    if (k.compare_scales && r.scale_max > k.scale_max) {
        r.decided_by = "scaled by " + aogen::format_number(r.scale_worst) + " a pixel differs by " + fixed_text(r.scale_max * 255, 1) +
                       "/255 (at most " + fixed_text(k.scale_max * 255, 1) + "/255)";
        return;
    }
    if (!k.compare_error) {
        r.pass = true;
        if (k.compare_depth)
            r.decided_by = "depth conventions agree within " + fixed_text(r.depth_max, 4) + " (mean " + fixed_text(r.depth_mean, 5) + ")";
        else if (k.compare_scales)
            r.decided_by = "every scale within " + fixed_text(r.scale_max * 255, 2) + "/255 (largest at × " + aogen::format_number(r.scale_worst) + ")";
        else
            r.decided_by = "no check failed";
        return;
    }
    r.error_limit = k.error_ratio * r.twin_rmse + k.error_slack;
    r.pass = r.rmse <= r.error_limit;
    r.decided_by = "RMSE " + fixed_text(r.rmse, 4) + (r.pass ? " <= " : " > ") + fixed_text(k.error_ratio, 2) + " × twin " +
                   fixed_text(r.twin_rmse, 4) + " + " + fixed_text(k.error_slack, 3);
}

} // namespace detail

inline suite_data run_suite(const suite_settings& settings)
{
    if (settings.cases.empty()) aogen::fail("stability suite", "no cases", "valid: at least one case");
    if (settings.variants.empty()) aogen::fail("stability suite", "no variants", "valid: at least one variant");
    // What makes a case impossible to score, before anything runs.
    for (const stability_case& c : settings.cases) {
        for (const aogen::scenes::scene* s : {&c.scene, &c.twin}) {
            require_radius_works(*s);
            aogen::scenes::require_scoreable(*s, *aogen::scenes::make_tracer(*s));
        }
        if (c.criterion.compare_scales)
            for (double k : scale_factors()) require_radius_works(detail::scaled(c.scene, k));
    }
    aogen::vulkan::context ctx(settings.device);
    detail::chain_cache chains(ctx, settings.templates);
    chains.prepare(detail::chains_needed(settings));
    suite_data out;
    out.device = ctx.device_name();
    out.grid = settings.grid;
    for (const aogen::variant& v : settings.variants) out.variants.push_back(aogen::to_name(v));

    for (size_t ci = 0; ci < settings.cases.size(); ++ci) {
        const stability_case& c = settings.cases[ci];
        settings.progress("[case " + std::to_string(ci + 1) + "/" + std::to_string(settings.cases.size()) + "] " + c.name);
        scene_bench scene(ctx, c.scene, settings.grid), twin(ctx, c.twin, settings.grid);
        suite_case_record record{c, scene.truth().noise_rms, {}};
        // The scaled scenes: only their G-buffers and which pixels hold geometry are read, so
        // the fewest reference rays (2 × 2) are enough.
        std::vector<std::pair<double, std::unique_ptr<scene_bench>>> scaled;
        if (c.criterion.compare_scales)
            for (double k : scale_factors()) scaled.emplace_back(k, std::make_unique<scene_bench>(ctx, detail::scaled(c.scene, k), 2));
        const bench_inputs inputs{c.faults, c.noise_rotation};
        for (const aogen::variant& base : settings.variants) {
            suite_run r;
            const aogen::variant v = detail::adapted(base, c.scene.camera), vt = detail::adapted(base, c.twin.camera);
            r.variant = aogen::to_name(v);
            r.skipped = cannot_run(v, c.scene);
            if (r.skipped.empty()) r.skipped = cannot_run(vt, c.twin);
            if (!r.ran()) {
                record.runs.push_back(r);
                continue;
            }
            const detail::one_run a = detail::run_once(chains, v, scene, inputs);
            const detail::one_run b = detail::run_once(chains, vt, twin, {});
            for (const aogen::vulkan::raw_counts& k : a.out().raw) r.raw += k;
            for (size_t i = 0; i < a.must_be_one.size(); ++i)
                if (a.must_be_one[i]) r.background_pixels += 1, r.background_not_one += a.out().ao[i] != 1.0f;
            // A -bn variant's bent normal: unit wherever the AO is not held at 1 (aogen/bent_normals.hpp's none is 0).
            const std::vector<float>& bent = a.out().bent_normal;
            for (size_t i = 0; i < a.must_be_one.size() && !bent.empty(); ++i)
                if (!a.must_be_one[i]) r.bent_pixels += 1, r.bent_missing += bent[3 * i] == 0.0f && bent[3 * i + 1] == 0.0f && bent[3 * i + 2] == 0.0f;
            r.rmse = compare(a.run.full, scene.truth().ao, detail::scored_pixels(scene.truth(), a.faulted)).rmse;
            r.twin_rmse = compare(b.run.full, twin.truth().ao, detail::twin_scored_pixels(c, twin.truth())).rmse;
            if (!c.faults.empty()) detail::compare_with_twin(r, a, b, c);
            if (c.criterion.compare_depth)
                for (aogen::depth_convention d : {aogen::depth_convention::standard, aogen::depth_convention::reversed, aogen::depth_convention::reversed_infinite}) {
                    aogen::variant vd = v;
                    vd.depth = d;
                    if (vd.depth == v.depth) continue;
                    const detail::one_run o = detail::run_once(chains, vd, scene, inputs);
                    double sum = 0;
                    for (size_t i = 0; i < o.out().ao.size(); ++i) {
                        const double diff = std::fabs(double(o.out().ao[i]) - a.out().ao[i]);
                        r.depth_max = std::max(r.depth_max, diff), sum += diff;
                    }
                    r.depth_mean = std::max(r.depth_mean, sum / double(std::max<size_t>(1, o.out().ao.size())));
                }
            if (has_history_pass(v)) r.history = detail::history_failure(chains, v, scene);
            // Raw NaN, Inf and excess are judged over every run of the variant on the case.
            std::vector<aogen::vulkan::raw_counts> per_pass = a.out().raw;
            for (const auto& [k, p] : scaled) {
                const detail::one_run o = detail::run_once(chains, v, *p, inputs);
                for (size_t i = 0; i < per_pass.size(); ++i) per_pass[i] += o.out().raw[i], r.raw += o.out().raw[i];
                for (size_t i = 0; i < o.out().ao.size(); ++i) {
                    const double diff = std::fabs(double(o.out().ao[i]) - a.out().ao[i]);
                    if (diff > r.scale_max) r.scale_max = diff, r.scale_worst = k;
                }
            }
            detail::judge(r, c.criterion, a.out().passes, per_pass);
            record.runs.push_back(r);
        }
        out.cases.push_back(std::move(record));
    }
    return out;
}

} // namespace aogen_report
