// The tracer's deviates against their exact laws: Kolmogorov–Smirnov distance of 2·10⁵ normal and
// exponential deviates to Φ and 1 − e^{−x} (the 0.1 % critical value 1.95/√N), the first moments
// within 4 standard errors, and the tails of 4·10⁶ deviates (the ziggurat's separate tail branches:
// counts beyond 3σ, 4σ, 5σ and 10, 15 means within 4 Poisson standard deviations, and the KS distance
// of the conditional law beyond the ziggurat's base strip). Seeds are fixed, so each check is
// deterministic.
#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <functional>
#include <vector>

#include "kinetic/random.hpp"

using coldblast::kinetic::Random;

namespace {
constexpr int samples = 200000;

double ks_distance(std::vector<double> x, const std::function<double(double)>& cdf) {
  std::sort(x.begin(), x.end());
  const double n = static_cast<double>(x.size());
  double distance = 0.0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    const double F = cdf(x[i]);
    distance = std::max({distance, F - i / n, (i + 1) / n - F});
  }
  return distance;
}

double moment(const std::vector<double>& x, int k) {
  double sum = 0.0;
  for (const double v : x) sum += std::pow(v, k);
  return sum / static_cast<double>(x.size());
}
}  // namespace

TEST_CASE("random: normal deviates follow the standard normal law") {
  Random rng(17, 3);
  std::vector<double> x(samples);
  for (double& v : x) v = rng.normal();
  CHECK(ks_distance(x, [](double z) { return 0.5 * std::erfc(-z / std::sqrt(2.0)); }) < 1.95 / std::sqrt(samples));
  const double n = samples;
  CHECK(std::abs(moment(x, 1)) < 4.0 / std::sqrt(n));               // var 1
  CHECK(std::abs(moment(x, 2) - 1.0) < 4.0 * std::sqrt(2.0 / n));   // var of z² is 2
  CHECK(std::abs(moment(x, 4) - 3.0) < 4.0 * std::sqrt(96.0 / n));  // var of z⁴ is 105 − 9
  CHECK(std::abs(moment(x, 3)) < 4.0 * std::sqrt(15.0 / n));        // var of z³ is 15
}

TEST_CASE("random: consecutive normal deviates are uncorrelated") {
  Random rng(5, 9);
  double sum = 0.0;
  for (int i = 0; i < samples; ++i) sum += rng.normal() * rng.normal();
  CHECK(std::abs(sum / samples) < 4.0 / std::sqrt(static_cast<double>(samples)));
}

TEST_CASE("random: exponential deviates have unit mean and the exponential law") {
  Random rng(23, 1);
  std::vector<double> x(samples);
  for (double& v : x) v = rng.exponential();
  CHECK(ks_distance(x, [](double y) { return 1.0 - std::exp(-y); }) < 1.95 / std::sqrt(samples));
  CHECK(std::abs(moment(x, 1) - 1.0) < 4.0 / std::sqrt(static_cast<double>(samples)));
  CHECK(*std::min_element(x.begin(), x.end()) >= 0.0);
}

namespace {
constexpr int tail_samples = 4000000;

/// |count − N p| within 4 Poisson standard deviations (plus one for the smallest expectations).
bool tail_count_agrees(long count, double p) {
  const double expected = tail_samples * p;
  return std::abs(static_cast<double>(count) - expected) < 4.0 * std::sqrt(expected) + 1.0;
}
}  // namespace

TEST_CASE("random: normal tails beyond 3, 4, 5 sigma and the conditional law beyond the ziggurat's base") {
  Random rng(41, 7);
  const double tail_start = 3.4426198558966521214;  // Boost's base strip edge (normal_table::table_x[1])
  const auto upper_tail = [](double z) { return 0.5 * std::erfc(z / std::sqrt(2.0)); };
  long beyond3 = 0, beyond4 = 0, beyond5 = 0;
  std::vector<double> tail;
  for (int i = 0; i < tail_samples; ++i) {
    const double z = std::abs(rng.normal());
    beyond3 += z > 3.0;
    beyond4 += z > 4.0;
    beyond5 += z > 5.0;
    if (z > tail_start) tail.push_back(z);
  }
  CHECK(tail_count_agrees(beyond3, 2 * upper_tail(3.0)));  // 2.70e-3: 10 798 expected
  CHECK(tail_count_agrees(beyond4, 2 * upper_tail(4.0)));  // 6.33e-5: 253 expected
  CHECK(tail_count_agrees(beyond5, 2 * upper_tail(5.0)));  // 5.73e-7: 2.3 expected
  CHECK(tail_count_agrees(static_cast<long>(tail.size()), 2 * upper_tail(tail_start)));
  const double Q0 = upper_tail(tail_start);
  CHECK(ks_distance(tail, [&](double z) { return 1.0 - upper_tail(z) / Q0; }) < 1.95 / std::sqrt(tail.size()));
}

TEST_CASE("random: exponential tails beyond 10 and 15 means and the law beyond the ziggurat's base") {
  Random rng(43, 2);
  const double tail_start = 7.6971174701310497140;  // Boost's base strip edge (exponential_table::table_x[1])
  long beyond10 = 0, beyond15 = 0;
  std::vector<double> excess;
  for (int i = 0; i < tail_samples; ++i) {
    const double x = rng.exponential();
    beyond10 += x > 10.0;
    beyond15 += x > 15.0;
    if (x > tail_start) excess.push_back(x - tail_start);
  }
  CHECK(tail_count_agrees(beyond10, std::exp(-10.0)));  // 4.54e-5: 182 expected
  CHECK(tail_count_agrees(beyond15, std::exp(-15.0)));  // 3.06e-7: 1.2 expected
  CHECK(tail_count_agrees(static_cast<long>(excess.size()), std::exp(-tail_start)));
  // Memorylessness: the excess over the strip edge is again a unit exponential.
  CHECK(ks_distance(excess, [](double y) { return 1.0 - std::exp(-y); }) < 1.95 / std::sqrt(excess.size()));
}
