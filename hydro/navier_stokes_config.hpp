#pragma once
// Configuration of the radial Navier–Stokes blast (paper Sec. III, Eqs. (13)-(16), in docs/hydro.md's
// total-energy form): the physical model (d, E, n∞, a, EOS, transport, the start), the numerics, their
// validation with messages naming each field and its range, and the defaults the library resolves.
#include <optional>
#include <string>
#include <vector>

#include "hydro/equation_of_state.hpp"
#include "hydro/transport.hpp"

namespace coldblast::hydro {

/// How the energy E enters (docs/hydro.md, "Starts"): `self_similar`, a smooth hot region of radius
/// initial_width R_ref at R_ref/λ = 2 (the Barenblatt–Pattle profile); `hotspot`, the MD's hot spot:
/// E as heat, zero velocity, uniform in the disc or sphere of radius r0 at the ambient density.
enum class Start { self_similar, hotspot };

/// "self-similar" or "hotspot".
std::string to_string(Start start);
/// Inverse of to_string; throws std::invalid_argument naming `option` and the allowed values.
Start start_from_string(const std::string& text, const std::string& option = "start");

/// φ∞ used when the EOS is a hard-particle one and phi is left at 0: the paper's MD value.
constexpr double default_packing_fraction = 0.118;

/// Random close packing of equal spheres, φ ≈ 0.64: the densest amorphous packing (the maximally
/// random jammed state, Torquato, Truskett & Debenedetti, Phys. Rev. Lett. 84, 2064 (2000)).
constexpr double random_close_packing_spheres = 0.64;

/// Finite-volume cells of every core solve unless told otherwise (hydro core, compare's continuum,
/// the tracer's background, Python); 512 for the Euler check, where A_d meets 0.1 % against the exact
/// TvNS solution in d = 2 and 3 (-6.9e-4, -9.4e-4; first order in the cell size: docs/hydro.md).
inline constexpr int default_core_cells = 256;
inline constexpr int default_euler_cells = 512;

/// R_ref/λ of the grid at the self-similar start.
inline constexpr double default_start_R_over_lambda = 2.0;

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
  /// How E enters; with `hotspot` the times t of the result count from the deposition (as in the MD),
  /// with `self_similar` from the virtual point explosion of R_ref(t).
  Start start = Start::self_similar;
  /// Hot-spot radius r0/λ (in mean free paths, like the R/λ of the numerics), > 0 for start = hotspot;
  /// must stay 0 otherwise. A hot spot holding N particles at φ∞ = 0.118 has r0/λ = 0.22 √N (2D),
  /// 0.18 N^(1/3) (3D) (docs/hydro.md, "Starts").
  double r0_over_lambda = 0;
  /// φ∞ actually used: phi, or default_packing_fraction for a hard-particle EOS with phi = 0.
  double resolved_phi() const;
};

/// Discretisation and integrator options; none of them changes the physics being solved.
struct NavierStokesNumerics {
  int cells = default_core_cells;  ///< finite-volume cells in [0, outer_margin R_ref], [16, 100000]
  /// R_ref/λ of the grid at the initial time, (0, until); default 2 (self-similar start) or
  /// max(2, (r0/λ)/initial_width) (hotspot: large enough to hold the hot spot and its early heat wave).
  std::optional<double> start_R_over_lambda;
  /// Hot region radius / R_ref(t_start), (0, 0.8]: the self-similar start's hot region; with a hotspot
  /// start it sets the default start_R_over_lambda.
  double initial_width = 0.2;
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
  /// Extra profiles at these times t (the result's t: from the deposition with a hotspot start), each
  /// after the start and before R_ref reaches until_R_over_lambda (checked when the run plans its
  /// outputs: std::invalid_argument naming profile_times). Matches an MD time directly, as the
  /// hot spot's partner must (compare's continuum, the tracer's hot-spot background).
  std::vector<double> profile_times;
};

/// One blast run: physics, numerics, and how far to go.
struct NavierStokesConfig {
  NavierStokesPhysics physics;
  NavierStokesNumerics numerics;
  double until_R_over_lambda = 1e4;  ///< stop when R_ref/λ reaches this, (start_R_over_lambda, 1e12]
  /// Throws std::invalid_argument naming the first field out of range, its value and the range.
  void validate() const;
  /// numerics.start_R_over_lambda, or its default for the start (see NavierStokesNumerics).
  double resolved_start_R_over_lambda() const;
  /// Euler mode: neither heat conduction nor viscosity.
  bool euler() const { return !physics.heat_conduction && !physics.viscosity; }
};

/// The validated config with the library's defaults filled in: φ∞ (resolved_phi), the start's
/// R_ref/λ, the grid's core resolution and shock band. Throws as NavierStokesConfig::validate.
NavierStokesConfig resolve_defaults(const NavierStokesConfig& input);

}  // namespace coldblast::hydro
