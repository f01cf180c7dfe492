// generator/cmd_layout.hpp — `aogen layout`: a struct's layout, or its declaration.
//
//   aogen layout --rules std140 params.json              JSON: every offset and stride
//   aogen layout --rules std140 --emit glsl params.json  the GLSL block declaration
#pragma once

#include <aogen_tools/files.hpp>
#include <aogen_tools/options.hpp>
#include "struct_json.hpp"

#include <aogen/declare.hpp>

#include <CLI/CLI.hpp>

#include <optional>

namespace aogen::cli {

using namespace tools; // the readers and writers the command line shares with the report (tools/)

struct layout_command {
    std::string rules;
    std::string language;
    std::string input;
    std::string out;
    layout::declaration_options declaration;
    CLI::Option *set_option = nullptr, *binding_option = nullptr, *instance_option = nullptr; // only with --emit

    void add_to(CLI::App& app)
    {
        CLI::App* sub = app.add_subcommand("layout", "Lay out a struct (JSON) under a rule set; print the layout or a declaration");
        sub->add_option("--rules", rules, "Rule set: " + layout::rules_names())->required();
        sub->add_option("--emit", language, "Print a declaration instead of JSON: glsl, hlsl, msl, wgsl, cpp");
        set_option = sub->add_option("--set", declaration.set, "Descriptor set / bind group / register space of the declaration")->check(integer_in(0, 4294967295u));
        binding_option = sub->add_option("--binding", declaration.binding, "Binding / register of the declaration")->check(integer_in(0, 4294967295u));
        instance_option = sub->add_option("--instance", declaration.instance, "Block instance or variable name of the declaration")->check(declaration_name());
        sub->add_option("--out", out, "Write to this file instead of standard output")->check(not_empty("a file path, or - for standard output"));
        sub->add_option("STRUCT.json", input, "The struct description (see docs/cli.md#struct-files)")->required();
        sub->callback([this] { run(); });
    }

    void run() const
    {
        const layout::rules rule = layout::rules_from_name(rules);
        std::optional<layout::language> declaration_language;
        if (!language.empty()) declaration_language = layout::language_from_name(language);
        for (const CLI::Option* o : {set_option, binding_option, instance_option})
            if (!declaration_language && o->count() > 0)
                fail(o->get_name(), "shapes a declaration, and without --emit none is printed", "valid: give --emit glsl|hlsl|msl|wgsl|cpp, or leave it out");
        const nlohmann::json document = json_reader::parse(read_file(input), input);
        const layout::struct_layout result = layout::compute(block_from_json(json_reader(document, input)), rule);
        if (declaration_language) emit(out, layout::declare(result, *declaration_language, declaration));
        else emit(out, layout_to_json(result).dump(2) + "\n");
    }
};

} // namespace aogen::cli
