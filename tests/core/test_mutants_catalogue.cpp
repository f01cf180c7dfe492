// The planted faults' catalogue (tests/mutants/mutants.json) as docs/tests.md § Planted faults
// shows it: one row per mutant, in the catalogue's order, and the counts docs/tests.md states.
// A mutant added without its row, or a row whose mutant is gone, fails here.
#include <catch2/catch.hpp>

#include <nlohmann/json.hpp>

#include <fstream>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

// One namespace per test file: the files of one executable share a translation unit
// (tests/CMakeLists.txt: a unity build), and their helpers must not meet.
namespace unity_test_mutants_catalogue {

TEST_CASE("mutants: docs/tests.md's table of planted faults is tests/mutants/mutants.json's", "[docs]")
{
    std::ifstream json_in(AOGEN_MUTANTS_FILE);
    REQUIRE(json_in);
    const nlohmann::json catalogue = nlohmann::json::parse(json_in);
    std::vector<std::string> names;
    size_t kill_tests = 0;
    for (const nlohmann::json& m : catalogue.at("mutants")) {
        names.push_back(m.at("name"));
        kill_tests += m.at("killed_by").size();
        CHECK(!m.at("killed_by").empty());
    }

    std::ifstream doc_in(AOGEN_SOURCE_DIR "/docs/tests.md");
    REQUIRE(doc_in);
    std::stringstream text;
    text << doc_in.rdbuf();
    const std::string doc = text.str();
    std::vector<std::string> rows;
    const std::regex row("\\n\\| `([a-z0-9_]+)` \\| [^\\n]*\\| `[^\\n]*\\|");
    const size_t table = doc.find("| mutant | planted in | the fault | killed by |");
    REQUIRE(table != std::string::npos);
    const std::string after = doc.substr(table, doc.find("\n\n", table) - table);
    for (std::sregex_iterator i(after.begin(), after.end(), row), end; i != end; ++i) rows.push_back((*i)[1]);
    CHECK(rows == names);
    CHECK(doc.find(std::to_string(names.size()) + " mutants, " + std::to_string(kill_tests) + " kill tests") != std::string::npos);
}

} // namespace unity_test_mutants_catalogue
