// The emitted GLSL 450 executed: each variant's compute passes as SPIRV-Cross writes them for
// OpenGL (compile.hpp's glsl target), run on Mesa's llvmpipe through aogen::gl, against the
// same variant's SPIR-V on the Vulkan harness (lavapipe) with the same G-buffer, kernel,
// noise and uniform bytes: every pixel within 1/255, and how many are bit-identical.
#include "vulkan/harness.hpp"

#include <aogen/compile.hpp>
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

// The text of each pass of `v` for `target` (glsl: GLSL 450, essl: ESSL 310), generated with `o`.
std::vector<std::string> texts_of(const variant& v, compile::target target, const codegen::options& o)
{
    std::vector<std::string> out;
    for (const codegen::shader_source& s : codegen::generate(v, o)) out.push_back(compile::compile(s.glsl, s.stage, s.name, {target}).text.at(target));
    return out;
}

// Eight compute variants: SSAO, GTAO, VBAO; every blur; half and full resolution, with and
// without the upsample; view-space and reconstructed normals; the point-cloud fallback.
const char* const variants[] = {"ssao-s16-half-bilateral-gbufworld-std-persp-cs", "ssao-s8-full-box-recon-std-persp-cs",
                                "gtao-2x3-half-bilateral-gbufworld-std-persp-cs", "gtao-4x4-full-denoise-gbufview-std-persp-cs",
                                "gtao-2x2-half-denoise-gbufworld-std-persp-cs",   "gtao-1x2-half-noblur-gbufworld-std-persp-cs-nearest",
                                "vbao-3x3-half-bilateral-gbufworld-std-persp-cs", "ssao-s64-full-noblur-recon-std-persp-cs-pc-rc004"};

// Every variant's `target` text on `api` against its SPIR-V on the Vulkan harness.
void compare_with_spirv(gl::api api, compile::target target, const codegen::options& o)
{
    vulkan::context* vk = shared_context();
    gl::context* gl = shared_gl(api);
    if (!vk || !gl) return;
    INFO(gl->version() << " | " << gl->renderer());
    CHECK(gl->version().rfind(api == gl::api::opengl_es ? "OpenGL ES 3." : "4.5", 0) == 0);
    const int W = 64, H = 40;
    const mat4 proj = perspective(0.6f, float(W) / H, 0.1f, 100.0f);
    const vulkan::gbuffer g = crease(W, H, 0.6f, proj);
    const vulkan::chain_settings s = settings_for(proj);
    for (const char* name : variants) {
        const variant v = variant_from_name(name);
        INFO(name);
        const vulkan::chain_result expected = vulkan::chain(*vk, v).run(g, s);
        const auto [tw, th] = target_size(v, W, H);
        const gl::chain_result got = gl::run(*gl, v, texts_of(v, target, o), g, inputs_for(v, s, tw, th), o);
        REQUIRE(got.width == expected.width);
        REQUIRE(got.height == expected.height);
        size_t exact = 0;
        float worst = 0;
        for (size_t i = 0; i < got.ao.size(); ++i) {
            const float d = std::fabs(got.ao[i] - expected.ao[i]);
            worst = std::max(worst, d);
            exact += d == 0.0f;
        }
        std::cout << compile::to_name(target) << " " << name << ": " << exact << " of " << got.ao.size()
                  << " pixels bit-identical, largest difference " << worst * 255 << "/255\n";
        CHECK(worst <= 1.0f / 255 + 1e-6f);
        // Not a comparison of two blank images: the crease is occluded in both.
        CHECK(*std::min_element(got.ao.begin(), got.ao.end()) < 0.98f);
    }
    require_clean(*vk);
}

} // namespace

TEST_CASE("gl: the emitted GLSL 450 gives the SPIR-V's AO within 1/255 on every pixel (OpenGL 4.5)")
{
    compare_with_spirv(gl::api::opengl, compile::target::glsl, {});
}

TEST_CASE("gl: the emitted ESSL 310 gives the SPIR-V's AO within 1/255 on every pixel (OpenGL ES 3.2)")
{
    codegen::options rgba8; // ESSL 310 has no r8 image format
    rgba8.output_format = "rgba8";
    compare_with_spirv(gl::api::opengl_es, compile::target::essl, rgba8);
}
