#pragma once
// Figures beyond the exponent panels, drawn from the optional files of an MD run: the Fig. 3-style
// collapse of p_imp(r, t) with the fitted Gaussian of Eq. (39) [eq:pr], MD radial profiles against
// continuum profiles computed beforehand (compare/continuum.hpp: no solver runs here), and the
// paper's Fig. 1 (compare/figure_blast.hpp).
#include <filesystem>
#include <optional>
#include <string>

#include "compare/amplitudes.hpp"
#include "compare/continuum.hpp"
#include "compare/run_data.hpp"

namespace coldblast::compare {

/// Fit of the radial impurity distribution at one time to S_d r^(d-1) P(r) with the Gaussian P
/// of Eq. (35) [Prt-d] and R_imp = b t^(spread) (in 2D exactly Eq. (39) [eq:pr], the paper's Fig. 3).
struct DistributionFit {
  double t = 0;
  double spread = 0;                  ///< exact R_imp time exponent (2D: 2/5) used to scale r
  double b_fit = 0, b_fit_error = 0;  ///< least-squares b and its 1-sigma error (Δχ² = 1)
  double b_direct = 0;                ///< R_imp(t)/t^spread from the R_imp observable (paper: 1.71)
  double residual_rms = 0;            ///< root-mean-square residual of p (1/length)
  int bins = 0;
  /// Shape tests of the Gaussian (docs/verification.md, Campaign 1): chi^2 per degree of freedom
  /// of the fitted Gaussian against the per-bin standard errors (bins with an error > 0; NaN if
  /// fewer than two), and the moment ratio <r^4>/<r^2>^2 of the histogram with its error
  /// (linear propagation of the per-bin errors, bins taken as independent), which is (d+2)/d for
  /// any isotropic Gaussian (Eq. (35)) whatever its width.
  double chi2_per_dof = 0;
  int weighted_bins = 0;
  double moment_ratio = 0, moment_ratio_error = 0, moment_ratio_gaussian = 0;
};

/// Fits p_imp.csv at its recorded time t (relative tolerance 1e-9; 0: its last time); nullopt when
/// the run has no p_imp.csv or no histogram at t.
std::optional<DistributionFit> fit_impurity_distribution(const RunData& run, double t = 0.0);

/// The figure files written into `folder` (empty names for figures whose data is absent).
struct ExtraFigures {
  std::string distribution, profiles, blast;  ///< blast: the paper's Fig. 1 (compare/figure_blast.hpp)
  std::string amplitudes;                     ///< amplitude_history_figure's (written by the report)
};

/// Draws every figure whose data the run holds; returns the file names written. The profile figure
/// shows the MD's profiles at its last profile time <= t_profile (0: the last one) beside the
/// given continuum curves (n/n∞, u/Ṙ, T/Ṙ² against r/R), drawn as they are.
ExtraFigures write_extra_figures(const RunData& run, const std::optional<DistributionFit>& fit,
                                 const std::vector<ProfileCurve>& continuum, const std::filesystem::path& folder,
                                 double t_profile = 0.0, const std::filesystem::path& drawn_blast_figure = {});

/// The MD's amplitudes against the continuum's at every recorded time from R/λ = 10 on
/// (CompareResult::amplitude_history): one panel per amplitude, MD/NS − 1 in per cent with its
/// 1σ error against R/λ, the continuum bound (Kn², λ/R for R) as a band and the last time's
/// verdict in the title; `model` names the NS model. Writes amplitudes.dat, .gp, .png and .pdf into
/// `folder` and returns "amplitudes.png", or "" (nothing written) when fewer than two times.
std::string amplitude_history_figure(const std::vector<AmplitudeVerdict>& history, const std::string& caption,
                                     const std::string& model, const std::filesystem::path& folder);

}  // namespace coldblast::compare
