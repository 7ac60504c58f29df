// Tests of hydro/blast_measurements on constructed data: the crossing radius of linear profiles, running
// exponents of exact power laws (the centred differences are exact for them), their interpolation in
// R/λ and its range check, and the final sample nearest to the end time.
#include <catch2/catch.hpp>
#include <cmath>
#include <stdexcept>
#include <vector>

#include "hydro/blast_measurements.hpp"

using namespace coldblast;

namespace {

/// Samples of exact power laws in t (R ∝ t^(1/2), H ∝ t^(2/5), n0 ∝ t^(-1/5), T0 ∝ t^(-4/5): the 2D
/// rationals) at t = 10^(k/10), with λ = 1.
std::vector<hydro::NavierStokesSample> power_law_samples(int count) {
  std::vector<hydro::NavierStokesSample> samples;
  for (int k = 0; k < count; ++k) {
    hydro::NavierStokesSample s;
    s.t = std::pow(10.0, k / 10.0);
    s.R = 3.0 * std::pow(s.t, 0.5);
    s.R_over_lambda = s.R;
    s.H = 2.0 * std::pow(s.t, 0.4);
    s.H_density = 1.5 * std::pow(s.t, 0.4);
    s.n0 = 0.7 * std::pow(s.t, -0.2);
    s.T0 = 5.0 * std::pow(s.t, -0.8);
    samples.push_back(s);
  }
  return samples;
}

}  // namespace

TEST_CASE("crossing_radius interpolates linear profiles exactly and returns NaN without a crossing", "[fast]") {
  const std::vector<double> centres = {0.5, 1.5, 2.5, 3.5};
  const std::vector<double> falling = {4.0, 3.0, 2.0, 1.0};  // 4.5 - r
  CHECK(hydro::crossing_radius(centres, falling, 0, 2.25, true) == Approx(2.25).epsilon(1e-15));
  CHECK(std::isnan(hydro::crossing_radius(centres, falling, 0, 0.5, true)));
  const std::vector<double> rising = {1.0, 2.0, 4.0, 8.0};
  CHECK(hydro::crossing_radius(centres, rising, 0, 3.0, false) == Approx(2.0).epsilon(1e-15));
  CHECK(hydro::crossing_radius(centres, rising, 2, 6.0, false) == Approx(3.0).epsilon(1e-15));
}

TEST_CASE("running exponents of exact power laws are the exponents, in t and in R/lambda", "[fast]") {
  const std::vector<hydro::RunningExponents> exponents = hydro::running_exponents(power_law_samples(12));
  REQUIRE(exponents.size() == 10);
  for (const hydro::RunningExponents& e : exponents) {
    CHECK(e.R == Approx(0.5).epsilon(1e-12));
    CHECK(e.H == Approx(0.4).epsilon(1e-12));
    CHECK(e.H_density == Approx(0.4).epsilon(1e-12));
    CHECK(e.n0 == Approx(-0.2).epsilon(1e-12));
    CHECK(e.T0 == Approx(-0.8).epsilon(1e-12));
    CHECK(e.H_in_R == Approx(0.8).epsilon(1e-12));
    CHECK(e.n0_in_R == Approx(-0.4).epsilon(1e-12));
    CHECK(e.T0_in_R == Approx(-1.6).epsilon(1e-12));
  }
  CHECK(hydro::running_exponents(power_law_samples(2)).empty());
}

TEST_CASE("exponents_at interpolates linearly in ln R/lambda and refuses R/lambda outside the samples", "[fast]") {
  hydro::NavierStokesResult result;
  result.samples = power_law_samples(12);
  result.exponents = hydro::running_exponents(result.samples);
  // make n0's exponent vary linearly in ln R/λ, so that the interpolation has something to do
  for (hydro::RunningExponents& e : result.exponents) e.n0 = std::log(e.R_over_lambda);
  const double x = std::sqrt(result.exponents[3].R_over_lambda * result.exponents[4].R_over_lambda);
  const hydro::RunningExponents e = result.exponents_at(x);
  CHECK(e.R_over_lambda == x);
  CHECK(e.n0 == Approx(std::log(x)).epsilon(1e-13));
  CHECK(e.T0 == Approx(-0.8).epsilon(1e-12));
  CHECK_THROWS_WITH(result.exponents_at(0.5 * result.exponents.front().R_over_lambda),
                    Catch::Contains("R_over_lambda"));
  CHECK_THROWS_AS(result.exponents_at(2 * result.exponents.back().R_over_lambda), std::invalid_argument);
}

TEST_CASE("the final sample and exponents are those nearest to the final profile's time", "[fast]") {
  hydro::NavierStokesResult result;
  result.samples = power_law_samples(12);
  result.exponents = hydro::running_exponents(result.samples);
  hydro::NavierStokesProfile profile;
  profile.t = 1.05 * result.samples[9].t;
  result.profiles.push_back(profile);
  CHECK(&result.final_sample() == &result.samples[9]);
  CHECK(result.final_exponents().t == result.exponents[8].t);  // exponents start at the second sample
}
