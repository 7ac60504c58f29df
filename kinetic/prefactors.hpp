#pragma once
// The impurity's amplitudes measured by the tracer, divided by the paper's estimates with their O(1)
// factors set to 1 (theory::scaling_estimates: R_imp = C λ (R/λ)^{h_d}, Eq. (6); V_imp, Eq. (8);
// C_imp, Eq. (10)), and their running exponents in R/λ, at every recording time, with block-jackknife
// errors. R/λ is Eq. (1) with the run's A_d. Written as prefactors.csv (run/tracer_files.hpp,
// docs/kinetic.md).
#include <map>
#include <string>
#include <vector>

#include "md/blast_config.hpp"
#include "md/block_sums.hpp"

namespace coldblast::kinetic {

/// The observables whose prefactors are measured (the catalogue's TracerUse::prefactor: R_imp, V_imp,
/// C_imp), in column order.
const std::vector<std::string>& prefactor_observables();

/// One recording time: for each of prefactor_observables() the prefactor X/X_estimate and the running
/// exponent d ln X / d ln(R/λ) over [t_k / prefactor_window, t_k], with jackknife errors (NaN where
/// undefined: X = 0, or no recording time a window earlier).
struct PrefactorRow {
  double t = 0.0, R_over_lambda = 0.0;
  std::vector<double> prefactor, prefactor_error, exponent, exponent_error;
};

/// Ratio of the two recording times of a running exponent (a factor 4 in t).
inline constexpr double prefactor_window = 4.0;

/// Rows at every recording time of a tracer run's scene and md-layout block sums (trajectories start
/// at the scene's t_min or later).
std::vector<PrefactorRow> prefactor_rows(const md::ResolvedScene& scene,
                                         const std::map<long long, md::BlockSums>& blocks);

}  // namespace coldblast::kinetic
