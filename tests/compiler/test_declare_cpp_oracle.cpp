// Oracle: the C++ compiler itself, for the C++ declarations of declare.hpp.
//
// declare(layout, language::cpp) writes a struct with explicit padding and a
// static_assert on every member's offsetof and on the sizeof of each struct. A real
// C++17 compiler evaluating those asserts is an independent check that the emitted
// C++ puts every member exactly where aogen's layout says (it knows the sizes and
// alignments of float, std::int32_t, std::array and the padding helpers; aogen only
// chooses the text). Random structs under every rule set (those a rule set rejects are
// skipped) go into one translation unit, each in its own namespace, compiled with
// `c++ -std=c++17 -fsyntax-only`; the test passes when the compiler exits with 0.
//
// The compiler is `c++` from PATH, or AOGEN_TEST_CXX_COMPILER when the build defines it;
// when neither can be run the test is skipped with a warning.

#include "random_structs.hpp"
#include "support.hpp"

#include <aogen/declare.hpp>
#include <aogen/layout.hpp>

#include <catch2/catch.hpp>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <unistd.h>

// One namespace per test file: the files of one executable share a translation unit
// (tests/CMakeLists.txt: a unity build), and their helpers must not meet.
namespace unity_test_declare_cpp_oracle {

using namespace aogen::layout;

namespace {

constexpr uint32_t cpp_structs_per_rule = 40;

#ifdef AOGEN_TEST_CXX_COMPILER
const char* const cxx = AOGEN_TEST_CXX_COMPILER;
#else
const char* const cxx = "c++";
#endif

std::string quote(const std::string& s) { return "'" + s + "'"; } // paths we make have no quotes

std::string read_file(const std::filesystem::path& p)
{
    std::ifstream in(p);
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
}

// Removes the helper prelude from a declaration: the translation unit defines it once,
// at global scope, and #include lines do not belong inside a namespace.
std::string without_prelude(std::string declaration)
{
    const std::string prelude = detail::cpp_prelude();
    const size_t at = declaration.find(prelude);
    if (at != std::string::npos) declaration.erase(at, prelude.size());
    return declaration;
}

} // namespace

TEST_CASE("C++ compiler oracle: declare(language::cpp) compiles and its static_asserts hold", "[layout][oracle][cpp]")
{
    if (std::system((std::string("command -v ") + cxx + " >/dev/null 2>&1").c_str()) != 0) {
        aogen_test::skip_missing_dependency(std::string("no C++ compiler '") + cxx + "' on PATH for the C++ declaration oracle");
        return;
    }
    std::ostringstream unit;
    int declared = 0, rejected = 0;
    bool first = true;
    for (rules r : all_rules) {
        aogen_test::generator_options options;
        options.runtime_array = allows_runtime_array(r);
        for (uint32_t seed = 1; seed <= cpp_structs_per_rule; ++seed) {
            const block_desc block = aogen_test::random_block(seed, options);
            struct_layout l;
            try {
                l = compute(block, r);
            } catch (const aogen::error&) {
                ++rejected; // e.g. wgsl-uniform: an array stride that is not a multiple of 16
                continue;
            }
            const std::string declaration = declare(l, language::cpp);
            std::string ns = std::string("rules_") + to_name(r) + "_seed" + std::to_string(seed);
            for (char& c : ns)
                if (c == '-') c = '_';
            if (first) { // the first one exactly as emitted, prelude and all, at global scope
                unit << "// " << ns << ": " << aogen_test::describe(block) << "\n" << declaration << "\n";
                first = false;
            } else {
                unit << "// " << aogen_test::describe(block) << "\nnamespace " << ns << " {\n"
                     << without_prelude(declaration) << "} // namespace " << ns << "\n\n";
            }
            ++declared;
        }
    }
    INFO(declared << " declarations, " << rejected << " random structs rejected by their rule set");
    CHECK(declared >= 200);

    const std::filesystem::path dir =
        std::filesystem::temp_directory_path() / ("aogen_cpp_oracle_" + std::to_string(::getpid()));
    std::filesystem::create_directories(dir);
    const std::filesystem::path source = dir / "declarations.cpp", log = dir / "compiler.log";
    {
        std::ofstream out(source);
        out << unit.str();
    }
    const std::string command = std::string(cxx) + " -std=c++17 -fsyntax-only -Wall -Wextra " + quote(source.string()) +
                                " >" + quote(log.string()) + " 2>&1";
    const int status = std::system(command.c_str());
    const std::string messages = read_file(log);
    INFO(command << "\n" << messages.substr(0, 6000));
    CHECK(status == 0);
    if (status == 0) std::filesystem::remove_all(dir); // kept for inspection when it fails
}

} // namespace unity_test_declare_cpp_oracle
