#pragma once
// Amplitude verdicts of `compare --against hydro`: the MD's core density n0/n∞, core temperature
// T0/Ṙ², shock radius R and core size H/R at its last recorded time, each ± its MD error, against
// the Navier–Stokes value at the same R/λ (no fitted parameter). Definitions shared by both sides
// are in docs/compare.md ("Amplitudes").
#include <functional>
#include <string>
#include <vector>

#include "compare/continuum.hpp"
#include "compare/run_data.hpp"
#include "theory/observables.hpp"

namespace coldblast::compare {

/// The word of one verdict, an amplitude's or an exponent's (docs/compare.md, "Verdicts"):
/// - pass: within k σ of the combined errors;
/// - miss: beyond k σ, but within the stated bound of what the reference leaves out: for an
///   amplitude |MD/NS − 1| ≤ the first order the Navier–Stokes equations drop (Kn² for the core,
///   Kn = λ n∞/(n0 H) of the NS core, Burnett order; λ/R for the shock radius, a front a few λ
///   thick); for an exponent |α_S − α_ref| ≤ k σ + the finite-R/λ allowance. A measured miss;
/// - fail: beyond that too, a wrong model or a bug (or an exponent that cannot be measured).
enum class Outcome { pass, miss, fail };
/// "pass", "miss", "FAIL".
std::string to_string(Outcome outcome);

struct AmplitudeVerdict {
  theory::Amplitude amplitude = theory::Amplitude::R;  ///< its catalogue entry (theory/observables.hpp)
  std::string name;                                    ///< the catalogue's: "n0/n", "T0/Rdot^2", "R", "H/R"
  std::string definition;                              ///< one line: how both sides measure it
  double t = 0;                                        ///< the MD time
  double R_over_lambda = 0;
  double measured = 0, error = 0;  ///< MD value and its error (jackknife; H, R: propagated bin errors)
  double reference = 0;            ///< NS at the same R/λ (R: at the same t)
  double reference_error = 0;      ///< the NS value's numerical error (grid and reading)
  double deviation_sigma = 0;      ///< (measured - reference)/√(error² + reference_error²)
  double relative_difference = 0;  ///< measured/reference - 1
  double tolerance = 0;            ///< k √(error² + reference_error²)
  double continuum_bound = 0;      ///< relative: Kn² (core) or λ/R (shock radius)
  Outcome outcome = Outcome::fail;
  bool pass = false;  ///< outcome == pass
};

/// Judges one amplitude: fills deviation_sigma, relative_difference, tolerance, outcome and pass
/// from measured ± error, reference ± reference_error, continuum_bound and k = sigma.
AmplitudeVerdict judge_amplitude(AmplitudeVerdict v, double sigma);

/// The amplitude verdicts, in the catalogue's order (theory::amplitude_catalogue), for every amplitude
/// the run records (n0 and T0 need n0, T0 and R in blocks.csv; R needs R; H needs profiles.csv), at
/// the run's last recorded time; k = sigma.
std::vector<AmplitudeVerdict> amplitude_verdicts(const RunData& run, const ContinuumReference& continuum, double sigma);

/// The amplitude verdicts at every time of continuum.history (ContinuumReference::history: the MD's
/// recorded times from R/λ = 10 on), time by time, each in the catalogue's order, judged against the NS
/// value at that time with the MD's error alone (the NS's numerical error is known at the last time
/// only: continuum.errors, about 1e-4 relative) and that time's Kn² bound; empty without a history.
std::vector<AmplitudeVerdict> amplitude_history(const RunData& run, const ContinuumReference& continuum, double sigma);

/// Kn = λ n∞/(n0 H) of the continuum's core at the MD's last time (n0 in the MD's ball, H by the
/// binned density rule in the MD's shells): the model's own estimate of its validity, free of MD
/// noise. NaN when the continuum's amplitudes give none.
double core_knudsen(const ContinuumReference& continuum);

/// The MD's core size at time t from profiles.csv (the latest profile time <= t); NaN when the
/// run has no profiles or the density never reaches twice its innermost bin.
CoreSize md_core_size(const RunData& run, double t);
/// The MD's shock front r/R at time t from profiles.csv under binned_front_radius; NaN as above.
CoreSize md_front_radius(const RunData& run, double t);

/// Value at the last recorded time of f(A_1, A_2, ...) of several observables' ensemble values,
/// with the delete-one-block jackknife error over their common blocks.
struct JackknifedValue {
  double value = 0, error = 0;
};
JackknifedValue jackknife_last(const std::vector<const BlockSeries*>& series,
                               const std::function<double(const std::vector<double>&)>& f);
/// The same at the recorded time t (relative tolerance 1e-9; std::invalid_argument if a series lacks it).
JackknifedValue jackknife_at(const std::vector<const BlockSeries*>& series, double t,
                             const std::function<double(const std::vector<double>&)>& f);

}  // namespace coldblast::compare
