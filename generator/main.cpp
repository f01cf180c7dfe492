// aogen — the command line.
//
//   aogen layout  --rules R [--emit glsl|hlsl|msl|wgsl|cpp] STRUCT.json
//   aogen kernel  --kind crytek|cosine|hammersley --count N --seed S --format json|cpp|glsl|wgsl|bin
//   aogen noise   --size N --seed S --pattern P --encoding E --format json|cpp|bin
//   aogen seeds   --out DIR     the seeds' default configurations' data, written to DIR
//   aogen list    [--variants]  the variant axes and their values, or the default matrix
//   aogen generate [--variants SPEC.json] [--scene SCENE.json] --targets T,... --out DIR [NAME ...]
//
// Every failure is one line on stderr ("aogen: <what>: <problem> (<valid>)") and a
// non-zero exit; files are written whole or not at all. `aogen <command> --help` says more.
#include "cmd_generate.hpp"
#include "cmd_kernel.hpp"
#include "cmd_layout.hpp"
#include "cmd_list.hpp"
#include "cmd_noise.hpp"
#include "cmd_seeds.hpp"

#include <aogen_tools/options.hpp>

#include <CLI/CLI.hpp>

#include <algorithm>
#include <iostream>
#include <string>
#include <vector>

int main(int argc, char** argv)
{
    aogen::tools::keep_broken_pipes_as_errors();
    CLI::App app{"aogen: ambient-occlusion kernels, noise, uniform layouts and shader variants"};
    app.require_subcommand(1);
    app.set_help_all_flag("--help-all", "Show the help of every command");

    aogen::cli::layout_command layout;
    aogen::cli::kernel_command kernel;
    aogen::cli::noise_command noise;
    aogen::cli::seeds_command seeds;
    aogen::cli::list_command list;
    aogen::cli::generate_command generate;
    layout.add_to(app);
    kernel.add_to(app);
    noise.add_to(app);
    seeds.add_to(app);
    list.add_to(app);
    generate.add_to(app);

    std::vector<std::string> commands;
    for (const CLI::App* sub : app.get_subcommands([](CLI::App*) { return true; })) commands.push_back(sub->get_name());
    try {
        // CLI11 answers an unknown or a missing command with "A subcommand is required".
        const std::string first = argc > 1 ? argv[1] : "";
        if (first.empty() || (first[0] != '-' && std::find(commands.begin(), commands.end(), first) == commands.end())) {
            std::string valid;
            for (const std::string& c : commands) valid += (valid.empty() ? "" : ", ") + c;
            aogen::fail("command", first.empty() ? "is missing" : aogen::quote(first) + " is not a command", "valid: " + valid + "; see aogen --help");
        }
        app.parse(argc, argv);
        aogen::tools::finish_standard_output();
    } catch (const CLI::CallForHelp&) {
        std::cout << app.help();
        return 0;
    } catch (const CLI::CallForAllHelp&) {
        std::cout << app.help("", CLI::AppFormatMode::All);
        return 0;
    } catch (const CLI::ParseError& e) {
        std::cerr << "aogen: " << aogen::tools::parse_error_line(app, e, "aogen") << "\n";
        return 2;
    } catch (const aogen::error& e) {
        std::cerr << "aogen: " << e.what() << "\n";
        return 1;
    } catch (const std::exception& e) {
        std::cerr << "aogen: " << aogen::tools::exception_line(e) << "\n";
        return 1;
    }
    return 0;
}
