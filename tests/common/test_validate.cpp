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
using coldblast::common::format_measurement;
using coldblast::common::format_number;
using coldblast::common::format_significant;
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

TEST_CASE("the context follows the range after exactly one space", "[fast]") {
  // Callers write it with or without a leading space; the message reads the same.
  for (const std::string context : {"(0 = automatic)", " (0 = automatic)", "   (0 = automatic)"}) {
    REQUIRE_THROWS_WITH(require_integer_in_range("cells", -1, 0, 9, context),
                        "cells = -1 is outside [0, 9] (0 = automatic)");
    REQUIRE_THROWS_WITH(require_in_range("x", -1.0, 0.0, 1.0, Bound::closed, Bound::open, context),
                        "x = -1 is outside [0, 1) (0 = automatic)");
  }
  REQUIRE_THROWS_WITH(require_integer_in_range("cells", -1, 0, 9, " "), "cells = -1 is outside [0, 9]");
}

TEST_CASE("format_number round-trips doubles with the fewest digits", "[fast]") {
  REQUIRE(format_number(0.1) == "0.1");
  REQUIRE(format_number(2.0) == "2");
  const double x = 0.35193590695;
  REQUIRE(std::stod(format_number(x)) == x);
  REQUIRE(format_number(1.0 / 3.0) == "0.3333333333333333");
}

TEST_CASE("format_significant rounds to the given significant digits", "[fast]") {
  REQUIRE(format_significant(3363.585661014858, 6) == "3363.59");
  REQUIRE(format_significant(10008.350573534844, 6) == "10008.4");
  REQUIRE(format_significant(8.881784197001252e-16, 2) == "8.9e-16");
  REQUIRE(format_significant(4000.0, 6) == "4000");
  REQUIRE(format_significant(-0.0012525467, 2) == "-0.0013");
  REQUIRE(format_significant(12345.0, 4) == "12350");  // not "%.4g"'s 1.234e+04
  REQUIRE(format_significant(1.7339746558403595, 4) == "1.734");
  REQUIRE(format_significant(0.0, 3) == "0");
  REQUIRE(format_significant(std::numeric_limits<double>::quiet_NaN(), 3) == "nan");
}

TEST_CASE("format_measurement quotes the value to the error's second significant digit", "[fast]") {
  // The report's Fig. 3 fit, the A_2 solver's precision, a shock radius, an exponent.
  REQUIRE(format_measurement(1.837558583236845, 0.03661178942101602) == "1.838 ± 0.037");
  REQUIRE(format_measurement(0.351935906848599, 2.5e-14) == "0.351935906848599 ± 2.5e-14");
  REQUIRE(format_measurement(232.5, 0.062) == "232.500 ± 0.062");
  REQUIRE(format_measurement(-0.40594, 0.10621) == "-0.41 ± 0.11");
  // Rounding carries the error to one more digit: 0.0996 is 0.10, and the value follows that place.
  REQUIRE(format_measurement(1.23456, 0.0996) == "1.23 ± 0.10");
  // Errors of 10 and more: integers, never a trailing point.
  REQUIRE(format_measurement(3363.6, 12.3) == "3364 ± 12");
  REQUIRE(format_measurement(123456.0, 1234.0) == "123500 ± 1200");
  // One digit on request, no negative zero, large magnitudes in exponent form.
  REQUIRE(format_measurement(0.014, 0.19, 1) == "0.0 ± 0.2");
  REQUIRE(format_measurement(-0.0004, 0.03) == "0.000 ± 0.030");
  REQUIRE(format_measurement(6.02214076e23, 3.1e20) == "6.0221e+23 ± 3.1e+20");
  // No usable error: both at full precision, nothing hidden.
  REQUIRE(format_measurement(1.5, 0.0) == "1.5 ± 0");
  REQUIRE(format_measurement(1.5, std::numeric_limits<double>::quiet_NaN()) == "1.5 ± nan");
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
