// Error metrics against values worked out by hand.
#include <aogen_report/metrics.hpp>

#include <catch2/catch.hpp>

#include <limits>

// One namespace per test file: the files of one executable share a translation unit
// (tests/CMakeLists.txt: a unity build), and their helpers must not meet.
namespace unity_metrics_test {

using aogen_report::compare;

TEST_CASE("metrics: hand-worked errors over valid pixels only")
{
    // Errors +0.1, -0.3, +0.2 on three valid pixels; the fourth is background.
    const std::vector<float> ao{0.6f, 0.2f, 1.0f, 0.0f};
    const std::vector<float> truth{0.5f, 0.5f, 0.8f, 1.0f};
    const std::vector<uint8_t> valid{1, 1, 1, 0};
    const auto m = compare(ao, truth, valid);
    CHECK(m.pixels == 3);
    CHECK(m.non_finite == 0);
    CHECK(m.mae == Approx((0.1 + 0.3 + 0.2) / 3).epsilon(1e-6));
    CHECK(m.mean_signed == Approx(0.0).margin(1e-7));
    CHECK(m.rmse == Approx(std::sqrt((0.01 + 0.09 + 0.04) / 3)).epsilon(1e-6));
    CHECK(m.p99_abs == Approx(0.3).epsilon(1e-6)); // nearest rank ceil(0.99·3) = 3: the largest
}

TEST_CASE("metrics: the 99th percentile by nearest rank, NaN and inf counted apart")
{
    std::vector<float> ao(200, 0.5f), truth(200, 0.5f);
    std::vector<uint8_t> valid(200, 1);
    ao[0] = 0.9f;                                          // one error of 0.4
    ao[1] = 0.7f;                                          // one of 0.2
    ao[2] = 0.75f;                                         // and one of 0.25
    ao[3] = std::numeric_limits<float>::quiet_NaN();
    ao[4] = std::numeric_limits<float>::infinity();
    const auto m = compare(ao, truth, valid);
    CHECK(m.non_finite == 2);
    CHECK(m.pixels == 198);
    // rank ceil(0.99·198) = 197 of the sorted errors: 195 zeros, then 0.2, 0.25, 0.4 → 0.25.
    CHECK(m.p99_abs == Approx(0.25).epsilon(1e-6));
    CHECK(m.mean_signed == Approx((0.4 + 0.2 + 0.25) / 198).epsilon(1e-5));
}

TEST_CASE("metrics: mismatched sizes are an error, an empty mask gives zeros")
{
    CHECK_THROWS_WITH(compare({1.0f}, {1.0f, 1.0f}, {1}), Catch::Contains("same size"));
    const auto m = compare({0.5f}, {1.0f}, {0});
    CHECK(m.pixels == 0);
    CHECK(m.rmse == 0.0);
}

} // namespace unity_metrics_test
