// coldblast compare: MD running exponents against theory, the paper's Table 1 or hydro, with a
// verdict (exit 0 for PASS and MISS, with a warning for MISS; 3 for FAIL), a Markdown report and figures.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <sstream>

#include "cli/commands.hpp"
#include "common/input.hpp"
#include "common/validate.hpp"
#include "compare/report.hpp"
#include "compare/verdict.hpp"
#include "hydro/equation_of_state.hpp"
#include "hydro/options.hpp"

namespace coldblast::cli {

namespace {

struct CompareOptions {
  std::string run_dir;
  std::string against = "theory";
  std::string observables;
  std::string out;
  bool no_report = false;
  bool no_figures = false;
  Format format = Format::table;
  compare::CompareConfig config;
  std::string hydro_eos, hydro_transport, hydro_viscosity;
  std::string hydro_config;  // --hydro-config FILE: its [hydro] table (flags win)
  double hydro_phi = 0;
  CLI::Option* hydro_phi_option = nullptr;
  double allowance = 0;
  CLI::Option* allowance_option = nullptr;
};

std::vector<std::string> split_list(const std::string& text) {
  std::vector<std::string> items;
  for (std::string& item : common::split_fields(text))
    if (!item.empty()) items.push_back(std::move(item));
  return items;
}

/// One exponent row of the table.
void print_exponent_row(const compare::ObservableVerdict& v) {
  char reference[64], measured[64], window[64];
  std::snprintf(reference, sizeof reference, v.alpha_reference_error > 0 ? "%.4f±%.3f" : "%.4f", v.alpha_reference,
                v.alpha_reference_error);
  // An exponent (or its jackknife error) is undefined when the observable's ensemble mean, or a
  // delete-one-block mean, is <= 0 at one of its times (u_flow: the thermal-noise correction
  // exceeds the signal); say so instead of printing nan.
  if (std::isfinite(v.alpha_measured) && std::isfinite(v.alpha_error))
    std::snprintf(measured, sizeof measured, "%.4f±%.4f @%g", v.alpha_measured, v.alpha_error, v.t_measured);
  else
    std::snprintf(measured, sizeof measured, "undefined @%g", v.t_measured);
  if (v.window.points < 2)
    std::snprintf(window, sizeof window, "none (%d time)", v.window.points);
  else if (std::isfinite(v.window.exponent) && std::isfinite(v.window.exponent_error))
    std::snprintf(window, sizeof window, "%.4f±%.4f", v.window.exponent, v.window.exponent_error);
  else
    std::snprintf(window, sizeof window, "undefined");
  char deviation[32];
  if (std::isfinite(v.deviation_sigma))
    std::snprintf(deviation, sizeof deviation, "%+8.2f", v.deviation_sigma);
  else
    std::snprintf(deviation, sizeof deviation, "%8s", "-");
  std::printf("%-7s %-10s %-17s %-24s %-19s %s %6.3f  %s\n", v.name.c_str(), v.alpha_theory_rational.c_str(), reference,
              measured, window, deviation, v.allowance, compare::to_string(v.outcome).c_str());
}

/// The amplitudes of --against hydro (or why there are none).
void print_amplitudes(const compare::CompareResult& result) {
  if (result.against == compare::Reference::hydro && result.continuum && result.amplitudes.empty())
    std::printf("\namplitudes: none (they need n0, T0 and R in blocks.csv, or profiles.csv; this %s run has none)\n",
                compare::run_label(result.run).c_str());
  if (result.against == compare::Reference::hydro && result.continuum && !result.amplitudes.empty()) {
    std::printf("\namplitudes at t = %g (R/lambda = %.2f) against %s:\n", result.amplitudes[0].t,
                result.continuum->R_over_lambda_last, result.continuum->model.describe().c_str());
    std::printf("%-16s %-20s %-20s %9s %8s %7s  %s\n", "quantity", "MD", "NS", "MD/NS-1", "dev/sig", "bound",
                "verdict");
    // "value±error" to the error's second digit, padded to 20 columns (± is two bytes in UTF-8).
    const auto cell = [](double value, double error) {
      std::string text = common::format_measurement(value, error);
      text.erase(std::remove(text.begin(), text.end(), ' '), text.end());
      return text + std::string(text.size() < 21 ? 21 - text.size() : 0, ' ');  // 20 visible columns
    };
    for (const auto& a : result.amplitudes) {
      std::printf("%-16s %s %s %+8.2f%% %+8.2f %6.2g%%  %s\n", a.name.c_str(), cell(a.measured, a.error).c_str(),
                  cell(a.reference, a.reference_error).c_str(), 100 * a.relative_difference, a.deviation_sigma,
                  100 * a.continuum_bound, compare::to_string(a.outcome).c_str());
    }
    std::printf(
        "(sigma combines the MD error and the NS value's numerical error; a miss is beyond k sigma but within\n"
        " the bound, the first order NS drops: Kn^2 in the core, lambda/R at the shock; docs/compare.md)\n");
  }
}

/// A tracer run against its MD run at their last common time.
void print_tracer_md(const compare::TracerMdComparison& c) {
  std::printf("\ntracer%s%s against the MD run %s%s (tracer/MD - 1, combined jackknife error):\n",
              c.background.empty() ? "" : (" " + c.background).c_str(),
              c.tracer_from_md_states
                  ? (" (started from its impurities at t = " + common::format_number(c.start_time) + ")").c_str()
                  : "",
              c.md_directory.string().c_str(), c.md_recollisions_off ? ", recollisions switched off" : "");
  for (const auto& s : c.series) {
    const compare::TracerMdPoint& p = s.points.back();
    std::printf("  %-6s t = %-9g tracer %s, MD %s: %s%s\n", s.observable.c_str(), p.t,
                common::format_measurement(p.tracer, p.tracer_error).c_str(),
                common::format_measurement(p.md, p.md_error).c_str(), p.ratio >= 0 ? "+" : "",
                common::format_measurement(p.ratio, p.ratio_error).c_str());
  }
  if (c.distribution)
    std::printf("  p_imp  t = %-9g <r^4>/<r^2>^2 tracer %s, MD %s, Gaussian %.4f; chi2/dof %.3g\n", c.distribution->t,
                common::format_measurement(c.distribution->ratio_tracer, c.distribution->ratio_tracer_error).c_str(),
                common::format_measurement(c.distribution->ratio_md, c.distribution->ratio_md_error).c_str(),
                c.distribution->ratio_gaussian, c.distribution->chi2_per_dof);
}

void print_table(const compare::CompareResult& result) {
  std::printf(
      "%s (d = %d) against %s: errors by delete-one-block jackknife; pass within %g sigma%s, miss within that + the "
      "row's allowance, else FAIL\nallowance: %s\n\n",
      compare::run_label(result.run).c_str(), result.d, compare::to_string(result.against).c_str(), result.sigma,
      result.against == compare::Reference::paper ? " (combined with the paper's error)" : "",
      result.allowance_rule.c_str());
  std::printf("%-7s %-10s %-17s %-24s %-19s %8s %6s  %s\n", "obs", "alpha_T", "reference", "alpha_S(last two t)",
              "window fit", "dev/sig", "allow", "verdict");
  for (const auto& v : result.observables) print_exponent_row(v);
  for (const auto& note : result.notes) std::printf("note: %s\n", note.c_str());
  print_amplitudes(result);
  if (result.tracer_md) print_tracer_md(*result.tracer_md);
  std::printf("\nverdict: %s\n", compare::verdict_summary(result).c_str());
}

/// The Navier-Stokes model of --against hydro: --hydro-config's [hydro] keys, then the flags (which
/// win, and take over the name in messages).
compare::HydroModelOptions hydro_model(const CompareOptions& options) {
  compare::HydroModelOptions model;
  if (!options.hydro_config.empty()) {
    // The [hydro] keys first; a flag given as well replaces its key (and its name in messages).
    const hydro::HydroModelKeys keys = hydro::read_hydro_model_keys(
        common::read_text(options.hydro_config, "--hydro-config", common::text_size_limit), options.hydro_config);
    if (keys.start || keys.r0)
      throw std::invalid_argument("hydro.start and hydro.r0 in " + options.hydro_config +
                                  " are not used by compare --against hydro, whose Navier-Stokes solve starts as "
                                  "the MD run did (its scene's [start]: a hot spot or the self-similar start; "
                                  "docs/compare.md, \"Which start\")");
    if (keys.eos) model.eos = hydro::eos_from_string(*keys.eos, model.eos_name = "hydro.eos");
    if (keys.phi) model.phi = *keys.phi, model.phi_name = "hydro.phi";
    if (keys.transport)
      model.transport = hydro::transport_from_string(*keys.transport, model.transport_name = "hydro.transport");
    if (keys.viscosity) model.viscosity = *keys.viscosity, model.viscosity_name = "hydro.viscosity";
  }
  if (!options.hydro_eos.empty()) model.eos = hydro::eos_from_string(options.hydro_eos, model.eos_name = "--hydro-eos");
  if (!options.hydro_transport.empty())
    model.transport = hydro::transport_from_string(options.hydro_transport, model.transport_name = "--hydro-transport");
  if (options.hydro_phi_option->count() > 0) model.phi = options.hydro_phi, model.phi_name = "--hydro-phi";
  if (!options.hydro_viscosity.empty()) {
    if (options.hydro_viscosity != "on" && options.hydro_viscosity != "off")
      throw std::invalid_argument("--hydro-viscosity = " + options.hydro_viscosity + " is not one of on, off");
    model.viscosity = options.hydro_viscosity == "on";
    model.viscosity_name = "--hydro-viscosity";
  }
  return model;
}

void run(CompareOptions& options) {
  options.config.run_dir = options.run_dir;
  options.config.against = compare::parse_reference(options.against);
  // The report goes beside the run unless --out says where (or --no-report that it is not wanted).
  if (options.out.empty() && !options.no_report && std::filesystem::is_directory(options.run_dir))
    options.out = compare::default_report_folder(options.run_dir, options.config.against).string();
  if (!options.out.empty()) compare::report_folder(options.out);  // before the work, not after
  options.config.continuum_for_figures = !options.out.empty() && !options.no_figures;
  options.config.observables = split_list(options.observables);
  if (options.config.observables.empty() && !options.observables.empty())
    throw std::invalid_argument("--observables = '" + options.observables + "' names no observable");
  if (options.allowance_option->count() > 0) options.config.allowance = options.allowance;
  options.config.hydro_model = hydro_model(options);
  // The continuum's solves (--against hydro) take seconds, minutes with --hydro-cells in the
  // thousands: a line when a solve starts, then per decade of R/λ or every 2 s.
  ProgressPacer pacer;
  std::string solving;
  compare::CompareProgress progress;
  progress.continuum = [&](const std::string& solve, double R_over_lambda) {
    if (!pacer.due_at(R_over_lambda, solve != solving)) return;
    solving = solve;
    std::cerr << "compare: Navier-Stokes " << solve << ": R/lambda = " << common::format_significant(R_over_lambda, 4)
              << '\n';
  };
  const compare::CompareResult result = compare::run_compare(options.config, progress);
  if (!options.out.empty()) {
    const auto files = compare::write_report(result, {options.out, !options.no_figures});
    std::cerr << "compare: wrote " << files.size() << " files to " << options.out << '\n';
  }
  for (const auto& warning : result.warnings) std::cerr << "compare: warning: " << warning << '\n';
  if (options.format == Format::json)
    print_json(compare::verdict_json(result));
  else
    print_table(result);
  // A miss is a measured deviation within its stated allowance, not a failure: exit 0, said on stderr.
  if (result.miss)
    std::cerr << "compare: warning: verdict MISS (exit 0; only FAIL exits 3): "
              << compare::verdict_reasons(result).size() << " verdict(s) beyond the errors, within their allowance\n";
  if (!result.pass && !result.miss) throw ExitStatus{3};
}

}  // namespace

void add_compare_command(CLI::App& app) {
  auto options = std::make_shared<CompareOptions>();
  CLI::App* command = app.add_subcommand(
      "compare",
      "Check an MD (or tracer) run's exponents against theory, the paper's Table 1 or hydro; exit 0 PASS or MISS, 3 "
      "FAIL");
  command
      ->add_option("RUN_DIR", options->run_dir,
                   "Output directory of `coldblast md run` or `coldblast tracer` (blocks.csv, summary.json)")
      ->required();
  command->add_option("--against", options->against, "Reference: theory (exact rationals), paper (Table 1) or hydro")
      ->capture_default_str();
  command
      ->add_option("--sigma", options->config.sigma,
                   "k: pass when |alpha_S - alpha_ref| <= k*error, miss within k*error + allowance; (0, 10]")
      ->capture_default_str();
  options->allowance_option =
      command->add_option("--allowance", options->allowance,
                          "Finite-R/lambda allowance on |alpha_S - alpha_ref| for theory/hydro, [0, 1], separating "
                          "miss from FAIL; default: each exponent's own, derived from the Navier-Stokes blast at "
                          "the run's R/lambda (docs/compare.md); the paper comparison has none");
  command
      ->add_option("--window-decades", options->config.window_decades,
                   "Window fit over the last W decades of recorded time, (0, 6]")
      ->capture_default_str();
  command->add_option("--until", options->config.until,
                      "Measure as of time T: ignore recorded times after T (default: all); "
                      "T in [second, last recorded time]");
  command->add_option("--observables", options->observables,
                      "Comma-separated subset of R_imp,C_imp,V_imp,u_imp,T0,n0 (default: all recorded)");
  command
      ->add_option("--hydro-cells", options->config.hydro_cells,
                   "Navier–Stokes cells for --against hydro, [16, 100000]")
      ->capture_default_str();
  command->add_option("--hydro-config", options->hydro_config,
                      "TOML file whose [hydro] table sets eos, phi, transport, viscosity of --against hydro (a scene "
                      "file may carry it; --hydro-eos/--hydro-phi/--hydro-transport/--hydro-viscosity win; "
                      "docs/hydro.md)");
  command->add_option("--hydro-eos", options->hydro_eos,
                      "NS equation of state for --against hydro: ideal, henderson (2D), carnahan-starling (3D); "
                      "default: the run's hard-particle EOS");
  options->hydro_phi_option =
      command->add_option("--hydro-phi", options->hydro_phi,
                          "NS ambient packing fraction (hard-particle EOS only); default: the run's phi");
  command->add_option("--hydro-transport", options->hydro_transport,
                      "NS transport: enskog (dense, needs a hard-particle EOS) or dilute; default enskog");
  command->add_option("--hydro-viscosity", options->hydro_viscosity,
                      "NS shear (and Enskog bulk) viscosity for --against hydro: on or off; default off, the "
                      "paper's conduction-only core (Eq. 15; docs/verification.md, \"Viscosity in the comparison\")");
  CLI::Option* out_option = command->add_option("--out", options->out,
                                                "Report directory (report.md, verdict.json, exponents.csv, figures/ as "
                                                "PNG and PDF); default: RUN_DIR/compare-AGAINST");
  command->add_flag("--no-report", options->no_report, "Write no report: the summary on stdout only")
      ->excludes(out_option);
  command->add_option("--md-run", options->config.md_run,
                      "MD run of the same scene for a tracer RUN_DIR: tracer against MD at every common time "
                      "(figures tracer_vs_md.png, tracer_p_imp.png; tracer_vs_md.csv)");
  command->add_flag("--no-figures", options->no_figures, "Do not run gnuplot");
  add_format_option(*command, options->format);
  command->callback([options] { run(*options); });
}

}  // namespace coldblast::cli
