// aogen_target_check — every emitted target executed against the SPIR-V (issues 13, 19): each
// variant's GLSL 450 on OpenGL 4.5 and ESSL (310 compute, 300 fragment) on OpenGL ES 3.2
// (aogen::gl, llvmpipe), its SM 5.0 and 6.0 HLSL compiled back by glslang and its WGSL
// translated back by naga, both run on the Vulkan harness, on the G-buffers of built-in
// scenes, each compared per pixel with the variant's SPIR-V run on the same bytes.
//
//   aogen_target_check [--variants NAME,...] [--targets glsl,essl,hlsl,hlsl60,wgsl] [--scenes a,b,c] [--size WxH]
//
// Default: the default matrix (compute and fragment variants) on crease, room and engine at
// 320×180. Prints, per target, the variant × scene runs, how many were bit-identical, the
// largest difference (a Markdown table, BENCHMARKS.md keeps it); exits 1 when a pixel differs
// by more than 1/255.
#include <aogen_report/arguments.hpp>
#include <aogen_tools/options.hpp>
#include <aogen_report/run.hpp>
#include <aogen_report/scene_bench.hpp>
#include <aogen_report/settings.hpp>

#include <aogen/ao_difference.hpp>
#include <aogen/compile.hpp>
#include <aogen/emitted.hpp>
#include <aogen/gl/chain.hpp>
#include <aogen/matrix.hpp>
#include <aogen/vulkan/hlsl_round_trip.hpp>
#include <aogen/vulkan/wgsl_round_trip.hpp>
#include <aogen/wgsl_dawn.hpp>

#include <CLI/CLI.hpp>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <map>
#include <optional>

namespace {

struct tally {
    int runs = 0, fragment = 0, exact = 0, over = 0; // runs, of them fragment, bit-identical, over 1/255
    float worst = 0;
    std::string worst_variant;
};

} // namespace

int main(int argc, char** argv)
{
    CLI::App app{"aogen_target_check: every emitted target executed against the SPIR-V"};
    std::string variants, scenes = "crease,room,engine", size = "320x180", targets = "glsl,essl,hlsl,hlsl60,wgsl";
    app.add_option("--variants", variants, "canonical names, comma-separated (default: the default matrix's compute variants)");
    app.add_option("--scenes", scenes, "built-in scenes or scene files")->capture_default_str();
    app.add_option("--size", size, "WxH of every scene")->capture_default_str();
    app.add_option("--targets", targets, "the targets to run, comma-separated")->capture_default_str();
    CLI11_PARSE(app, argc, argv);
    try {
        int w = 0, h = 0;
        aogen_report::parse_size(size, w, h);
        std::vector<aogen::variant> vs;
        if (variants.empty()) vs = aogen::default_matrix();
        else for (const std::string& n : aogen_report::comma_list(variants)) vs.push_back(aogen::variant_from_name(n));
        namespace cc = aogen::compile;
        // wgsl is checked twice: on Dawn, and through naga's round trip.
        const std::vector<cc::target> checkable{cc::target::glsl, cc::target::essl, cc::target::hlsl, cc::target::hlsl60, cc::target::wgsl};
        const char* const names[] = {"glsl (OpenGL 4.5)", "essl (OpenGL ES 3.2)", "hlsl sm50 (glslang round trip)", "hlsl sm60 (glslang round trip)",
                                     "wgsl (naga round trip)", "wgsl (Dawn, OpenGL ES backend)"};
        std::vector<int> chosen; // indices into checkable
        for (const std::string& t : aogen_report::comma_list(targets)) {
            const cc::target target = cc::target_from_name(t, "--targets");
            const auto at = std::find(checkable.begin(), checkable.end(), target);
            if (at == checkable.end()) aogen::fail("--targets", t + " is not run against the SPIR-V here", "valid: glsl, essl, hlsl, hlsl60, wgsl");
            chosen.push_back(int(at - checkable.begin()));
            if (target == cc::target::wgsl) chosen.push_back(5);
        }
        const auto wanted = [&](int k) { return std::find(chosen.begin(), chosen.end(), k) != chosen.end(); };
        aogen::vulkan::context vk(aogen::vulkan::device_options{});
        aogen::gl::context gl(aogen::gl::api::opengl), es(aogen::gl::api::opengl_es);
        std::cerr << "aogen_target_check: " << vk.device_name() << "; " << gl.version() << "; " << es.version() << "\n";
        // Each variant planned once; every target's texts come from its plan (plan_for).
        std::vector<aogen::codegen::plan> plans;
        for (const aogen::variant& v : vs) plans.push_back(aogen::codegen::make_plan(v));
        // WGSL: every variant's texts translated in one batch, up front. fp16 variants have no
        // WGSL form (compile.hpp refuses them), like GLSL and ESSL.
        std::vector<aogen::codegen::plan> wgsl_plans;
        for (const aogen::codegen::plan& p : plans)
            if (!p.variant().fp16) wgsl_plans.push_back(p);
        std::optional<aogen::vulkan::wgsl_round_trips> wgsl;
        if (wanted(4) || wanted(5)) wgsl.emplace(wgsl_plans);
        tally t[6];
        for (aogen::scenes::scene s : aogen_report::load_scenes(scenes)) {
            s.camera.width = w, s.camera.height = h;
            aogen_report::require_radius_works(s);
            const std::unique_ptr<aogen::truth::scene> tracer = aogen::scenes::make_tracer(s);
            aogen_report::gbuffer_cache gbuffers(vk, s, *tracer);
            std::cerr << "aogen_target_check: scene " << s.name << "\n";
            for (const aogen::codegen::plan& p : plans) {
                const aogen::variant& v = p.variant();
                const std::string& name = p.name();
                if (!aogen_report::cannot_run(v, s).empty()) continue; // an orthographic variant on a perspective camera, ...
                const aogen::chain_inputs in = p.inputs(aogen_report::default_settings(v, s), w, h);
                const aogen::vulkan::chain spirv(vk, p);
                const std::vector<float> expected = aogen::vulkan::bound_chain(vk, spirv.passes(), gbuffers.gpu(v), in).run_once().ao;
                // Target k's AO. fp16 variants: GLSL and ESSL have no fp16 form (compile.hpp
                // refuses them), and glslang reads their HLSL's min16float as 32-bit floats
                // (and has no min16float3x3), so a round trip would not run their arithmetic.
                const auto run = [&](int k) -> std::optional<std::vector<float>> {
                    if (v.fp16 || !wanted(k)) return std::nullopt;
                    if (k == 4) return aogen::vulkan::bound_chain(vk, *wgsl->passes(vk, p), gbuffers.gpu(v), in).run_once().ao;
                    if (k == 5) {
                        const std::vector<uint8_t> bytes =
                            aogen::wgsl::run_variant_on_dawn(aogen::plan_for(p, cc::target::wgsl), wgsl->texts(p), gbuffers.host(v), in).ao;
                        std::vector<float> ao(bytes.size());
                        for (size_t i = 0; i < ao.size(); ++i) ao[i] = bytes[i] / 255.0f;
                        return ao;
                    }
                    if (k == 0 || k == 1) {
                        const cc::target target = k == 0 ? cc::target::glsl : cc::target::essl;
                        const aogen::codegen::plan planned = aogen::plan_for(p, target);
                        return aogen::gl::run(k == 0 ? gl : es, planned, aogen::emitted_texts(planned, target), gbuffers.host(v), in).ao;
                    }
                    const aogen::compile::target hlsl = k == 2 ? aogen::compile::target::hlsl : aogen::compile::target::hlsl60;
                    return aogen::vulkan::bound_chain(vk, *aogen::vulkan::hlsl_round_trip(vk, p, hlsl), gbuffers.gpu(v), in).run_once().ao;
                };
                for (int k = 0; k < 6; ++k) {
                    const std::optional<std::vector<float>> got = run(k);
                    if (!got) continue;
                    const aogen::ao_difference d = aogen::difference_of(*got, expected);
                    ++t[k].runs, t[k].fragment += v.stage == aogen::pipeline_stage::fragment;
                    t[k].exact += d.bit_identical(), t[k].over += !d.within_one_step();
                    if (!d.within_one_step()) std::cerr << "aogen_target_check: " << names[k] << " " << name << " on " << s.name << ": " << d.largest * 255 << "/255\n";
                    if (d.largest > t[k].worst || t[k].worst_variant.empty()) t[k].worst = std::max(t[k].worst, d.largest), t[k].worst_variant = name + " on " + s.name;
                }
            }
        }
        bool ok = true;
        std::cout << "| target | variant × scene runs | of them fragment | bit-identical | over 1/255 | largest difference | where |\n"
                     "|---|---:|---:|---:|---:|---:|---|\n";
        for (int k : chosen) {
            std::cout << "| " << names[k] << " | " << t[k].runs << " | " << t[k].fragment << " | " << t[k].exact << " | " << t[k].over << " | "
                      << t[k].worst * 255 << "/255 | " << (t[k].worst > 0 ? "`" + t[k].worst_variant + "`" : "—") << " |\n";
            ok = ok && t[k].over == 0;
        }
        return ok ? 0 : 1;
    } catch (const std::exception& e) {
        std::cerr << "aogen_target_check: " << aogen::tools::exception_line(e) << "\n";
        return 1;
    }
}
