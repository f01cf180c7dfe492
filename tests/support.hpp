// tests/support.hpp — small helpers the test files share.
#pragma once

#include <aogen/error.hpp>
#include <aogen/layout.hpp>

#include <catch2/catch.hpp>

#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <string>

namespace aogen_test {

// The aogen::error message `f` throws; any other exception fails the test by escaping.
template <class F>
std::string error_of(F&& f)
{
    try {
        f();
    } catch (const aogen::error& e) {
        return e.what();
    }
    return "<no aogen::error thrown>";
}

// A test whose dependency is missing (no Vulkan device, no assimp or its test models):
// a failure naming it, since install-deps.sh installs all of them and a missing one means
// a broken setup; with AOGEN_TESTS_OPTIONAL_DEPS=1, a warning and a skip instead (returns
// false, and the caller returns), for machines that cannot have it: the skip is an explicit
// SUCCEED, since a test that asserts nothing fails (catch_main.cpp).
inline bool skip_missing_dependency(const std::string& what)
{
    const char* optional = std::getenv("AOGEN_TESTS_OPTIONAL_DEPS");
    if (optional && std::string(optional) == "1") {
        WARN("skipped: " << what);
        SUCCEED("skipped on purpose (AOGEN_TESTS_OPTIONAL_DEPS=1)"); // every test must assert (catch_main.cpp)
        return false;
    }
    FAIL(what << " (set AOGEN_TESTS_OPTIONAL_DEPS=1 to skip instead)");
    return false;
}

inline uint32_t bits_of(float value)
{
    uint32_t bits;
    std::memcpy(&bits, &value, sizeof bits);
    return bits;
}

inline float float_from_bits(uint32_t bits)
{
    float value;
    std::memcpy(&value, &bits, sizeof value);
    return value;
}

// The member at `path` of a layout; fails the test when there is none.
inline const aogen::layout::member_layout& at(const aogen::layout::struct_layout& l, const char* path)
{
    const aogen::layout::member_layout* m = aogen::layout::find(l, path);
    INFO("member " << path);
    REQUIRE(m != nullptr);
    return *m;
}

} // namespace aogen_test
