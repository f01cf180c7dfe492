// The reference tracer (bench/truth) against DESIGN.md's closed forms, to within 0.005,
// with its reported standard error below 0.005 too.
#include <aogen_truth/tracer.hpp>

#include <catch2/catch.hpp>

#include <cmath>

using aogen::truth::estimate;
using aogen::truth::options;
using aogen::truth::scene;
using aogen::truth::vec3;

namespace {

constexpr double pi = 3.14159265358979323846;
constexpr double tolerance = 0.005;

void check(const estimate& e, double expected)
{
    INFO("AO " << e.value << ", expected " << expected << ", standard error " << e.standard_error
               << ", binomial bound " << e.binomial_bound);
    CHECK(e.rays >= 1024);
    CHECK(std::abs(e.value - expected) <= tolerance);
    CHECK(e.standard_error < tolerance);
}

// Floor z = 0 and a wall rising from the line x = d at interior angle α (measured from the
// floor on the point's side), both 10⁴ long: "infinite" for the point at the origin.
void floor_and_wall(scene& s, double d, double alpha_degrees, double wall_length = 1e4)
{
    const double a = alpha_degrees * pi / 180;
    s.add_plane({0, 0, 0}, {0, 0, 1});
    s.add_quad({d, -1e4, 0}, {0, 2e4, 0}, wall_length * vec3{-std::cos(a), 0, std::sin(a)});
}

} // namespace

TEST_CASE("truth: open plane sees everything", "[truth]")
{
    scene s;
    s.add_plane({0, 0, 0}, {0, 0, 1});
    s.commit();
    const estimate e = s.ao({0.3, -0.2, 0}, {0, 0, 1});
    check(e, 1.0);
    CHECK(e.value == 1.0);
}

TEST_CASE("truth: floor point by an infinite wall, (1 - cos a)/2", "[truth]")
{
    for (double alpha : {60.0, 90.0, 120.0}) {
        for (double d : {0.25, 1.0}) {
            scene s;
            floor_and_wall(s, d, alpha);
            s.commit();
            INFO("alpha " << alpha << " d " << d);
            check(s.ao({0, 0, 0}, {0, 0, 1}), (1 - std::cos(alpha * pi / 180)) / 2);
        }
    }
}

TEST_CASE("truth: apex of a 90 degree groove, normal along the bisector", "[truth]")
{
    scene s;  // planes x = z and x = -z meeting on the y axis, opening towards +x
    s.add_quad({0, -1e4, 0}, {0, 2e4, 0}, 1e4 * vec3{1, 0, 1});
    s.add_quad({0, -1e4, 0}, {0, 2e4, 0}, 1e4 * vec3{1, 0, -1});
    s.commit();
    check(s.ao({0, 0, 0}, {1, 0, 0}), std::sqrt(0.5));
}

TEST_CASE("truth: floor point by a wall of height H, (1 + d/sqrt(d^2 + H^2))/2", "[truth]")
{
    for (double h : {1.0, 2.0}) {
        scene s;
        floor_and_wall(s, 1.0, 90.0, h);
        s.commit();
        INFO("H " << h);
        check(s.ao({0, 0, 0}, {0, 0, 1}), 0.5 * (1 + 1 / std::sqrt(1 + h * h)));
    }
    SECTION("the same wall as a box") {
        scene s;
        s.add_plane({0, 0, 0}, {0, 0, 1});
        s.add_box({1, -1e4, 0}, {1.5, 1e4, 1});
        s.commit();
        check(s.ao({0, 0, 0}, {0, 0, 1}), 0.8536);
    }
}

TEST_CASE("truth: floor point by a sphere resting on the floor, 1 - (r/sqrt(s^2 + r^2))^3", "[truth]")
{
    const double r = 0.5;
    scene s;
    s.add_plane({0, 0, 0}, {0, 0, 1});
    s.add_sphere({0, 0, r}, r);
    s.commit();
    for (double k : {1.0, 2.0, 0.5}) {
        const double dist = k * r;
        INFO("s = " << k << " r");
        check(s.ao({dist * 0.6, dist * 0.8, 0}, {0, 0, 1}), 1 - std::pow(r / std::sqrt(dist * dist + r * r), 3));
    }
    CHECK(std::abs(s.ao({r, 0, 0}, {0, 0, 1}).value - 0.6464) <= tolerance);
    CHECK(std::abs(s.ao({0, 2 * r, 0}, {0, 0, 1}).value - 0.9106) <= tolerance);
}

TEST_CASE("truth: bounded radius R", "[truth]")
{
    SECTION("a wall farther than R does not occlude") {
        scene s;
        floor_and_wall(s, 1.5, 90.0);
        s.commit();
        options o;
        o.radius = 1.0;
        const estimate e = s.ao({0, 0, 0}, {0, 0, 1}, o);
        check(e, 1.0);
        CHECK(e.value == 1.0);
        o.radius = 1e30;  // and does when R is large
        check(s.ao({0, 0, 0}, {0, 0, 1}, o), 0.5);
    }
    SECTION("a parallel ceiling at height h < R: (h/R)^2") {
        // Occluded where h/cos θ < R, i.e. cos θ > h/R: (1/π)∫ cos θ dω there is 1 − (h/R)².
        scene s;
        s.add_plane({0, 0, 0}, {0, 0, 1});
        s.add_plane({0, 0, 0.5}, {0, 0, -1});
        s.commit();
        for (double radius : {0.75, 1.0, 2.0}) {
            options o;
            o.radius = radius;
            INFO("R " << radius);
            check(s.ao({0, 0, 0}, {0, 0, 1}, o), (0.5 / radius) * (0.5 / radius));
        }
    }
}

TEST_CASE("truth: deterministic, and the seed changes only the noise", "[truth]")
{
    scene s;
    s.add_plane({0, 0, 0}, {0, 0, 1});
    s.add_sphere({0, 0, 1}, 1);
    s.commit();
    const estimate a = s.ao({1, 0, 0}, {0, 0, 1});
    const estimate b = s.ao({1, 0, 0}, {0, 0, 1});
    CHECK(a.value == b.value);
    CHECK(a.standard_error == b.standard_error);
    options o;
    o.seed = 7;
    const estimate c = s.ao({1, 0, 0}, {0, 0, 1}, o);
    CHECK(std::abs(c.value - a.value) <= 2 * tolerance);
    CHECK(a.binomial_bound >= a.standard_error);
}
