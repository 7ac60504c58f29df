#include <catch2/catch.hpp>
#include <cmath>
#include <random>
#include <stdexcept>
#include <vector>

#include "common/jackknife.hpp"

using coldblast::common::all_blocks;
using coldblast::common::block_jackknife;
using coldblast::common::Jackknife;
using coldblast::common::JackknifeCovariance;

namespace {
/// The mean of equal-weight block values, on all blocks or without one.
std::vector<double> mean_without(const std::vector<double>& x, long left_out) {
  double sum = 0.0, count = 0.0;
  for (long b = 0; b < static_cast<long>(x.size()); ++b)
    if (b != left_out) sum += x[static_cast<std::size_t>(b)], count += 1.0;
  return {sum / count};
}
}  // namespace

TEST_CASE("jackknife of a mean is the standard error of the block means, exactly", "[fast]") {
  // Block values 1, 3, 5, 7, 9: θ_-b = 6, 5.5, 5, 4.5, 4, θ̄ = 5, (B-1)/B Σ (θ_-b − θ̄)² = 4/5 · 5/2 = 2,
  // and s²/B = (16 + 4 + 0 + 4 + 16)/4/5 = 2: every number is a binary fraction.
  const std::vector<double> x{1, 3, 5, 7, 9};
  const Jackknife j = block_jackknife(5, [&](long b) { return mean_without(x, b); });
  CHECK(j.blocks == 5);
  CHECK(j.value.at(0) == 5.0);
  CHECK(j.variance.at(0) == 2.0);
  CHECK(j.error(0) == std::sqrt(2.0));
  CHECK(j.covariance.empty());
  CHECK_THROWS_AS(j.covariance_at(0, 0), std::logic_error);
}

TEST_CASE("jackknife of a mean equals s/sqrt(B) for any block values (seeded)", "[fast]") {
  const unsigned seed = 20261127;
  INFO("seed " << seed);
  std::mt19937_64 engine(seed);
  std::normal_distribution<double> normal(3.0, 0.7);
  for (const long B : {2L, 7L, 64L}) {
    std::vector<double> x(static_cast<std::size_t>(B));
    for (double& v : x) v = normal(engine);
    double mean = 0.0, squares = 0.0;
    for (const double v : x) mean += v / B;
    for (const double v : x) squares += (v - mean) * (v - mean);
    const double standard_error = std::sqrt(squares / (B - 1) / B);
    const Jackknife j = block_jackknife(B, [&](long b) { return mean_without(x, b); });
    CHECK(j.value.at(0) == Approx(mean).epsilon(1e-14));
    CHECK(j.error(0) == Approx(standard_error).epsilon(1e-12));
  }
}

TEST_CASE("jackknife of a nonlinear estimator: (m, m²) of blocks 0, 1, 2 by hand", "[fast]") {
  // θ_-b of m: 1.5, 1, 0.5 (mean 1); of m²: 2.25, 1, 0.25 (mean 7/6, deviations 13/12, −2/12, −11/12).
  // var m = 2/3 · 1/2 = 1/3; var m² = 2/3 · 294/144 = 49/36; cov = 2/3 · (13/24 + 11/24) = 2/3.
  const std::vector<double> x{0, 1, 2};
  const auto estimate = [&](long b) {
    const double m = mean_without(x, b)[0];
    return std::vector<double>{m, m * m};
  };
  const Jackknife j = block_jackknife(3, estimate, JackknifeCovariance::full);
  CHECK(j.value == std::vector<double>{1.0, 1.0});
  CHECK(j.variance.at(0) == Approx(1.0 / 3).epsilon(1e-15));
  CHECK(j.variance.at(1) == Approx(49.0 / 36).epsilon(1e-15));
  CHECK(j.error(1) == Approx(7.0 / 6).epsilon(1e-15));
  CHECK(j.covariance_at(0, 1) == Approx(2.0 / 3).epsilon(1e-15));
  CHECK(j.covariance_at(1, 0) == j.covariance_at(0, 1));
  // The diagonal of the full covariance is the variance, bit for bit.
  CHECK(j.covariance_at(0, 0) == j.variance.at(0));
  CHECK(j.covariance_at(1, 1) == j.variance.at(1));
  // The diagonal-only call gives the same variances.
  CHECK(block_jackknife(3, estimate).variance == j.variance);
}

TEST_CASE("jackknife: the estimator is called on all blocks, then without each block in order", "[fast]") {
  std::vector<long> calls;
  block_jackknife(3, [&](long b) {
    calls.push_back(b);
    return std::vector<double>{0.0};
  });
  CHECK(calls == std::vector<long>{all_blocks, 0, 1, 2});
}

TEST_CASE("jackknife with fewer than 2 blocks: the value and NaN errors, bad input throws", "[fast]") {
  const Jackknife one = block_jackknife(
      1,
      [](long) {
        return std::vector<double>{4.0, 5.0};
      },
      JackknifeCovariance::full);
  CHECK(one.value == std::vector<double>{4.0, 5.0});
  CHECK(std::isnan(one.error(0)));
  CHECK(std::isnan(one.covariance_at(1, 0)));
  CHECK_THROWS_AS(block_jackknife(-1, [](long) { return std::vector<double>{}; }), std::invalid_argument);
  // An estimator whose size changes with the block left out is a bug of the caller.
  CHECK_THROWS_AS(block_jackknife(2, [](long b) { return std::vector<double>(b == all_blocks ? 2 : 1, 0.0); }),
                  std::logic_error);
}
