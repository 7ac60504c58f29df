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

CoreSize md_core_size(const RunData& run, double t) {
  const auto path = run.directory / "profiles.csv";
  if (!std::filesystem::exists(path)) return {NAN, NAN};
  const CsvTable table = read_numeric_csv(path);
  const std::size_t ct = table.column("t"), lo = table.column("r_over_R_lo"), hi = table.column("r_over_R_hi"),
                    cn = table.column("density_over_n"), ce = table.column("density_stderr");
  double t_profile = -1;
  for (const auto& row : table.rows)
    if (row[ct] <= t * (1 + 1e-9)) t_profile = std::max(t_profile, row[ct]);
  std::vector<double> centre, density, error;
  for (const auto& row : table.rows)
    if (row[ct] == t_profile) {
      centre.push_back(0.5 * (row[lo] + row[hi]));
      density.push_back(row[cn]);
      error.push_back(std::isfinite(row[ce]) ? row[ce] : 0.0);
    }
  return binned_core_size(centre, density, error);
}

namespace {

AmplitudeVerdict judge(AmplitudeVerdict v, double sigma) {
  v.deviation_sigma = v.error > 0 ? (v.measured - v.reference) / v.error : NAN;
  v.relative_difference = v.measured / v.reference - 1.0;
  v.tolerance = sigma * v.error + amplitude_allowance * std::abs(v.reference);
  v.pass = std::isfinite(v.measured) && std::isfinite(v.error) && std::abs(v.measured - v.reference) <= v.tolerance;
  return v;
}

}  // namespace

std::vector<AmplitudeVerdict> amplitude_verdicts(const RunData& run, const ContinuumReference& continuum,
                                                 double sigma) {
  std::vector<AmplitudeVerdict> verdicts;
  const auto& s = run.series;
  if (!s.count("R")) return verdicts;
  const BlockSeries& R = s.at("R");
  const double t = R.t.back(), n = run.summary["n"].get<double>(), E = run.summary["E"].get<double>();
  const int d = run.d;
  const ContinuumAmplitudes& ns = continuum.amplitudes;
  AmplitudeVerdict base;
  base.t = t;
  base.R_over_lambda = continuum.R_over_lambda_last;
  if (s.count("n0")) {
    AmplitudeVerdict v = base;
    v.name = "n0/n";
    v.definition = "particles per volume in the ball that held 100 particles at t = 0, over n";
    const JackknifedValue j = jackknife_last({&s.at("n0")}, [n](const std::vector<double>& a) { return a[0] / n; });
    v.measured = j.value;
    v.error = j.error;
    v.reference = ns.n0_over_n;
    verdicts.push_back(judge(v, sigma));
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
    verdicts.push_back(judge(v, sigma));
  }
  {
    AmplitudeVerdict v = base;
    v.name = "R";
    v.definition =
        "shock radius from the moving mass; NS: (E t^2/(n A))^(1/(d+2)) with A of the NS blast at that R/lambda";
    const JackknifedValue j = jackknife_last({&R}, [](const std::vector<double>& a) { return a[0]; });
    v.measured = j.value;
    v.error = j.error;
    v.reference = theory::shock_radius(d, E, n, ns.A, t);  // Eq. (1) with the NS blast's A
    verdicts.push_back(judge(v, sigma));
  }
  const CoreSize H = md_core_size(run, t);
  if (std::isfinite(H.H_over_R)) {
    AmplitudeVerdict v = base;
    v.name = "H/R";
    v.definition = "r/R where the density, in the MD's r/R bins, first reaches twice its innermost bin";
    v.measured = H.H_over_R;
    v.error = H.error;
    v.reference = ns.H_over_R;
    verdicts.push_back(judge(v, sigma));
  }
  return verdicts;
}

}  // namespace coldblast::compare
