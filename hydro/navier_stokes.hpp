#pragma once
// Radially symmetric compressible Navier–Stokes blast (d = 1, 2, 3) of an ideal monatomic gas with
// hard-sphere heat conduction κ = c_κ n∞ λ √T (paper Sec. III, Eqs. (13)-(20)), or of the dense
// hard-particle gas at the MD's packing fraction (Henderson / Carnahan–Starling EOS, Enskog transport;
// issue 12): measures the core radius H, central density n0 and temperature T0 and their running
// exponents from R/λ ≈ 2 upward.
// Numerics (docs/hydro.md): finite volumes on a grid r = ξ R_ref(t), HLLC, CVODE BDF, banded Jacobian.
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "hydro/equation_of_state.hpp"

namespace coldblast::hydro {

/// Transport coefficients: dilute Chapman–Enskog (κ = c_κ n∞ λ √T, μ = c_μ n∞ λ √T, no bulk viscosity),
/// or Enskog's dense gas (the same times the factors of hydro/enskog.hpp at the local φ, with bulk viscosity).
enum class Transport { dilute, enskog };

/// "dilute" or "enskog".
std::string to_string(Transport transport);
/// Inverse of to_string; throws std::invalid_argument naming `option` and the allowed values.
Transport transport_from_string(const std::string& text, const std::string& option = "transport");

/// φ∞ used when the EOS is a hard-particle one and phi is left at 0: the paper's MD value.
constexpr double default_packing_fraction = 0.118;

/// Random close packing of equal spheres, φ ≈ 0.64: the densest amorphous packing (the maximally
/// random jammed state, Torquato, Truskett & Debenedetti, Phys. Rev. Lett. 84, 2064 (2000)).
constexpr double random_close_packing_spheres = 0.64;

/// The largest ambient φ∞ the Navier–Stokes blast accepts (open bound). Henderson (discs):
/// max_ambient_packing_fraction (0.89286), where the strong shock reaches close packing; the solver
/// runs to R/λ = 1e12 up to it. Carnahan–Starling (spheres): random close packing 0.64, not the
/// Hugoniot's 0.72042, since an amorphous gas at rest cannot be denser (a physical bound, not a fitted
/// one). Measured to R/λ = 1e12 at 128 cells (docs/stress.md): 0.639, 0.641 and 0.65 run in about
/// 10 s; 0.66 exits 1 at R/λ = 2.5e9 (the shell is driven past close packing); 0.67 and 0.685 empty
/// their centre (n0/n∞ ~ 1e-20 at 0.685: a mean free path of 1e17 R) and CVODE's steps collapse (no
/// progress past R/λ = 2e6 in 5 and 15 min). Ideal gas: no bound (phi must be 0).
double navier_stokes_max_packing_fraction(Eos eos);

/// Physical model (units: m = 1, k_B = 1; a is the particle radius).
struct NavierStokesPhysics {
  int d = 2;                              ///< spatial dimension, 1 (planar), 2 (cylindrical) or 3 (spherical)
  double E = 1.0;                         ///< blast energy, > 0
  double n_inf = 1.0;                     ///< ambient number density n∞ (1/length^d), > 0
  double a = 0.5;                         ///< particle radius (length), > 0; sets λ = 1/(n∞ Ω_{d-1} a^{d-1})
  bool heat_conduction = true;            ///< false together with viscosity = false is the Euler mode
  std::optional<double> kappa_prefactor;  ///< c_κ >= 0 in κ = c_κ n∞ λ √T; default chapman_enskog_kappa_prefactor(d)
  bool viscosity = false;                 ///< shear viscosity μ = c_μ n∞ λ √T (zero bulk viscosity)
  std::optional<double> viscosity_prefactor;  ///< c_μ >= 0; default chapman_enskog_viscosity_prefactor(d)
  /// p = n T Z(φ), φ = φ∞ n/n∞; ideal (Z = 1), henderson (d = 2) or carnahan_starling (d = 3).
  Eos eos = Eos::ideal;
  /// Ambient packing fraction φ∞: 0 for the ideal gas; for a hard-particle EOS in
  /// (0, navier_stokes_max_packing_fraction(eos)), and 0 means default_packing_fraction (resolved_phi()).
  /// An independent parameter: λ still follows from n∞ and a (Eq. (5)), as in `tvns --eos --phi`.
  double phi = 0;
  Transport transport = Transport::dilute;  ///< enskog needs a hard-particle EOS
  /// Verification only: u ≡ 0 and n ≡ n∞ (no pressure work, no advection), leaving the nonlinear heat
  /// conduction of the energy equation (the Zel'dovich–Raizer / Barenblatt–Pattle heat wave). Samples
  /// then report R = R_ref(t), the grid scale, instead of a shock radius.
  bool frozen_flow = false;
  /// φ∞ actually used: phi, or default_packing_fraction for a hard-particle EOS with phi = 0.
  double resolved_phi() const;
};

/// Discretisation and integrator options; none of them changes the physics being solved.
struct NavierStokesNumerics {
  int cells = 256;                   ///< finite-volume cells in [0, outer_margin R_ref], [16, 100000]
  double start_R_over_lambda = 2.0;  ///< R_ref/λ at the initial time, (0, until)
  double initial_width = 0.2;        ///< radius of the initial hot region / R_ref(t_start), (0, 0.8]
  double temperature_floor = 1e-6;   ///< T of the cold gas entering the grid / Ṙ_ref(t)², (0, 1e-2]: never T = 0
  double relative_tolerance = 1e-6;  ///< CVODE relative tolerance, [1e-12, 1e-2]
  int samples_per_decade = 20;       ///< diagnostics per decade of R/λ, [4, 200]
  double outer_margin = 1.15;        ///< outer grid edge / R_ref(t), [1.05, 2]
  std::optional<double>
      core_resolution;  ///< ξ_c of the grid (cells ~ ξ_c + ξ near the centre); default from H/R at `until`
  std::optional<double>
      shock_band_fraction;     ///< share of cells in 0.85 < r/R_ref < 1.03, [0, 0.9]; default 0.25 (Euler: 0.75)
  bool project_totals = true;  ///< restore exact mass/energy totals after each step (CVODE projection)
  std::vector<double> profile_R_over_lambda;  ///< extra profile times (R_ref/λ); the final profile is always kept
};

/// One blast run: physics, numerics, and how far to go.
struct NavierStokesConfig {
  NavierStokesPhysics physics;
  NavierStokesNumerics numerics;
  double until_R_over_lambda = 1e4;  ///< stop when R_ref/λ reaches this, (start_R_over_lambda, 1e12]
  /// Throws std::invalid_argument naming the first field out of range, its value and the range.
  void validate() const;
};

/// Default c_κ: dilute Chapman–Enskog (first Sonine order) conductivity of hard discs (2D: 2/√π)
/// and spheres (3D: 75√π/256) in units n∞ λ √T; d = 1 has no such limit and uses 1 (Eq. (15) as written).
double chapman_enskog_kappa_prefactor(int d);
/// Default c_μ: Chapman–Enskog shear viscosity (2D: 1/(2√π), 3D: 5√π/64); d = 1: c_κ/4 (no effect, see docs).
double chapman_enskog_viscosity_prefactor(int d);

/// Diagnostics at one time (physical units unless stated).
struct NavierStokesSample {
  double t = 0;                   ///< time since the (virtual) point explosion of R_ref(t)
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
  NavierStokesConfig config;
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

/// The final profile against the exact TvNS solution for γ = 1 + 2/d, or for the run's hard-particle
/// EOS at its φ∞ (hydro/tvns.hpp).
struct TvnsComparison {
  double A_measured = 0, A_exact = 0, A_relative_error = 0;  ///< A_measured/A_exact - 1
  /// Σ|numerical - exact| Δx / Σ|exact| Δx over cells with x = r/R_exact in [x_min, 1), R_exact from
  /// Eq. (1) with A_exact (so shock-position errors count); density ρ/n∞, velocity u/Ṙ, pressure p/(n∞Ṙ²).
  double L1_density = 0, L1_velocity = 0, L1_pressure = 0;
  double x_min = 0;
};
/// Compares result.profiles.back(); x_min in [0, 1) (use > H/R to look only outside the core).
TvnsComparison compare_to_tvns(const NavierStokesResult& result, double x_min = 0.0);

/// Called with each sample as it is produced (progress reports).
using NavierStokesProgress = std::function<void(const NavierStokesSample&)>;

/// Integrates the blast; throws std::invalid_argument for a bad config and std::runtime_error (with
/// the CVODE flag name) if the integrator fails or positivity is lost.
NavierStokesResult run_navier_stokes(const NavierStokesConfig& config, const NavierStokesProgress& progress = {});

/// Convenience for compare/: the conduction-only core run in scaled units (E = n∞ = λ = 1) up to
/// R/λ = until (> 2, the start), default numerics; exponents_at(R/λ) then gives running exponents.
/// `physics`, if given, sets the model (eos, phi, transport, viscosity and the prefactors); its d is
/// replaced by `d` and E, n∞, a by the scaled units.
NavierStokesResult run_hydro_core(int d, double until_R_over_lambda, int cells = 256,
                                  const std::optional<NavierStokesPhysics>& physics = std::nullopt);

/// Euler mode (κ = μ = 0) with the same numerics, for comparison with the exact TvNS solution;
/// `physics`, if given, sets the EOS (eos, phi); conduction and viscosity are switched off.
NavierStokesResult run_hydro_euler(int d, double until_R_over_lambda, int cells = 512,
                                   const std::optional<NavierStokesPhysics>& physics = std::nullopt);

}  // namespace coldblast::hydro
