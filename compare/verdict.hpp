#pragma once
// The verdict of an MD run against a reference, observable by observable, as in the paper's
// Table 1: alpha_S ± delta alpha at the last two recorded times and over a window, the reference
// exponent, the deviation in units of the error, and pass/fail.
#include <filesystem>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "compare/amplitudes.hpp"
#include "compare/continuum.hpp"
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
  double sigma = 2.0;  ///< k: pass when |dev| <= k * error (+ allowance), k in (0, 10]
  /// Finite-time allowance added to k * error for theory and hydro, in [0, 1]; none selects the
  /// documented default of the reference (theory 0.10, hydro 0.05, paper 0: docs/compare.md).
  std::optional<double> allowance;
  double window_decades = 0.5;  ///< window fit over [t_max 10^-w, t_max], w in (0, 6]
  /// Compare as of this time: recorded times > until are ignored (0: use every recorded time). It
  /// must lie in [second recorded time, last recorded time] of the run.
  double until = 0.0;
  std::vector<std::string> observables;  ///< empty: every Table 1 observable present in the run
  int hydro_cells = 256;                 ///< Navier–Stokes cells for Reference::hydro, [16, 100000]
  /// The NS model for Reference::hydro (unset: the dense model at the run's φ); only with hydro.
  HydroModelOptions hydro_model;
  /// An MD run of the same scene for a tracer run_dir (--md-run; empty: none): the tracer against
  /// the MD (compare/tracer_md.hpp), as of `until` as well.
  std::filesystem::path md_run;
  void validate() const;
  /// The allowance in force: `allowance` if given, else the reference's default.
  double effective_allowance() const;
};

/// The verdict for one observable.
struct ObservableVerdict {
  std::string name;
  double alpha_theory = 0;            ///< exact rational of theory/ as a number
  std::string alpha_theory_rational;  ///< "p/q"
  double alpha_reference = 0;         ///< what was compared with (theory, paper or hydro value)
  double alpha_reference_error = 0;   ///< its own error (paper: its delta alpha; else 0)
  double alpha_measured = 0;          ///< running exponent at the last two recorded times
  double alpha_error = 0;             ///< its jackknife error
  double t_measured = 0;              ///< the earlier of those two times
  PowerLawFit window;                 ///< least-squares exponent over the window
  double deviation_sigma = 0;         ///< (alpha_measured - alpha_reference)/combined error
  double tolerance = 0;               ///< the bound |alpha_measured - alpha_reference| must meet
  bool pass = false;
  std::vector<RunningExponent> running;  ///< alpha(t) at every recorded pair
};

struct CompareResult {
  int d = 0;
  Reference against = Reference::theory;
  double sigma = 0, allowance = 0;
  double until = 0;  ///< the last recorded time used (the run's last one unless --until was given)
  std::vector<ObservableVerdict> observables;
  /// Reference::hydro: the MD's core amplitudes against the NS model at the same R/λ.
  std::vector<AmplitudeVerdict> amplitudes;
  /// Observables recorded but deliberately not judged, with the reason (u_imp against theory/hydro).
  std::vector<std::string> notes;
  bool pass = false;  ///< every exponent and amplitude verdict passes
  /// Not every verdict passes, but the only ones that do not are amplitude misses (a measured
  /// continuum miss beyond the errors, within the first order NS drops; AmplitudeOutcome::miss)
  bool miss = false;
  RunData run;
  /// The continuum solved for this run (hydro: always; else when a report drew the profiles);
  /// shared so that the reports of one `reproduce` use one solve.
  std::shared_ptr<const ContinuumReference> continuum;
  /// With CompareConfig::md_run: the run (a tracer's) against that MD run.
  std::optional<TracerMdComparison> tracer_md;
};

/// "PASS", "MISS" (CompareResult::miss) or "FAIL".
std::string verdict_word(const CompareResult& result);
/// One line for summaries: the verdict word and, unless PASS, which amplitudes missed or failed
/// and by how much, e.g. "MISS: T0/Rdot^2 -3.4 % (-3.6 sigma; continuum bound 10 %)".
std::string verdict_summary(const CompareResult& result);

/// Reads the run and compares every requested observable; for Reference::hydro it first solves the
/// continuum once (solve_continuum, the model of config.hydro_model) and adds the amplitude
/// verdicts. Throws std::invalid_argument for a bad config or run directory (including --against
/// paper for d != 2, and an inconsistent NS model naming its option). `progress.continuum` follows
/// the continuum's solves (may be empty).
struct CompareProgress {
  ContinuumProgress continuum;
};
CompareResult run_compare(const CompareConfig& config, const CompareProgress& progress = {});

/// Reference::hydro against an already solved continuum (e.g. `reproduce`'s one solve): exponent
/// verdicts from its NS running exponents at the MD's R/λ, amplitude verdicts from its amplitudes.
CompareResult run_compare(const CompareConfig& config, std::shared_ptr<const ContinuumReference> continuum);

/// The observables judged by default: every Table 1 observable the run records, except that for
/// theory and hydro the flow speed is judged by u_flow (unbiased) and u_imp is left out with a
/// note (its thermal-noise bias, docs/verification.md); `paper` keeps u_imp and has no u_flow.
std::vector<std::string> default_observables(const RunData& run, Reference against, std::vector<std::string>& notes);

/// The MD's R/λ at time t: its recorded shock radius R (log-interpolated) over summary.json's
/// lambda, or Eq. (1) with the run's E, n, a, A_d when R was not recorded.
double md_R_over_lambda(const RunData& run, double t);

/// Exponents predicted by another model at the MD's times, used for Reference::hydro.
using ReferenceExponents = std::function<double(const std::string& observable, double t)>;
/// As run_compare, with the reference exponents supplied by the caller (the CLI wires hydro in).
CompareResult run_compare(const CompareConfig& config, const ReferenceExponents& reference);

}  // namespace coldblast::compare
