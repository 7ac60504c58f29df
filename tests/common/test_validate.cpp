#include <catch2/catch.hpp>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <random>
#include <stdexcept>

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

TEST_CASE("format_number equals the %g round-trip search (at least 6 digits) on random doubles", "[fast]") {
  // Independent method: "%.*g" for 6, 7, ... 17 digits until strtod reads the same double back.
  const auto reference = [](double value) {
    char buffer[40];
    for (int digits = 6; digits <= 17; ++digits) {
      std::snprintf(buffer, sizeof buffer, "%.*g", digits, value);
      if (std::strtod(buffer, nullptr) == value) break;
    }
    return std::string(buffer);
  };
  REQUIRE(format_number(100000.0) == "100000");
  REQUIRE(format_number(1e6) == "1e+06");
  REQUIRE(format_number(1e-5) == "1e-05");
  REQUIRE(format_number(-0.0) == "-0");
  REQUIRE(format_number(1234567.0) == "1234567");
  std::mt19937_64 rng(7);
  std::uniform_int_distribution<std::uint64_t> bits;
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  std::uniform_int_distribution<int> decade(-12, 12);
  for (int i = 0; i < 20000; ++i) {
    double value;
    if (i % 2 == 0) {  // any finite bit pattern, denormals included
      const std::uint64_t b = bits(rng);
      std::memcpy(&value, &b, sizeof value);
      if (!std::isfinite(value)) continue;
    } else {  // the magnitudes results have, with short and long decimal expansions
      value = std::round(unit(rng) * 1e4) * std::pow(10.0, decade(rng)) / (i % 4 == 1 ? 1.0 : 3.0);
    }
    INFO("bits of the value: " << std::hexfloat << value);
    REQUIRE(format_number(value) == reference(value));
  }
}
