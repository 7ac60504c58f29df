#include "compare/amplitudes.hpp"

#include <cmath>
#include <filesystem>
#include <stdexcept>

#include "compare/verdict.hpp"
#include "theory/prefactors.hpp"

namespace coldblast::compare {

JackknifedValue jackknife_last(const std::vector<const BlockSeries*>& series,
                               const std::function<double(const std::vector<double>&)>& f) {
  const std::size_t blocks = series.front()->block_count();
  for (const auto* s : series)
    if (s->block_count() != blocks) throw std::invalid_argument("blocks.csv: observables have different block counts");
  const auto value = [&](long excluded) {
    std::vector<double> args;
    for (const auto* s : series) args.push_back(s->ensemble_values(excluded).back());
    return f(args);
  };
  JackknifedValue result;
  result.value = value(-1);
  if (blocks < 2) throw std::invalid_argument("blocks.csv: fewer than 2 blocks, no jackknife error");
  std::vector<double> partial;
  double mean = 0;
  for (std::size_t b = 0; b < blocks; ++b) {
    partial.push_back(value(static_cast<long>(b)));
    mean += partial.back() / blocks;
  }
  double sum = 0;
  for (double p : partial) sum += (p - mean) * (p - mean);
  result.error = std::sqrt((blocks - 1.0) / blocks * sum);
  return result;
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

std::vector<AmplitudeVerdict> amplitude_verdicts(const RunData& run, const ContinuumReference& continuum,
                                                 double sigma) {
  std::vector<AmplitudeVerdict> verdicts;
  const auto& s = run.series;
  if (!s.count("R")) return verdicts;
  const BlockSeries& R = s.at("R");
  const double t = R.t.back(), n = run.summary["n"].get<double>(), E = run.summary["E"].get<double>();
  const int d = run.d;
  const ContinuumAmplitudes& ns = continuum.amplitudes;
  const ContinuumAmplitudes& ns_error = continuum.errors;
  const double x = continuum.R_over_lambda_last;
  // The first order NS drops: Burnett, O(Kn²), in the core with Kn of the NS core (the model's own
  // estimate of its validity, free of MD noise); λ/R at the shock, which is a few λ thick.
  const double Kn = core_knudsen(continuum);
  const double core_bound = std::isfinite(Kn) && Kn > 0 ? Kn * Kn : 0.0;
  AmplitudeVerdict base;
  base.t = t;
  base.R_over_lambda = x;
  base.continuum_bound = core_bound;
  if (s.count("n0")) {
    AmplitudeVerdict v = base;
    v.name = "n0/n";
    v.definition = "particles per volume in the ball that held 100 particles at t = 0, over n";
    const JackknifedValue j = jackknife_last({&s.at("n0")}, [n](const std::vector<double>& a) { return a[0] / n; });
    v.measured = j.value;
    v.error = j.error;
    v.reference = ns.n0_over_n;
    v.reference_error = ns_error.n0_over_n;
    verdicts.push_back(judge_amplitude(v, sigma));
  }
  if (s.count("T0")) {
    AmplitudeVerdict v = base;
    v.name = "T0/Rdot^2";
    v.definition = "(2/d) kinetic energy per particle in that ball, over (2R/((d+2)t))^2";
    const JackknifedValue j = jackknife_last({&s.at("T0"), &R}, [&](const std::vector<double>& a) {
      const double Rdot = theory::shock_speed_at(d, a[1], t);
      return a[0] / (Rdot * Rdot);
    });
    v.measured = j.value;
    v.error = j.error;
    v.reference = ns.T0_over_Rdot2;
    v.reference_error = ns_error.T0_over_Rdot2;
    verdicts.push_back(judge_amplitude(v, sigma));
  }
  {
    AmplitudeVerdict v = base;
    v.name = "R";
    v.continuum_bound = 1.0 / x;
    const double R_ns = theory::shock_radius(d, E, n, ns.A, t);  // Eq. (1) with the NS blast's A, at t
    const CoreSize front = md_front_radius(run, t);
    if (std::isfinite(front.H_over_R) && std::isfinite(ns.front_over_R)) {
      // One definition on both sides: the binned density's mid-height front in the MD's absolute shells.
      v.definition =
          "shock front: where the density in the MD's shells (profiles.csv) falls to the midpoint of its "
          "peak and n, both sides in the same absolute shells at the MD's last time";
      // Both fronts are in units of the MD's R (the NS's in the MD's absolute shells at the same t).
      const JackknifedValue j = jackknife_last({&R}, [](const std::vector<double>& a) { return a[0]; });
      v.measured = front.H_over_R * j.value;
      v.error = std::hypot(front.error * j.value, front.H_over_R * j.error);
      v.reference = ns.front_over_R * j.value;
      v.reference_error = ns_error.front_over_R * j.value;
    } else {
      // Without profiles there is no shared definition: the moving mass against the NS's
      // conservative front, which differ by a fraction of the front's width (docs/compare.md).
      v.definition =
          "shock radius from the moving mass; NS: (E t^2/(n A))^(1/(d+2)) with A of the NS blast at that "
          "R/lambda (two definitions: no profiles.csv)";
      const JackknifedValue j = jackknife_last({&R}, [](const std::vector<double>& a) { return a[0]; });
      v.measured = j.value;
      v.error = j.error;
      v.reference = R_ns;
      v.reference_error = R_ns * ns_error.A / (std::abs(ns.A) * (d + 2));
    }
    verdicts.push_back(judge_amplitude(v, sigma));
  }
  const CoreSize H = md_core_size(run, t);
  if (std::isfinite(H.H_over_R)) {
    AmplitudeVerdict v = base;
    v.name = "H/R";
    v.definition = "r/R where the density, in the MD's r/R bins, first reaches twice its innermost bin";
    v.measured = H.H_over_R;
    v.error = H.error;
    v.reference = ns.H_over_R;
    v.reference_error = ns_error.H_over_R;
    verdicts.push_back(judge_amplitude(v, sigma));
  }
  return verdicts;
}

}  // namespace coldblast::compare
