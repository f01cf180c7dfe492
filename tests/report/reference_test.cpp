// The report's reference image against a closed form at every pixel (docs/design.md
// § Ground truth), R unbounded unless told: every point of a 90° crease has AO (1 − cos 90°)/2 = 1/2 wherever
// it is (the other plane covers the same share of the hemisphere at any distance). The
// built-in groove is the same configuration turned 45° — its walls are tilted planes, the
// case where a tracer that occludes itself (float precision of large triangles) fails. The
// crease and the groove do not notice how far a point is lifted off its surface; the
// built-in wall of height H does (a floor point lifted by ε sees a wall of height H − ε).
// Between a floor and a ceiling h apart, with R > h, every point has (h/R)². Each is
// checked where the scene was drawn and moved 10⁶ and 10⁷ from the world's zero, and the
// crease, the groove and the wall also in a telephoto view, 0.1° high from 5 km: the
// G-buffer's points and the reference's rays are as precise there as anywhere.
#include <aogen_report/reference.hpp>

#include <catch2/catch.hpp>

#include <cmath>
#include <functional>
#include <limits>
#include <string>
#include <vector>

// One namespace per test file: the files of one executable share a translation unit
// (tests/CMakeLists.txt: a unity build), and their helpers must not meet.
namespace unity_reference_test {

namespace {

using aogen::scenes::gbuffer;
using aogen::scenes::scene;
using aogen::truth::vec3;

constexpr double pi = 3.14159265358979323846;
constexpr double unbounded = std::numeric_limits<double>::infinity();
constexpr double not_checked = std::numeric_limits<double>::quiet_NaN();

// The scenes as drawn, and moved 10⁶ and 10⁷ from the world's zero.
const std::vector<double> distances_from_zero = {0, 1e6, 1e7};

// `s` (planes and boxes) with its geometry and camera moved `distance` from where it was
// drawn, along a direction with irrational coordinates: the same picture, far from the zero.
scene moved(scene s, double distance)
{
    REQUIRE((s.spheres.empty() && s.quads.empty() && s.meshes.empty() && s.point_sets.empty()));
    const vec3 shift = distance * aogen::truth::normalize({1, -std::sqrt(2.0), std::sqrt(3.0)});
    for (aogen::scenes::plane& p : s.planes) p.point = p.point + shift;
    for (aogen::scenes::box& b : s.boxes) b.lo = b.lo + shift, b.hi = b.hi + shift;
    s.camera.eye = s.camera.eye + shift, s.camera.target = s.camera.target + shift;
    return s;
}

// `s` seen through a 0.1° vertical field of view from 5 km along its camera's line of
// sight: about the picture of a 60° view from 7 units.
scene telephoto(scene s)
{
    aogen::scenes::camera& c = s.camera;
    c.eye = c.target + 5000.0 * aogen::truth::normalize(c.eye - c.target);
    c.tan_half_fov_y = float(std::tan(0.05 * pi / 180));
    c.near = 100, c.far = 10000;
    return s;
}

// A floor and a ceiling 0.5 apart, seen from between them, AO radius 1: (h/R)² = 1/4 on both.
scene floor_and_ceiling()
{
    scene s;
    s.name = "floor and ceiling";
    s.planes = {{{0, 0, 0}, {0, 0, 1}}, {{0, 0, 0.5}, {0, 0, -1}}};
    s.camera.eye = {0, -3, 0.25}, s.camera.target = {0, 0, 0.25}, s.camera.up = {0, 0, 1};
    s.camera.far = 30; // the floor and ceiling beyond are background, not 10⁴ units of slab
    s.ao_radius = 1;
    return s;
}

vec3 position(const gbuffer& g, size_t i) { return {g.position[3 * i], g.position[3 * i + 1], g.position[3 * i + 2]}; }

// Whether pixel i's point lies within the tracer's own offset (truth::surface_offset) of a
// crease along y through `on_crease` (every crease here runs along y). A primary ray that
// close to a crease between two meshes can slip past one mesh's float edge onto the other
// behind it — Embree is watertight only along the edges a mesh shares; from 5 km the wall's
// foot let one ray through 5·10⁻⁶ behind its face — and no lift takes a point out of the
// wrong side. Such pixels are not checked, as tests/scenes/splats_depth.cpp leaves out rays
// within a hair of a splat's edge.
bool at_crease(const gbuffer& g, size_t i, vec3 eye, vec3 on_crease)
{
    const vec3 p = position(g, i);
    const double off_crease = std::hypot(p.x - on_crease.x, p.z - on_crease.z);
    return off_crease < aogen::truth::surface_offset(p - eye, unbounded);
}

// The AO the closed form gives at pixel i of a G-buffer (world normals), or not_checked.
using closed_form = std::function<double(const gbuffer& g, size_t i)>;

// The crease and the groove: 1/2 everywhere, their planes meeting along y through the
// planes' point.
closed_form half_except_at_the_crease(const scene& s)
{
    return [eye = s.camera.eye, on_crease = s.planes[0].point](const gbuffer& g, size_t i) {
        return at_crease(g, i, eye, on_crease) ? not_checked : 0.5;
    };
}

// The built-in wall, a box of height H standing on the floor: a floor point at distance d
// from the wall's nearer face sees ½(1 + d/√(d² + H²)); on the wall, a side face has the
// floor fill half its hemisphere (½) and the top sees nothing (1).
closed_form wall_of_height_h(const scene& s)
{
    const aogen::scenes::box wall = s.boxes.at(0);
    const int wall_id = int(s.planes.size()); // build order: planes, then boxes
    return [eye = s.camera.eye, wall, wall_id](const gbuffer& g, size_t i) {
        const vec3 front_foot{wall.hi.x, 0, wall.lo.z}, back_foot{wall.lo.x, 0, wall.lo.z};
        if (at_crease(g, i, eye, front_foot) || at_crease(g, i, eye, back_foot)) return not_checked;
        if (g.geometry[i] == wall_id) return std::abs(g.normals[4 * i + 2]) > 0.5 ? 1.0 : 0.5;
        const double x = position(g, i).x, h = wall.hi.z - wall.lo.z;
        const double d = x >= wall.hi.x ? x - wall.hi.x : wall.lo.x - x;
        return 0.5 * (1 + d / std::sqrt(d * d + h * h));
    };
}

closed_form everywhere(double value)
{
    return [value](const gbuffer&, size_t) { return value; };
}

// Every valid pixel of the reference of `s` at 48×27 with grid × grid rays within 0.005 of
// the closed form, more than half of them checked.
// The G-buffer (world normals) of `s` at 48×27 and its reference with grid × grid rays.
struct traced {
    gbuffer g;
    aogen_report::reference r;
};
traced trace_at_48x27(scene s, double radius, int grid)
{
    s.camera.width = 48, s.camera.height = 27;
    const auto t = aogen::scenes::make_tracer(s);
    aogen::scenes::gbuffer_options world;
    world.use_scene_normals = false;
    world.normals = aogen::scenes::normal_space::world;
    gbuffer g = aogen::scenes::render_gbuffer(s, *t, world);
    aogen_report::reference r = aogen_report::trace_reference(*t, g, radius, grid, 2);
    return {std::move(g), std::move(r)};
}

void check_every_pixel(scene s, const closed_form& expected, double radius = unbounded, int grid = 32)
{
    const auto [g, r] = trace_at_48x27(s, radius, grid);
    int checked = 0;
    double sum = 0, expected_sum = 0;
    for (size_t i = 0; i < r.ao.size(); ++i) {
        if (!r.valid[i]) {
            CHECK(std::isnan(r.ao[i]));
            continue;
        }
        const double want = expected(g, i);
        if (std::isnan(want)) continue;
        INFO(s.name << " pixel " << i % 48 << "," << i / 48 << ": " << r.ao[i] << ", closed form " << want);
        CHECK(std::fabs(r.ao[i] - want) <= 0.005);
        sum += r.ao[i], expected_sum += want, ++checked;
    }
    REQUIRE(checked > 48 * 27 / 2);
    CHECK(sum / checked == Approx(expected_sum / checked).margin(0.002));
    CHECK(r.noise_rms < 0.005);
    CHECK(r.rays_per_pixel == grid * grid);
}

} // namespace

TEST_CASE("reference: every pixel of the crease is 1/2 with an unbounded radius")
{
    const double distance = GENERATE(from_range(distances_from_zero));
    INFO("crease " << distance << " from the world's zero");
    const scene s = moved(aogen::scenes::builtin_scene("crease"), distance);
    check_every_pixel(s, half_except_at_the_crease(s));
}

TEST_CASE("reference: every pixel of the groove's tilted walls is 1/2 with an unbounded radius")
{
    const double distance = GENERATE(from_range(distances_from_zero));
    INFO("groove " << distance << " from the world's zero");
    const scene s = moved(aogen::scenes::builtin_scene("groove"), distance);
    check_every_pixel(s, half_except_at_the_crease(s));
}

TEST_CASE("reference: every pixel of the crease and the groove has its closed-form bent normal")
{
    // A pixel on one of two perpendicular planes facing each other sees the wedge away from the
    // other: its bent normal is normalise(π/3 · n + 2/3 · m), n its plane's normal and m the
    // other's (32.5° from n; truth's closed forms, tests/truth). Within 1° at 32 × 32 rays (measured
    // at most 0.39° over the 7737 pixels checked, 2026-12-05).
    const std::string name = GENERATE("crease", "groove");
    const double distance = GENERATE(from_range(distances_from_zero));
    const scene s = moved(aogen::scenes::builtin_scene(name), distance);
    const auto [g, r] = trace_at_48x27(s, unbounded, 32);
    const closed_form away_from_crease = half_except_at_the_crease(s);
    int checked = 0;
    for (size_t i = 0; i < r.ao.size(); ++i) {
        if (!r.valid[i] || std::isnan(away_from_crease(g, i))) continue;
        const auto &n = s.planes.at(size_t(g.geometry[i])).normal, &m = s.planes.at(size_t(1 - g.geometry[i])).normal;
        const double k = 3.14159265358979323846 / 3, l = 2.0 / 3;
        const vec3 want{k * n.x + l * m.x, k * n.y + l * m.y, k * n.z + l * m.z};
        const double length = std::sqrt(want.x * want.x + want.y * want.y + want.z * want.z);
        const double cosine = (r.bent_normal[3 * i] * want.x + r.bent_normal[3 * i + 1] * want.y + r.bent_normal[3 * i + 2] * want.z) / length;
        INFO(name << " " << distance << " from zero, pixel " << i % 48 << "," << i / 48);
        CHECK(std::acos(std::min(1.0, cosine)) * 180 / 3.14159265358979323846 <= 1.0);
        ++checked;
    }
    CHECK(checked > 48 * 27 / 2);
    for (size_t i = 0; i < r.ao.size(); ++i)
        if (!r.valid[i]) CHECK(std::isnan(r.bent_normal[3 * i]));
}

TEST_CASE("reference: every pixel by a wall of height H is its closed form")
{
    // 64×64 rays: the wall's closed form has no stratum-aligned boundary, and at 32×32 a
    // few pixels' noise reaches 0.005.
    const double distance = GENERATE(0.0, 1e7);
    INFO("wall " << distance << " from the world's zero");
    const scene s = moved(aogen::scenes::builtin_scene("wall"), distance);
    check_every_pixel(s, wall_of_height_h(s), unbounded, 64);
}

TEST_CASE("reference: seen from 5 km through a 0.1 degree field of view, every pixel is its closed form")
{
    const double distance = GENERATE(0.0, 1e7);
    for (const char* name : {"crease", "groove"}) {
        INFO(name << " " << distance << " from the world's zero, seen from 5 km");
        const scene s = telephoto(moved(aogen::scenes::builtin_scene(name), distance));
        check_every_pixel(s, half_except_at_the_crease(s));
    }
    INFO("wall " << distance << " from the world's zero, seen from 5 km");
    const scene s = telephoto(moved(aogen::scenes::builtin_scene("wall"), distance));
    check_every_pixel(s, wall_of_height_h(s), unbounded, 64);
}

TEST_CASE("reference: every pixel between a floor and a ceiling h apart is (h/R)^2")
{
    const double distance = GENERATE(from_range(distances_from_zero));
    INFO("floor and ceiling " << distance << " from the world's zero");
    check_every_pixel(moved(floor_and_ceiling(), distance), everywhere(0.25), 1.0);
}

TEST_CASE("reference: seen from 6 km with R = 1, too far for a tracer at the eye, every pixel is traced from one among the geometry")
{
    // Float geometry places rays of length 1 reliably within truth::reliable_extent(1) ≈ 4.8 km
    // of a tracer's origin: from the eye, 6 km away, no pixel can be trusted; from the centre
    // of the hits, every one. The floor, seen from 30° above it through a 0.1° lens, is open:
    // 1 at every pixel — where a ray placed imprecisely starts below the floor, it reads a
    // false occlusion.
    scene s;
    s.name = "floor from 6 km";
    s.planes = {{{0, 0, 0}, {0, 0, 1}}};
    s.camera.target = {0, 0, 0}, s.camera.up = {0, 0, 1};
    s.camera.eye = {0, -6000 * std::cos(pi / 6), 6000 * std::sin(pi / 6)}; // 5196 along y: past 4.8 km on one axis
    s.camera.tan_half_fov_y = float(std::tan(0.05 * pi / 180));
    s.camera.near = 5000, s.camera.far = 7000;
    s.camera.width = 48, s.camera.height = 27;
    s.ao_radius = 1;
    REQUIRE(aogen::truth::reliable_extent(s.ao_radius) < 5196);
    const auto t = aogen::scenes::make_tracer(s);
    aogen::scenes::gbuffer_options world;
    world.use_scene_normals = false;
    world.normals = aogen::scenes::normal_space::world;
    const gbuffer g = aogen::scenes::render_gbuffer(s, *t, world);
    size_t hits = 0;
    for (uint8_t h : g.hit) hits += h;
    REQUIRE(hits > 48 * 27 / 2);

    const aogen_report::reference from_eye = aogen_report::trace_reference(*t, g, s.ao_radius, 32, 2);
    CHECK(from_eye.untrusted == hits); // every hit left out, none refused, none traced
    for (size_t i = 0; i < g.hit.size(); ++i) CHECK((from_eye.valid[i] == 0 && from_eye.hit[i] == g.hit[i] && std::isnan(from_eye.ao[i])));

    const aogen_report::reference r = aogen_report::trace_reference(s, *t, g, 32, 2);
    CHECK(r.untrusted == 0);
    for (size_t i = 0; i < g.hit.size(); ++i) {
        if (!g.hit[i]) continue;
        INFO("pixel " << i % 48 << "," << i / 48 << ": " << r.ao[i]);
        REQUIRE(r.valid[i]);
        CHECK(std::fabs(r.ao[i] - 1.0) <= 0.005);
    }
    CHECK(r.noise_rms < 0.005);
}

TEST_CASE("reference: a floor to the horizon at a small radius is scored where it can be trusted, the rest left out and counted")
{
    scene s = aogen::scenes::builtin_scene("far_floor");
    s.camera.width = 64, s.camera.height = 36;
    s.ao_radius = 5e-3; // reliable within about 24 units of a tracer's origin
    const auto t = aogen::scenes::make_tracer(s);
    aogen::scenes::gbuffer_options world;
    world.use_scene_normals = false;
    world.normals = aogen::scenes::normal_space::world;
    const gbuffer g = aogen::scenes::render_gbuffer(s, *t, world);
    const aogen_report::reference r = aogen_report::trace_reference(s, *t, g, 16, 2);
    size_t hits = 0, valid = 0;
    for (size_t i = 0; i < g.hit.size(); ++i) {
        hits += g.hit[i], valid += r.valid[i];
        if (r.valid[i]) CHECK(r.ao[i] == Approx(1.0).margin(1e-6)); // an open floor
        else if (g.hit[i]) CHECK(std::isnan(r.ao[i]));
    }
    CHECK(valid > 0);
    CHECK(r.untrusted > 0);
    CHECK(valid + r.untrusted == hits);
    aogen::scenes::require_scoreable(s, *t); // not refused: some of it can be trusted
    s.ao_radius = 1e-6;                       // none can: refused, naming ao_radius and what would do
    std::string refusal = "<no aogen::error thrown>";
    try {
        aogen::scenes::require_scoreable(s, *t);
    } catch (const aogen::error& e) {
        refusal = e.what();
    }
    CHECK_THAT(refusal, Catch::Contains("ao_radius: 1e-06 is too small for a reliable reference anywhere in view") && Catch::Contains("valid: ao_radius >= "));
}

TEST_CASE("reference: the same image for any number of threads")
{
    aogen::scenes::scene s = aogen::scenes::builtin_scene("room");
    s.camera.width = 32, s.camera.height = 18;
    const auto t = aogen::scenes::make_tracer(s);
    aogen::scenes::gbuffer_options world;
    world.use_scene_normals = false;
    const aogen::scenes::gbuffer g = aogen::scenes::render_gbuffer(s, *t, world);
    const aogen_report::reference one = aogen_report::trace_reference(*t, g, 1.0, 32, 1);
    const aogen_report::reference three = aogen_report::trace_reference(*t, g, 1.0, 32, 3);
    for (size_t i = 0; i < one.ao.size(); ++i)
        if (one.valid[i]) CHECK(one.ao[i] == three.ao[i]);
    CHECK(one.noise_rms == three.noise_rms);
}

} // namespace unity_reference_test
