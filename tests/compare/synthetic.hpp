#pragma once
// Synthetic ensembles with a known exponent: realization r has inner value
// X_r(t_k) = c t_k^beta (1 + eps_k), eps a stationary AR(1) sequence with correlation rho between
// successive times (as in MD, successive times are correlated) and standard deviation sigma.
// The ensemble mean is exactly c t^beta, so A = transform(mean) has exponent beta (identity)
// or beta/2 (sqrt).
#include <cmath>
#include <random>

#include "compare/run_data.hpp"

namespace coldblast::compare::testing {

inline BlockSeries synthetic_series(unsigned seed, int blocks, int per_block, int times, double beta, double sigma,
                                    double rho, Transform transform = Transform::identity) {
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> normal(0.0, 1.0);
  BlockSeries s;
  s.observable = transform == Transform::sqrt ? "R_imp" : "C_imp";
  s.transform = transform;
  for (int k = 0; k < times; ++k) s.t.push_back(10.0 * std::pow(2.0, 0.25 * k));
  s.sums.assign(blocks, std::vector<double>(times, 0.0));
  s.counts.assign(blocks, std::vector<double>(times, static_cast<double>(per_block)));
  for (int b = 0; b < blocks; ++b)
    for (int r = 0; r < per_block; ++r) {
      double eps = sigma * normal(rng);
      for (int k = 0; k < times; ++k) {
        if (k > 0) eps = rho * eps + std::sqrt(1 - rho * rho) * sigma * normal(rng);
        s.sums[b][k] += 3.0 * std::pow(s.t[k], beta) * (1.0 + eps);
      }
    }
  return s;
}

}  // namespace coldblast::compare::testing

#include <filesystem>
#include <map>
#include <sstream>

#include "common/output.hpp"

namespace coldblast::compare::testing {

/// Writes a run directory (summary.json + blocks.csv) holding the given series.
inline void write_synthetic_run(const std::filesystem::path& dir, int d,
                                const std::map<std::string, BlockSeries>& series) {
  std::ostringstream csv;
  csv.precision(17);
  csv << "# synthetic run\nblock,t,observable,sum,count\n";
  for (const auto& [name, s] : series)
    for (std::size_t b = 0; b < s.block_count(); ++b)
      for (std::size_t k = 0; k < s.time_count(); ++k)
        csv << b << ',' << s.t[k] << ',' << name << ',' << s.sums[b][k] << ',' << s.counts[b][k] << '\n';
  std::filesystem::remove_all(dir);
  common::write_file_atomic(dir / "blocks.csv", csv.str());
  common::write_file_atomic(dir / "summary.json", "{\"scene\": {\"d\": " + std::to_string(d) + "}}");
}

}  // namespace coldblast::compare::testing
