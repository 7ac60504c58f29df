// coldblast tvns: the exact TvNS blast (paper Eq. (1) [R-shock], Eqs. (18a,b) [r-est, T-est]):
// A_d with its error estimate from two methods, and the self-similar profile at any r/R.
#include <cmath>
#include <cstdio>
#include <iostream>
#include <memory>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "cli/commands.hpp"
#include "common/input.hpp"
#include "common/output.hpp"
#include "common/validate.hpp"
#include "hydro/options.hpp"
#include "hydro/tvns.hpp"

namespace coldblast::cli {

namespace {

struct TvnsOptions {
  int d = 2;
  double gamma = 0.0;
  std::string eos = "ideal";
  double phi = 0.0;
  double tolerance = 1e-13;
  std::string profile;
  int points = 100;
  std::string at;
  Format format = Format::table;
};

const char* geometry(int d) {
  return d == 1 ? "planar" : d == 2 ? "cylindrical" : "spherical";
}

const char* case_name(hydro::TvnsCase c) {
  switch (c) {
    case hydro::TvnsCase::standard:
      return "standard";
    case hydro::TvnsCase::singular:
      return "singular";
    case hydro::TvnsCase::vacuum:
      return "vacuum";
  }
  return "?";
}

std::string number(double value, int digits = 17) {
  char buffer[48];
  std::snprintf(buffer, sizeof buffer, "%.*g", digits, value);
  return buffer;
}

/// Maps the flags to a TvnsConfig (validation and messages in hydro/options.hpp).
hydro::TvnsConfig make_config(const TvnsOptions& options) {
  return hydro::tvns_config({options.d, options.gamma, options.eos, options.phi, options.tolerance});
}

common::Json point_json(const hydro::TvnsPoint& p) {
  // JSON has no infinity: the centre's temperature (standard case) is written as null.
  const auto finite_or_null = [](double value) { return std::isfinite(value) ? common::Json(value) : common::Json(); };
  return {{"r_over_R", p.r_over_R},
          {"density", p.density},
          {"velocity", p.velocity},
          {"pressure", p.pressure},
          {"temperature", finite_or_null(p.temperature)}};
}

void write_profile(const std::string& path, const hydro::TvnsSolution& s, const std::vector<hydro::TvnsPoint>& points) {
  const hydro::TvnsConfig& c = s.config();
  std::string text =
      common::provenance_header({{"d", std::to_string(c.d)},
                                 {"gamma", number(s.gamma())},
                                 {"eos", hydro::to_string(c.eos)},
                                 {"phi", number(c.phi)},
                                 {"tolerance", number(c.tolerance)},
                                 {"case", case_name(s.solution_case())},
                                 {"A", number(s.A())},
                                 {"A_error", number(s.A_error(), 3)},
                                 {"method_agreement", number(s.method_agreement(), 3)},
                                 {"cavity_radius", number(s.cavity_radius())},
                                 {"note", "temperature is inf where the density is 0 (the centre, or below 1e-308)"}},
                                "r_over_R = r/R; density = rho/rho0; velocity = u/Rdot; pressure = p/(rho0 Rdot^2); "
                                "temperature = T/Rdot^2 with T = p/(n Z), k_B = m = 1");
  text += "r_over_R,density,velocity,pressure,temperature\n";
  for (const hydro::TvnsPoint& p : points) {
    if (!(std::isfinite(p.density) && std::isfinite(p.velocity) && std::isfinite(p.pressure)))
      throw std::runtime_error("tvns: non-finite profile value at r/R = " + number(p.r_over_R));
    text += number(p.r_over_R) + "," + number(p.density) + "," + number(p.velocity) + "," + number(p.pressure) + "," +
            (std::isfinite(p.temperature) ? number(p.temperature) : std::string("inf")) + "\n";
  }
  common::write_file_atomic(path, text);
  std::cerr << "tvns: wrote " << path << " (" << points.size() << " points)\n";
}

common::Json summary_json(const TvnsOptions& options, const hydro::TvnsSolution& s,
                          const std::vector<hydro::TvnsPoint>& points) {
  const auto finite_or_null = [](double value) { return std::isfinite(value) ? common::Json(value) : common::Json(); };
  const hydro::TvnsConfig& config = s.config();
  common::Json document = {{"d", config.d},
                           {"gamma", s.gamma()},
                           {"eos", hydro::to_string(config.eos)},
                           {"phi", config.phi},
                           {"A", s.A()},
                           {"A_error", s.A_error()},
                           {"method_agreement", s.method_agreement()},
                           {"A_closed_form", finite_or_null(s.A_closed_form())},
                           {"A_ode", s.A_ode()},
                           {"case", case_name(s.solution_case())},
                           {"tolerance", config.tolerance},
                           {"shock_compression", s.shock_compression()},
                           {"shock_packing_fraction", s.shock_packing_fraction()},
                           {"cavity_radius", s.cavity_radius()},
                           {"density_exponent", s.density_exponent()},
                           {"temperature_exponent", s.temperature_exponent()}};
  if (!options.profile.empty()) document["profile_file"] = options.profile;
  if (!options.at.empty()) {
    common::Json profile = common::Json::array();
    for (const hydro::TvnsPoint& p : points) profile.push_back(point_json(p));
    document["profile"] = profile;
  }
  return document;
}

void print_table(const hydro::TvnsSolution& s, const std::vector<hydro::TvnsPoint>& points) {
  const hydro::TvnsConfig& config = s.config();
  const bool ideal = config.eos == hydro::Eos::ideal;
  std::cout << "TvNS blast, d = " << config.d << " (" << geometry(config.d) << "), "
            << (ideal ? "ideal gas, gamma = " + number(s.gamma(), 15)
                      : hydro::to_string(config.eos) + ", phi = " + number(config.phi, 15))
            << ", " << case_name(s.solution_case()) << " case\n"
            << "  A_d = " << number(s.A(), 15) << " +- " << number(s.A_error(), 2)
            << "   (Eq. 1: R = (E t^2/(A_d n))^(1/(d+2)))\n";
  if (ideal)
    std::cout << "  closed form " << number(s.A_closed_form(), 15) << ", ODE " << number(s.A_ode(), 15);
  else
    std::cout << "  Bulirsch-Stoer " << number(s.A(), 15) << ", Dormand-Prince check";
  std::cout << ", relative agreement " << number(s.method_agreement(), 2) << "\n"
            << "  shock: rho1/rho0 = " << number(s.shock_compression(), 12);
  if (!ideal) std::cout << ", phi1 = " << number(s.shock_packing_fraction(), 12);
  std::cout << "\n";
  if (s.solution_case() == hydro::TvnsCase::vacuum)
    std::cout << "  empty cavity for r/R < " << number(s.cavity_radius(), 12) << "; at its edge rho ∝ (r/R - "
              << number(s.cavity_radius(), 6) << ")^" << number(s.density_exponent(), 6) << ", T ∝ (r/R - ...)^"
              << number(s.temperature_exponent(), 6) << "\n";
  else
    std::cout << "  near the centre (Eqs. 18a,b): rho ∝ (r/R)^" << number(s.density_exponent(), 12) << ", T ∝ (r/R)^"
              << number(s.temperature_exponent(), 12) << "\n";
  if (points.empty()) return;
  std::cout << "\n  r/R                  rho/rho0             u/Rdot               p/(rho0 Rdot^2)      T/Rdot^2\n";
  for (const hydro::TvnsPoint& p : points) {
    char line[200];
    std::snprintf(line, sizeof line, "  %-20.15g %-20.15g %-20.15g %-20.15g %-20.15g\n", p.r_over_R, p.density,
                  p.velocity, p.pressure, p.temperature);
    std::cout << line;
  }
}

/// The r/R of --at, or i/N of --points.
std::vector<double> profile_points(const TvnsOptions& options) {
  if (!options.at.empty()) return hydro::parse_profile_points(options.at);
  common::require_integer_in_range("--points", options.points, 1, 10000000);
  std::vector<double> xs;
  for (int i = 1; i <= options.points; ++i) xs.push_back(static_cast<double>(i) / options.points);
  return xs;
}

void run(const TvnsOptions& options) {
  const hydro::TvnsConfig config = make_config(options);
  const std::vector<double> xs = profile_points(options);
  const hydro::TvnsSolution s = hydro::solve_tvns(config);
  std::vector<hydro::TvnsPoint> points;
  if (!options.profile.empty() || !options.at.empty()) points = s.profile(xs);
  if (!options.profile.empty()) write_profile(options.profile, s, points);
  if (options.format == Format::json)
    print_json(summary_json(options, s, points));
  else
    print_table(s, options.at.empty() ? std::vector<hydro::TvnsPoint>{} : points);
}

}  // namespace

void add_tvns_command(CLI::App& app) {
  auto options = std::make_shared<TvnsOptions>();
  CLI::App* command = app.add_subcommand(
      "tvns", "Exact Taylor-von Neumann-Sedov blast: A_d of Eq. (1) with its error, and the profile at any r/R");
  command->add_option("--d", options->d, "Spatial dimension d (integer, 1 planar, 2 cylindrical, 3 spherical)")
      ->capture_default_str();
  command
      ->add_option("--gamma", options->gamma,
                   "Adiabatic index gamma in [1.001, 1000] (dimensionless, ideal EOS only; default 0 means 1 + 2/d)")
      ->capture_default_str();
  command
      ->add_option("--eos", options->eos,
                   "Equation of state: ideal, henderson (hard discs, d = 2) or carnahan-starling (hard spheres, d = 3)")
      ->capture_default_str();
  command
      ->add_option("--phi", options->phi,
                   "Ambient packing fraction phi (dimensionless; hard-particle EOS only: henderson (0, 0.89286), "
                   "carnahan-starling (0, 0.686): docs/stress.md)")
      ->capture_default_str();
  command->add_option("--tolerance", options->tolerance, "Requested relative accuracy of A_d (1e-14..1e-3)")
      ->capture_default_str();
  command->add_option("--profile", options->profile,
                      "Write the profile to this CSV file (r/R, rho/rho0, u/Rdot, p/(rho0 Rdot^2), T/Rdot^2); "
                      "default: no file");
  auto* points_option =
      command->add_option("--points", options->points, "Profile points r/R = i/N, i = 1..N (integer N >= 1)")
          ->capture_default_str();
  command
      ->add_option("--at", options->at,
                   "Evaluate the profile exactly at these r/R in [0, 1], comma-separated (printed, and written "
                   "to --profile if given); default: none")
      ->excludes(points_option);
  add_format_option(*command, options->format);
  command->callback([options] { run(*options); });
}

}  // namespace coldblast::cli
