// tests/compiler/test_generate_plans.cpp — `aogen generate` plans each variant once.
//
// The command (generator/cmd_generate.hpp) used to plan each variant three times -- its
// Vulkan GLSL, its ESSL set (even where ESSL was not asked for), its WebGPU set -- and lay each
// pass's uniform block out twice more for the manifest. Now it makes one plan per variant,
// moves it to each target's options (plan_for: nothing is planned again) and reads each
// block's layout from the plan. The counters are plan.hpp's and layout.hpp's.
#include <aogen/codegen.hpp>
#include <aogen/matrix.hpp>

#include <catch2/catch.hpp>

#include "cmd_generate.hpp"

#include <unistd.h>

#include <filesystem>
#include <string>
#include <vector>

namespace unity_test_generate_plans {

using namespace aogen;

TEST_CASE("generate: aogen generate plans each variant once and lays each uniform block out once, for every target", "[generate][plan]")
{
    namespace fs = std::filesystem;
    const fs::path out = fs::temp_directory_path() / ("aogen_generate_plans_" + std::to_string(::getpid()));
    fs::remove_all(out);
    const std::vector<std::string> names{"ssao-s8-full-bilateral-gbufworld-std-persp-cs", "gtao-2x2-half-denoise-recon-rev-persp-fs",
                                         "sao-s12-full-noblur-gbufview-std-persp-cs"};
    size_t pass_count = 0;
    for (const std::string& n : names) pass_count += passes(variant_from_name(n)).size();

    aogen::cli::generate_command cmd;
    cmd.out = out.string();
    cmd.targets = "spv,glsl,essl,hlsl,hlsl60,msl,msl_ios"; // every target but WGSL, which needs Node.js
    cmd.variant_names = names;
    cmd.quiet = true;
    const unsigned long plans = codegen::detail::plans_made(), layouts = layout::detail::computations();
    cmd.run();
    CHECK(codegen::detail::plans_made() - plans == names.size());
    CHECK(layout::detail::computations() - layouts == pass_count); // std140, once per pass: the plan's
    CHECK(fs::exists(out / "manifest.json"));
    fs::remove_all(out);
}

TEST_CASE("generate: a history variant's manifest entry names the bindings it reads and where it writes the history, per stage", "[generate][history]")
{
    const nlohmann::ordered_json compute = cli::history_entry(variant_from_name("gtao-1x4-half-noblur-gbufworld-std-persp-cs-histmv"));
    CHECK(compute["format"] == "rgba16f");
    CHECK(compute["read"]["binding"] == 6);
    CHECK(compute["read"]["wgsl_binding"] == 8);
    CHECK(compute["written"]["name"] == "u_history_output");
    CHECK(compute["written"]["binding"] == 7);
    CHECK(compute["written"]["wgsl_binding"] == 9);
    CHECK(compute["motion_vectors"]["binding"] == 8);
    CHECK(compute["motion_vectors"]["wgsl_binding"] == 10);
    // A fragment pass writes the history as its second colour attachment (history.glsl's o_history).
    const nlohmann::ordered_json fragment = cli::history_entry(variant_from_name("ssao-s16-half-bilateral-gbufworld-std-persp-fs-hist"));
    CHECK(fragment["written"]["name"] == "o_history");
    CHECK(fragment["written"]["colour_attachment"] == 1);
    CHECK(!fragment["written"].contains("binding"));
    CHECK(!fragment.contains("motion_vectors")); // -hist reads none
    CHECK(fragment["each_frame"].get<std::string>().find("attachment 1") != std::string::npos);
}

} // namespace unity_test_generate_plans
