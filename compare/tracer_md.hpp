#pragma once
// A kinetic tracer run (`coldblast tracer`, paper Eq. (36) [LB-full]) against an MD run of the same
// scene (`coldblast compare TRACER --md-run MD`): R_imp, V_imp and C_imp of both at every common
// recording time with block-jackknife errors and tracer/MD − 1, and p_imp at the last common time
// beside the Gaussian of Eq. (35) [Prt-d] (Eq. (39) [eq:pr] in 2D) with the MD's ⟨r²⟩. Nothing is
// fitted. The figures (tracer_vs_md.png, tracer_p_imp.png) are drawn from these results only.
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "compare/run_data.hpp"

namespace coldblast::compare {

/// One observable at one common recording time.
struct TracerMdPoint {
  double t = 0;
  double tracer = 0, tracer_error = 0;  ///< catalogue transform of the ensemble mean, jackknife error
  double md = 0, md_error = 0;
  double ratio = 0, ratio_error = 0;  ///< tracer/md − 1 and its error (the two runs independent)
};

/// tracer/MD − 1 of a point in per cent, signed, as quoted: "+3.8 ± 1.1 %".
std::string format_ratio_percent(const TracerMdPoint& point);

/// One observable's series (times common to both runs, ascending).
struct TracerMdSeries {
  std::string observable;
  std::string alpha_rational;  ///< the paper's time exponent (theory::scaling_exponents)
  double alpha = 0;
  std::vector<TracerMdPoint> points;
};

/// p_imp of both runs at one time, on the MD's bins (the tracer's must be the same: same scene and A_d).
struct TracerMdDistribution {
  double t = 0;
  std::vector<double> r, width;  ///< bin centres and widths
  std::vector<double> p_tracer, p_tracer_error, p_md, p_md_error;
  /// Eq. (35)'s radial density S_d r^(d−1) P(r) at the bin centres with ⟨r²⟩ = the MD's 2 R_imp²,
  /// i.e. its R_imp parameter = R_imp(MD) √(2/d).
  std::vector<double> p_gaussian;
  double gaussian_R = 0;
  /// ⟨r⁴⟩/⟨r²⟩² of the histograms (compare/figures.hpp's definition) and of any Gaussian, (d+2)/d.
  double ratio_tracer = 0, ratio_tracer_error = 0, ratio_md = 0, ratio_md_error = 0, ratio_gaussian = 0;
  double chi2_per_dof = 0;  ///< Σ (p_tracer − p_md)²/(δ_tracer² + δ_md²) over bins with errors, per bin
  int dof = 0;
};

struct TracerMdComparison {
  int d = 0;
  std::filesystem::path tracer_directory, md_directory;
  /// The MD run switched recollisions off (impurities.recollide = false): a numerical experiment.
  bool md_recollisions_off = false;
  /// The tracer started from the MD's impurities (--start states) at start_time; points before its
  /// start time (summary.json's start_time, 0 if absent) are left out.
  bool tracer_from_md_states = false;
  double start_time = 0.0;
  /// The tracer's background in words for titles and reports (tracer_background_phrase), "" when its
  /// summary.json does not say.
  std::string background;
  std::vector<TracerMdSeries> series;                ///< R_imp, V_imp, C_imp (those both runs record)
  std::optional<TracerMdDistribution> distribution;  ///< when both runs have p_imp.csv at a common time
};

/// Compares a tracer run with an MD run at their common recording times from the tracer's start time
/// on (summary.json's start_time: a --start states or thermal run holds its start state before it). Throws
/// std::invalid_argument naming --md-run when the runs differ in d or in their scenes' physics (n, a, E, the
/// impurities' count, mass and radius), share no recording time or no impurity observable, or their p_imp bins differ.
TracerMdComparison compare_tracer_with_md(const RunData& tracer, const RunData& md);

/// The background the tracer ran in, from its summary.json (background, transport, md_run_id), as a
/// phrase: "in the dense NS background (Enskog transport)", "in this MD run's own fields" (its md_run_id
/// is the MD run's run_id), "in the fields of MD run ID", "in the TvNS background", "in an equilibrium
/// gas"; "" when the summary has no background (runs written before it was recorded).
std::string tracer_background_phrase(const common::Json& tracer_summary, const common::Json& md_summary);

/// tracer_vs_md.csv: t, observable, tracer, tracer_stderr, md, md_stderr, ratio_minus_1, its stderr.
std::string tracer_md_csv(const TracerMdComparison& comparison);

/// The figure files written (empty name: no data for it).
struct TracerMdFigures {
  std::string observables, distribution;
};

/// Draws tracer_vs_md (per observable: tracer and MD log–log with error bars and the paper's t^α
/// through the MD's last point; below, tracer/MD − 1) and tracer_p_imp (p_imp at the last common
/// time: tracer, MD, Gaussian) into `folder` as PNG and PDF, with their .dat and .gp files; the
/// titles open with `caption` (the scene: compare/gnuplot.hpp's scene_caption).
TracerMdFigures write_tracer_md_figures(const TracerMdComparison& comparison, const std::string& caption,
                                        const std::filesystem::path& folder);

}  // namespace coldblast::compare
