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
#include "hydro/result_files.hpp"

namespace coldblast::cli {

namespace {

/// The flags: the model and numerics bind straight into the library's hydro::HydroOptions.
struct HydroOptions {
  hydro::HydroOptions library;
  std::string viscosity = "off";  // on | off (core), the library's bool
  std::string config_file;        // --config FILE: its [hydro] model keys (docs/hydro.md; flags win)
  hydro::HydroModelKeys file_keys;
  std::string out;
  Format format = Format::table;
};

std::string number(double value, int digits = 17) {
  char buffer[48];
  std::snprintf(buffer, sizeof buffer, "%.*g", digits, value);
  return buffer;
}

/// The library config (validation and messages in hydro/options.hpp).
hydro::NavierStokesConfig make_config(HydroOptions options, bool euler) {
  if (!euler && options.viscosity != "on" && options.viscosity != "off")
    throw std::invalid_argument("--viscosity = " + options.viscosity + " is not one of on, off");
  options.library.viscosity = options.viscosity == "on";
  return hydro::navier_stokes_config(options.library, euler, options.file_keys);
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

void write_files(const hydro::NavierStokesResult& r, const std::string& directory) {
  if (directory.empty()) return;
  hydro::write_result_files(r, directory);
  std::cerr << "hydro: wrote samples.csv, exponents.csv, profile.csv in " << directory << '\n';
}

/// The table of `hydro core`, read from the result's summary (hydro/result_files.hpp).
void print_core(const hydro::NavierStokesResult& r, const common::Json& summary) {
  std::printf("Navier-Stokes core, d = %d, R/lambda = %s, %d cells, c_kappa = %.6g, c_mu = %.6g\n",
              summary["d"].get<int>(), number(summary["R_over_lambda"], 6).c_str(), summary["cells"].get<int>(),
              summary["kappa_prefactor"].get<double>(), summary["viscosity_prefactor"].get<double>());
  print_model(r);
  std::printf("running time exponents d ln X / d ln t at the end:\n  %-4s %10s %10s %10s\n", "X", "measured", "theory",
              "");
  for (const auto& [name, e] : summary["exponents"].items())
    std::printf("  %-4s %10.5f %10.5f %10s\n", name.c_str(), e["measured"].get<double>(), e["theory"].get<double>(),
                e["theory_rational"].get<std::string>().c_str());
  const common::Json& prefactors = summary["prefactors"];
  std::printf(
      "prefactors: H/(lambda x^h_d) = %.4f, n0/(n_inf x^-2d^2/(8+3d^2)) = %.4f, T0/(Rdot^2 x^2d^2/(8+3d^2)) = "
      "%.4f (x = R/lambda)\n",
      prefactors["H"].get<double>(), prefactors["n0"].get<double>(), prefactors["T0"].get<double>());
  std::printf(
      "central pressure p0/(n_inf Rdot^2) = %.4f; energy error %.2e (drift before projection %.2e); %.2f s, "
      "%ld RHS evaluations\n",
      summary["p0_scaled"].get<double>(), summary["energy_error"].get<double>(),
      summary["energy_drift_before_projection"].get<double>(), summary["wall_seconds"].get<double>(),
      summary["rhs_evaluations"].get<long>());
}

/// The table of `hydro euler`, read from the result's summary.
void print_euler(const hydro::NavierStokesResult& r, const common::Json& summary) {
  std::printf("Euler (kappa = mu = 0), d = %d, %d cells, R/(initial width) = %.4g\n", summary["d"].get<int>(),
              summary["cells"].get<int>(), summary["R_over_initial_width"].get<double>());
  print_model(r);
  std::printf("  A measured %.7f  exact %.7f  relative error %+.2e\n", summary["A_measured"].get<double>(),
              summary["A_exact"].get<double>(), summary["A_relative_error"].get<double>());
  const common::Json& L1 = summary["profile_L1_error"];
  std::printf("  profile L1 errors: density %.2e  velocity %.2e  pressure %.2e\n", L1["density"].get<double>(),
              L1["velocity"].get<double>(), L1["pressure"].get<double>());
  std::printf("  energy error %.2e (drift before projection %.2e); %.2f s, %ld RHS evaluations\n",
              summary["energy_error"].get<double>(), summary["energy_drift_before_projection"].get<double>(),
              summary["wall_seconds"].get<double>(), summary["rhs_evaluations"].get<long>());
}

/// hydro core (euler = false) or hydro euler: solve, write the files, print the summary.
void run_hydro(const HydroOptions& options, bool euler) {
  if (!options.out.empty()) common::require_output_folder(options.out, "--out");
  const hydro::NavierStokesResult r = solve(make_config(options, euler), euler ? "euler" : "core");
  write_files(r, options.out);
  const common::Json summary = hydro::result_summary(r);
  if (options.format == Format::json)
    print_json(summary);
  else if (euler)
    print_euler(r, summary);
  else
    print_core(r, summary);
}

void add_common_options(CLI::App& command, HydroOptions& options, const char* until_help) {
  command.add_option("--d", options.library.d, "Spatial dimension: 1 planar, 2 cylindrical, 3 spherical")
      ->capture_default_str();
  command.add_option("--until", options.library.until, until_help);
  command.add_option(
      "--cells", options.library.cells,
      "Finite-volume cells, [16, 100000] (0 or none: " + std::to_string(hydro::default_core_cells) + " for core; " +
          std::to_string(hydro::default_euler_cells) +
          " for euler, where A_d meets 0.1 %); the time grows as cells^2 (1000 cells: 7 s to R/lambda = 20; 4000: 2 "
          "min)");
  command
      .add_option("--eos", options.library.eos,
                  "Equation of state: ideal, henderson (d = 2) or carnahan-starling (d = 3)")
      ->capture_default_str();
  command.add_option("--phi", options.library.phi,
                     "Ambient packing fraction for a hard-particle --eos (0 or none: 0.118, the paper's MD)");
  command.add_option("--outer-margin", options.library.outer_margin,
                     "Outer grid edge / shock radius, [1.05, 2] (0 or none: 1.15; raise it when heat conduction "
                     "outruns the shock at the start, as in dense gases near close packing)");
  command.add_option("--config", options.config_file,
                     "TOML file whose [hydro] table sets eos, phi, transport, viscosity, start, r0 (a scene file may "
                     "carry it; flags win; docs/hydro.md)");
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
  // core only: --transport, --viscosity, --start, --r0
  const auto given = [&](const char* flag) { return command.get_option_no_throw(flag) && command.count(flag) > 0; };
  if (given("--transport")) options.file_keys.transport.reset();
  if (given("--viscosity")) options.file_keys.viscosity.reset();
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
  core->add_option("--transport", core_options->library.transport,
                   "dilute (Chapman-Enskog) or enskog (dense hard particles: needs a hard-particle --eos)")
      ->capture_default_str();
  core->add_option("--start", core_options->library.start,
                   "How the energy enters: self-similar (a smooth hot region at R/lambda = 2) or hotspot (E as heat, "
                   "at rest, uniform within --r0 at the ambient density: the MD's hot spot; times count from it)")
      ->capture_default_str();
  core->add_option("--r0", core_options->library.r0,
                   "Hot-spot radius for --start hotspot in mean free paths, r0/lambda > 0 (a hot spot holding N "
                   "particles at phi = 0.118: 0.22 sqrt(N) in 2D, 0.18 N^(1/3) in 3D); the grid starts at R_ref = "
                   "max(2 lambda, 5 r0)");
  core->add_option_function<double>(
      "--kappa-prefactor", [core_options](const double& value) { core_options->library.kappa_prefactor = value; },
      "c_kappa in kappa = c_kappa n_inf lambda sqrt(T), >= 0 (default: Chapman-Enskog, 2/sqrt(pi) in 2D, "
      "75 sqrt(pi)/256 in 3D)");
  core->callback([core_options, core] {
    read_config_keys(*core, *core_options);
    run_hydro(*core_options, false);
  });

  auto euler_options = std::make_shared<HydroOptions>();
  CLI::App* euler = hydro->add_subcommand("euler", "kappa = mu = 0: A_d and profiles against the exact TvNS solution");
  add_common_options(*euler, *euler_options,
                     "Stop at R/lambda (0 or none: 500; the initial hot region has R/lambda = 0.4)");
  euler->callback([euler_options, euler] {
    read_config_keys(*euler, *euler_options);
    run_hydro(*euler_options, true);
  });
}

}  // namespace coldblast::cli
