// compare/ recovers known exponents from synthetic noisy power laws, and its jackknife error bars
// have the right coverage (about 68 % of seeds within 1 sigma).
#include <catch2/catch.hpp>
#include <cmath>

#include "compare/power_law.hpp"
#include "synthetic.hpp"

using namespace coldblast::compare;
using coldblast::compare::testing::synthetic_series;

TEST_CASE("noise-free power laws give the exact exponent and zero error", "[fast]") {
  const BlockSeries s = synthetic_series(1, 8, 3, 12, 0.4, 0.0, 0.0);
  for (const auto& point : running_exponents(s)) {
    CHECK(point.alpha == Approx(0.4).epsilon(1e-12));
    CHECK(point.error < 1e-12);
  }
  const BlockSeries r = synthetic_series(1, 8, 3, 12, 0.8, 0.0, 0.0, Transform::sqrt);
  const PowerLawFit fit = fit_power_law(r, 0.0, 1e9);
  CHECK(fit.exponent == Approx(0.4).epsilon(1e-12));  // sqrt of t^0.8
  CHECK(fit.log_amplitude == Approx(0.5 * std::log(3.0)).epsilon(1e-12));
  CHECK(fit.points == 12);
}

TEST_CASE("the paper's grid: alpha = 4[ln A(2^(1/4) t) - ln A(t)]/ln 2", "[fast]") {
  BlockSeries s = synthetic_series(2, 4, 1, 3, 0.0, 0.0, 0.0);
  for (auto& block : s.sums) block = {1.0, 2.0, 2.0};
  const auto alpha = running_exponents(s);
  REQUIRE(alpha.size() == 2);
  CHECK(alpha[0].alpha == Approx(4.0).epsilon(1e-13));  // A doubles over a factor 2^(1/4) in t
  CHECK(alpha[1].alpha == Approx(0.0).margin(1e-13));
}

TEST_CASE("jackknife errors have ~68% coverage on correlated noisy power laws", "[slow]") {
  const int seeds = 400;
  const double beta = -0.4;
  int running_inside = 0, fit_inside = 0;
  double pull_sq = 0.0;
  for (int seed = 0; seed < seeds; ++seed) {
    const BlockSeries s = synthetic_series(1000u + seed, 40, 5, 10, beta, 0.3, 0.8);
    const auto alpha = running_exponents(s);
    const auto& last = alpha.back();  // the paper reports the last two recorded times
    if (std::abs(last.alpha - beta) < last.error) ++running_inside;
    const PowerLawFit fit = fit_power_law(s, 0.0, 1e9);
    if (std::abs(fit.exponent - beta) < fit.exponent_error) ++fit_inside;
    pull_sq += std::pow((fit.exponent - beta) / fit.exponent_error, 2);
  }
  // Binomial(400, 0.683): standard deviation 0.023; accept within 4 sigma (jackknife with 40
  // blocks slightly under-covers, by about 1/(2*40) in the variance).
  const double p_running = running_inside / double(seeds), p_fit = fit_inside / double(seeds);
  INFO("coverage running = " << p_running << ", fit = " << p_fit << ", mean pull^2 = " << pull_sq / seeds);
  CHECK(std::abs(p_running - 0.683) < 4 * 0.023);
  CHECK(std::abs(p_fit - 0.683) < 4 * 0.023);
  CHECK(pull_sq / seeds == Approx(1.0).margin(0.3));
}

TEST_CASE("the exponent is recovered within its error for the sqrt transform", "[fast]") {
  const BlockSeries s = synthetic_series(77, 50, 10, 16, 0.8, 0.2, 0.9, Transform::sqrt);
  const PowerLawFit fit = fit_power_law(s, 0.0, 1e9);
  INFO("seed 77: exponent " << fit.exponent << " +- " << fit.exponent_error);
  CHECK(fit.exponent_error > 0.0);
  CHECK(std::abs(fit.exponent - 0.4) < 4 * fit.exponent_error);
}

TEST_CASE("too few blocks or times is an error, not a number", "[fast]") {
  const BlockSeries one_block = synthetic_series(3, 1, 10, 8, 0.4, 0.1, 0.5);
  CHECK_THROWS_WITH(running_exponents(one_block), Catch::Contains("at least 2"));
  const BlockSeries s = synthetic_series(3, 10, 2, 8, 0.4, 0.1, 0.5);
  CHECK_THROWS_WITH(fit_power_law(s, 1e6, 1e7), Catch::Contains("window"));
  const BlockSeries one_time = synthetic_series(3, 10, 2, 1, 0.4, 0.1, 0.5);
  CHECK_THROWS_WITH(running_exponents(one_time), Catch::Contains("2 recording times"));
}
