// tests/fuzz/struct_fuzz.cpp — libFuzzer target: the struct files of `aogen layout`.
//
// Each input is the text of a STRUCT.json. It goes the way `aogen layout` takes it
// (generator/cmd_layout.hpp): json_reader::parse, then cli::block_from_json. A block that
// parses is then laid out under every rule set (layout::compute), and each layout that
// succeeds is printed as `aogen layout` prints it (layout_to_json) and declared in every
// language (layout::declare): a struct that is bad in a way the reader does not see reaches
// those, so they are fuzzed with it. Which failures are answers and which are findings:
// fuzz_support.hpp.
#include "fuzz_support.hpp"

#include "struct_json.hpp" // generator/

#include <aogen/declare.hpp>
#include <aogen/layout.hpp>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
    using namespace aogen;
    const std::string text = fuzz::text_of(data, size);
    fuzz::expect_errors([&] {
        const nlohmann::json document = tools::json_reader::parse(text, "struct.json");
        const layout::block_desc block = cli::block_from_json(tools::json_reader(document, "struct.json"));
        // Each rule set, and each language, on its own: one rejecting the block (a runtime
        // array in a uniform block, HLSL without hlsl-cbuffer) must not hide the others.
        for (layout::rules r : layout::all_rules)
            fuzz::expect_errors([&] {
                const layout::struct_layout l = layout::compute(block, r);
                (void)cli::layout_to_json(l).dump(2);
                for (layout::language language : layout::all_languages)
                    fuzz::expect_errors([&] { (void)layout::declare(l, language); });
            });
    });
    return 0;
}
