#pragma once
// Exact Taylor-von Neumann-Sedov (TvNS) blast in a cold uniform gas (paper Sec. I, Eq. (1)
// [R-shock], Eqs. (18a,b) [r-est, T-est]): A_d by two independent methods (Kamm & Timmes closed
// form, LA-UR-07-2849; direct integration of the self-similar ODEs) and profiles at any r/R,
// for an ideal gas of any gamma or hard discs/spheres at packing fraction phi.
#include <memory>
#include <string>
#include <vector>

#include "hydro/equation_of_state.hpp"
#include "theory/prefactors.hpp"

namespace coldblast::hydro {

/// Range of the adiabatic index: closer to 1 the shocked shell (density ratio (gamma+1)/(gamma-1))
/// is thinner than double precision resolves; beyond 1000 the two methods no longer agree to 1e-10.
constexpr double min_gamma = 1.001;
constexpr double max_gamma = 1000.0;

/// Largest ambient packing fraction TvNS solves for a hard-particle EOS (exclusive): Henderson up to
/// max_ambient_packing_fraction (0.89286); Carnahan-Starling only up to 0.686, below its 0.72042.
/// Above phi ≈ 0.686 the spheres' self-similar flow all but empties its interior: V/(x Rdot) runs
/// into 1 and the density falls by more than ten decades within 1.5 < -ln(r/R) < 1.7, where the
/// ODE's step control stalls (more than 200000 steps at 0.687-0.69 and 0.702-0.71; docs/stress.md).
/// The EOS is a fluid-branch fit that stops being trustworthy at freezing (shocked phi ≈ 0.494,
/// reached from ambient phi ≈ 0.40), so the range lost holds no trustworthy physics.
double tvns_max_packing_fraction(Eos eos);

/// Physical and numerical options of the self-similar blast (units: m = 1, k_B = 1).
struct TvnsConfig {
  int d = 2;                 ///< spatial dimension: 1 planar, 2 cylindrical, 3 spherical
  double gamma = 0.0;        ///< adiabatic index in [min_gamma, max_gamma] (ideal EOS only); 0 means 1 + 2/d
  Eos eos = Eos::ideal;      ///< ideal, henderson (d = 2) or carnahan_starling (d = 3)
  double phi = 0.0;          ///< ambient packing fraction, (0, tvns_max_packing_fraction) for hard particles
  double tolerance = 1e-13;  ///< requested relative accuracy of A_d, [1e-14, 1e-3]
  /// Throws std::invalid_argument naming the first field out of range and the range.
  void validate() const;
  /// gamma with 0 replaced by 1 + 2/d; for hard particles the dilute value 1 + 2/d.
  double resolved_gamma() const;
};

/// One point of the self-similar profile: rho/rho0, u/Rdot, p/(rho0 Rdot^2), T/Rdot^2 (k_B T = p/(n Z), which
/// is p/n for the ideal gas; m = 1).
struct TvnsPoint {
  double r_over_R, density, velocity, pressure, temperature;
};

/// Which branch of the ideal-gas solution applies (Kamm & Timmes, Sec. 2).
enum class TvnsCase {
  standard,  ///< gas down to the centre, rho -> 0, T -> inf there
  singular,  ///< d = 3, gamma = 7: power-law solution rho ∝ r, T ∝ r^2
  vacuum,    ///< d = 3, gamma > 7: empty cavity for r/R < cavity_radius()
};

/// How A_d is computed.
enum class TvnsMethod {
  closed_form,  ///< Kamm & Timmes parametric solution, GSL quadrature (ideal gas only)
  ode,          ///< self-similar ODEs from the shock inward, Boost.Odeint Bulirsch-Stoer
  ode_check,    ///< the same ODEs with an independent stepper, Dormand-Prince 5(4)
};

/// A_d from one method, with its own error estimate.
struct TvnsAmplitude {
  double A = 0.0;        ///< Eq. (1) amplitude, dimensionless
  double A_error = 0.0;  ///< absolute error estimate of A
  long evaluations = 0;  ///< integrand or right-hand-side evaluations used
};

/// Eq. (1) amplitude A_d of one method at config.tolerance; throws std::invalid_argument on bad
/// config (closed_form with a non-ideal EOS included), std::runtime_error if a solver fails.
TvnsAmplitude tvns_amplitude(const TvnsConfig& config, TvnsMethod method);

/// The solved blast: amplitude, error estimates, profiles and near-centre power laws.
class TvnsSolution {
 public:
  explicit TvnsSolution(const TvnsConfig& config);

  const TvnsConfig& config() const { return config_; }
  /// Resolved adiabatic index (1 + 2/d for hard particles: their dilute limit).
  double gamma() const { return gamma_; }
  TvnsCase solution_case() const { return case_; }
  /// Eq. (1) [R-shock]: R = (E t^2/(A_d n))^(1/(d+2)), E = ∫ [rho u^2/2 + rho e] dV over all space.
  double A() const { return A_; }
  /// Absolute error estimate of A() (quadrature/ODE estimates and the two methods' difference; for a
  /// non-ideal EOS also twice the difference from Bulirsch-Stoer at 10x tighter tolerance).
  double A_error() const { return A_error_; }
  /// |A_1 - A_2|/A of the two independent methods (closed form vs ODE; Bulirsch-Stoer vs Dormand-Prince
  /// if non-ideal).
  double method_agreement() const { return method_agreement_; }
  /// A from each method (closed_form is NaN for a non-ideal EOS).
  double A_closed_form() const { return A_closed_form_; }
  double A_ode() const { return A_ode_; }
  /// Post-shock state (r/R = 1): rho1/rho0, and the post-shock packing fraction (0 if ideal).
  double shock_compression() const { return shock_compression_; }
  double shock_packing_fraction() const { return shock_compression_ * config_.phi; }
  /// r/R of the edge of the empty central cavity (vacuum case), else 0.
  double cavity_radius() const { return cavity_radius_; }

  /// Profile at r/R in [0, 1]; in the standard case the temperature is +inf at r/R = 0 and wherever
  /// rho/rho0 underflows (below 2.2e-308, e.g. d = 1, gamma = 1.01, r/R < 1e-3); inside the cavity
  /// (vacuum case) every field is 0. Throws std::invalid_argument outside [0, 1].
  TvnsPoint at(double r_over_R) const;
  /// Profile at many r/R, in the given order (non-ideal EOS: each from the nearest stored ODE checkpoint,
  /// so near the centre its error grows like tolerance x (r/R)^-d: docs/cli.md).
  std::vector<TvnsPoint> profile(const std::vector<double>& r_over_R) const;

  /// Near-centre power laws, Eqs. (18a,b) [r-est, T-est]: rho ∝ x^density_exponent,
  /// T ∝ x^temperature_exponent with x = r/R (standard: d/(gamma-1), -d/(gamma-1); singular: 1, 2)
  /// and x = r/R - cavity_radius() in the vacuum case (2/(gamma-2), 1).
  double density_exponent() const { return density_exponent_; }
  double temperature_exponent() const { return temperature_exponent_; }

  /// Self-similar energy integrals ∫0^1 G V^2/2 x^(d-1) dx and ∫0^1 e x^(d-1) dx (e = internal energy per
  /// volume in rho0 Rdot^2) recomputed from at() by GSL QAGS in x, independent of how A was obtained;
  /// A = 4 S_d (kinetic + internal)/(d+2)^2. Thousands of at() calls (~10 ms): for tests and verification.
  struct ProfileEnergy {
    double kinetic, internal, error;
  };
  ProfileEnergy energy_from_profile(double tolerance = 1e-13) const;

 private:
  struct Impl;
  std::shared_ptr<const Impl> impl_;
  TvnsConfig config_;
  double gamma_ = 0.0;
  TvnsCase case_ = TvnsCase::standard;
  double A_ = 0.0, A_error_ = 0.0, method_agreement_ = 0.0;
  double A_closed_form_ = 0.0, A_ode_ = 0.0;
  double shock_compression_ = 0.0, cavity_radius_ = 0.0;
  double density_exponent_ = 0.0, temperature_exponent_ = 0.0;
};

/// Solves the blast for a validated config; throws std::invalid_argument on bad config.
TvnsSolution solve_tvns(const TvnsConfig& config);

/// The hard-particle TvNS solution at packing fraction phi: Henderson EOS in 2D, Carnahan-Starling
/// in 3D, solved to relative accuracy 1e-8. Throws std::invalid_argument for d outside {2, 3} or
/// phi out of range.
TvnsSolution solve_tvns_for_md(int d, double phi);

/// The A_d policy of the MD box, the project's one: a scene with A_d = 0 ("not given") is sized
/// with the hard-particle amplitude A_d(phi) of solve_tvns_for_md. md cannot include hydro, so run/
/// (run::resolve_blast_scene, under `md run`, `reproduce`, `md states` and the Python module)
/// injects this function into md::resolve_scene; the tracer calls it directly. A scene therefore
/// gets the same box, and the same trajectories, whichever way it is run.
theory::AmplitudeChoice md_amplitude(int d, double phi);

/// Which branch applies for an ideal gas with this d and gamma.
TvnsCase tvns_case(int d, double gamma);

/// A = 4 S_d J/(d+2)^2 from the self-similar energy integral J, S_d = 2, 2π, 4π (Eq. (1) with
/// E = rho0 R^d Rdot^2 S_d J and Rdot = 2R/((d+2)t)).
double amplitude_from_energy_integral(int d, double J);

}  // namespace coldblast::hydro
