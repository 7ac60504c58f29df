#pragma once
// The Euler limit of the Navier–Stokes blast (κ = μ = 0) against the exact TvNS solution (hydro/tvns.hpp):
// the amplitude A_d of Eq. (1) [R-shock] and the profiles behind the shock, for γ = 1 + 2/d or the run's
// hard-particle EOS at its φ∞. Evidence and numbers: docs/hydro.md ("Verification of the dense solver").
#include <optional>

#include "hydro/blast_measurements.hpp"

namespace coldblast::hydro {

/// The final profile of a run against the exact TvNS solution.
struct TvnsComparison {
  double A_measured = 0, A_exact = 0, A_relative_error = 0;  ///< A_measured/A_exact - 1
  /// Σ|numerical - exact| Δx / Σ|exact| Δx over cells with x = r/R_exact in [x_min, 1), R_exact from
  /// Eq. (1) with A_exact (so shock-position errors count); density ρ/n∞, velocity u/Ṙ, pressure p/(n∞Ṙ²).
  double L1_density = 0, L1_velocity = 0, L1_pressure = 0;
  double x_min = 0;
};
/// Compares result.profiles.back(); x_min in [0, 1) (use > H/R to look only outside the core).
TvnsComparison compare_to_tvns(const NavierStokesResult& result, double x_min = 0.0);

/// The Euler-mode run (κ = μ = 0) of the check, default numerics otherwise; `physics`, if given, sets
/// the EOS (eos, phi). Compare it with compare_to_tvns.
NavierStokesResult run_hydro_euler(int d, double until_R_over_lambda, int cells = default_euler_cells,
                                   const std::optional<NavierStokesPhysics>& physics = std::nullopt);

}  // namespace coldblast::hydro
