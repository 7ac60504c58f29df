#pragma once
// The O(1) prefactors the paper leaves open ("cannot be fixed", Sec. IV), computed — not derived —
// by `coldblast tracer`, the Monte Carlo of the paper's Eq. (36) [LB-full] in the dense (Enskog)
// Navier–Stokes blast (docs/kinetic.md, docs/verification.md). A prefactor is X divided by the
// paper's estimate of X with its O(1) factor set to 1 (scaling_estimates: R_imp = C λ (R/λ)^{h_d},
// Eq. (6); V_imp, Eq. (8); C_imp, Eq. (10)) at the recorded R/λ (Eq. (1) with the hard-particle
// A_d(φ)). The one home of these numbers: `coldblast theory` prints them, tests/kinetic reproduces
// the small-R/λ entries with a fresh tracer run, and docs/verification.md records how they were made.
#include <string>
#include <vector>

namespace coldblast::theory {

/// The run that produced a set of prefactors.
struct PrefactorSource {
  const char* command;      ///< the exact `coldblast tracer` command
  long long trajectories;   ///< impurity trajectories of the run
  const char* description;  ///< background, start and what the run took
};

/// One computed prefactor: X / estimate at one recording time of one run, with its standard error.
struct ComputedPrefactor {
  int d;                   ///< dimension (2: scenes/paper-2d.toml, 3: scenes/paper-3d.toml)
  const char* observable;  ///< "R_imp", "V_imp" or "C_imp"
  double t;                ///< recording time
  double R_over_lambda;    ///< Eq. (1) at t with the run's A_d
  double value, error;     ///< prefactor and its block-jackknife standard error
  int source;              ///< index into prefactor_sources()
};

/// The runs, indexed by ComputedPrefactor::source.
const std::vector<PrefactorSource>& prefactor_sources();
/// Every computed prefactor, by dimension, observable and increasing R/λ.
const std::vector<ComputedPrefactor>& computed_prefactors();
/// The entries of dimension d (empty when none are known).
std::vector<ComputedPrefactor> computed_prefactors(int d);
/// The entries of dimension d and one observable, by increasing R/λ.
std::vector<ComputedPrefactor> computed_prefactors(int d, const std::string& observable);

}  // namespace coldblast::theory
