// gtao.glsl's slice integral, evaluated from the shader's own GLSL, against integrals the
// test computes independently: the 1D slice integral by quadrature, and the whole
// hemisphere against DESIGN.md's closed forms (floor and infinite wall, a tilted wall, a
// 90-degree groove, an open plane) with exact horizons.
//
// How the GLSL is evaluated without a GPU: the GTAO AO pass is generated as usual, with
// entry_compute.glsl replaced by a test entry point whose main() calls gtao.glsl's
// functions (ao_gtao_projected_normal, ao_gtao_slice_integral, ao_gtao_slice_unoccluded)
// with constant arguments and stores each result into a buffer. glslang compiles it;
// spirv-opt's performance passes inline the calls and fold most of the arithmetic to
// constants (SPIRV-Tools folds float arithmetic and GLSL.std.450's acos, atan2, cos,
// sqrt, clamp, ... in host float arithmetic). What they leave -- straight-line float
// arithmetic, such as the Fma instructions the folder makes of a multiply and an add
// before their operands are known -- run_main() evaluates, in float; anything else
// (a branch, an instruction it does not know) fails the test, naming it. The values
// compared are the shader's own SPIR-V's, not a C++ transcription of its formulas.

#include <aogen/codegen.hpp>
#include <aogen/compile.hpp>

#include <catch2/catch.hpp>

#include <spirv_cross/GLSL.std.450.h>
#include <spirv_cross/spirv.hpp>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <functional>
#include <map>
#include <optional>
#include <string>
#include <vector>

using namespace aogen;

namespace {

constexpr double pi = 3.14159265358979323846;
constexpr double half_pi = pi / 2;

std::string lit(double x) { return codegen::detail::glsl_float(static_cast<float>(x)); }

// ---- evaluating GLSL expressions through glslang + spirv-opt -----------------------------

// Runs main() of an optimized module on the CPU, as far as spirv-opt left anything to
// run: straight-line float arithmetic and GLSL.std.450 calls on constants (its folder
// leaves, for instance, the Fma instructions it makes of a multiply and an add). Returns
// the floats main() stores into ao_test.r[i], by i. Branches, loops, memory other than
// the stores, and instructions not listed below fail the test, naming the opcode.
// Arithmetic is in float, as on a GPU.
std::vector<float> run_main(const std::vector<uint32_t>& words, size_t count)
{
    std::map<uint32_t, std::vector<float>> values; // id -> components (bools as 0 / 1)
    std::map<uint32_t, uint32_t> chain_index;      // access chain -> its last index's id
    std::map<uint32_t, bool> float_type;           // scalar and vector types: float or not
    uint32_t main_function = 0;
    bool in_main = false, seen_label = false;
    std::vector<std::optional<float>> out(count);
    auto value = [&](uint32_t id) -> const std::vector<float>& {
        auto v = values.find(id);
        if (v == values.end()) FAIL("SPIR-V id " << id << " has no value (not a constant, nor computed before use)");
        return v->second;
    };
    auto scalar = [&](uint32_t id) {
        const std::vector<float>& v = value(id);
        REQUIRE(v.size() == 1);
        return v[0];
    };
    auto map = [&](uint32_t a, auto f) {
        std::vector<float> r = value(a);
        for (float& x : r) x = f(x);
        return r;
    };
    auto map2 = [&](uint32_t a, uint32_t b, auto f) {
        std::vector<float> r = value(a);
        const std::vector<float>& y = value(b);
        REQUIRE(y.size() == r.size());
        for (size_t i = 0; i < r.size(); ++i) r[i] = f(r[i], y[i]);
        return r;
    };
    for (size_t i = 5; i < words.size();) {
        const uint32_t length = words[i] >> 16;
        const auto op = static_cast<spv::Op>(words[i] & 0xffffu);
        REQUIRE(length > 0);
        REQUIRE(i + length <= words.size());
        const uint32_t* w = &words[i];
        i += length;
        switch (op) {
        case spv::OpEntryPoint: main_function = w[2]; continue;
        case spv::OpTypeFloat: float_type[w[1]] = true; continue;
        case spv::OpTypeInt:
        case spv::OpTypeBool: float_type[w[1]] = false; continue;
        case spv::OpTypeVector: float_type[w[1]] = float_type[w[2]]; continue;
        case spv::OpConstant: {
            float f;
            if (float_type[w[1]]) std::memcpy(&f, &w[3], sizeof f);
            else f = static_cast<float>(w[3]);
            values[w[2]] = {f};
            continue;
        }
        case spv::OpConstantTrue: values[w[2]] = {1.0f}; continue;
        case spv::OpConstantFalse: values[w[2]] = {0.0f}; continue;
        case spv::OpConstantComposite:
            if (!in_main) {
                std::vector<float> v;
                bool ok = true;
                for (uint32_t k = 3; k < length; ++k) {
                    auto c = values.find(w[k]);
                    if (c == values.end()) ok = false;
                    else v.insert(v.end(), c->second.begin(), c->second.end());
                }
                if (ok) values[w[2]] = v;
            }
            continue;
        case spv::OpFunction: in_main = w[2] == main_function; continue;
        case spv::OpFunctionEnd: in_main = false; continue;
        default: break;
        }
        if (!in_main) continue;
        switch (op) {
        case spv::OpLabel:
            if (seen_label) FAIL("main() has more than one block: branches were not folded away");
            seen_label = true;
            break;
        case spv::OpReturn: break;
        case spv::OpAccessChain:
        case spv::OpInBoundsAccessChain: chain_index[w[2]] = w[length - 1]; break;
        case spv::OpStore: {
            auto chain = chain_index.find(w[1]);
            REQUIRE(chain != chain_index.end());
            const size_t slot = static_cast<size_t>(scalar(chain->second));
            REQUIRE(slot < count);
            out[slot] = scalar(w[2]);
            break;
        }
        case spv::OpCompositeExtract: values[w[2]] = {value(w[3]).at(w[4])}; break;
        case spv::OpCompositeConstruct: {
            std::vector<float> v;
            for (uint32_t k = 3; k < length; ++k) v.insert(v.end(), value(w[k]).begin(), value(w[k]).end());
            values[w[2]] = v;
            break;
        }
        case spv::OpFNegate: values[w[2]] = map(w[3], [](float x) { return -x; }); break;
        case spv::OpFAdd: values[w[2]] = map2(w[3], w[4], [](float x, float y) { return x + y; }); break;
        case spv::OpFSub: values[w[2]] = map2(w[3], w[4], [](float x, float y) { return x - y; }); break;
        case spv::OpFMul: values[w[2]] = map2(w[3], w[4], [](float x, float y) { return x * y; }); break;
        case spv::OpFDiv: values[w[2]] = map2(w[3], w[4], [](float x, float y) { return x / y; }); break;
        case spv::OpSelect: values[w[2]] = scalar(w[3]) != 0.0f ? value(w[4]) : value(w[5]); break;
        case spv::OpExtInst: {
            const uint32_t a = w[5];
            switch (static_cast<GLSLstd450>(w[4])) {
            case GLSLstd450Sin: values[w[2]] = map(a, [](float x) { return std::sin(x); }); break;
            case GLSLstd450Cos: values[w[2]] = map(a, [](float x) { return std::cos(x); }); break;
            case GLSLstd450Acos: values[w[2]] = map(a, [](float x) { return std::acos(x); }); break;
            case GLSLstd450Sqrt: values[w[2]] = map(a, [](float x) { return std::sqrt(x); }); break;
            case GLSLstd450Atan2: values[w[2]] = map2(a, w[6], [](float y, float x) { return std::atan2(y, x); }); break;
            case GLSLstd450FMin: values[w[2]] = map2(a, w[6], [](float x, float y) { return std::min(x, y); }); break;
            case GLSLstd450FMax: values[w[2]] = map2(a, w[6], [](float x, float y) { return std::max(x, y); }); break;
            case GLSLstd450FClamp: {
                const std::vector<float> lo = value(w[6]), hi = value(w[7]);
                std::vector<float> r = value(a);
                REQUIRE(lo.size() == r.size());
                REQUIRE(hi.size() == r.size());
                for (size_t k = 0; k < r.size(); ++k) r[k] = std::min(std::max(r[k], lo[k]), hi[k]);
                values[w[2]] = r;
                break;
            }
            case GLSLstd450Fma: {
                const std::vector<float> y = value(w[6]), z = value(w[7]);
                std::vector<float> r = value(a);
                REQUIRE(y.size() == r.size());
                REQUIRE(z.size() == r.size());
                for (size_t k = 0; k < r.size(); ++k) r[k] = std::fma(r[k], y[k], z[k]);
                values[w[2]] = r;
                break;
            }
            default: FAIL("main() calls GLSL.std.450 instruction " << w[4] << ", which this test does not evaluate");
            }
            break;
        }
        default: FAIL("main() has opcode " << int(op) << ", which this test does not evaluate");
        }
    }
    std::vector<float> r;
    for (size_t k = 0; k < count; ++k) {
        INFO("ao_test.r[" << k << "]");
        REQUIRE(out[k].has_value());
        r.push_back(*out[k]);
    }
    return r;
}

// Each GLSL float expression evaluated with gtao.glsl (and the files before it) in scope.
std::vector<float> evaluate(const std::vector<std::string>& expressions)
{
    std::string entry = "layout(local_size_x = 1, local_size_y = 1, local_size_z = 1) in;\n"
                        "layout(std430, set = 1, binding = 0) writeonly buffer AoTest { float r[]; } ao_test;\n"
                        "void main()\n{\n";
    for (size_t i = 0; i < expressions.size(); ++i)
        entry += "    ao_test.r[" + std::to_string(i) + "] = " + expressions[i] + ";\n";
    entry += "}\n";
    const codegen::template_reader read = [&entry](const std::string& path) {
        return path == "entry_compute.glsl" ? entry : codegen::embedded_template(path);
    };
    variant v;
    v.tech = technique::gtao;
    const codegen::shader_source s = codegen::generate_shader(v, pass_kind::ao, shader_stage::compute, read);
    REQUIRE(s.glsl.find("ao_half ao_gtao_slice_integral(") != std::string::npos); // ao_half: float here (no fp16)
    const std::vector<uint32_t> words =
        compile::optimize_spirv(compile::glsl_to_spirv(s.glsl, shader_stage::compute, "gtao slice test"), "gtao slice test");
    return run_main(words, expressions.size());
}

// ---- independent references ---------------------------------------------------------------

// integral_a^b cos(t - n) |sin t| dt by composite Simpson, split at 0.
double slice_quadrature(double a, double b, double n)
{
    auto simpson = [n](double lo, double hi) {
        const int steps = 2000;
        const double h = (hi - lo) / steps;
        double sum = 0;
        for (int i = 0; i <= steps; ++i) {
            const double t = lo + i * h;
            const double f = std::cos(t - n) * std::abs(std::sin(t));
            sum += f * (i == 0 || i == steps ? 1 : i % 2 ? 4 : 2);
        }
        return sum * h / 3;
    };
    if (a < 0 && b > 0) return simpson(a, 0) + simpson(0, b);
    return simpson(a, b);
}

struct vec3d {
    double x = 0, y = 0, z = 0;
};
vec3d operator+(vec3d a, vec3d b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
vec3d operator*(vec3d a, double s) { return {a.x * s, a.y * s, a.z * s}; }
double dot(vec3d a, vec3d b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
vec3d cross(vec3d a, vec3d b) { return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x}; }
vec3d normalize(vec3d a) { return a * (1 / std::sqrt(dot(a, a))); }
std::string glsl(vec3d a) { return "vec3(" + lit(a.x) + ", " + lit(a.y) + ", " + lit(a.z) + ")"; }

using visible_set = std::function<bool(vec3d)>;

// Walking from V toward `toward` (unit, perpendicular to V) in the slice plane: the first
// angle at which the direction leaves the visible set (pi if it never does). The visible
// sets here are intersections of half-spaces, so along a slice they are one arc around V,
// and this is that arc's end: the exact horizon on that side.
double first_hidden(vec3d V, vec3d toward, const visible_set& visible)
{
    auto direction = [&](double t) { return V * std::cos(t) + toward * std::sin(t); };
    const int steps = 4096;
    double previous = 0;
    for (int i = 1; i <= steps; ++i) {
        const double t = pi * i / steps;
        if (!visible(direction(t))) {
            double lo = previous, hi = t;
            for (int k = 0; k < 60; ++k) {
                const double mid = 0.5 * (lo + hi);
                (visible(direction(mid)) ? lo : hi) = mid;
            }
            return hi;
        }
        previous = t;
    }
    return pi;
}

// AO at a point with normal n, seen from direction V, whose unoccluded directions are
// `visible` (a subset of n's hemisphere), from `slices` slices with exact horizons, each
// slice's projected normal and integrals computed by the shader's functions. The sums
// are ao_pass's: sum |n_p| a / sum |n_p| (cos n + n sin n).
double shader_ao(vec3d n, vec3d V, const visible_set& visible, int slices)
{
    REQUIRE(visible(V));
    const vec3d e1 = normalize(cross(V, vec3d{0.31, 0.77, 0.55}));
    const vec3d e2 = cross(V, e1);
    std::vector<std::string> expressions;
    for (int k = 0; k < slices; ++k) {
        const double phi = (k + 0.5) * pi / slices;
        const vec3d side = e1 * std::cos(phi) + e2 * std::sin(phi);
        const double cos_ahead = std::cos(first_hidden(V, side, visible));
        const double cos_behind = std::cos(first_hidden(V, side * -1.0, visible));
        const std::string projected = "ao_gtao_projected_normal(" + glsl(n) + ", " + glsl(V) + ", " + glsl(side) + ")";
        expressions.push_back(projected + ".x");
        expressions.push_back("ao_gtao_slice_integral(" + projected + ".y, " + lit(cos_behind) + ", " + lit(cos_ahead) + ")");
        expressions.push_back("ao_gtao_slice_unoccluded(" + projected + ".y)");
    }
    const std::vector<float> r = evaluate(expressions);
    double visibility = 0, unoccluded = 0;
    for (int k = 0; k < slices; ++k) {
        visibility += double(r[3 * k]) * r[3 * k + 1];
        unoccluded += double(r[3 * k]) * r[3 * k + 2];
    }
    REQUIRE(unoccluded > 0);
    return visibility / unoccluded;
}

} // namespace

TEST_CASE("gtao slice integral: the shader's a(h-, n) + a(h+, n) against quadrature of cos(t - n) |sin t|",
          "[gtao][glslang]")
{
    const std::vector<double> normals{-half_pi, -1.2, -0.5, 0.0, 0.3, 1.0, half_pi};
    const std::vector<double> cosines{-1.0, -0.6, 0.0, 0.4, 0.9, 1.0};
    std::vector<std::string> expressions;
    std::vector<double> expected;
    for (double n : normals) {
        for (double c_behind : cosines)
            for (double c_ahead : cosines) {
                // The visible arc: from each horizon toward V, inside n's hemisphere.
                const double h_ahead = std::clamp(std::acos(c_ahead), n - half_pi, n + half_pi);
                const double h_behind = std::clamp(-std::acos(c_behind), n - half_pi, n + half_pi);
                expressions.push_back("ao_gtao_slice_integral(" + lit(n) + ", " + lit(c_behind) + ", " + lit(c_ahead) + ")");
                expected.push_back(slice_quadrature(h_behind, h_ahead, n));
            }
        // The unoccluded slice, both ways: no horizons, and the closed form.
        expressions.push_back("ao_gtao_slice_integral(" + lit(n) + ", -1.0, -1.0)");
        expected.push_back(slice_quadrature(n - half_pi, n + half_pi, n));
        expressions.push_back("ao_gtao_slice_unoccluded(" + lit(n) + ")");
        expected.push_back(slice_quadrature(n - half_pi, n + half_pi, n));
    }
    const std::vector<float> got = evaluate(expressions);
    for (size_t i = 0; i < got.size(); ++i) {
        INFO(expressions[i]);
        CHECK(got[i] == Approx(expected[i]).margin(2e-6));
    }
    // cos n + n sin n: 1 facing V, pi/2 for a normal in the view plane.
    CHECK(evaluate({"ao_gtao_slice_unoccluded(0.0)"})[0] == Approx(1.0).margin(1e-6));
    CHECK(evaluate({"ao_gtao_slice_unoccluded(" + lit(half_pi) + ")"})[0] == Approx(half_pi).margin(1e-6));
}

TEST_CASE("gtao slice integral: horizons outside [-1, 1], NaN and infinity, degenerate projected normals",
          "[gtao][glslang]")
{
    const std::string nan = "uintBitsToFloat(0x7fc00000u)", inf = "uintBitsToFloat(0x7f800000u)";
    const std::vector<float> r = evaluate({
        "ao_gtao_slice_integral(0.4, " + nan + ", " + nan + ")", // 0: no horizons
        "ao_gtao_slice_integral(0.4, -1.0, -1.0)",               // 1
        "ao_gtao_slice_integral(0.4, -7.0, 3.0)",                // 2: clamped to -1, 1
        "ao_gtao_slice_integral(0.4, -1.0, 1.0)",                // 3
        "ao_gtao_slice_integral(0.4, " + inf + ", -" + inf + ")", // 4: not finite: no horizons
        "ao_gtao_slice_integral(9.0, 0.5, 0.5)",                 // 5: n clamped to pi/2
        "ao_gtao_slice_integral(" + lit(half_pi) + ", 0.5, 0.5)", // 6
        // Projected normals: perpendicular to the slice plane; in the view plane; tilted.
        "ao_gtao_projected_normal(vec3(0.0, 1.0, 0.0), vec3(0.0, 0.0, 1.0), vec3(1.0, 0.0, 0.0)).x", // 7
        "ao_gtao_projected_normal(vec3(0.0, 1.0, 0.0), vec3(0.0, 0.0, 1.0), vec3(1.0, 0.0, 0.0)).y", // 8
        "ao_gtao_projected_normal(vec3(-1.0, 0.0, 0.0), vec3(0.0, 0.0, 1.0), vec3(1.0, 0.0, 0.0)).x", // 9
        "ao_gtao_projected_normal(vec3(-1.0, 0.0, 0.0), vec3(0.0, 0.0, 1.0), vec3(1.0, 0.0, 0.0)).y", // 10
        "ao_gtao_projected_normal(vec3(0.6, 0.0, 0.8), vec3(0.0, 0.0, 1.0), vec3(1.0, 0.0, 0.0)).x",  // 11
        "ao_gtao_projected_normal(vec3(0.6, 0.0, 0.8), vec3(0.0, 0.0, 1.0), vec3(1.0, 0.0, 0.0)).y",  // 12
        "ao_gtao_slice_integral(0.4, 1.0, 1.0)", // 13: both horizons at V: nothing visible
    });
    for (float x : r) CHECK(std::isfinite(x));
    CHECK(r[0] == r[1]);
    CHECK(r[2] == r[3]);
    CHECK(r[3] == Approx(slice_quadrature(0.4 - half_pi, 0.0, 0.4)).margin(2e-6)); // behind open, ahead closed at V
    CHECK(r[4] == r[1]);
    CHECK(r[5] == r[6]);
    CHECK(r[7] == 0.0f);
    CHECK(r[8] == 0.0f);
    CHECK(r[9] == Approx(1.0).margin(1e-6));
    CHECK(r[10] == Approx(-half_pi).margin(1e-6));
    CHECK(r[11] == Approx(1.0).margin(1e-6));
    CHECK(r[12] == Approx(std::atan2(0.6, 0.8)).margin(1e-6));
    CHECK(r[13] == Approx(0.0).margin(1e-7));
}

TEST_CASE("gtao slice integral: DESIGN.md's closed forms from exact horizons", "[gtao][glslang]")
{
    const vec3d up{0, 1, 0};
    auto above = [](vec3d normal) { return [normal](vec3d w) { return dot(w, normal) >= 0; }; };
    auto both = [](visible_set a, visible_set b) { return [a, b](vec3d w) { return a(w) && b(w); }; };
    struct closed_form {
        const char* name;
        vec3d n, V;
        visible_set visible;
        double exact;
        int slices;
        double margin;
    };
    // Floor point next to an infinite wall at interior angle alpha (any distance): the
    // open directions are above the floor and on the floor's side of the wall's plane;
    // AO = (1 - cos alpha) / 2.
    const double alpha = pi / 3;
    const vec3d wall_90{-1, 0, 0}, wall_60{-std::sin(alpha), -std::cos(alpha), 0}; // into the open side
    // Apex of a 90-degree groove, normal along the bisector: sin 45 degrees.
    const vec3d groove_a = normalize({1, 1, 0}), groove_b = normalize({-1, 1, 0});
    const std::vector<closed_form> cases{
        {"open plane, oblique view, 3 slices", up, normalize({-0.3, 0.8, 0.5}), above(up), 1.0, 3, 1e-5},
        {"open plane, grazing view, 2 slices", up, normalize({0.9, 0.1, 0.3}), above(up), 1.0, 2, 1e-5},
        {"floor + wall 90, oblique view", up, normalize({-0.3, 0.8, 0.5}), both(above(up), above(wall_90)), 0.5, 64, 2e-4},
        {"floor + wall 90, view along n", up, up, both(above(up), above(wall_90)), 0.5, 64, 2e-4},
        {"floor + wall 90, low view", up, normalize({-0.8, 0.3, -0.2}), both(above(up), above(wall_90)), 0.5, 64, 2e-4},
        {"floor + wall 60", up, normalize({-0.5, 0.8, 0.2}), both(above(up), above(wall_60)), (1 - std::cos(alpha)) / 2, 64,
         1e-3},
        {"90-degree groove apex", normalize(groove_a + groove_b), normalize({0.2, 0.9, 0.4}),
         both(above(groove_a), above(groove_b)), std::sqrt(0.5), 64, 2e-4},
    };
    for (const closed_form& c : cases) {
        INFO(c.name << ": exact " << c.exact);
        const double ao = shader_ao(c.n, c.V, c.visible, c.slices);
        CHECK(ao == Approx(c.exact).margin(c.margin));
    }
}
