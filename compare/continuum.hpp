#pragma once
// The continuum predictions an MD run is compared with, computed once per comparison (or once per
// `reproduce` for its three reports) and handed to the verdicts and the figures, which never run a
// solver themselves: the Navier–Stokes blast of the chosen model at the MD's own R/λ (exponents,
// core amplitudes, profile at the MD's last time), the dilute NS profile, and the exact TvNS
// profiles for the ideal gas and for the hard-particle EOS at the run's packing fraction.
#include <cmath>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "compare/run_data.hpp"
#include "hydro/equation_of_state.hpp"
#include "hydro/navier_stokes.hpp"

namespace coldblast::compare {

/// The Navier–Stokes model `--against hydro` solves.
struct HydroModel {
  hydro::Eos eos = hydro::Eos::ideal;
  double phi = 0.0;  ///< ambient packing fraction (0 for the ideal gas)
  hydro::Transport transport = hydro::Transport::dilute;
  /// Shear viscosity (and, with Enskog transport, bulk viscosity) beside heat conduction. Off by
  /// default: the paper's core model is heat conduction only (Eq. 15); on, it is the full
  /// Navier-Stokes blast (docs/verification.md, "Viscosity in the comparison").
  bool viscosity = false;
  /// How E enters (with_run_start): self_similar for the MD's kick and single starts, hotspot (of
  /// radius r0_over_lambda mean free paths, times from the deposition) for its hot spot.
  hydro::Start start = hydro::Start::self_similar;
  double r0_over_lambda = 0.0;
  /// "dense NS (henderson EOS at phi = 0.1178, enskog transport)" or "dilute NS (ideal gas, ...)",
  /// with "... transport, viscous)" when viscosity is on, followed by ", hot-spot start r0 = 1 lambda"
  /// for a hotspot start.
  std::string describe() const;
  /// "self-similar" or "hotspot r0/lambda = 1" (reports and verdict.json).
  std::string describe_start() const;
  bool dilute() const { return eos == hydro::Eos::ideal && transport == hydro::Transport::dilute; }
};

/// What the user asked for (CLI --hydro-eos, --hydro-phi, --hydro-transport, --hydro-viscosity);
/// unset fields take the run's defaults: the hard-particle EOS of the run's d at the run's φ with
/// Enskog transport, no viscosity.
struct HydroModelOptions {
  std::optional<hydro::Eos> eos;
  std::optional<double> phi;
  std::optional<hydro::Transport> transport;
  std::optional<bool> viscosity;
  /// How messages name each field: the flag, or hydro.<key> for a value from --hydro-config's file.
  std::string eos_name = "--hydro-eos", phi_name = "--hydro-phi", transport_name = "--hydro-transport",
              viscosity_name = "--hydro-viscosity";
  bool any() const { return eos || phi || transport || viscosity; }
};

/// The dense default for a run of dimension d at packing fraction phi: Henderson (d = 2) or
/// Carnahan–Starling (d = 3) at phi, Enskog transport; the dilute ideal-gas model when d = 1 or
/// phi = 0 (no hard-particle EOS applies).
HydroModel default_hydro_model(int d, double phi);

/// Resolves the options against a run of dimension d and packing fraction run_phi. Throws
/// std::invalid_argument naming the option for an inconsistent combination: --hydro-phi with the
/// ideal EOS, an EOS of another dimension, enskog transport with the ideal EOS, φ outside (0, φ_max).
HydroModel resolve_hydro_model(const HydroModelOptions& options, int d, double run_phi);

/// The run's packing fraction from summary.json ("phi", else n and a), 0 when absent.
double run_packing_fraction(const RunData& run);

/// `model` with the continuum start that matches the run's (its scene's [start] table, summary.json's
/// scene_toml): a `hotspot` MD start of radius r0 gets the NS hot spot of the same E and r0/λ (λ of
/// the run), so that both count time from the same deposition (docs/verification.md, "The start's
/// memory"); `kick` and `single` (E on a few particles, no extended hot region) and runs without a
/// scene keep the self-similar start.
HydroModel with_run_start(HydroModel model, const RunData& run);

/// One curve of the profile figure: n/n∞, u/Ṙ, T/Ṙ² against r/R.
struct ProfileCurve {
  enum class Kind { tvns_ideal, tvns_phi, ns_dilute, ns_model } kind = Kind::ns_model;
  std::string label;
  std::vector<double> r_over_R, density, velocity, temperature;
};

/// The MD run's amplitudes as the continuum predicts them at the MD's last time t, with the
/// definitions of docs/compare.md ("Amplitudes") applied to the NS profile exactly as to the MD and
/// in the MD's units: its n0 ball, its absolute r/R_MD shells and its Ṙ = 2R_MD/((d+2)t). (At the
/// same t the two blasts' shared shock fronts agree to 0.013 % on campaign 1, so this is also the
/// same R/λ under one definition.)
struct ContinuumAmplitudes {
  double R_over_lambda = 0;         ///< the NS's own R/λ at t (its conservative front)
  double n0_over_n = 0;             ///< particles per volume in the MD's n0 ball, / n∞
  double T0_over_Rdot2 = 0;         ///< (2/d) kinetic energy per particle in that ball / Ṙ_MD²
  double A = 0;                     ///< E t²/(n∞ R^{d+2}) of the NS blast at that R/λ
  double H_over_R = 0;              ///< core size in r/R_MD: binned density reaches twice its innermost bin
  double H_temperature_over_R = 0;  ///< NS's own core radius (T falls to T0/2), for information
  /// Shock front under the shared binned rule (binned_front_radius) on the NS density averaged over
  /// the MD's absolute shells, in units of R_MD
  double front_over_R = 0;
  /// The innermost of the MD's r/R bins: n/n∞ by volume, and T/Ṙ_MD² as the MD pools its particles
  /// there, (⟨v²⟩ − ū_r²)/d per particle (theory::Amplitude::n_centre_over_n, T_centre_over_Rdot2)
  double n_centre_over_n = 0, T_centre_over_Rdot2 = 0;
  /// n/n∞ averaged over each of the MD's r/R bins (centres in bin_centres): the profile residuals
  std::vector<double> bin_centres, binned_density;
};

/// The continuum's amplitudes at one of the MD's recorded times, in the MD's units as at the last
/// time (ContinuumAmplitudes), and its core's Knudsen number λ n∞/(n0 H) there.
struct ContinuumAtTime {
  double t = 0;
  ContinuumAmplitudes amplitudes;
  double knudsen = NAN;
};

/// The amplitudes' history starts at this R/λ of the MD (below it the NS, started at R/λ = 2, has
/// not forgotten its start; docs/hydro.md, "Starts").
inline constexpr double amplitude_history_min_R_over_lambda = 10.0;

/// Everything continuum the comparison of one MD run needs.
struct ContinuumReference {
  HydroModel model;
  double R_over_lambda_last = 0;                       ///< the MD's R/λ at its last recorded time
  hydro::NavierStokesResult ns;                        ///< the model's blast, with a profile at R_over_lambda_last
  std::optional<hydro::NavierStokesResult> ns_dilute;  ///< the dilute blast when `model` is not dilute
  ContinuumAmplitudes amplitudes;                      ///< of `ns` at the MD's last time, in its units
  /// The numerical error of each NS amplitude (same fields): the change from `cells` to 2 `cells`
  /// and, in quadrature, the error of reading it at the MD's R/λ (linear against quadratic
  /// interpolation in ln(R/λ) between the profiles); 0 where not computed
  ContinuumAmplitudes errors;
  std::vector<ProfileCurve> profiles;  ///< TvNS ideal, TvNS(φ), NS dilute, NS model (absent ones left out)
  /// The model's amplitudes at each of the MD's recorded times with R/λ ≥
  /// amplitude_history_min_R_over_lambda, the last one included, from a solve of its own with
  /// profiles around each of them (a hot spot's timed from the deposition, as at the last time);
  /// empty with fewer than two such times
  std::vector<ContinuumAtTime> history;
};

/// Solves the continuum for `run`: the model's NS from R/λ = 2 to max(20, 1.5 R/λ_last, until),
/// the same at 2 `cells` to max(20, 1.5 R/λ_last) for the amplitudes' grid error, the dilute NS to
/// max(20, 1.5 R/λ_last) when the model is not dilute, and the TvNS profiles. `cells` as
/// CompareConfig::hydro_cells. Throws std::invalid_argument if the run has no λ or R/λ ≤ 2.
/// Progress of those solves: (which solve, e.g. "dense NS (...), 256 cells"; the R/λ it reached),
/// at each of its diagnostics' samples (20 per decade).
using ContinuumProgress = std::function<void(const std::string& solve, double R_over_lambda)>;

/// With `history`, also ContinuumReference::history (one more solve, to 1.2 R/λ_last).
std::shared_ptr<const ContinuumReference> solve_continuum(const RunData& run, const HydroModel& model, int cells,
                                                          double until = 0.0, const ContinuumProgress& progress = {},
                                                          bool history = false);

/// The NS blast of `model` in scaled units (E = n∞ = λ = 1, so t in units √(n∞ λ^(d+2)/E)) from its
/// start to `until`, with extra profiles at `profile_R_over_lambda` and at `profile_times`; progress
/// (may be empty) names it by model.describe() and cells.
hydro::NavierStokesResult solve_hydro_model(int d, const HydroModel& model, double until, int cells,
                                            std::vector<double> profile_R_over_lambda = {},
                                            const ContinuumProgress& progress = {},
                                            std::vector<double> profile_times = {});

/// R_MD/R_NS at the MD's time t: the MD's shock radius over Eq. (1) with the NS blast's amplitude A.
double md_over_ns_radius(const RunData& run, double A, double t);

/// Core size from a binned density profile (the MD's profiles.csv bins): the r/R at which the
/// density first reaches twice its value in the innermost bin, linear between bin centres, with
/// the error propagated from per-bin errors (bins taken as independent). NaN if never reached.
struct CoreSize {
  double H_over_R = 0, error = 0;
};
/// Shock front from a binned density profile in units of n∞ (the MD's profiles.csv bins): the r/R
/// beyond the densest bin at which the density first falls to the midpoint (n_peak + 1)/2 of the
/// peak and the gas ahead, linear between bin centres, with the error propagated from per-bin
/// errors (bins independent). One definition for the MD and the NS profile averaged over the same
/// absolute shells (docs/compare.md, "Amplitudes"). NaN if it never falls that far.
CoreSize binned_front_radius(const std::vector<double>& r_centre, const std::vector<double>& density,
                             const std::vector<double>& density_error);
CoreSize binned_core_size(const std::vector<double>& r_centre, const std::vector<double>& density,
                          const std::vector<double>& density_error);

}  // namespace coldblast::compare
