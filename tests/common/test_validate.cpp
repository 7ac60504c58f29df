#include <limits>
#include <stdexcept>

#include <catch2/catch.hpp>

#include "common/validate.hpp"

using coldblast::common::Bound;
using coldblast::common::format_number;
using coldblast::common::require_in_range;
using coldblast::common::require_integer_in_range;

TEST_CASE("require_in_range names the parameter, its value and the range", "[fast]") {
  REQUIRE_NOTHROW(require_in_range("phi", 0.5, 0.0, 0.9069));
  try {
    require_in_range("phi", 0.95, 0.0, 0.9069, Bound::open, Bound::open, "for d = 2");
    FAIL("no exception");
  } catch (const std::invalid_argument& e) {
    REQUIRE(std::string(e.what()) == "phi = 0.95 is outside (0, 0.9069) for d = 2");
  }
}

TEST_CASE("require_in_range honours open and closed bounds and rejects NaN", "[fast]") {
  REQUIRE_THROWS_AS(require_in_range("x", 0.0, 0.0, 1.0), std::invalid_argument);
  REQUIRE_NOTHROW(require_in_range("x", 0.0, 0.0, 1.0, Bound::closed, Bound::closed));
  REQUIRE_NOTHROW(require_in_range("x", 1.0, 0.0, 1.0, Bound::closed, Bound::closed));
  REQUIRE_THROWS_AS(require_in_range("x", 1.0, 0.0, 1.0, Bound::closed, Bound::open), std::invalid_argument);
  REQUIRE_THROWS_AS(require_in_range("x", std::numeric_limits<double>::quiet_NaN(), -1e300, 1e300),
                    std::invalid_argument);
  REQUIRE_THROWS_WITH(require_integer_in_range("d", 4, 1, 3), "d = 4 is outside [1, 3]");
}

TEST_CASE("format_number round-trips doubles with the fewest digits", "[fast]") {
  REQUIRE(format_number(0.1) == "0.1");
  REQUIRE(format_number(2.0) == "2");
  const double x = 0.35193590695;
  REQUIRE(std::stod(format_number(x)) == x);
  REQUIRE(format_number(1.0 / 3.0) == "0.3333333333333333");
}
