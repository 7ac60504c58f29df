#pragma once
// What the Navier–Stokes blast measures (paper Eqs. (4), (11)-(12), whose laws Eqs. (19)-(20) repeat):
// the shock radius R, the core radius H, the central density n0 and temperature T0, their prefactors
// and running exponents, and the profiles; the result type of run_navier_stokes (hydro/navier_stokes.hpp).
#include <vector>

#include "hydro/navier_stokes_config.hpp"

namespace coldblast::hydro {

class RadialBlast;

/// Diagnostics at one time (physical units unless stated).
struct NavierStokesSample {
  double t = 0;  ///< time since the start's origin: the virtual point explosion of R_ref(t), or the hot spot
  double R_over_lambda = 0;       ///< measured shock radius / λ
  double R = 0;                   ///< shock radius: outermost r where n = (n∞ + n_max)/2
  double H = 0;                   ///< core radius: r where T falls to T0/2
  double H_density = 0;           ///< second core radius: r where n rises to 2 n0
  double n0 = 0, T0 = 0, p0 = 0;  ///< centre-cell density, temperature, pressure (n0 T0 Z(φ0))
  double energy = 0, mass = 0;    ///< totals over the grid, including the cold gas swept in
  double energy_error = 0;        ///< |energy - (E + energy that entered through the outer edge)|/E
  double mass_error = 0;          ///< |mass - n∞ V(grid)|/mass
  /// Prefactors of Eqs. (4), (11), (12) with Ṙ = 2R/((d+2)t) and x = R/λ: H/(λ x^h_d),
  /// n0/(n∞ x^(-2d²/(8+3d²))), T0/(Ṙ² x^(2d²/(8+3d²))); and the central pressure p0/(n∞ Ṙ²).
  double H_prefactor = 0, n0_prefactor = 0, T0_prefactor = 0, p0_scaled = 0;
};

/// d ln X / d ln t (time) and d ln X / d ln(R/λ) of the diagnostics, centred differences.
struct RunningExponents {
  double t = 0, R_over_lambda = 0;
  double R = 0, H = 0, H_density = 0, n0 = 0, T0 = 0;               ///< time exponents
  double H_in_R = 0, H_density_in_R = 0, n0_in_R = 0, T0_in_R = 0;  ///< exponents in R/λ
};

/// The core quantities whose time exponents a result reports, in report order, each with its field of
/// RunningExponents; the name is also theory::ScalingExponents' (Eqs. (1), (4), (11), (12)). The one
/// list that the result files, reproduce's JSON, its report and its summary line go through.
struct CoreExponent {
  const char* name;
  double RunningExponents::*time_exponent;
};
inline constexpr CoreExponent core_exponents[] = {{"H", &RunningExponents::H},
                                                  {"n0", &RunningExponents::n0},
                                                  {"T0", &RunningExponents::T0},
                                                  {"R", &RunningExponents::R}};

/// Profile columns of the CSV: r, r_over_R, density, velocity, temperature, pressure, heat_flux.
struct NavierStokesProfile {
  double t = 0, R = 0;
  std::vector<double> r, r_over_R, density, velocity, temperature, pressure, heat_flux;
};

/// Work counters of one solve.
struct NavierStokesStatistics {
  long steps = 0, rhs_evaluations = 0, jacobian_evaluations = 0, nonlinear_iterations = 0;
  long error_test_failures = 0, nonlinear_failures = 0;
  double wall_seconds = 0;
};

/// Result of run_navier_stokes.
struct NavierStokesResult {
  NavierStokesConfig config;                            ///< with the library's defaults resolved
  double lambda = 0;                                    ///< Eq. (5) [eq:mfp] mean free path
  double kappa_prefactor = 0, viscosity_prefactor = 0;  ///< c_κ, c_μ used (0 when off)
  double A_reference = 0;                               ///< A_d used for the grid scale R_ref(t)
  double A_measured = 0;                                ///< E t^2/(n∞ R^(d+2)) at the last sample
  double max_energy_error = 0;                          ///< max over samples of sample.energy_error
  double energy_projected = 0;                  ///< Σ |energy corrections| of the projection / E (integrator drift)
  double mass_projected = 0;                    ///< Σ |mass corrections| / final mass
  double min_density = 0, min_temperature = 0;  ///< over all samples and cells (positivity check)
  std::vector<NavierStokesSample> samples;      ///< log-spaced in R/λ, up to slightly beyond `until`
  std::vector<RunningExponents> exponents;      ///< at the interior samples
  std::vector<NavierStokesProfile> profiles;    ///< requested times, then the final one (R/λ = until)
  NavierStokesStatistics statistics;
  /// Running exponents interpolated (linear in ln R/λ) at R/λ inside the sampled range; throws otherwise.
  RunningExponents exponents_at(double R_over_lambda) const;
  /// Running exponents at R_over_lambda = until.
  RunningExponents final_exponents() const;
  /// Sample nearest to R/λ = until.
  const NavierStokesSample& final_sample() const;
};

/// Linear interpolation of the radius where `values` (at `centres`) crosses `level`, searching outward
/// from index `first` for a fall to (falling) or a rise to the level; NaN if never crossed.
double crossing_radius(const std::vector<double>& centres, const std::vector<double>& values, int first, double level,
                       bool falling);

/// Diagnostics of `state` (the cell totals) at time t; blast.rhs(t, state) must have been evaluated.
/// Throws std::runtime_error if the shock left the grid or a diagnostic is not finite.
NavierStokesSample measure_sample(const RadialBlast& blast, const double* state, const std::vector<double>& centres,
                                  const NavierStokesConfig& config, double t);

/// The profile of the last blast.rhs() evaluation at time t, with shock radius R.
NavierStokesProfile make_profile(const RadialBlast& blast, const std::vector<double>& centres, double t, double R);

/// Running exponents: centred differences between the neighbouring samples (none for fewer than 3).
std::vector<RunningExponents> running_exponents(const std::vector<NavierStokesSample>& samples);

}  // namespace coldblast::hydro
