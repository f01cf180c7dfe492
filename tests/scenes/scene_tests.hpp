// Helpers shared by the aogen::scenes tests: float distances, the projection's depth formula,
// JSON error messages and built-in scenes whose model files may be missing.
#pragma once

#include <aogen_scenes/gbuffer.hpp>

#include "support.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <string>

using namespace aogen;
using namespace aogen::scenes;

// Distance in representable floats between a and b (same sign assumed, both finite).
inline int64_t ulps(float a, float b)
{
    int32_t ia, ib;
    std::memcpy(&ia, &a, 4);
    std::memcpy(&ib, &b, 4);
    return std::abs(int64_t(ia) - int64_t(ib));
}

// The projection's depth formula for view distance z (float math, as a GPU would).
inline float expected_depth(depth_convention d, float n, float f, float z)
{
    switch (d) {
    case depth_convention::standard: return (f / (n - f) * -z + n * f / (n - f)) / z;
    case depth_convention::reversed: return (n / (f - n) * -z + n * f / (f - n)) / z;
    case depth_convention::reversed_infinite: return n / z;
    }
    return 0;
}

// The error message read_scene gives for `json` ("(no error)" when it parses).
inline std::string message_of(const std::string& json, const std::string& source = "scene.json")
{
    try {
        read_scene(json, source);
    } catch (const aogen::error& e) {
        return e.what();
    }
    return "(no error)";
}

// The built-in scene `name` into `out`; when its model file is missing (assimp-testmodels
// not installed) or aogen::scenes was built without assimp, a failure, or false with
// AOGEN_TESTS_OPTIONAL_DEPS=1 (support.hpp).
inline bool builtin_or_skip(const std::string& name, scene& out)
{
    try {
        out = builtin_scene(name);
        return true;
    } catch (const aogen::error& e) {
        const std::string m = e.what();
        if (m.find("install assimp-testmodels") == std::string::npos && m.find("built without") == std::string::npos) throw;
        return aogen_test::skip_missing_dependency(m);
    }
}

// Whether aogen::scenes has assimp; without it a failure, or false with
// AOGEN_TESTS_OPTIONAL_DEPS=1 (support.hpp).
inline bool have_assimp()
{
#ifdef AOGEN_SCENES_ASSIMP
    return true;
#else
    return aogen_test::skip_missing_dependency("aogen::scenes was built without assimp (libassimp-dev)");
#endif
}
