// Tests for aogen/names.hpp: round trips, '-' and '_' as one character on both sides,
// the wording of unknown names and out-of-table values, and the constexpr helpers.
#include <aogen/names.hpp>

#include <catch2/catch.hpp>

#include "support.hpp"

#include <array>
#include <string>

// One namespace per test file: the files of one executable share a translation unit
// (tests/CMakeLists.txt: a unity build), and their helpers must not meet.
namespace unity_test_names {

namespace names = aogen::names;
using aogen_test::error_of;

namespace {

enum class fruit { blood_orange, star_fruit, kiwi };

// One name spelled with '_', one with '-', as params.hpp and layout.hpp spell theirs.
constexpr std::array<aogen::enum_name<fruit>, 3> fruit_names{{
    {fruit::blood_orange, "blood_orange"},
    {fruit::star_fruit, "star-fruit"},
    {fruit::kiwi, "kiwi"},
}};

// An enum with an unsigned underlying type, for the number in the value error.
enum class small : unsigned char { one = 1, two = 2 };
constexpr std::array<aogen::enum_name<small>, 2> small_names{{{small::one, "one"}, {small::two, "two"}}};

} // namespace

static_assert(names::distinct(fruit_names));
static_assert(names::is_listed(fruit_names, fruit::kiwi));
static_assert(!names::is_listed(fruit_names, static_cast<fruit>(3)));
static_assert(names::values(fruit_names)[1] == fruit::star_fruit);
static_assert(names::same_name("wgsl-storage", "wgsl_storage"));
static_assert(!names::same_name("wgsl-storage", "wgsl-storag"));

TEST_CASE("names: every entry round-trips", "[names]")
{
    for (const auto& e : fruit_names) {
        CHECK(std::string(names::name_of(fruit_names, e.value, "fruit")) == e.name);
        CHECK(names::value_of(fruit_names, e.name, "fruit") == e.value);
    }
    CHECK(names::values(fruit_names) == std::array<fruit, 3>{fruit::blood_orange, fruit::star_fruit, fruit::kiwi});
    CHECK(names::list(fruit_names) == "blood_orange, star-fruit, kiwi");
}

TEST_CASE("names: '-' and '_' are the same character, on both sides", "[names]")
{
    // The table says '_', the name '-'.
    CHECK(names::value_of(fruit_names, "blood-orange", "fruit") == fruit::blood_orange);
    // The table says '-', the name '_'.
    CHECK(names::value_of(fruit_names, "star_fruit", "fruit") == fruit::star_fruit);
    // name_of keeps the table's own spelling.
    CHECK(std::string(names::name_of(fruit_names, fruit::star_fruit, "fruit")) == "star-fruit");
    CHECK(std::string(names::name_of(fruit_names, fruit::blood_orange, "fruit")) == "blood_orange");
    // Nothing else is folded: case matters, and '-' is not a wildcard.
    CHECK(error_of([] { names::value_of(fruit_names, "Kiwi", "fruit"); }) ==
          "fruit: 'Kiwi' is not a known name (valid: blood_orange, star-fruit, kiwi)");
    CHECK(error_of([] { names::value_of(fruit_names, "star fruit", "fruit"); }) ==
          "fruit: 'star fruit' is not a known name (valid: blood_orange, star-fruit, kiwi)");
}

TEST_CASE("names: an unknown name is an error listing the valid names", "[names]")
{
    CHECK(error_of([] { names::value_of(fruit_names, "lemon", "--fruit"); }) ==
          "--fruit: 'lemon' is not a known name (valid: blood_orange, star-fruit, kiwi)");
    CHECK(error_of([] { names::value_of(fruit_names, "", "basket.fruit"); }) ==
          "basket.fruit: '' is not a known name (valid: blood_orange, star-fruit, kiwi)");
    // The message repeats the name as given, not folded.
    CHECK(error_of([] { names::value_of(fruit_names, "blood-lemon", "fruit"); }) ==
          "fruit: 'blood-lemon' is not a known name (valid: blood_orange, star-fruit, kiwi)");
}

TEST_CASE("names: a value outside the table is an error listing the valid names", "[names]")
{
    const std::string valid = " (valid: blood_orange, star-fruit, kiwi)";
    CHECK(error_of([] { names::name_of(fruit_names, static_cast<fruit>(7), "fruit"); }) ==
          "fruit: 7 is not a valid value" + valid);
    CHECK(error_of([] { names::name_of(fruit_names, static_cast<fruit>(-1), "fruit"); }) ==
          "fruit: -1 is not a valid value" + valid);
    CHECK(error_of([] { names::require_listed(fruit_names, static_cast<fruit>(3), "basket.fruit"); }) ==
          "basket.fruit: 3 is not a valid value" + valid);
    CHECK(error_of([] { names::fail_unlisted(fruit_names, static_cast<fruit>(9), "fruit"); }) ==
          "fruit: 9 is not a valid value" + valid);
    CHECK(error_of([] { names::name_of(small_names, static_cast<small>(200), "small"); }) ==
          "small: 200 is not a valid value (valid: one, two)");
    CHECK_NOTHROW(names::require_listed(fruit_names, fruit::kiwi, "fruit"));
    CHECK(names::is_listed(small_names, small::two));
    CHECK_FALSE(names::is_listed(small_names, static_cast<small>(0)));
}

TEST_CASE("names: distinct rejects a repeated value or a name repeated up to '-'/'_'", "[names]")
{
    constexpr std::array<aogen::enum_name<fruit>, 2> same_value{{{fruit::kiwi, "kiwi"}, {fruit::kiwi, "kiwi2"}}};
    constexpr std::array<aogen::enum_name<fruit>, 2> same_name{
        {{fruit::blood_orange, "blood_orange"}, {fruit::kiwi, "blood-orange"}}};
    static_assert(!names::distinct(same_value));
    static_assert(!names::distinct(same_name));
    CHECK(names::distinct(small_names));
}

// Planted: a test that asserts nothing. Hidden ([.]); ctest runs it by name and requires it to
// fail (tests/CMakeLists.txt), which proves catch_main.cpp's NoAssertions rule is in force.
TEST_CASE("planted: a test that asserts nothing", "[.][planted]") {}

} // namespace unity_test_names
