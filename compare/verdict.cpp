#include "compare/verdict.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <optional>
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
    const std::string& option = hydro_model.eos         ? hydro_model.eos_name
                                : hydro_model.phi       ? hydro_model.phi_name
                                : hydro_model.transport ? hydro_model.transport_name
                                                        : hydro_model.viscosity_name;
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

namespace {

/// The continuum for the profile figure of a comparison whose verdicts need none: solved with the
/// comparison's model when the run has profiles.csv and λ; a run it cannot be solved for gets a
/// warning instead of curves.
void add_figure_continuum(CompareResult& result, const CompareConfig& config, const CompareProgress& progress) {
  const RunData& run = result.run;
  if (!std::filesystem::exists(run.directory / "profiles.csv") || !run.summary.contains("lambda")) return;
  try {
    const HydroModel model =
        with_run_start(resolve_hydro_model(config.hydro_model, run.d, run_packing_fraction(run)), run);
    result.continuum = solve_continuum(run, model, config.hydro_cells, 0.0, progress.continuum);
  } catch (const std::invalid_argument& e) {
    result.warnings.push_back(std::string("no continuum curves in the profile figure: ") + e.what());
  }
}

}  // namespace

CompareResult run_compare(const CompareConfig& config, const CompareProgress& progress) {
  config.validate();
  if (config.against == Reference::paper || (config.against == Reference::theory && config.allowance)) {
    CompareResult result = run_compare(config, ReferenceExponents{});
    if (config.continuum_for_figures) add_figure_continuum(result, config, progress);
    return result;
  }
  // The Navier–Stokes blast at the MD's own R/λ (no fitted parameter), solved once: the hydro
  // reference, or (theory) where the finite-R/λ allowances come from.
  RunData run = read_run(config.run_dir);
  if (config.until > 0) truncate_run(run, config.until);
  const HydroModel model =
      with_run_start(resolve_hydro_model(config.hydro_model, run.d, run_packing_fraction(run)), run);
  if (config.against == Reference::hydro)
    return run_compare(config, solve_continuum(run, model, config.hydro_cells, 0.0, progress.continuum, true));
  std::shared_ptr<const ContinuumReference> continuum;
  try {
    continuum = solve_continuum(run, model, config.hydro_cells, 0.0, progress.continuum);
  } catch (const std::invalid_argument& e) {
    // No continuum for this run (no λ in summary.json, or R/λ at or below the NS start): nothing to
    // derive an allowance from, so none, and the rule says why.
    CompareResult result = run_compare(config, ReferenceExponents{});
    result.allowance_rule =
        std::string("none (no continuum to derive one from: ") + e.what() + "; --allowance X sets one)";
    return result;
  }
  return run_compare(config, std::move(continuum));
}

std::string verdict_word(const CompareResult& result) {
  return result.pass ? "PASS" : result.miss ? "MISS" : "FAIL";
}

namespace {
/// Why one exponent row is not a pass, in one line.
std::string exponent_reason(const ObservableVerdict& v, double k) {
  char text[400];
  if (!std::isfinite(v.alpha_measured) || !std::isfinite(v.alpha_error)) {
    std::snprintf(text, sizeof text,
                  "%s exponent FAIL: undefined (an ensemble or delete-one-block mean <= 0 at one of its last two "
                  "times), nothing to judge",
                  v.name.c_str());
    return text;
  }
  std::snprintf(text, sizeof text, "%s exponent %s: %.4f +- %.4f against %.4f, %+.4f (%+.1f sigma), beyond %s sigma",
                v.name.c_str(), to_string(v.outcome).c_str(), v.alpha_measured, v.alpha_error, v.alpha_reference,
                v.alpha_measured - v.alpha_reference, v.deviation_sigma, common::format_number(k).c_str());
  const std::string allowance = common::format_significant(v.allowance, 2) + " (" + v.allowance_origin + ")";
  if (v.outcome == Outcome::miss) return text + (", within the allowance " + allowance);
  return text + (v.allowance > 0 ? " + the allowance " + allowance : " (allowance " + v.allowance_origin + ")");
}
}  // namespace

std::vector<std::string> verdict_reasons(const CompareResult& result) {
  std::vector<std::string> reasons;
  for (const auto& v : result.observables)
    if (!v.pass) reasons.push_back(exponent_reason(v, result.sigma));
  char item[300];
  for (const auto& a : result.amplitudes)
    if (!a.pass) {
      std::snprintf(item, sizeof item, "%s amplitude %s: %+.2g %% (%+.1f sigma), %s the continuum bound %.2g %%",
                    a.name.c_str(), to_string(a.outcome).c_str(), 100 * a.relative_difference, a.deviation_sigma,
                    a.outcome == Outcome::miss ? "beyond the errors, within" : "beyond", 100 * a.continuum_bound);
      reasons.emplace_back(item);
    }
  return reasons;
}

std::string verdict_summary(const CompareResult& result) {
  std::string text = verdict_word(result);
  if (result.pass) return text;
  if (result.miss) text += " (measured deviations beyond the errors, within the stated allowances; not a bug)";
  std::string details;
  for (const auto& reason : verdict_reasons(result)) details += (details.empty() ? "" : "; ") + reason;
  return text + ": " + details;
}

std::vector<std::string> default_observables(const RunData& run, Reference against, std::vector<std::string>& notes) {
  // Table 1's rows in its column order, then (not against the paper, which has only those) the other
  // judged observables in catalogue order: u_flow.
  std::vector<std::string> names;
  for (const auto& name : table1_observables())
    if (run.series.count(name) &&
        (against == Reference::paper || !theory::is_paper_only(theory::observable_info(name))))
      names.push_back(name);
  if (against == Reference::paper) return names;
  for (const theory::ObservableInfo& o : theory::observable_catalogue())
    if (o.verdict && o.table1_row < 0 && run.series.count(o.name)) names.push_back(o.name);
  for (const theory::ObservableInfo& o : theory::observable_catalogue())
    if (theory::is_paper_only(o) && run.series.count(o.name)) {
      const std::string instead = o.judged_instead;
      notes.push_back(std::string(o.name) + " is not judged against " + to_string(against) + ": " + o.paper_only_note +
                      " " + (run.series.count(instead) ? instead : instead + ", which this run did not record"));
    }
  return names;
}

namespace {

/// The finite-R/λ allowance of one row: (observable, its exact exponent, the time it is measured at).
using AllowanceRule = std::function<ExponentAllowance(const std::string&, double, double)>;

/// One observable's verdict: its running exponent at the last two times (and the window fit)
/// against the reference that config.against names, with the allowance `rule` gives.
ObservableVerdict judge_observable(const std::string& name, const BlockSeries& series,
                                   const theory::ScalingExponents& exact, const CompareConfig& config,
                                   const ReferenceExponents& reference, const AllowanceRule& rule) {
  ObservableVerdict v;
  v.name = name;
  const theory::Exponent law = theory::observable_exponent(theory::observable_info(name), exact.d);  // u_flow: u_imp's
  v.alpha_theory = theory::to_double(law.in_time);
  v.alpha_theory_rational = theory::to_string(law.in_time);
  v.running = running_exponents(series);
  v.alpha_measured = v.running.back().alpha;
  v.alpha_error = v.running.back().error;
  v.t_measured = v.running.back().t;
  const double t_last = series.t.back(), t_first = t_last * std::pow(10.0, -config.window_decades);
  v.window.points = recorded_times_in(series, t_first, t_last);
  if (v.window.points >= 2) {
    v.window = fit_power_law(series, t_first, t_last);
  } else {  // no fit: CompareResult::warnings says so
    v.window.exponent = v.window.exponent_error = NAN;
    v.window.t_first = t_first;
    v.window.t_last = t_last;
  }

  double combined = v.alpha_error;
  switch (config.against) {
    case Reference::theory:
      v.alpha_reference = v.alpha_theory;
      break;
    case Reference::paper: {
      const PaperValue p = paper_table1(name);
      v.alpha_reference = p.alpha;
      v.alpha_reference_error = p.error;
      combined = std::hypot(v.alpha_error, p.error);
      break;
    }
    case Reference::hydro:
      v.alpha_reference = reference(name, v.t_measured);
      break;
  }
  if (config.against == Reference::paper) {
    v.allowance_origin = "none: the paper comparison is k sigma of both errors combined";
  } else if (config.allowance) {
    v.allowance = *config.allowance;
    v.allowance_origin = "given by --allowance";
  } else if (rule) {
    const ExponentAllowance a = rule(name, v.alpha_theory, v.t_measured);
    v.allowance = a.value;
    v.allowance_origin = a.origin;
  } else {
    v.allowance_origin = "none: no continuum";
  }
  v.tolerance = config.sigma * combined;
  const double difference = v.alpha_measured - v.alpha_reference;
  v.deviation_sigma = combined > 0 ? difference / combined : (difference == 0 ? 0.0 : INFINITY);
  v.outcome = exponent_outcome(v.alpha_measured, v.alpha_reference, combined, config.sigma, v.allowance);
  v.pass = v.outcome == Outcome::pass;
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

/// The run's R/λ at time t when it can be known (summary.json's λ), else none.
std::optional<double> known_R_over_lambda(const RunData& run, double t) {
  if (!run.summary.contains("lambda")) return std::nullopt;
  try {
    return md_R_over_lambda(run, t);
  } catch (const std::invalid_argument&) {
    return std::nullopt;
  }
}

/// CompareResult::warnings: what makes these verdicts less than they look.
std::vector<std::string> verdict_warnings(const CompareResult& result, const CompareConfig& config) {
  std::vector<std::string> warnings;
  int blocks = std::numeric_limits<int>::max();
  std::string short_windows;
  for (const auto& v : result.observables) {
    blocks = std::min(blocks, nonempty_blocks(result.run.series.at(v.name)));
    if (v.window.points < 2) short_windows += (short_windows.empty() ? "" : ", ") + v.name;
  }
  char text[600];
  if (blocks < 8) {
    // The jackknife variance from B blocks has about B - 1 degrees of freedom: its square root, the
    // error bar, is uncertain by about 1/sqrt(2 (B - 1)).
    std::snprintf(text, sizeof text,
                  "only %d jackknife blocks (fewer than 8): each error bar is itself uncertain by about "
                  "1/sqrt(2(B-1)) = %.0f %%, so a k sigma verdict is that loose (more realizations, or a "
                  "smaller block_size, give more blocks)",
                  blocks, 100 / std::sqrt(2.0 * std::max(1, blocks - 1)));
    warnings.emplace_back(text);
  }
  if (const auto x = known_R_over_lambda(result.run, result.until); x && *x < 10) {
    std::snprintf(text, sizeof text,
                  "R/lambda = %.3g at the last time t = %s (below 10): the blast is not yet self-similar, so "
                  "the exponents judged are a transient's (docs/compare.md)",
                  *x, common::format_significant(result.until, 6).c_str());
    warnings.emplace_back(text);
  }
  if (!short_windows.empty())
    warnings.push_back("the window fit (--window-decades " + common::format_number(config.window_decades) +
                       ") holds fewer than two recorded times of " + short_windows +
                       ": no window fit (widen --window-decades)");
  return warnings;
}

/// Judges every requested observable of the run against the reference, each with `rule`'s allowance
/// (empty: config.allowance, or 0), and collects the warnings.
CompareResult judge_run(const CompareConfig& config, const ReferenceExponents& reference, const AllowanceRule& rule) {
  config.validate();
  CompareResult result;
  result.run = read_run(config.run_dir);
  if (config.until > 0) truncate_run(result.run, config.until);
  result.d = result.run.d;
  result.against = config.against;
  result.sigma = config.sigma;
  result.allowance = config.allowance;
  if (config.against == Reference::paper && result.d != 2)
    throw std::invalid_argument("--against paper: the paper's Table 1 is for d = 2, the run has d = " +
                                std::to_string(result.d));
  if (config.against == Reference::hydro && !reference)
    throw std::invalid_argument("--against hydro: no hydro reference exponents were supplied");
  result.allowance_rule = config.against == Reference::paper ? "none (the paper's Table 1: a pure k sigma test)"
                          : config.allowance ? "--allowance " + common::format_number(*config.allowance) + " (given)"
                                             : "none (no continuum was solved)";

  std::vector<std::string> names = config.observables;
  if (names.empty()) names = default_observables(result.run, config.against, result.notes);
  if (names.empty())
    throw std::invalid_argument("RUN_DIR = " + config.run_dir.string() + ": blocks.csv holds none of " +
                                theory::join_names(table1_observables()));

  const theory::ScalingExponents exact = theory::scaling_exponents(result.d);
  result.pass = true;
  bool any_fail = false;
  for (const auto& name : names) {
    const auto found = result.run.series.find(name);
    if (found == result.run.series.end())
      throw std::invalid_argument("--observables: " + name + " is not recorded in " + config.run_dir.string());
    result.until = std::max(result.until, found->second.t.back());
    ObservableVerdict v = judge_observable(name, found->second, exact, config, reference, rule);
    result.pass = result.pass && v.pass;
    any_fail = any_fail || v.outcome == Outcome::fail;
    result.observables.push_back(std::move(v));
  }
  result.miss = !result.pass && !any_fail;
  result.warnings = verdict_warnings(result, config);
  if (!config.md_run.empty()) result.tracer_md = tracer_against_md(config, result.run);
  return result;
}

}  // namespace

Outcome exponent_outcome(double alpha_measured, double alpha_reference, double error, double k, double allowance) {
  const double difference = std::abs(alpha_measured - alpha_reference);
  if (!std::isfinite(alpha_measured) || !std::isfinite(error)) return Outcome::fail;
  if (difference <= k * error) return Outcome::pass;
  if (difference <= k * error + allowance) return Outcome::miss;
  return Outcome::fail;
}

ExponentAllowance derived_allowance(Reference against, const std::string& observable, double alpha_theory,
                                    double R_over_lambda, const ContinuumReference& continuum,
                                    const HydroReference& ns) {
  if (against == Reference::paper)
    throw std::invalid_argument("--against paper: the paper comparison has no finite-R/lambda allowance");
  // The first order NS drops changes an amplitude by a relative O(Kn²) (the amplitudes' bound,
  // coefficient 1); in a running exponent d ln A/d ln t that is d(Kn²)/d ln t = -2 Kn² (α_n0 + α_H),
  // since Kn ∝ 1/(n0 H). Kn and the exponents are the NS core's at the run's last time.
  const double x_last = continuum.R_over_lambda_last;
  const double Kn = core_knudsen(continuum);
  const double rate =
      std::isfinite(Kn) ? 2 * Kn * Kn * std::abs(ns.exponent("n0", x_last) + ns.exponent("H", x_last)) : 0.0;
  char text[240];
  if (against == Reference::hydro) {
    std::snprintf(text, sizeof text, "Kn^2 rate %.3f, Kn = %.3f", rate, Kn);
    return {rate, text};
  }
  const double offset = std::abs(ns.exponent(observable, R_over_lambda) - alpha_theory);
  std::snprintf(text, sizeof text, "NS offset %.3f at R/lambda = %.3g + Kn^2 rate %.3f, Kn = %.3f", offset,
                R_over_lambda, rate, Kn);
  return {offset + rate, text};
}

CompareResult run_compare(const CompareConfig& config, std::shared_ptr<const ContinuumReference> continuum) {
  if (!continuum) throw std::invalid_argument("--against hydro: no continuum reference was supplied");
  if (config.against == Reference::paper)
    throw std::invalid_argument("--against paper: the paper's Table 1 needs no continuum");
  const HydroReference hydro(continuum->ns);
  RunData run = read_run(config.run_dir);
  if (config.until > 0) truncate_run(run, config.until);
  const ReferenceExponents reference = [&](const std::string& observable, double t) {
    return hydro.exponent(observable, md_R_over_lambda(run, t));
  };
  const AllowanceRule rule = [&](const std::string& observable, double alpha_theory, double t) {
    return derived_allowance(config.against, observable, alpha_theory, md_R_over_lambda(run, t), *continuum, hydro);
  };
  CompareResult result = judge_run(config, config.against == Reference::hydro ? reference : ReferenceExponents{}, rule);
  result.continuum = std::move(continuum);
  if (!config.allowance) {
    char text[400];
    std::snprintf(
        text, sizeof text,
        "derived from %s at the run's R/lambda (docs/compare.md, \"Where the allowance comes from\"): %s"
        "2 Kn^2 |alpha_n0 + alpha_H|, the rate at which the first order NS drops (Kn^2 of its core, Kn = %.3f "
        "at R/lambda = %.3g) moves a running exponent",
        result.continuum->model.describe().c_str(),
        config.against == Reference::theory ? "|alpha_NS - alpha_T| at the measured time + " : "",
        core_knudsen(*result.continuum), result.continuum->R_over_lambda_last);
    result.allowance_rule = text;
  }
  if (config.against == Reference::hydro) {
    result.amplitudes = amplitude_verdicts(result.run, *result.continuum, config.sigma);
    result.amplitude_history = amplitude_history(result.run, *result.continuum, config.sigma);
    bool any_fail = false;
    for (const auto& v : result.observables) any_fail = any_fail || v.outcome == Outcome::fail;
    for (const auto& a : result.amplitudes) {
      result.pass = result.pass && a.pass;
      any_fail = any_fail || a.outcome == Outcome::fail;
    }
    result.miss = !result.pass && !any_fail;
  }
  return result;
}

CompareResult run_compare(const CompareConfig& config, const ReferenceExponents& reference) {
  return judge_run(config, reference, {});
}

}  // namespace coldblast::compare
