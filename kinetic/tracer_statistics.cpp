#include "kinetic/tracer_statistics.hpp"

#include <algorithm>
#include <cmath>

#include "common/jackknife.hpp"

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
  // ⟨r²⟩, ⟨r⁴⟩/⟨r²⟩², ⟨v²⟩, ⟨v⁴⟩/⟨v²⟩² at every time from the moment sums of all blocks or all but one.
  const std::size_t K = times.size();
  std::vector<double> total(4 * K, 0.0);
  double N = 0.0;
  std::vector<const TracerBlock*> block_list;
  for (const auto& [b, s] : blocks) {
    for (std::size_t e = 0; e < total.size(); ++e) total[e] += s.moments[e];
    N += static_cast<double>(s.count);
    block_list.push_back(&s);
  }
  const auto values = [&](const std::vector<double>& sums, double count) {
    std::vector<double> out;
    for (std::size_t k = 0; k < K; ++k) {
      const double r2 = sums[4 * k] / count, r4 = sums[4 * k + 1] / count;
      const double v2 = sums[4 * k + 2] / count, v4 = sums[4 * k + 3] / count;
      out.insert(out.end(), {r2, r2 > 0 ? r4 / (r2 * r2) : 0.0, v2, v2 > 0 ? v4 / (v2 * v2) : 0.0});
    }
    return out;
  };
  const common::Jackknife j = common::block_jackknife(static_cast<long>(block_list.size()), [&](long left_out) {
    if (left_out == common::all_blocks) return values(total, N);
    const TracerBlock& s = *block_list[static_cast<std::size_t>(left_out)];
    std::vector<double> rest(total);
    for (std::size_t e = 0; e < rest.size(); ++e) rest[e] -= s.moments[e];
    return values(rest, N - static_cast<double>(s.count));
  });
  std::vector<MomentRow> rows;
  for (std::size_t k = 0; k < K; ++k) {
    const std::size_t i = 4 * k;
    rows.push_back({times[k], j.value[i], j.error(i), j.value[i + 1], j.error(i + 1), j.value[i + 2], j.error(i + 2),
                    j.value[i + 3], j.error(i + 3)});
  }
  return rows;
}

}  // namespace coldblast::kinetic
