#pragma once
// The verdict of an MD run against a reference, observable by observable, as in the paper's
// Table 1: alpha_S ± delta alpha at the last two recorded times and over a window, the reference
// exponent, the deviation in units of the error, and the verdict word (pass, miss, FAIL) with the
// finite-R/λ allowance that separates a miss from a FAIL and where that allowance comes from.
#include <filesystem>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "compare/amplitudes.hpp"
#include "compare/continuum.hpp"
#include "compare/hydro_reference.hpp"
#include "compare/power_law.hpp"
#include "compare/run_data.hpp"
#include "compare/tracer_md.hpp"

namespace coldblast::compare {

/// What the measured exponents are compared with.
enum class Reference {
  theory,  ///< the exact rationals of theory/ (asymptotic, t -> infinity)
  paper,   ///< the paper's Table 1 (alpha_S ± delta alpha, d = 2 scene, t = 4000)
  hydro    ///< the Navier–Stokes running exponents at the MD's own R/lambda
};

/// Parses "theory", "paper" or "hydro"; throws std::invalid_argument naming --against.
Reference parse_reference(const std::string& text);
std::string to_string(Reference reference);

/// The impurity and core observables of Table 1, in the paper's column order (from the catalogue).
const std::vector<std::string>& table1_observables();

/// The paper's Table 1 value alpha_S ± delta alpha for one observable (d = 2, t = 4000), from the
/// catalogue theory/observables.hpp.
using theory::PaperValue;
/// Throws std::invalid_argument for an observable not in Table 1.
PaperValue paper_table1(const std::string& observable);

struct CompareConfig {
  std::filesystem::path run_dir;  ///< an `md run` output directory
  Reference against = Reference::theory;
  double sigma = 2.0;  ///< k: pass when |dev| <= k * error, miss within k * error + allowance; (0, 10]
  /// Finite-R/λ allowance of every exponent for theory and hydro, in [0, 1]; none: each exponent's
  /// own, derived from the Navier–Stokes blast at the run's R/λ (derived_allowance; docs/compare.md,
  /// "Where the allowance comes from"); the paper comparison has none.
  std::optional<double> allowance;
  double window_decades = 0.5;  ///< window fit over [t_max 10^-w, t_max], w in (0, 6]
  /// Compare as of this time: recorded times > until are ignored (0: use every recorded time). It
  /// must lie in [second recorded time, last recorded time] of the run.
  double until = 0.0;
  std::vector<std::string> observables;         ///< empty: every Table 1 observable present in the run
  int hydro_cells = hydro::default_core_cells;  ///< Navier–Stokes cells for Reference::hydro, [16, 100000]
  /// The NS model for Reference::hydro (unset: the dense model at the run's φ); only with hydro.
  HydroModelOptions hydro_model;
  /// An MD run of the same scene for a tracer run_dir (--md-run; empty: none): the tracer against
  /// the MD (compare/tracer_md.hpp), as of `until` as well.
  std::filesystem::path md_run;
  /// Solve the continuum for the report's profile figure as well when the verdicts need none
  /// (paper, or theory with a given allowance) and the run has profiles.csv and λ: the report
  /// draws the curves it is given and never runs a solver.
  bool continuum_for_figures = false;
  void validate() const;
};

/// An exponent verdict's finite-R/λ allowance: a deviation beyond k σ but within k σ + value is a
/// miss, beyond it a FAIL.
struct ExponentAllowance {
  double value = 0;
  std::string origin;  ///< where `value` comes from, printed beside the verdict
};

/// The verdict for one observable.
struct ObservableVerdict {
  std::string name;
  double alpha_theory = 0;               ///< exact rational of theory/ as a number
  std::string alpha_theory_rational;     ///< "p/q"
  double alpha_reference = 0;            ///< what was compared with (theory, paper or hydro value)
  double alpha_reference_error = 0;      ///< its own error (paper: its delta alpha; else 0)
  double alpha_measured = 0;             ///< running exponent at the last two recorded times
  double alpha_error = 0;                ///< its jackknife error
  double t_measured = 0;                 ///< the earlier of those two times
  PowerLawFit window;                    ///< least-squares exponent over the window
  double deviation_sigma = 0;            ///< (alpha_measured - alpha_reference)/combined error
  double tolerance = 0;                  ///< k × the combined error: the bound of a pass
  double allowance = 0;                  ///< finite-R/λ allowance: a miss is within tolerance + allowance
  std::string allowance_origin;          ///< where the allowance comes from
  Outcome outcome = Outcome::fail;       ///< pass, miss or FAIL (an undefined exponent is a FAIL)
  bool pass = false;                     ///< outcome == pass
  std::vector<RunningExponent> running;  ///< alpha(t) at every recorded pair
};

struct CompareResult {
  int d = 0;
  Reference against = Reference::theory;
  double sigma = 0;
  std::optional<double> allowance;  ///< the --allowance given; none: each row's own (ObservableVerdict::allowance)
  std::string allowance_rule;       ///< how the rows' allowances were made, one sentence (docs/compare.md)
  double until = 0;                 ///< the last recorded time used (the run's last one unless --until was given)
  std::vector<ObservableVerdict> observables;
  /// Reference::hydro: the MD's core amplitudes against the NS model at the same R/λ.
  std::vector<AmplitudeVerdict> amplitudes;
  /// Reference::hydro: the same at every recorded time from R/λ = 10 on (amplitude_history), when the
  /// continuum was solved with its history; for the report's amplitudes.csv and figure, not the verdict.
  std::vector<AmplitudeVerdict> amplitude_history;
  /// Observables recorded but deliberately not judged, with the reason (u_imp against theory/hydro).
  std::vector<std::string> notes;
  /// What makes the verdicts less than they look: fewer than 8 jackknife blocks, R/λ below 10 at
  /// the last time, a window fit over fewer than two recorded times (report, JSON and stderr)
  std::vector<std::string> warnings;
  bool pass = false;  ///< every exponent and amplitude verdict passes
  /// Not every verdict passes, but the only ones that do not are misses (Outcome::miss: beyond the
  /// errors, within the stated allowance or continuum bound): a measured deviation, exit 0
  bool miss = false;
  RunData run;
  /// The continuum solved for this run (hydro: always; theory: unless --allowance is given; else
  /// with CompareConfig::continuum_for_figures);
  /// shared so that the reports of one `reproduce` use one solve.
  std::shared_ptr<const ContinuumReference> continuum;
  /// With CompareConfig::md_run: the run (a tracer's) against that MD run.
  std::optional<TracerMdComparison> tracer_md;
};

/// "PASS", "MISS" (CompareResult::miss) or "FAIL".
std::string verdict_word(const CompareResult& result);
/// One line per exponent or amplitude that does not pass, saying why: its word, how far it is off
/// (in σ and absolutely) and the bound it missed, e.g. "C_imp exponent miss: 0.3666 +- 0.0028
/// against 0.4000, -0.0334 (-12.0 sigma), beyond 2 sigma, within 2 sigma + allowance 0.048 (...)".
std::vector<std::string> verdict_reasons(const CompareResult& result);
/// One line for summaries: the verdict word and, unless PASS, verdict_reasons joined by "; ".
std::string verdict_summary(const CompareResult& result);

/// The word of one exponent verdict: pass when |alpha_measured - alpha_reference| <= k error,
/// miss when within k error + allowance, else FAIL (also for a non-finite exponent or error).
Outcome exponent_outcome(double alpha_measured, double alpha_reference, double error, double k, double allowance);

/// The finite-R/λ allowance of one exponent derived from the continuum solved for the run
/// (docs/compare.md, "Where the allowance comes from"); nothing in it is fitted:
/// - the first order Navier–Stokes drops moves a running exponent by b = 2 Kn² |α_n0 + α_H|
///   (a relative correction of size Kn², Kn = λ n∞/(n0 H) of the NS core at the run's last time,
///   differentiated in ln t; the amplitudes' bound carried over to exponents);
/// - against hydro the allowance is b; against theory it is |α_NS(x) − α_T| + b, the distance of
///   the NS running exponent to the rational at the run's R/λ x at the measured time, plus b.
/// `ns` wraps continuum.ns. Throws std::invalid_argument for Reference::paper (no allowance).
ExponentAllowance derived_allowance(Reference against, const std::string& observable, double alpha_theory,
                                    double R_over_lambda, const ContinuumReference& continuum,
                                    const HydroReference& ns);

/// Reads the run and compares every requested observable; for Reference::hydro it first solves the
/// continuum once (solve_continuum, the model of config.hydro_model) and adds the amplitude
/// verdicts; for Reference::theory without config.allowance it solves the default model to derive
/// the allowances (a run the continuum cannot be solved for, e.g. without λ, gets allowance 0 and
/// its rule says why). Throws std::invalid_argument for a bad config or run directory (including --against
/// paper for d != 2, and an inconsistent NS model naming its option). `progress.continuum` follows
/// the continuum's solves (may be empty).
struct CompareProgress {
  ContinuumProgress continuum;
};
CompareResult run_compare(const CompareConfig& config, const CompareProgress& progress = {});

/// Reference::hydro or theory against an already solved continuum (e.g. `reproduce`'s one solve):
/// allowances derived from it (unless config.allowance), and for hydro the exponent verdicts from
/// its NS running exponents at the MD's R/λ and the amplitude verdicts from its amplitudes.
CompareResult run_compare(const CompareConfig& config, std::shared_ptr<const ContinuumReference> continuum);

/// The observables judged by default: every Table 1 observable the run records, except that for
/// theory and hydro the flow speed is judged by u_flow (unbiased) and u_imp is left out with a
/// note (its thermal-noise bias, docs/verification.md); `paper` keeps u_imp and has no u_flow.
std::vector<std::string> default_observables(const RunData& run, Reference against, std::vector<std::string>& notes);

/// Exponents predicted by another model at the MD's times, used for Reference::hydro.
using ReferenceExponents = std::function<double(const std::string& observable, double t)>;
/// As run_compare, with the reference exponents supplied by the caller (hydro only) and no
/// continuum: the allowance is config.allowance, or 0.
CompareResult run_compare(const CompareConfig& config, const ReferenceExponents& reference);

}  // namespace coldblast::compare
