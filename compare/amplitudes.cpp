#include "compare/amplitudes.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <stdexcept>

#include "common/jackknife.hpp"
#include "compare/verdict.hpp"
#include "theory/observables.hpp"
#include "theory/prefactors.hpp"

namespace coldblast::compare {

namespace {

// The index of recorded time t in s (relative tolerance 1e-9).
std::size_t time_index(const BlockSeries& s, double t) {
  for (std::size_t k = 0; k < s.t.size(); ++k)
    if (std::abs(s.t[k] - t) <= 1e-9 * std::abs(t)) return k;
  throw std::invalid_argument("blocks.csv: " + s.observable + " has no recorded time " + std::to_string(t));
}

}  // namespace

JackknifedValue jackknife_at(const std::vector<const BlockSeries*>& series, double t,
                             const std::function<double(const std::vector<double>&)>& f) {
  const std::size_t blocks = series.front()->block_count();
  std::vector<std::size_t> index;
  for (const auto* s : series) {
    if (s->block_count() != blocks) throw std::invalid_argument("blocks.csv: observables have different block counts");
    index.push_back(time_index(*s, t));
  }
  if (blocks < 2) throw std::invalid_argument("blocks.csv: fewer than 2 blocks, no jackknife error");
  const common::Jackknife j = common::block_jackknife(static_cast<long>(blocks), [&](long left_out) {
    std::vector<double> args;
    for (std::size_t i = 0; i < series.size(); ++i) args.push_back(series[i]->ensemble_values(left_out)[index[i]]);
    return std::vector<double>{f(args)};
  });
  return {j.value[0], j.error(0)};
}

JackknifedValue jackknife_last(const std::vector<const BlockSeries*>& series,
                               const std::function<double(const std::vector<double>&)>& f) {
  return jackknife_at(series, series.front()->t.back(), f);
}

namespace {

// The MD's density profile at the latest profile time <= t (bin centres in r/R, n/n∞, errors);
// false when the run has no profiles.csv.
bool md_density_profile(const RunData& run, double t, std::vector<double>& centre, std::vector<double>& density,
                        std::vector<double>& error) {
  const auto path = run.directory / "profiles.csv";
  if (!std::filesystem::exists(path)) return false;
  const CsvTable table = read_numeric_csv(path);
  const std::size_t ct = table.column("t"), lo = table.column("r_over_R_lo"), hi = table.column("r_over_R_hi"),
                    cn = table.column("density_over_n"), ce = table.column("density_stderr");
  double t_profile = -1;
  for (const auto& row : table.rows)
    if (row[ct] <= t * (1 + 1e-9)) t_profile = std::max(t_profile, row[ct]);
  for (const auto& row : table.rows)
    if (row[ct] == t_profile) {
      centre.push_back(0.5 * (row[lo] + row[hi]));
      density.push_back(row[cn]);
      error.push_back(std::isfinite(row[ce]) ? row[ce] : 0.0);
    }
  return true;
}

/// The MD's innermost profile bin at the latest profile time <= t: n/n∞ and T with their errors
/// (profiles.csv; T's error is NaN in files written before its temperature_stderr column).
struct CentreBin {
  double n = NAN, n_error = NAN, T = NAN, T_error = NAN;
};
CentreBin md_centre_bin(const RunData& run, double t) {
  CentreBin c;
  const auto path = run.directory / "profiles.csv";
  if (!std::filesystem::exists(path)) return c;
  const CsvTable table = read_numeric_csv(path);
  const std::size_t ct = table.column("t"), lo = table.column("r_over_R_lo"), cn = table.column("density_over_n"),
                    ce = table.column("density_stderr"), cT = table.column("temperature");
  const auto& names = table.columns;
  const bool has_T_error = std::find(names.begin(), names.end(), "temperature_stderr") != names.end();
  double t_profile = -1;
  for (const auto& row : table.rows)
    if (row[ct] <= t * (1 + 1e-9)) t_profile = std::max(t_profile, row[ct]);
  for (const auto& row : table.rows)
    if (row[ct] == t_profile && row[lo] == 0.0) {
      c = {row[cn], row[ce], row[cT], has_T_error ? row[table.column("temperature_stderr")] : NAN};
      break;
    }
  return c;
}

}  // namespace

CoreSize md_core_size(const RunData& run, double t) {
  std::vector<double> centre, density, error;
  if (!md_density_profile(run, t, centre, density, error)) return {NAN, NAN};
  return binned_core_size(centre, density, error);
}

CoreSize md_front_radius(const RunData& run, double t) {
  std::vector<double> centre, density, error;
  if (!md_density_profile(run, t, centre, density, error)) return {NAN, NAN};
  return binned_front_radius(centre, density, error);
}

std::string to_string(Outcome outcome) {
  switch (outcome) {
    case Outcome::pass:
      return "pass";
    case Outcome::miss:
      return "miss";
    case Outcome::fail:
      return "FAIL";
  }
  throw std::logic_error("unknown Outcome");
}

AmplitudeVerdict judge_amplitude(AmplitudeVerdict v, double sigma) {
  const double combined = std::hypot(v.error, v.reference_error);
  const double difference = v.measured - v.reference;
  v.deviation_sigma = combined > 0 ? difference / combined : NAN;
  v.relative_difference = v.measured / v.reference - 1.0;
  v.tolerance = sigma * combined;
  const bool finite = std::isfinite(v.measured) && std::isfinite(combined);
  if (finite && std::abs(difference) <= v.tolerance)
    v.outcome = Outcome::pass;
  else if (finite && std::abs(v.relative_difference) <= v.continuum_bound)
    v.outcome = Outcome::miss;
  else
    v.outcome = Outcome::fail;
  v.pass = v.outcome == Outcome::pass;
  return v;
}

double core_knudsen(const ContinuumReference& continuum) {
  const ContinuumAmplitudes& ns = continuum.amplitudes;
  const double Kn = 1.0 / (ns.n0_over_n * ns.H_over_R * continuum.R_over_lambda_last);
  return std::isfinite(Kn) && Kn > 0 ? Kn : NAN;
}

namespace {

/// What every amplitude of one run shares: its series, scene, the MD's last time and the NS values.
struct AmplitudeInputs {
  const RunData& run;
  const BlockSeries& R;
  double t, n, E;
  const ContinuumAmplitudes &ns, &ns_error;
};

/// The shock radius, both sides in one definition when profiles.csv exists (the binned density's
/// mid-height front in the MD's absolute shells, both in units of the MD's R), else the moving mass
/// against the NS's conservative front, which differ by a fraction of the front's width (docs/compare.md).
void measure_shock_radius(const AmplitudeInputs& in, AmplitudeVerdict& v) {
  const JackknifedValue j = jackknife_at({&in.R}, in.t, [](const std::vector<double>& a) { return a[0]; });
  const CoreSize front = md_front_radius(in.run, in.t);
  if (std::isfinite(front.H_over_R) && std::isfinite(in.ns.front_over_R)) {
    v.measured = front.H_over_R * j.value;
    v.error = std::hypot(front.error * j.value, front.H_over_R * j.error);
    v.reference = in.ns.front_over_R * j.value;
    v.reference_error = in.ns_error.front_over_R * j.value;
    return;
  }
  const int d = in.run.d;
  v.definition = theory::amplitude_info(theory::Amplitude::R).definition_without_profiles;
  v.measured = j.value;
  v.error = j.error;
  v.reference = theory::shock_radius(d, in.E, in.n, in.ns.A, in.t);  // Eq. (1) with the NS blast's A, at t
  v.reference_error = v.reference * in.ns_error.A / (std::abs(in.ns.A) * (d + 2));
}

/// The centre's amplitudes from the innermost profile bin (n(centre)/n, T(centre)/Ṙ²); false when
/// profiles.csv lacks the bin or its error (temperature_stderr: files written before it).
bool measure_centre(theory::Amplitude id, const AmplitudeInputs& in, AmplitudeVerdict& v) {
  const CentreBin c = md_centre_bin(in.run, in.t);
  if (id == theory::Amplitude::n_centre_over_n) {
    if (!std::isfinite(c.n_error) || !(c.n > 0)) return false;
    v.measured = c.n;
    v.error = c.n_error;
    v.reference = in.ns.n_centre_over_n;
    v.reference_error = in.ns_error.n_centre_over_n;
    return true;
  }
  if (!std::isfinite(c.T_error) || !(c.T > 0)) return false;
  // Ṙ from the ensemble R at t (Eq. (1) form, as for T0); its jackknife error joins T's.
  const JackknifedValue R = jackknife_at({&in.R}, in.t, [](const std::vector<double>& a) { return a[0]; });
  const double Rdot = theory::shock_speed_at(in.run.d, R.value, in.t);
  v.measured = c.T / (Rdot * Rdot);
  v.error = v.measured * std::hypot(c.T_error / c.T, 2.0 * R.error / R.value);
  v.reference = in.ns.T_centre_over_Rdot2;
  v.reference_error = in.ns_error.T_centre_over_Rdot2;
  return true;
}

/// Fills `v` (its name, definition, MD and NS values) for amplitude `id`; false when the run does not
/// record what it needs (n0, T0 in blocks.csv; H/R needs profiles.csv).
bool measure_amplitude(theory::Amplitude id, const AmplitudeInputs& in, AmplitudeVerdict& v) {
  const theory::AmplitudeInfo& info = theory::amplitude_info(id);
  v.amplitude = id;
  v.name = info.name;
  v.definition = info.definition;
  const auto& s = in.run.series;
  switch (id) {
    case theory::Amplitude::n0_over_n: {
      if (!s.count("n0")) return false;
      const double n = in.n;
      const JackknifedValue j =
          jackknife_at({&s.at("n0")}, in.t, [n](const std::vector<double>& a) { return a[0] / n; });
      v.measured = j.value;
      v.error = j.error;
      v.reference = in.ns.n0_over_n;
      v.reference_error = in.ns_error.n0_over_n;
      return true;
    }
    case theory::Amplitude::T0_over_Rdot2: {
      if (!s.count("T0")) return false;
      const JackknifedValue j = jackknife_at({&s.at("T0"), &in.R}, in.t, [&](const std::vector<double>& a) {
        const double Rdot = theory::shock_speed_at(in.run.d, a[1], in.t);
        return a[0] / (Rdot * Rdot);
      });
      v.measured = j.value;
      v.error = j.error;
      v.reference = in.ns.T0_over_Rdot2;
      v.reference_error = in.ns_error.T0_over_Rdot2;
      return true;
    }
    case theory::Amplitude::R:
      measure_shock_radius(in, v);
      return true;
    case theory::Amplitude::n_centre_over_n:
    case theory::Amplitude::T_centre_over_Rdot2:
      return measure_centre(id, in, v);
    case theory::Amplitude::H_over_R: {
      const CoreSize H = md_core_size(in.run, in.t);
      if (!std::isfinite(H.H_over_R)) return false;
      v.measured = H.H_over_R;
      v.error = H.error;
      v.reference = in.ns.H_over_R;
      v.reference_error = in.ns_error.H_over_R;
      return true;
    }
  }
  throw std::logic_error("unknown theory::Amplitude");
}

}  // namespace

namespace {

// Every amplitude the run records at its recorded time t (R/λ = x there), against the continuum's
// values `ns` ± `ns_error` with its core's Knudsen number Kn, in the catalogue's order.
std::vector<AmplitudeVerdict> verdicts_at(const RunData& run, double t, double x, const ContinuumAmplitudes& ns,
                                          const ContinuumAmplitudes& ns_error, double Kn, double sigma) {
  std::vector<AmplitudeVerdict> verdicts;
  const AmplitudeInputs in{
      run, run.series.at("R"), t, run.summary["n"].get<double>(), run.summary["E"].get<double>(), ns, ns_error};
  // The first order NS drops: Burnett, O(Kn²), in the core with Kn of the NS core (the model's own
  // estimate of its validity, free of MD noise); λ/R at the shock, which is a few λ thick.
  for (const theory::AmplitudeInfo& info : theory::amplitude_catalogue()) {
    AmplitudeVerdict v;
    v.t = t;
    v.R_over_lambda = x;
    v.continuum_bound = info.id == theory::Amplitude::R ? 1.0 / x : std::isfinite(Kn) && Kn > 0 ? Kn * Kn : 0.0;
    if (measure_amplitude(info.id, in, v)) verdicts.push_back(judge_amplitude(v, sigma));
  }
  return verdicts;
}

}  // namespace

std::vector<AmplitudeVerdict> amplitude_verdicts(const RunData& run, const ContinuumReference& continuum,
                                                 double sigma) {
  if (!run.series.count("R")) return {};
  return verdicts_at(run, run.series.at("R").t.back(), continuum.R_over_lambda_last, continuum.amplitudes,
                     continuum.errors, core_knudsen(continuum), sigma);
}

std::vector<AmplitudeVerdict> amplitude_history(const RunData& run, const ContinuumReference& continuum, double sigma) {
  std::vector<AmplitudeVerdict> history;
  if (!run.series.count("R")) return history;
  // The NS values' numerical errors are known at the last time only (continuum.errors); each time
  // is judged against its NS value alone, so the MD's error is the sigma (the NS's is ~1e-4 or less).
  const ContinuumAmplitudes no_error;
  for (const ContinuumAtTime& c : continuum.history) {
    const auto at = verdicts_at(run, c.t, md_R_over_lambda(run, c.t), c.amplitudes, no_error, c.knudsen, sigma);
    history.insert(history.end(), at.begin(), at.end());
  }
  return history;
}

}  // namespace coldblast::compare
