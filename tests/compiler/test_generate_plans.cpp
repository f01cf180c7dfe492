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

} // namespace unity_test_generate_plans
