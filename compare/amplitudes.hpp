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

namespace coldblast::compare {

/// Relative allowance for what the comparison does not resolve (docs/compare.md, "Amplitudes"): the
/// NS grid error (≤ 0.05 % between 128 and 512 cells) and the two shock-radius definitions (moving
/// mass against the NS front's mid-density, which differ by a fraction of the shock width).
constexpr double amplitude_allowance = 0.01;

struct AmplitudeVerdict {
  std::string name;        ///< "n0/n", "T0/Rdot^2", "R", "H/R"
  std::string definition;  ///< one line: how both sides measure it
  double t = 0;            ///< the MD time
  double R_over_lambda = 0;
  double measured = 0, error = 0;  ///< MD value and its error (jackknife; H: propagated bin errors)
  double reference = 0;            ///< NS at the same R/λ
  double deviation_sigma = 0;      ///< (measured - reference)/error
  double relative_difference = 0;  ///< measured/reference - 1
  double tolerance = 0;            ///< k error + amplitude_allowance |reference|
  bool pass = false;
};

/// The amplitude verdicts for every amplitude the run records (n0 and T0 need n0, T0 and R in
/// blocks.csv; R needs R; H needs profiles.csv), at the run's last recorded time; k = sigma.
std::vector<AmplitudeVerdict> amplitude_verdicts(const RunData& run, const ContinuumReference& continuum, double sigma);

/// The MD's core size at time t from profiles.csv (the latest profile time <= t); NaN when the
/// run has no profiles or the density never reaches twice its innermost bin.
CoreSize md_core_size(const RunData& run, double t);

/// Value at the last recorded time of f(A_1, A_2, ...) of several observables' ensemble values,
/// with the delete-one-block jackknife error over their common blocks.
struct JackknifedValue {
  double value = 0, error = 0;
};
JackknifedValue jackknife_last(const std::vector<const BlockSeries*>& series,
                               const std::function<double(const std::vector<double>&)>& f);

}  // namespace coldblast::compare
