#include "kinetic/tracer_statistics.hpp"

#include <algorithm>
#include <array>
#include <cmath>

namespace coldblast::kinetic {

std::uint64_t total_collisions(const TracerBlocks& blocks) {
  std::uint64_t total = 0;
  for (const auto& [b, s] : blocks) total += s.collisions;
  return total;
}
std::uint64_t total_candidates(const TracerBlocks& blocks) {
  std::uint64_t total = 0;
  for (const auto& [b, s] : blocks) total += s.candidates;
  return total;
}
long long total_trajectories(const TracerBlocks& blocks) {
  long long total = 0;
  for (const auto& [b, s] : blocks) total += s.count;
  return total;
}
double collision_rate(const TracerBlocks& blocks, double duration) {
  const double N = static_cast<double>(total_trajectories(blocks));
  return static_cast<double>(total_collisions(blocks)) / N / duration;
}
double collision_rate_error(const TracerBlocks& blocks, double duration) {
  const double N = static_cast<double>(total_trajectories(blocks));
  double squares = 0.0;
  for (const auto& [b, s] : blocks) squares += s.collisions_squares;
  const double mean = static_cast<double>(total_collisions(blocks)) / N;
  const double variance = std::max(0.0, (squares - N * mean * mean) / (N - 1));
  return std::sqrt(variance / N) / duration;
}
double temperature_final(const TracerBlocks& blocks, double mass, int d) {
  double sum = 0.0;
  for (const auto& [b, s] : blocks) sum += s.v2_final;
  return mass * sum / static_cast<double>(total_trajectories(blocks)) / d;
}
double temperature_final_error(const TracerBlocks& blocks, double mass, int d) {
  const double N = static_cast<double>(total_trajectories(blocks));
  double sum = 0.0, squares = 0.0;
  for (const auto& [b, s] : blocks) {
    sum += s.v2_final;
    squares += s.v2_final_squares;
  }
  const double mean = sum / N;
  const double variance = std::max(0.0, (squares - N * mean * mean) / (N - 1));
  return mass * std::sqrt(variance / N) / d;
}
double rejection_rate(const TracerBlocks& blocks) {
  const double candidates_total = static_cast<double>(total_candidates(blocks));
  return candidates_total > 0 ? 1.0 - static_cast<double>(total_collisions(blocks)) / candidates_total : 0.0;
}

std::vector<MomentRow> moment_rows(const std::vector<double>& times, const TracerBlocks& blocks) {
  std::vector<MomentRow> rows;
  // Totals, then leave-one-block-out values for the jackknife.
  const std::size_t K = times.size();
  std::vector<double> total(4 * K, 0.0);
  double N = 0.0;
  for (const auto& [b, s] : blocks) {
    for (std::size_t e = 0; e < total.size(); ++e) total[e] += s.moments[e];
    N += static_cast<double>(s.count);
  }
  const auto values = [&](const std::vector<double>& sums, double count, std::size_t k) {
    const double r2 = sums[4 * k] / count, r4 = sums[4 * k + 1] / count;
    const double v2 = sums[4 * k + 2] / count, v4 = sums[4 * k + 3] / count;
    return std::array<double, 4>{r2, r2 > 0 ? r4 / (r2 * r2) : 0.0, v2, v2 > 0 ? v4 / (v2 * v2) : 0.0};
  };
  const double B = static_cast<double>(blocks.size());
  for (std::size_t k = 0; k < K; ++k) {
    const auto full = values(total, N, k);
    std::array<double, 4> mean{}, square{};
    for (const auto& [b, s] : blocks) {
      std::vector<double> rest(total);
      for (std::size_t e = 4 * k; e < 4 * k + 4; ++e) rest[e] -= s.moments[e];
      const auto leave = values(rest, N - static_cast<double>(s.count), k);
      for (int q = 0; q < 4; ++q) {
        mean[q] += leave[q] / B;
        square[q] += leave[q] * leave[q] / B;
      }
    }
    std::array<double, 4> error{};
    for (int q = 0; q < 4; ++q)
      error[q] = B > 1 ? std::sqrt(std::max(0.0, (B - 1) * (square[q] - mean[q] * mean[q]))) : std::nan("");
    rows.push_back({times[k], full[0], error[0], full[1], error[1], full[2], error[2], full[3], error[3]});
  }
  return rows;
}

}  // namespace coldblast::kinetic
