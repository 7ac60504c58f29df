// coldblast hydro core|euler: the radial Navier–Stokes blast of paper Sec. III, Eqs. (13)-(16)
// (hydro/navier_stokes.hpp; docs/hydro.md): running exponents of H, n0, T0 beside the theory's
// rationals, or the Euler limit (κ = μ = 0) against the exact TvNS solution (hydro/euler_check.hpp).
#include <cmath>
#include <cstdio>
#include <iostream>
#include <memory>
#include <string>

#include "cli/commands.hpp"
#include "common/input.hpp"
#include "common/output.hpp"
#include "common/validate.hpp"
#include "hydro/navier_stokes.hpp"
#include "hydro/options.hpp"
#include "theory/exponents.hpp"

namespace coldblast::cli {

namespace {

struct HydroOptions {
  int d = 2;
  double until = 0;  // 0: the mode's default
  int cells = 0;     // 0: the mode's default
  std::string viscosity = "off";
  double kappa_prefactor = -1;  // < 0: Chapman–Enskog default (only the flag's own value is range-checked)
  bool kappa_given = false;
  std::string eos = "ideal";
  double phi = 0;  // 0: the library's default for a hard-particle EOS
  std::string transport = "dilute";
  double outer_margin = 0;  // 0: the solver's default
  std::string start = "self-similar";
  double r0 = 0;
  std::string config_file;  // --config FILE: its [hydro] table's eos, phi, transport, start, r0 (flags win)
  hydro::HydroModelKeys file_keys;
  std::string out;
  Format format = Format::table;
};

std::string number(double value, int digits = 17) {
  char buffer[48];
  std::snprintf(buffer, sizeof buffer, "%.*g", digits, value);
  return buffer;
}

/// Maps flags to the library config (validation and messages in hydro/options.hpp).
hydro::NavierStokesConfig make_config(const HydroOptions& options, bool euler) {
  hydro::HydroOptions o;
  o.d = options.d;
  o.until = options.until;
  o.cells = options.cells;
  o.viscosity = options.viscosity == "on";
  if (options.kappa_given) o.kappa_prefactor = options.kappa_prefactor;
  o.eos = options.eos;
  o.phi = options.phi;
  o.transport = options.transport;
  o.outer_margin = options.outer_margin;
  o.start = options.start;
  o.r0 = options.r0;
  hydro::NavierStokesConfig config = hydro::navier_stokes_config(o, euler, options.file_keys);
  if (!euler && options.viscosity != "on" && options.viscosity != "off")
    throw std::invalid_argument("--viscosity = " + options.viscosity + " is not one of on, off");
  return config;
}

/// Progress on stderr: a line per decade of R/λ, and at the next sample once 2 s have passed
/// without one (a fine grid takes minutes per decade: the cost grows as cells²).
hydro::NavierStokesResult solve(const hydro::NavierStokesConfig& config, const char* mode) {
  ProgressPacer pacer;
  return hydro::run_navier_stokes(config, [&](const hydro::NavierStokesSample& s) {
    if (!pacer.due_at(s.R_over_lambda)) return;
    std::cerr << "hydro " << mode << ": R/lambda = " << number(s.R_over_lambda, 4) << '\n';
  });
}

std::string config_header(const hydro::NavierStokesResult& r) {
  const hydro::NavierStokesConfig& c = r.config;
  return common::provenance_header(
      {{"d", std::to_string(c.physics.d)},
       {"E", number(c.physics.E)},
       {"n_inf", number(c.physics.n_inf)},
       {"a", number(c.physics.a)},
       {"eos", hydro::to_string(c.physics.eos)},
       {"phi", number(c.physics.phi)},
       {"transport", hydro::to_string(c.physics.transport)},
       {"lambda", number(r.lambda)},
       {"kappa_prefactor", number(r.kappa_prefactor)},
       {"viscosity_prefactor", number(r.viscosity_prefactor)},
       {"until_R_over_lambda", number(c.until_R_over_lambda)},
       {"cells", std::to_string(c.numerics.cells)},
       {"start", hydro::to_string(c.physics.start)},
       {"r0_over_lambda", number(c.physics.r0_over_lambda)},
       {"start_R_over_lambda", number(*c.numerics.start_R_over_lambda)},
       {"initial_width", number(c.numerics.initial_width)},
       {"temperature_floor", number(c.numerics.temperature_floor)},
       {"relative_tolerance", number(c.numerics.relative_tolerance)},
       {"core_resolution", number(c.numerics.core_resolution.value_or(0))},
       {"shock_band_fraction", number(c.numerics.shock_band_fraction.value_or(0))},
       {"outer_margin", number(c.numerics.outer_margin)},
       {"A_reference", number(r.A_reference)},
       {"max_energy_error", number(r.max_energy_error, 3)}},
      "m = k_B = 1; lengths and times in the units of E, n_inf and a (lambda = 1/(n_inf Omega_{d-1} a^{d-1})); "
      "exponents are d ln X/d ln t (and d ln X/d ln(R/lambda) where marked _in_R)");
}

/// The physical model actually solved (phi resolved by the library); the start only when it is a hot spot.
void print_model(const hydro::NavierStokesResult& r) {
  const hydro::NavierStokesPhysics& p = r.config.physics;
  std::printf("  model: eos = %s, phi = %.6g, transport = %s", hydro::to_string(p.eos).c_str(), p.phi,
              hydro::to_string(p.transport).c_str());
  if (p.start == hydro::Start::hotspot)
    std::printf("; start = hotspot, r0/lambda = %.6g (grid from R_ref/lambda = %.4g; t counts from the deposition)",
                p.r0_over_lambda, *r.config.numerics.start_R_over_lambda);
  std::printf("\n");
}

common::Json model_json(const hydro::NavierStokesResult& r) {
  const hydro::NavierStokesPhysics& p = r.config.physics;
  common::Json model = {{"eos", hydro::to_string(p.eos)}, {"phi", p.phi}, {"transport", hydro::to_string(p.transport)}};
  if (p.start == hydro::Start::hotspot) {
    model["start"] = hydro::to_string(p.start);
    model["r0_over_lambda"] = p.r0_over_lambda;
  }
  return model;
}

void write_files(const hydro::NavierStokesResult& r, const std::string& directory) {
  if (directory.empty()) return;
  std::string series = config_header(r);
  series +=
      "t,R_over_lambda,R,H,H_density,n0,T0,p0,energy,mass,energy_error,H_prefactor,n0_prefactor,T0_prefactor,"
      "p0_scaled\n";
  for (const auto& s : r.samples)
    series += number(s.t) + "," + number(s.R_over_lambda) + "," + number(s.R) + "," + number(s.H) + "," +
              number(s.H_density) + "," + number(s.n0) + "," + number(s.T0) + "," + number(s.p0) + "," +
              number(s.energy) + "," + number(s.mass) + "," + number(s.energy_error, 3) + "," + number(s.H_prefactor) +
              "," + number(s.n0_prefactor) + "," + number(s.T0_prefactor) + "," + number(s.p0_scaled) + "\n";
  common::write_file_atomic(directory + "/samples.csv", series);
  std::string exponents = config_header(r);
  exponents += "t,R_over_lambda,R,H,H_density,n0,T0,H_in_R,H_density_in_R,n0_in_R,T0_in_R\n";
  for (const auto& e : r.exponents)
    exponents += number(e.t) + "," + number(e.R_over_lambda) + "," + number(e.R) + "," + number(e.H) + "," +
                 number(e.H_density) + "," + number(e.n0) + "," + number(e.T0) + "," + number(e.H_in_R) + "," +
                 number(e.H_density_in_R) + "," + number(e.n0_in_R) + "," + number(e.T0_in_R) + "\n";
  common::write_file_atomic(directory + "/exponents.csv", exponents);
  std::string profile_text = config_header(r);
  const auto& p = r.profiles.back();
  profile_text += "# t: " + number(p.t) + "\n# R: " + number(p.R) + "\n";
  profile_text += "r,r_over_R,density,velocity,temperature,pressure,heat_flux\n";
  for (std::size_t i = 0; i < p.r.size(); ++i)
    profile_text += number(p.r[i]) + "," + number(p.r_over_R[i]) + "," + number(p.density[i]) + "," +
                    number(p.velocity[i]) + "," + number(p.temperature[i]) + "," + number(p.pressure[i]) + "," +
                    number(p.heat_flux[i]) + "\n";
  common::write_file_atomic(directory + "/profile.csv", profile_text);
  std::cerr << "hydro: wrote samples.csv, exponents.csv, profile.csv in " << directory << '\n';
}

void run_core(const HydroOptions& options) {
  if (!options.out.empty()) common::require_output_folder(options.out, "--out");
  const hydro::NavierStokesConfig config = make_config(options, false);
  const hydro::NavierStokesResult r = solve(config, "core");
  write_files(r, options.out);
  const theory::ScalingExponents theory_exponents = theory::scaling_exponents(config.physics.d);
  const hydro::RunningExponents e = r.final_exponents();
  const hydro::NavierStokesSample& s = r.final_sample();
  struct Row {
    const char* name;
    double measured;
    theory::Rational theory;
  };
  const Row rows[] = {{"H", e.H, theory_exponents.H.in_time},
                      {"n0", e.n0, theory_exponents.n0.in_time},
                      {"T0", e.T0, theory_exponents.T0.in_time},
                      {"R", e.R, theory_exponents.R.in_time}};
  if (options.format == Format::json) {
    common::Json exponents = common::Json::object();
    for (const Row& row : rows)
      exponents[row.name] = {{"measured", row.measured},
                             {"theory", theory::to_double(row.theory)},
                             {"theory_rational", theory::to_string(row.theory)}};
    print_json({{"d", config.physics.d},
                {"R_over_lambda", s.R_over_lambda},
                {"exponents", exponents},
                {"prefactors", {{"H", s.H_prefactor}, {"n0", s.n0_prefactor}, {"T0", s.T0_prefactor}}},
                {"p0_scaled", s.p0_scaled},
                {"model", model_json(r)},
                {"kappa_prefactor", r.kappa_prefactor},
                {"viscosity_prefactor", r.viscosity_prefactor},
                {"energy_error", r.max_energy_error},
                {"energy_drift_before_projection", r.energy_projected},
                {"cells", config.numerics.cells},
                {"wall_seconds", r.statistics.wall_seconds},
                {"rhs_evaluations", r.statistics.rhs_evaluations}});
    return;
  }
  std::printf("Navier-Stokes core, d = %d, R/lambda = %s, %d cells, c_kappa = %.6g, c_mu = %.6g\n", config.physics.d,
              number(s.R_over_lambda, 6).c_str(), config.numerics.cells, r.kappa_prefactor, r.viscosity_prefactor);
  print_model(r);
  std::printf("running time exponents d ln X / d ln t at the end:\n  %-4s %10s %10s %10s\n", "X", "measured", "theory",
              "");
  for (const Row& row : rows)
    std::printf("  %-4s %10.5f %10.5f %10s\n", row.name, row.measured, theory::to_double(row.theory),
                theory::to_string(row.theory).c_str());
  std::printf(
      "prefactors: H/(lambda x^h_d) = %.4f, n0/(n_inf x^-2d^2/(8+3d^2)) = %.4f, T0/(Rdot^2 x^2d^2/(8+3d^2)) = "
      "%.4f (x = R/lambda)\n",
      s.H_prefactor, s.n0_prefactor, s.T0_prefactor);
  std::printf(
      "central pressure p0/(n_inf Rdot^2) = %.4f; energy error %.2e (drift before projection %.2e); %.2f s, "
      "%ld RHS evaluations\n",
      s.p0_scaled, r.max_energy_error, r.energy_projected, r.statistics.wall_seconds, r.statistics.rhs_evaluations);
}

void run_euler(const HydroOptions& options) {
  if (!options.out.empty()) common::require_output_folder(options.out, "--out");
  const hydro::NavierStokesConfig config = make_config(options, true);
  const hydro::NavierStokesResult r = solve(config, "euler");
  write_files(r, options.out);
  const hydro::TvnsComparison c = hydro::compare_to_tvns(r);
  if (options.format == Format::json) {
    print_json(
        {{"d", config.physics.d},
         {"model", model_json(r)},
         {"A_measured", c.A_measured},
         {"A_exact", c.A_exact},
         {"A_relative_error", c.A_relative_error},
         {"profile_L1_error", {{"density", c.L1_density}, {"velocity", c.L1_velocity}, {"pressure", c.L1_pressure}}},
         {"R_over_initial_width",
          config.until_R_over_lambda / (*r.config.numerics.start_R_over_lambda * config.numerics.initial_width)},
         {"cells", config.numerics.cells},
         {"energy_error", r.max_energy_error},
         {"energy_drift_before_projection", r.energy_projected},
         {"wall_seconds", r.statistics.wall_seconds}});
    return;
  }
  std::printf("Euler (kappa = mu = 0), d = %d, %d cells, R/(initial width) = %.4g\n", config.physics.d,
              config.numerics.cells,
              config.until_R_over_lambda / (*r.config.numerics.start_R_over_lambda * config.numerics.initial_width));
  print_model(r);
  std::printf("  A measured %.7f  exact %.7f  relative error %+.2e\n", c.A_measured, c.A_exact, c.A_relative_error);
  std::printf("  profile L1 errors: density %.2e  velocity %.2e  pressure %.2e\n", c.L1_density, c.L1_velocity,
              c.L1_pressure);
  std::printf("  energy error %.2e (drift before projection %.2e); %.2f s, %ld RHS evaluations\n", r.max_energy_error,
              r.energy_projected, r.statistics.wall_seconds, r.statistics.rhs_evaluations);
}

void add_common_options(CLI::App& command, HydroOptions& options, const char* until_help) {
  command.add_option("--d", options.d, "Spatial dimension: 1 planar, 2 cylindrical, 3 spherical")
      ->capture_default_str();
  command.add_option("--until", options.until, until_help);
  command.add_option(
      "--cells", options.cells,
      "Finite-volume cells, [16, 100000] (0 or none: " + std::to_string(hydro::default_core_cells) + " for core; " +
          std::to_string(hydro::default_euler_cells) +
          " for euler, where A_d meets 0.1 %); the time grows as cells^2 (1000 cells: 7 s to R/lambda = 20; 4000: 2 "
          "min)");
  command.add_option("--eos", options.eos, "Equation of state: ideal, henderson (d = 2) or carnahan-starling (d = 3)")
      ->capture_default_str();
  command.add_option("--phi", options.phi,
                     "Ambient packing fraction for a hard-particle --eos (0 or none: 0.118, the paper's MD)");
  command.add_option("--outer-margin", options.outer_margin,
                     "Outer grid edge / shock radius, [1.05, 2] (0 or none: 1.15; raise it when heat conduction "
                     "outruns the shock at the start, as in dense gases near close packing)");
  command.add_option(
      "--config", options.config_file,
      "TOML file whose [hydro] table sets eos, phi, transport, start, r0 (a scene file may carry it; flags win; "
      "docs/hydro.md)");
  command.add_option("--out", options.out, "Folder for samples.csv, exponents.csv, profile.csv (none if empty)");
  add_format_option(command, options.format);
}

/// Reads --config's [hydro] keys, minus those whose flag was given (flags win).
void read_config_keys(const CLI::App& command, HydroOptions& options) {
  if (options.config_file.empty()) return;
  options.file_keys = hydro::read_hydro_model_keys(
      common::read_text(options.config_file, "--config", common::text_size_limit), options.config_file);
  if (command.count("--eos")) options.file_keys.eos.reset();
  if (command.count("--phi")) options.file_keys.phi.reset();
  // core only: --transport, --start, --r0
  const auto given = [&](const char* flag) { return command.get_option_no_throw(flag) && command.count(flag) > 0; };
  if (given("--transport")) options.file_keys.transport.reset();
  if (given("--start")) options.file_keys.start.reset();
  if (given("--r0")) options.file_keys.r0.reset();
}

}  // namespace

void add_hydro_command(CLI::App& app) {
  CLI::App* hydro =
      app.add_subcommand("hydro", "Radial Navier-Stokes blast (paper Sec. III): core exponents, Euler check");
  hydro->require_subcommand(1);

  auto core_options = std::make_shared<HydroOptions>();
  CLI::App* core = hydro->add_subcommand(
      "core", "Heat-conducting blast: running exponents of H, n0, T0 and R beside the theory (Eqs. 4, 11, 12)");
  add_common_options(*core, *core_options, "Stop at R/lambda (0 or none: 1e4)");
  core->add_option("--viscosity", core_options->viscosity, "Shear viscosity mu = c_mu n_inf lambda sqrt(T): on or off")
      ->capture_default_str();
  core->add_option("--transport", core_options->transport,
                   "dilute (Chapman-Enskog) or enskog (dense hard particles: needs a hard-particle --eos)")
      ->capture_default_str();
  core->add_option("--start", core_options->start,
                   "How the energy enters: self-similar (a smooth hot region at R/lambda = 2) or hotspot (E as heat, "
                   "at rest, uniform within --r0 at the ambient density: the MD's hot spot; times count from it)")
      ->capture_default_str();
  core->add_option("--r0", core_options->r0,
                   "Hot-spot radius for --start hotspot in mean free paths, r0/lambda > 0 (a hot spot holding N "
                   "particles at phi = 0.118: 0.22 sqrt(N) in 2D, 0.18 N^(1/3) in 3D); the grid starts at R_ref = "
                   "max(2 lambda, 5 r0)");
  core->add_option_function<double>(
      "--kappa-prefactor",
      [core_options](const double& value) {
        core_options->kappa_prefactor = value;
        core_options->kappa_given = true;
      },
      "c_kappa in kappa = c_kappa n_inf lambda sqrt(T), >= 0 (default: Chapman-Enskog, 2/sqrt(pi) in 2D, "
      "75 sqrt(pi)/256 in 3D)");
  core->callback([core_options, core] {
    read_config_keys(*core, *core_options);
    run_core(*core_options);
  });

  auto euler_options = std::make_shared<HydroOptions>();
  CLI::App* euler = hydro->add_subcommand("euler", "kappa = mu = 0: A_d and profiles against the exact TvNS solution");
  add_common_options(*euler, *euler_options,
                     "Stop at R/lambda (0 or none: 500; the initial hot region has R/lambda = 0.4)");
  euler->callback([euler_options, euler] {
    read_config_keys(*euler, *euler_options);
    run_euler(*euler_options);
  });
}

}  // namespace coldblast::cli
