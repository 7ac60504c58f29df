#include "compare/verdict.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "common/validate.hpp"
#include "compare/hydro_reference.hpp"
#include "theory/exponents.hpp"
#include "theory/observables.hpp"
#include "theory/prefactors.hpp"

namespace coldblast::compare {

Reference parse_reference(const std::string& text) {
  if (text == "theory") return Reference::theory;
  if (text == "paper") return Reference::paper;
  if (text == "hydro") return Reference::hydro;
  throw std::invalid_argument("--against = " + text + " is not one of theory, paper, hydro");
}

std::string to_string(Reference reference) {
  switch (reference) {
    case Reference::theory:
      return "theory";
    case Reference::paper:
      return "paper";
    case Reference::hydro:
      return "hydro";
  }
  throw std::logic_error("unknown Reference");
}

const std::vector<std::string>& table1_observables() {
  static const std::vector<std::string> names = theory::table1_names();
  return names;
}

PaperValue paper_table1(const std::string& observable) {
  const theory::ObservableInfo* info = theory::find_observable(observable);
  if (info && info->table1_row >= 0) return info->table1;
  throw std::invalid_argument("observable = " + observable + " is not in the paper's Table 1 (" +
                              theory::join_names(table1_observables()) + ")");
}

void CompareConfig::validate() const {
  using common::Bound;
  using common::require_in_range;
  require_in_range("--sigma", sigma, 0.0, 10.0, Bound::open, Bound::closed);
  if (allowance) require_in_range("--allowance", *allowance, 0.0, 1.0, Bound::closed, Bound::closed);
  require_in_range("--window-decades", window_decades, 0.0, 6.0, Bound::open, Bound::closed);
  if (until != 0.0 && !(until > 0.0 && std::isfinite(until)))
    throw std::invalid_argument("--until = " + std::to_string(until) +
                                " must be a positive finite time (0: all times)");
  common::require_integer_in_range("--hydro-cells", hydro_cells, 16, 100000);
  if (against != Reference::hydro && hydro_model.any()) {
    const std::string& option = hydro_model.eos   ? hydro_model.eos_name
                                : hydro_model.phi ? hydro_model.phi_name
                                                  : hydro_model.transport_name;
    throw std::invalid_argument(option +
                                " chooses the Navier-Stokes model of --against hydro; the "
                                "comparison is --against " +
                                to_string(against));
  }
  for (auto name = observables.begin(); name != observables.end(); ++name) {
    const theory::ObservableInfo* info = theory::find_observable(*name);
    if (!info || !info->verdict)
      throw std::invalid_argument("--observables: " + *name +
                                  (info ? " is not an observable compare judges (" + std::string(info->equation) + ")"
                                        : std::string(" is unknown")) +
                                  "; allowed: " + theory::join_names(theory::observable_names(theory::is_verdict)));
    if (std::find(observables.begin(), name, *name) != name)
      throw std::invalid_argument("--observables: " + *name + " is given twice");
  }
}

double CompareConfig::effective_allowance() const {
  if (allowance) return *allowance;
  switch (against) {
    case Reference::theory:
      return 0.10;
    case Reference::hydro:
      return 0.05;
    case Reference::paper:
      return 0.0;
  }
  throw std::logic_error("unknown Reference");
}

CompareResult run_compare(const CompareConfig& config, const CompareProgress& progress) {
  if (config.against != Reference::hydro) return run_compare(config, ReferenceExponents{});
  // The Navier–Stokes prediction at the MD's own R/λ (no fitted parameter), solved once.
  config.validate();
  RunData run = read_run(config.run_dir);
  if (config.until > 0) truncate_run(run, config.until);
  const HydroModel model = resolve_hydro_model(config.hydro_model, run.d, run_packing_fraction(run));
  return run_compare(config, solve_continuum(run, model, config.hydro_cells, 0.0, progress.continuum));
}

CompareResult run_compare(const CompareConfig& config, std::shared_ptr<const ContinuumReference> continuum) {
  if (!continuum) throw std::invalid_argument("--against hydro: no continuum reference was supplied");
  const HydroReference hydro(continuum->ns);
  RunData run = read_run(config.run_dir);
  if (config.until > 0) truncate_run(run, config.until);
  CompareResult result = run_compare(config, [&](const std::string& observable, double t) {
    return hydro.exponent(observable, md_R_over_lambda(run, t));
  });
  result.continuum = std::move(continuum);
  if (config.against == Reference::hydro) {
    result.amplitudes = amplitude_verdicts(result.run, *result.continuum, config.sigma);
    const bool exponents_pass = result.pass;
    bool any_miss = false, any_fail = false;
    for (const auto& a : result.amplitudes) {
      result.pass = result.pass && a.pass;
      any_miss = any_miss || a.outcome == AmplitudeOutcome::miss;
      any_fail = any_fail || a.outcome == AmplitudeOutcome::fail;
    }
    result.miss = exponents_pass && any_miss && !any_fail;
  }
  return result;
}

std::string verdict_word(const CompareResult& result) {
  return result.pass ? "PASS" : result.miss ? "MISS" : "FAIL";
}

std::string verdict_summary(const CompareResult& result) {
  std::string text = verdict_word(result);
  if (result.pass) return text;
  std::string details;
  char item[240];
  for (const auto& v : result.observables)
    if (!v.pass) {
      std::snprintf(item, sizeof item, "%s exponent %+.3f off (%+.1f sigma)", v.name.c_str(),
                    v.alpha_measured - v.alpha_reference, v.deviation_sigma);
      details += (details.empty() ? "" : "; ") + std::string(item);
    }
  for (const auto& a : result.amplitudes)
    if (!a.pass) {
      std::snprintf(item, sizeof item, "%s %s %+.2g %% (%+.1f sigma; continuum bound %.2g %%)", a.name.c_str(),
                    a.outcome == AmplitudeOutcome::miss ? "missed by" : "FAILED by", 100 * a.relative_difference,
                    a.deviation_sigma, 100 * a.continuum_bound);
      details += (details.empty() ? "" : "; ") + std::string(item);
    }
  if (result.miss) text += " (a measured continuum miss beyond the errors, not a bug)";
  return text + ": " + details;
}

std::vector<std::string> default_observables(const RunData& run, Reference against, std::vector<std::string>& notes) {
  std::vector<std::string> names;
  for (const auto& name : table1_observables())
    if (run.series.count(name) && (name != "u_imp" || against == Reference::paper)) names.push_back(name);
  if (against == Reference::paper) return names;
  // The flow speed: u_flow removes the thermal noise that biases u_imp's exponent toward -0.3
  // (docs/verification.md, "the u_imp deviation is a bias of the estimator"), so only u_flow is judged.
  if (run.series.count("u_flow")) names.push_back("u_flow");
  if (run.series.count("u_imp"))
    notes.push_back(std::string("u_imp is not judged against ") + to_string(against) +
                    ": its thermal noise biases the exponent (docs/verification.md); the flow speed is judged by " +
                    (run.series.count("u_flow") ? "u_flow" : "u_flow, which this run did not record"));
  return names;
}

double md_R_over_lambda(const RunData& run, double t) {
  // The MD's own shock radius (observable R, interpolated in ln t) over λ of the run's summary;
  // without a recorded R, Eq. (1) with the run's E, n and A_d.
  const auto number = [&](const char* key) {
    if (!run.summary.contains(key) || !run.summary[key].is_number())
      throw std::invalid_argument((run.directory / "summary.json").string() + ": no number '" + key + "'");
    return run.summary[key].get<double>();
  };
  const double lambda = number("lambda");
  const auto found = run.series.find("R");
  if (found == run.series.end()) {
    const theory::BlastParameters p{run.d, number("n"), number("a"), number("E"), number("A_d")};
    return theory::shock_radius(p, t) / lambda;
  }
  const BlockSeries& R = found->second;
  const auto values = R.ensemble_values();
  if (t <= R.t.front()) return values.front() / lambda;
  if (t >= R.t.back()) return values.back() / lambda;
  const auto upper = std::upper_bound(R.t.begin(), R.t.end(), t);
  const std::size_t k = static_cast<std::size_t>(upper - R.t.begin());
  const double w = std::log(t / R.t[k - 1]) / std::log(R.t[k] / R.t[k - 1]);
  return std::exp((1 - w) * std::log(values[k - 1]) + w * std::log(values[k])) / lambda;
}

namespace {
/// One observable's verdict: its running exponent at the last two times (and the window fit)
/// against the reference that config.against names, with that reference's tolerance.
ObservableVerdict judge_observable(const std::string& name, const BlockSeries& series,
                                   const theory::ScalingExponents& exact, const CompareConfig& config, double allowance,
                                   const ReferenceExponents& reference) {
  ObservableVerdict v;
  v.name = name;
  const std::string law = theory::observable_info(name).law;  // u_flow: the law of u_imp
  v.alpha_theory = theory::to_double(exact.at(law).in_time);
  v.alpha_theory_rational = theory::to_string(exact.at(law).in_time);
  v.running = running_exponents(series);
  v.alpha_measured = v.running.back().alpha;
  v.alpha_error = v.running.back().error;
  v.t_measured = v.running.back().t;
  const double t_last = series.t.back();
  v.window = fit_power_law(series, t_last * std::pow(10.0, -config.window_decades), t_last);

  double combined = v.alpha_error;
  switch (config.against) {
    case Reference::theory:
      v.alpha_reference = v.alpha_theory;
      v.tolerance = config.sigma * v.alpha_error + allowance;
      break;
    case Reference::paper: {
      const PaperValue p = paper_table1(name);
      v.alpha_reference = p.alpha;
      v.alpha_reference_error = p.error;
      combined = std::hypot(v.alpha_error, p.error);
      v.tolerance = config.sigma * combined;
      break;
    }
    case Reference::hydro:
      v.alpha_reference = reference(name, v.t_measured);
      v.tolerance = config.sigma * v.alpha_error + allowance;
      break;
  }
  const double difference = v.alpha_measured - v.alpha_reference;
  v.deviation_sigma = combined > 0 ? difference / combined : (difference == 0 ? 0.0 : INFINITY);
  v.pass = std::isfinite(v.alpha_measured) && std::abs(difference) <= v.tolerance;
  return v;
}

/// --md-run: the tracer run `tracer` against the MD run config.md_run, cut at --until alike.
TracerMdComparison tracer_against_md(const CompareConfig& config, const RunData& tracer) {
  if (!is_tracer_run(tracer))
    throw std::invalid_argument("--md-run compares a tracer run (coldblast tracer) with an MD run, but RUN_DIR = " +
                                tracer.directory.string() + " is an MD run");
  RunData md;
  try {
    md = read_run(config.md_run);
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument(std::string("--md-run: ") + e.what());
  }
  if (is_tracer_run(md))
    throw std::invalid_argument("--md-run = " + config.md_run.string() +
                                " is a tracer run; it must be an MD run (coldblast md run)");
  if (config.until > 0) truncate_run(md, config.until);
  return compare_tracer_with_md(tracer, md);
}
}  // namespace

CompareResult run_compare(const CompareConfig& config, const ReferenceExponents& reference) {
  config.validate();
  CompareResult result;
  result.run = read_run(config.run_dir);
  if (config.until > 0) truncate_run(result.run, config.until);
  result.d = result.run.d;
  result.against = config.against;
  result.sigma = config.sigma;
  result.allowance = config.effective_allowance();
  if (config.against == Reference::paper && result.d != 2)
    throw std::invalid_argument("--against paper: the paper's Table 1 is for d = 2, the run has d = " +
                                std::to_string(result.d));
  if (config.against == Reference::hydro && !reference)
    throw std::invalid_argument("--against hydro: no hydro reference exponents were supplied");

  std::vector<std::string> names = config.observables;
  if (names.empty()) names = default_observables(result.run, config.against, result.notes);
  if (names.empty())
    throw std::invalid_argument("RUN_DIR = " + config.run_dir.string() + ": blocks.csv holds none of " +
                                theory::join_names(table1_observables()));

  const theory::ScalingExponents exact = theory::scaling_exponents(result.d);
  result.pass = true;
  for (const auto& name : names) {
    const auto found = result.run.series.find(name);
    if (found == result.run.series.end())
      throw std::invalid_argument("--observables: " + name + " is not recorded in " + config.run_dir.string());
    result.until = std::max(result.until, found->second.t.back());
    ObservableVerdict v = judge_observable(name, found->second, exact, config, result.allowance, reference);
    result.pass = result.pass && v.pass;
    result.observables.push_back(std::move(v));
  }
  if (!config.md_run.empty()) result.tracer_md = tracer_against_md(config, result.run);
  return result;
}

}  // namespace coldblast::compare
