#pragma once
// The tracer's own statistics beyond md's record layout: per block of trajectories the sums of the
// displacement and speed moments at each recording time, of the end state at t_max and of the work
// counters; the totals computed from them (collision rate, the impurity's final temperature,
// rejection rate) with their standard errors, and the moments' block-jackknife errors.
#include <cstdint>
#include <map>
#include <vector>

#include "md/block_sums.hpp"

namespace coldblast::kinetic {

/// Sums over the trajectories of one block beyond the md layout: per recording time k the sums of
/// |Δr|², |Δr|⁴, |v|², |v|⁴ (moments[4k + 0..3]); the end state at t_max; work counters.
struct TracerBlock {
  std::vector<double> moments;
  double collisions_squares = 0.0;  ///< Σ (collisions of the trajectory in [start, t_max])²
  double v2_final = 0.0, v2_final_squares = 0.0;
  std::uint64_t candidates = 0, collisions = 0;
  long long count = 0;
};

/// The tracer blocks of a run, by block index.
using TracerBlocks = std::map<long long, TracerBlock>;

/// One block's sums: md's layout (R_imp, V_imp, C_imp, u_imp, p_imp) and the tracer's own.
struct TracerBlockSums {
  md::BlockSums sums;
  TracerBlock tracer;
};

std::uint64_t total_collisions(const TracerBlocks& blocks);
std::uint64_t total_candidates(const TracerBlocks& blocks);
long long total_trajectories(const TracerBlocks& blocks);
/// Collisions per unit time per impurity over a duration (t_max - start time), and its standard error.
double collision_rate(const TracerBlocks& blocks, double duration);
double collision_rate_error(const TracerBlocks& blocks, double duration);
/// M ⟨v²⟩/d of the impurity (mass M) at t_max, and its standard error.
double temperature_final(const TracerBlocks& blocks, double mass, int d);
double temperature_final_error(const TracerBlocks& blocks, double mass, int d);
/// Share of majorant candidates that were not collisions.
double rejection_rate(const TracerBlocks& blocks);

/// Rows of moments.csv: at each recording time ⟨r²⟩, ⟨r⁴⟩/⟨r²⟩², ⟨v²⟩, ⟨v⁴⟩/⟨v²⟩² with block
/// jackknife errors (r = displacement from the start).
struct MomentRow {
  double t;
  double r2, r2_error, r_ratio, r_ratio_error, v2, v2_error, v_ratio, v_ratio_error;
};
std::vector<MomentRow> moment_rows(const std::vector<double>& times, const TracerBlocks& blocks);

}  // namespace coldblast::kinetic
