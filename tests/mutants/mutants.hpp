// tests/mutants/mutants.hpp — planted faults kept as tests. Every fault we ever planted by
// hand to see a test fire is an entry of tests/mutants/mutants.json: a small edit (one text
// found exactly once, replaced) of a template, of an emitted target's text, or of a C++
// header, and the test that must fail with it. A ctest test per entry (label `mutants`,
// tests/mutants/mutants.cmake) runs that test with the mutant planted and passes only when
// the test fails on an assertion; a mutant that survives is a finding.
//
//     AOGEN_MUTANT=gtao_projected_normal_dropped build/tests/aogen_accuracy_tests "accuracy: gtao*"
//
// How a test lets the mutant in: it reads templates through template_under_test() (or
// codegen::options from under_test(), or a harness chain from harness.hpp's
// chain_under_test()), and passes emitted texts through emitted_under_test(). Without
// AOGEN_MUTANT these are the embedded templates and the texts unchanged. Source mutants
// (kind "source") need no hook: CMake builds a copy of the test executable against the
// edited header.
#pragma once

#include <aogen/codegen.hpp>
#include <aogen/error.hpp>

#include <nlohmann/json.hpp>

#include <cstdlib>
#include <fstream>
#include <iostream>
#include <optional>
#include <string>

#ifndef AOGEN_MUTANTS_FILE
#error "tests/CMakeLists.txt defines AOGEN_MUTANTS_FILE (tests/mutants/mutants.json)"
#endif

namespace aogen_test {

struct mutant {
    std::string name;
    std::string kind;    // "template", "emitted", "source"
    std::string file;    // a template path ("gtao.glsl"), "<target>:<shader name>", or a header path
    std::string find;    // found exactly once in it
    std::string replace; // what it becomes
};

// The catalogue's entry `name`; aogen::error naming the valid ones when there is none.
inline mutant mutant_named(const std::string& name)
{
    std::ifstream in(AOGEN_MUTANTS_FILE);
    if (!in) aogen::fail("AOGEN_MUTANT", "cannot read " + std::string(AOGEN_MUTANTS_FILE), "valid: the source tree's tests/mutants/mutants.json");
    const nlohmann::json catalogue = nlohmann::json::parse(in);
    std::string valid;
    for (const nlohmann::json& m : catalogue.at("mutants")) {
        if (m.at("name") == name)
            return {m.at("name"), m.at("kind"), m.at("file"), m.at("find"), m.at("replace")};
        valid += (valid.empty() ? "" : ", ") + m.at("name").get<std::string>();
    }
    aogen::fail("AOGEN_MUTANT", "'" + name + "' is not in tests/mutants/mutants.json", "valid: " + valid);
}

// The mutant AOGEN_MUTANT names, read once; none when it is unset or empty.
inline const std::optional<mutant>& active_mutant()
{
    static const std::optional<mutant> active = []() -> std::optional<mutant> {
        const char* name = std::getenv("AOGEN_MUTANT");
        if (!name || !*name) return std::nullopt;
        return mutant_named(name);
    }();
    return active;
}

// `text` (`where`: the file it came from) with the active mutant planted when it is aimed
// at `file` of `kind`. The anchor must be there exactly once: a mutant that no longer
// matches its file throws, and a thrown test is not a killed mutant (kill.cmake).
inline std::string planted(std::string text, const std::string& kind, const std::string& file)
{
    const std::optional<mutant>& m = active_mutant();
    if (!m || m->kind != kind || m->file != file) return text;
    const size_t at = text.find(m->find);
    if (at == std::string::npos || text.find(m->find, at + 1) != std::string::npos)
        aogen::fail("mutant " + m->name, "its text is not found exactly once in " + file, "valid: update tests/mutants/mutants.json");
    static bool told = false;
    if (!told) std::cerr << "aogen mutant " << m->name << ": planted in " << file << "\n";
    told = true;
    return text.replace(at, m->find.size(), m->replace);
}

// The embedded template `path`, with a template mutant planted.
inline std::string template_under_test(const std::string& path)
{
    return planted(aogen::codegen::embedded_template(path), "template", path);
}

// `o`, reading its templates through template_under_test.
inline aogen::codegen::options under_test(aogen::codegen::options o = {})
{
    o.templates = template_under_test;
    return o;
}

// An emitted text, `where` naming it "<target>:<shader name>" ("hlsl:ssao-s16-...-cs.blur_x.comp"),
// with an emitted-text mutant aimed at it planted.
inline std::string emitted_under_test(std::string text, const std::string& where)
{
    return planted(std::move(text), "emitted", where);
}

} // namespace aogen_test
