#include "common/jackknife.hpp"

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace coldblast::common {

double Jackknife::error(std::size_t i) const {
  return std::sqrt(variance.at(i));
}

double Jackknife::covariance_at(std::size_t i, std::size_t j) const {
  if (covariance.empty()) throw std::logic_error("Jackknife::covariance_at: computed without the full covariance");
  return covariance.at(i * value.size() + j);
}

Jackknife block_jackknife(long blocks, const std::function<std::vector<double>(long left_out)>& estimate,
                          JackknifeCovariance covariance) {
  if (blocks < 0) throw std::invalid_argument("jackknife: blocks = " + std::to_string(blocks) + " is negative");
  Jackknife result;
  result.blocks = static_cast<int>(blocks);
  result.value = estimate(all_blocks);
  const std::size_t P = result.value.size();
  const bool full = covariance == JackknifeCovariance::full;
  if (blocks < 2) {
    result.variance.assign(P, std::numeric_limits<double>::quiet_NaN());
    if (full) result.covariance.assign(P * P, std::numeric_limits<double>::quiet_NaN());
    return result;
  }
  std::vector<std::vector<double>> samples;
  samples.reserve(static_cast<std::size_t>(blocks));
  std::vector<double> mean(P, 0.0);
  for (long b = 0; b < blocks; ++b) {
    samples.push_back(estimate(b));
    if (samples.back().size() != P)
      throw std::logic_error("jackknife: the estimator returned " + std::to_string(samples.back().size()) +
                             " values without block " + std::to_string(b) + ", " + std::to_string(P) + " on all");
    for (std::size_t i = 0; i < P; ++i) mean[i] += samples.back()[i];
  }
  const auto B = static_cast<double>(blocks);
  for (double& m : mean) m /= B;
  // Two passes (deviations from the mean, then their products): no cancellation between Σθ² and θ̄².
  result.variance.assign(P, 0.0);
  if (full) result.covariance.assign(P * P, 0.0);
  std::vector<double> deviation(P);
  for (const auto& sample : samples) {
    for (std::size_t i = 0; i < P; ++i) deviation[i] = sample[i] - mean[i];
    for (std::size_t i = 0; i < P; ++i) {
      result.variance[i] += deviation[i] * deviation[i];
      if (full)
        for (std::size_t j = 0; j < P; ++j) result.covariance[i * P + j] += deviation[i] * deviation[j];
    }
  }
  const double factor = (B - 1.0) / B;
  for (double& v : result.variance) v *= factor;
  for (double& c : result.covariance) c *= factor;
  return result;
}

}  // namespace coldblast::common
