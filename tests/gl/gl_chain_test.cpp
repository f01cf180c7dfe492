// The emitted GLSL 450 and ESSL executed: each variant's passes (compute, or vertex + fragment)
// as SPIRV-Cross writes them for OpenGL and OpenGL ES (compile.hpp's glsl and essl targets:
// GLSL 450, ESSL 310 compute, ESSL 300 fragment), run on Mesa's llvmpipe through aogen::gl, against the
// same variant's SPIR-V on the Vulkan harness (lavapipe) with the same G-buffer, kernel,
// noise and uniform bytes: every pixel within 1/255, and on llvmpipe bit-identical.
#include "vulkan/harness.hpp"

#include <aogen_report/settings.hpp>
#include <aogen_scenes/gbuffer.hpp>

#include <aogen/ao_difference.hpp>
#include <aogen/compile.hpp>
#include <aogen/emitted.hpp>
#include <aogen/gl/chain.hpp>

#include <iostream>

using namespace aogen;
using namespace aogen_test;

namespace {

gl::context* shared_gl(gl::api which)
{
    static std::string failure[2];
    static std::unique_ptr<gl::context> ctx[2];
    static bool tried[2] = {false, false};
    const int i = which == gl::api::opengl ? 0 : 1;
    if (!tried[i]) {
        tried[i] = true;
        try {
            ctx[i] = std::make_unique<gl::context>(which);
        } catch (const std::exception& e) {
            failure[i] = e.what();
        }
    }
    if (!ctx[i]) aogen_test::skip_missing_dependency("no OpenGL context: " + failure[i]);
    return ctx[i].get();
}

// `v`'s `target` text on `gl` against its SPIR-V on `vk`, on G-buffer `g` with settings `s`.
void compare_one(vulkan::context& vk, gl::context& gl, const variant& v, compile::target target, const codegen::options& o,
                 const vulkan::gbuffer& g, const vulkan::chain_settings& s)
{
    const vulkan::chain_result expected = chain_under_test(vk, v).run(g, s);
    const codegen::plan p = codegen::make_plan(v, under_test(o));
    const gl::chain_result got = gl::run(gl, plan_for(p, target), emitted_texts(p, target), g, p.inputs(s, g.width, g.height));
    REQUIRE(got.width == expected.width);
    REQUIRE(got.height == expected.height);
    const ao_difference d = difference_of(got.ao, expected.ao);
    CHECK(first_difference(got.bent_normal, expected.bent_normal) == ""); // a -bn variant's, byte for byte (empty otherwise)
    CHECK(got.bent_normal.size() == (v.bent_normals ? 3 * got.ao.size() : 0));
    std::cout << compile::to_name(target) << " " << to_name(v) << ": " << d.identical << " of " << d.pixels
              << " pixels bit-identical, largest difference " << d.largest * 255 << "/255\n";
    CHECK(d.within_one_step()); // issue 13's bound for any target
    // llvmpipe and lavapipe are one compiler back end: with the same operations in the text,
    // every pixel is the same byte (aogen_target_check: the whole default matrix).
    CHECK(d.bit_identical());
    // Not a comparison of two blank images: the crease is occluded in both.
    CHECK(*std::min_element(got.ao.begin(), got.ao.end()) < 0.98f);
}

// `v` on built-in scene `name` at 320 × 180 (aogen_target_check's size), ray-cast as the
// report renders it, with the report's default settings.
void compare_on_scene(vulkan::context& vk, gl::context& gl, const variant& v, compile::target target, const codegen::options& o,
                      const std::string& name)
{
    INFO("the " << name << " scene");
    scenes::scene scene = scenes::builtin_scene(name);
    scene.camera.width = 320, scene.camera.height = 180;
    const std::unique_ptr<truth::scene> tracer = scenes::make_tracer(scene);
    scenes::gbuffer_options go;
    go.use_scene_normals = false; // as aogen_report/run.hpp renders it
    go.face_camera = false;
    go.normals = v.normals == normal_source::gbuffer_view ? scenes::normal_space::view : scenes::normal_space::world;
    const vulkan::gbuffer ray_cast = with_test_albedo(scenes::to_gbuffer<vulkan::gbuffer>(scenes::render_gbuffer(aogen_report::for_variant(scene, v), *tracer, go)));
    compare_one(vk, gl, v, target, o, ray_cast, aogen_report::default_settings(v, scene));
}

// Every variant's `target` text on `api` against its SPIR-V, on the harness's analytic
// crease (64 × 40) and on the report's ray-cast `crease` scene (320 × 180, the report's
// default settings): the scene's depths are not exactly planar, so its interpolated depths
// land on thresholds the analytic one never reaches.
void compare_with_spirv(gl::api api, compile::target target, const codegen::options& o)
{
    vulkan::context* vk = shared_context();
    gl::context* gl = shared_gl(api);
    if (!vk || !gl) return;
    INFO(gl->version() << " | " << gl->renderer());
    CHECK(gl->version().rfind(api == gl::api::opengl_es ? "OpenGL ES 3." : "4.5", 0) == 0);
    const int W = 64, H = 40;
    const mat4 proj = perspective(0.6f, float(W) / H, 0.1f, 100.0f);
    const vulkan::gbuffer analytic = crease(W, H, 0.6f, proj);
    for (const char* name : emitted_target_variants) {
        const variant v = variant_from_name(name);
        INFO(name);
        compare_one(*vk, *gl, v, target, o, analytic, settings_for(proj));
        compare_on_scene(*vk, *gl, v, target, o, "crease");
    }
#if defined(AOGEN_SCENES_ASSIMP)
    // The engine mesh, where GLSL's acos and atan (Mesa builds them from two different
    // polynomials in its two front ends) put a GTAO pixel 1/255 apart: common/core.glsl's
    // ao_acos and ao_atan2.
    for (const char* name : {"gtao-2x3-full-noblur-gbufview-revinf-persp-fs", "gtao-2x3-full-noblur-gbufview-revinf-persp-cs"}) {
        INFO(name);
        compare_on_scene(*vk, *gl, variant_from_name(name), target, o, "engine");
    }
#endif
    require_clean(*vk);
}

} // namespace

TEST_CASE("gl: the emitted GLSL 450 gives the SPIR-V's AO bit for bit, compute and fragment (OpenGL 4.5)")
{
    compare_with_spirv(gl::api::opengl, compile::target::glsl, {});
}

TEST_CASE("gl: the emitted ESSL 310 (compute) and 300 (fragment) give the SPIR-V's AO bit for bit (OpenGL ES 3.2)")
{
    codegen::options rgba8; // ESSL 310 has no r8 image format
    rgba8.output_format = "rgba8";
    compare_with_spirv(gl::api::opengl_es, compile::target::essl, rgba8);
}

// A history variant's frames, each with its own camera and frame index on one G-buffer (the
// report's crease, with motion vectors of a sideways move): on OpenGL from the emitted text,
// its two history images swapped frame after frame (gl::run_frames), against the SPIR-V on one
// Vulkan binding frame after frame. Every frame's every pixel bit for bit, and the history is
// used: most texels of the history hold every frame.
TEST_CASE("gl: a history variant's frames (GLSL 450 and ESSL 310 compute, ESSL 300 fragment) give the SPIR-V's, frame after frame, bit for bit")
{
    vulkan::context* vk = shared_context();
    if (!vk) return;
    const scenes::scene scene = [] {
        scenes::scene s = scenes::builtin_scene("crease");
        s.camera.width = 160, s.camera.height = 90;
        return s;
    }();
    const std::unique_ptr<truth::scene> tracer = scenes::make_tracer(scene);
    scenes::gbuffer_options go;
    go.use_scene_normals = false, go.face_camera = false, go.motion = true;
    vulkan::gbuffer g = scenes::to_gbuffer<vulkan::gbuffer>(scenes::render_gbuffer(scene, *tracer, go));
    for (size_t i = 0; i < g.motion.size(); i += 2) g.motion[i] = -0.01f, g.motion[i + 1] = 0.004f; // NDC, current − previous
    for (const auto& [api, target] : {std::pair{gl::api::opengl, compile::target::glsl}, std::pair{gl::api::opengl_es, compile::target::essl}}) {
        gl::context* gl = shared_gl(api);
        if (!gl) return;
        codegen::options o;
        if (api == gl::api::opengl_es) o.output_format = "rgba8"; // ESSL 310 has no r8 image format
        for (const char* name : {"gtao-2x2-half-denoise-gbufworld-std-persp-cs-histmv", "ssao-s16-full-bilateral-gbufworld-std-persp-cs-hist",
                                 "gtao-1x4-half-noblur-gbufworld-std-persp-fs-histmv"}) { // fragment: ESSL 300, two colour attachments
            INFO(compile::to_name(target) << " " << name);
            const variant v = variant_from_name(name);
            const codegen::plan p = codegen::make_plan(v, under_test(o));
            const std::vector<chain_inputs> frames = sideways_frames(p, aogen_report::default_settings(v, scene), g.width, g.height, 4);
            const std::vector<gl::chain_result> got = gl::run_frames(*gl, plan_for(p, target), emitted_texts(p, target), g, frames);
            std::vector<float> history;
            const std::vector<vulkan::chain_result> expected = spirv_frames(*vk, chain_under_test(*vk, v), g, frames, &history);
            for (size_t f = 0; f < frames.size(); ++f) {
                INFO("frame " << f);
                REQUIRE(got[f].ao.size() == expected[f].ao.size());
                const ao_difference d = difference_of(got[f].ao, expected[f].ao);
                std::cout << "history frame " << f << ": " << d.identical << " of " << d.pixels << " pixels bit-identical, largest difference "
                          << d.largest * 255 << "/255\n";
                CHECK(first_difference(got[f].ao, expected[f].ao) == "");
            }
            const auto [held, surface] = held_of(history, float(frames.size()));
            CHECK(held * 2 > surface); // the history was used: most surface texels hold every frame
        }
    }
    require_clean(*vk);
}
