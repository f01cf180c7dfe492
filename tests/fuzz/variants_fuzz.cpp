// tests/fuzz/variants_fuzz.cpp — libFuzzer target: the variant specs and scene-need files of
// `aogen generate` (and the report's variant lists), tools/include/aogen_tools/variant_spec.hpp.
//
// Each input is read as both: a spec and a scene-need file share the parser (json_reader),
// and one corpus of both kinds lets mutations cross from one to the other. After
// json_reader::parse:
//   * tools::variants_from_json: each variant it returns is named (to_name) and described
//     (features), as `aogen generate` does, and its name must read back to the same variant
//     (variant_from_name): a name that does not is a variant the generator writes and no one
//     can ask for again, so it aborts as a finding.
//   * tools::scene_from_json: the needs select from each of the seeds' variants (select),
//     as `aogen generate --scene` does.
// Which failures are answers and which are findings: fuzz_support.hpp.
#include "fuzz_support.hpp"

#include <aogen_tools/variant_spec.hpp>

#include <aogen/matrix.hpp>
#include <aogen/selection.hpp>
#include <aogen/variant.hpp>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
    using namespace aogen;
    const std::string text = fuzz::text_of(data, size);
    fuzz::expect_errors([&] {
        const nlohmann::json document = tools::json_reader::parse(text, "spec.json");
        const tools::json_reader root(document, "spec.json");
        fuzz::expect_errors([&] {
            for (const variant& v : tools::variants_from_json(root)) {
                const std::string name = to_name(v);
                if (!(variant_from_name(name) == v)) {
                    std::fprintf(stderr, "aogen fuzz: variant '%s' does not read back from its name\n", name.c_str());
                    std::abort();
                }
                (void)features(v);
            }
        });
        fuzz::expect_errors([&] {
            const scene_needs needs = tools::scene_from_json(root);
            for (const variant& v : seed_variants()) (void)select(v, needs);
        });
    });
    return 0;
}
