#include "compare/power_law.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

namespace coldblast::compare {

namespace {
std::vector<long> used_blocks(const BlockSeries& series) {
  std::vector<long> used;
  for (std::size_t b = 0; b < series.block_count(); ++b) {
    double count = 0;
    for (double c : series.counts[b]) count += c;
    if (count > 0) used.push_back(static_cast<long>(b));
  }
  return used;
}

std::vector<std::size_t> times_inside(const BlockSeries& series, double t_first, double t_last) {
  std::vector<std::size_t> inside;
  for (std::size_t k = 0; k < series.time_count(); ++k)
    if (series.t[k] >= t_first && series.t[k] <= t_last) inside.push_back(k);
  return inside;
}
}  // namespace

int nonempty_blocks(const BlockSeries& series) {
  return static_cast<int>(used_blocks(series).size());
}

int recorded_times_in(const BlockSeries& series, double t_first, double t_last) {
  return static_cast<int>(times_inside(series, t_first, t_last).size());
}

common::Jackknife jackknife(const BlockSeries& series,
                            const std::function<std::vector<double>(const std::vector<double>&)>& estimator,
                            common::JackknifeCovariance covariance) {
  const std::vector<long> used = used_blocks(series);
  if (used.size() < 2)
    throw std::invalid_argument("observable " + series.observable + ": " + std::to_string(used.size()) +
                                " non-empty block(s); an error bar needs at least 2 (raise realizations "
                                "or lower block_size)");
  return common::block_jackknife(
      static_cast<long>(used.size()),
      [&](long left_out) {
        return estimator(series.ensemble_values(
            left_out == common::all_blocks ? common::all_blocks : used[static_cast<std::size_t>(left_out)]));
      },
      covariance);
}

std::vector<RunningExponent> running_exponents(const BlockSeries& series) {
  const std::size_t K = series.time_count();
  if (K < 2)
    throw std::invalid_argument("observable " + series.observable +
                                ": a running exponent needs at least 2 recording times");
  auto estimator = [&](const std::vector<double>& A) {
    std::vector<double> alpha(K - 1);
    for (std::size_t k = 0; k + 1 < K; ++k)
      alpha[k] = std::log(A[k + 1] / A[k]) / std::log(series.t[k + 1] / series.t[k]);  // Sec. V running exponent
    return alpha;
  };
  const common::Jackknife j = jackknife(series, estimator);
  std::vector<RunningExponent> out(K - 1);
  for (std::size_t k = 0; k + 1 < K; ++k) out[k] = {series.t[k], series.t[k + 1], j.value[k], j.error(k)};
  return out;
}

PowerLawFit fit_power_law(const BlockSeries& series, double t_first, double t_last) {
  const std::vector<std::size_t> inside = times_inside(series, t_first, t_last);
  if (inside.size() < 2)
    throw std::invalid_argument("observable " + series.observable + ": the fit window [" + std::to_string(t_first) +
                                ", " + std::to_string(t_last) + "] holds " + std::to_string(inside.size()) +
                                " recording time(s); at least 2 are needed");
  Eigen::MatrixXd X(static_cast<Eigen::Index>(inside.size()), 2);
  for (std::size_t i = 0; i < inside.size(); ++i) {
    X(static_cast<Eigen::Index>(i), 0) = 1.0;
    X(static_cast<Eigen::Index>(i), 1) = std::log(series.t[inside[i]]);
  }
  const auto qr = X.colPivHouseholderQr();
  auto estimator = [&](const std::vector<double>& A) {
    Eigen::VectorXd y(static_cast<Eigen::Index>(inside.size()));
    for (std::size_t i = 0; i < inside.size(); ++i) y[static_cast<Eigen::Index>(i)] = std::log(A[inside[i]]);
    const Eigen::VectorXd parameters = qr.solve(y);
    return std::vector<double>{parameters[0], parameters[1]};
  };
  const common::Jackknife j = jackknife(series, estimator, common::JackknifeCovariance::full);
  PowerLawFit fit;
  fit.log_amplitude = j.value[0];
  fit.exponent = j.value[1];
  fit.covariance << j.covariance_at(0, 0), j.covariance_at(0, 1), j.covariance_at(1, 0), j.covariance_at(1, 1);
  fit.log_amplitude_error = j.error(0);
  fit.exponent_error = j.error(1);
  fit.t_first = series.t[inside.front()];
  fit.t_last = series.t[inside.back()];
  fit.points = static_cast<int>(inside.size());
  fit.blocks = j.blocks;
  return fit;
}

}  // namespace coldblast::compare
