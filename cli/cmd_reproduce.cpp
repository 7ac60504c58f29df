// coldblast reproduce: A_2 and A_3, the Navier–Stokes core run, an MD ensemble of the paper's 2D
// scene, the kinetic tracer of the impurity, and comparisons against theory, the paper's Table 1,
// hydro and (the tracer) the MD, with reports.
#include <cmath>
#include <cstdio>
#include <iostream>

#include "cli/commands.hpp"
#include "common/interrupt.hpp"
#include "common/validate.hpp"
#include "compare/reproduce.hpp"
#include "compare/reproduce_report.hpp"
#include "hydro/blast_measurements.hpp"

namespace coldblast::cli {

namespace {

struct ReproduceOptions {
  std::string scale = "quick";
  bool no_figures = false;
  Format format = Format::table;
  compare::ReproduceConfig config;
};

void print_verdict(const char* name, const compare::CompareResult& result) {
  std::printf("\nagainst %-6s: %s\n", name, compare::verdict_word(result).c_str());
  // Why each row that is not a pass is not, one line each; then the rule behind the words, as `compare` prints it.
  for (const auto& reason : compare::verdict_reasons(result)) std::printf("  - %s\n", reason.c_str());
  for (const auto& warning : result.warnings) std::printf("  warning: %s\n", warning.c_str());
  std::printf("  (exponents pass within %g sigma%s, miss within that + the row's allowance; allowance: %s)\n",
              result.sigma, result.against == compare::Reference::paper ? " of MD and paper errors combined" : "",
              result.allowance_rule.c_str());
  for (const auto& v : result.observables) {
    char measured[80];  // an undefined exponent (a mean <= 0) is named, not printed as nan
    if (std::isfinite(v.alpha_measured) && std::isfinite(v.alpha_error))
      std::snprintf(measured, sizeof measured, "%8.4f ± %.4f  (%+.1f sigma", v.alpha_measured, v.alpha_error,
                    v.deviation_sigma);
    else
      std::snprintf(measured, sizeof measured, "undefined  (-");
    std::printf("  %-6s alpha_T = %-9s ref = %8.4f  alpha_S = %s, allowance %.3f)  %s\n", v.name.c_str(),
                v.alpha_theory_rational.c_str(), v.alpha_reference, measured, v.allowance,
                compare::to_string(v.outcome).c_str());
  }
  for (const auto& a : result.amplitudes)
    std::printf("  %-9s MD = %s  NS = %s  (%+.1f %%, %+.1f sigma, bound %.2g %%)  %s\n", a.name.c_str(),
                common::format_measurement(a.measured, a.error).c_str(),
                common::format_measurement(a.reference, a.reference_error).c_str(), 100 * a.relative_difference,
                a.deviation_sigma, 100 * a.continuum_bound, compare::to_string(a.outcome).c_str());
}

void print_tracer(const compare::ReproduceResult& r) {
  std::printf(
      "\ntracer (paper Eq. 36) in the %s Navier–Stokes background: %lld trajectories in %.1f s, nothing fitted\n",
      r.tracer["transport"].get<std::string>() == "enskog" ? "dense" : "dilute",
      r.tracer["trajectories"].get<long long>(), r.tracer["wall_seconds"].get<double>());
  if (!r.tracer_vs_md.tracer_md) return;
  for (const auto& s : r.tracer_vs_md.tracer_md->series) {
    const compare::TracerMdPoint& p = s.points.back();
    std::printf("  %-6s t = %-6g tracer = %s  MD = %s  (tracer/MD - 1 = %s)\n", s.observable.c_str(), p.t,
                common::format_measurement(p.tracer, p.tracer_error).c_str(),
                common::format_measurement(p.md, p.md_error).c_str(), compare::format_ratio_percent(p).c_str());
  }
  if (const auto& h = r.tracer_vs_md.tracer_md->distribution)
    std::printf("  p_imp  t = %-6g <r^4>/<r^2>^2: tracer = %s  MD = %s  (Gaussian %.4g)\n", h->t,
                common::format_measurement(h->ratio_tracer, h->ratio_tracer_error).c_str(),
                common::format_measurement(h->ratio_md, h->ratio_md_error).c_str(), h->ratio_gaussian);
}

void run(ReproduceOptions& options) {
  options.config.scale = compare::parse_scale(options.scale);
  options.config.figures = !options.no_figures;
  const compare::ReproduceResult r = compare::run_reproduce(
      options.config, [](const std::string& line) { std::cerr << "reproduce: " << line << '\n'; });
  if (options.format == Format::json) {
    print_json(compare::reproduce_summary(r));
    return;
  }
  std::printf("A_2 = %.15g ± %.1e   A_3 = %.15g ± %.1e   A_2(phi = %.4f) = %.10g ± %.1e\n", r.A2, r.A2_error, r.A3,
              r.A3_error, r.phi_md, r.A2_md, r.A2_md_error);
  std::printf("Navier–Stokes (%s) at R/lambda = %.3g:", r.hydro["model"].get<std::string>().c_str(),
              r.hydro["R_over_lambda"].get<double>());
  for (const hydro::CoreExponent& q :
       hydro::core_exponents)  // the core's; R's is Eq. (1)'s, printed in reproduce's report
    if (q.time_exponent != &hydro::RunningExponents::R)
      std::printf("  %s %.4f (theory %s)", q.name, r.hydro["exponents"][q.name]["measured"].get<double>(),
                  r.hydro["exponents"][q.name]["theory_rational"].get<std::string>().c_str());
  std::printf("\nMD: %lld realizations, %.3g collisions in %.1f s\n", r.md["realizations"].get<long long>(),
              r.md["collisions_total"].get<double>(), r.md["wall_seconds"].get<double>());
  print_verdict("theory", r.against_theory);
  print_verdict("paper", r.against_paper);
  print_verdict("hydro", r.against_hydro);
  print_tracer(r);
  std::printf("\nreport: %s/REPORT.md\n", r.out.string().c_str());
}

}  // namespace

void add_reproduce_command(CLI::App& app) {
  auto options = std::make_shared<ReproduceOptions>();
  CLI::App* command = app.add_subcommand(
      "reproduce",
      "Reproduce the paper: A_2, A_3, the Navier–Stokes core, an MD ensemble, the kinetic tracer and the comparisons");
  command->add_option("--scale", options->scale, "quick (minutes on 2 cores) or paper (the paper's 3e4 realizations)")
      ->capture_default_str();
  command->add_option("--out", options->config.out, "Output directory")->capture_default_str();
  command->add_option("--threads", options->config.threads, "MD worker threads; 0 = all hardware threads")
      ->capture_default_str();
  command->add_option("--seed", options->config.seed, "Master seed of the MD ensemble and the tracer (>= 0)")
      ->capture_default_str();
  command
      ->add_option("--realizations", options->config.realizations,
                   "MD realizations; 0 = the scale's default (quick 384, paper 30000)")
      ->capture_default_str();
  command
      ->add_option("--hydro-until", options->config.hydro_until,
                   "Navier–Stokes run up to this R/lambda, [20, 1e8]; 0 = the scale's default (1e4, 1e6)")
      ->capture_default_str();
  command->add_option("--md-run", options->config.md_run,
                      "Use this existing `md run` directory of the paper scene instead of running the MD step. "
                      "`md run scenes/paper-2d.toml --realizations 30000 --set block_size=468 --seed 1` is the "
                      "--scale paper ensemble bit for bit, and can --resume if killed");
  command
      ->add_option("--tracer-trajectories", options->config.tracer_trajectories,
                   "Kinetic tracer trajectories (paper Eq. 36 in the dense Navier–Stokes background); 0 = the "
                   "scale's default (quick 1e5, paper 1e6)")
      ->capture_default_str();
  command->add_flag("--no-figures", options->no_figures, "Do not run gnuplot");
  add_format_option(*command, options->format);
  command->callback([options] {
    common::install_stop_handlers();  // SIGINT/SIGTERM end the MD step between realizations
    run(*options);
  });
}

}  // namespace coldblast::cli
