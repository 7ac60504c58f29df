// The tracer's deviates against their exact laws: Kolmogorov–Smirnov distance of 2·10⁵ normal and
// exponential deviates to Φ and 1 − e^{−x} (the 0.1 % critical value 1.95/√N), and the first
// moments within 4 standard errors. Seeds are fixed, so each check is deterministic.
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

TEST_CASE("random: consecutive normal deviates are uncorrelated (the polar method's pairs)") {
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
