// generator/cmd_layout.hpp — `aogen layout`: a struct's layout, or its declaration.
//
//   aogen layout --rules std140 params.json              JSON: every offset and stride
//   aogen layout --rules std140 --emit glsl params.json  the GLSL block declaration
#pragma once

#include <aogen_tools/files.hpp>
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

    void add_to(CLI::App& app)
    {
        CLI::App* sub = app.add_subcommand("layout", "Lay out a struct (JSON) under a rule set; print the layout or a declaration");
        sub->add_option("--rules", rules, "Rule set: " + layout::rules_names())->required();
        sub->add_option("--emit", language, "Print a declaration instead of JSON: glsl, hlsl, msl, wgsl, cpp");
        sub->add_option("--set", declaration.set, "Descriptor set / bind group / register space of the declaration");
        sub->add_option("--binding", declaration.binding, "Binding / register of the declaration");
        sub->add_option("--instance", declaration.instance, "Block instance or variable name of the declaration");
        sub->add_option("--out", out, "Write to this file instead of standard output");
        sub->add_option("STRUCT.json", input, "The struct description (see README: Struct files)")->required();
        sub->callback([this] { run(); });
    }

    void run() const
    {
        const layout::rules rule = layout::rules_from_name(rules);
        std::optional<layout::language> declaration_language;
        if (!language.empty()) declaration_language = layout::language_from_name(language);
        const nlohmann::json document = json_reader::parse(read_file(input), input);
        const layout::struct_layout result = layout::compute(block_from_json(json_reader(document, input)), rule);
        if (declaration_language) emit(out, layout::declare(result, *declaration_language, declaration));
        else emit(out, layout_to_json(result).dump(2) + "\n");
    }
};

} // namespace aogen::cli
