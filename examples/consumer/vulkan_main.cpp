// aogen::vulkan from the installed package: open the headless context (validation on
// where the layer is installed), run the default variant's chain on a small G-buffer of
// one plane facing the camera, and print the device and the AO's range. Exits non-zero if
// the plane comes out occluded or a validation message appears; without a Vulkan device,
// 0 (nothing to run on) — unless AOGEN_REQUIRE_DEVICE is set, as aogen's package test sets it.
#include <aogen/vulkan/chain.hpp>
#include <aogen/vulkan/device.hpp>

#include <algorithm>
#include <cstdio>
#include <cstdlib>

int main()
{
    if (!aogen::vulkan::any_device()) {
        std::printf("no Vulkan device: nothing to run\n");
        return std::getenv("AOGEN_REQUIRE_DEVICE") ? 1 : 0;
    }
    aogen::vulkan::context ctx({true});
    const int w = 32, h = 20;
    const aogen::mat4 proj = aogen::perspective(0.6f, float(w) / h, 0.1f, 100.0f);
    const aogen::vec4 clip = proj * aogen::vec4{0, 0, -5, 1};
    aogen::vulkan::gbuffer g{w, h, std::vector<float>(w * h, clip.z / clip.w), std::vector<float>(w * h * 4, 0.0f)};
    for (int i = 0; i < w * h; ++i) g.normals[i * 4 + 2] = 1.0f; // facing the camera
    aogen::vulkan::chain_settings s;
    s.camera = {aogen::mat4{}, proj};
    aogen::vulkan::chain c(ctx, aogen::codegen::make_plan(aogen::variant{}));
    const aogen::vulkan::chain_result r = c.run(g, s);
    const auto [lo, hi] = std::minmax_element(r.ao.begin(), r.ao.end());
    std::printf("%s: %dx%d AO in [%g, %g], %zu validation messages\n", ctx.device_name().c_str(), r.width, r.height, *lo, *hi,
                ctx.messages().size());
    return *lo >= 254.0f / 255.0f && ctx.messages().empty() ? 0 : 1;
}
