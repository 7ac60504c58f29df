// coldblast theory: the paper's Table 2 (exact rational exponents) for any dimension d, and the impurity
// prefactors computed by coldblast tracer (theory/computed_prefactors.hpp) where they are known.
#include <algorithm>
#include <cstdio>
#include <iostream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "cli/commands.hpp"
#include "common/validate.hpp"
#include "theory/computed_prefactors.hpp"
#include "theory/exponents.hpp"
#include "theory/observables.hpp"

namespace coldblast::cli {

namespace {

constexpr const char* prefactor_definition =
    "X / (the paper's estimate of X with its O(1) factor set to 1: R_imp = C lambda (R/lambda)^h_d, Eq. (6); "
    "V_imp, Eq. (8); C_imp, Eq. (10)), computed by coldblast tracer (Monte Carlo of Eq. (36) in the dense "
    "Navier-Stokes blast), not derived; error: block-jackknife standard error";

struct TheoryOptions {
  int d = 2;
  std::string d_range;
  Format format = Format::table;
};

common::Json rational_json(const theory::Rational& value) {
  return {{"rational", theory::to_string(value)}, {"value", theory::to_double(value)}};
}

/// The computed prefactors of dimension d (theory/computed_prefactors.hpp) with their sources.
common::Json prefactors_json(int d) {
  common::Json entries = common::Json::array();
  std::vector<int> used;
  for (const theory::ComputedPrefactor& p : theory::computed_prefactors(d)) {
    entries.push_back({{"observable", p.observable},
                       {"t", p.t},
                       {"R_over_lambda", p.R_over_lambda},
                       {"value", p.value},
                       {"error", p.error},
                       {"source", p.source}});
    if (std::find(used.begin(), used.end(), p.source) == used.end()) used.push_back(p.source);
  }
  common::Json sources = common::Json::object();
  for (const int i : used) {
    const theory::PrefactorSource& s = theory::prefactor_sources().at(static_cast<std::size_t>(i));
    sources[std::to_string(i)] = {
        {"command", s.command}, {"trajectories", s.trajectories}, {"description", s.description}};
  }
  return {{"definition", prefactor_definition}, {"entries", entries}, {"sources", sources}};
}

common::Json dimension_json(int d) {
  const theory::ScalingExponents s = theory::scaling_exponents(d);
  const theory::ConvectionDiffusionExponents c = theory::convection_diffusion_exponents(d);
  common::Json exponents = common::Json::object();
  for (const auto& [name, e] : s.named()) {
    common::Json entry = rational_json(e.in_time);
    entry["R_over_lambda"] = rational_json(e.in_R_over_lambda);
    exponents[name] = entry;
  }
  return {{"d", d},
          {"pathological", s.pathological},
          {"h_d", rational_json(s.h_d)},
          {"omega_d", rational_json(s.omega_d)},
          {"exponents", exponents},
          {"convection_diffusion",
           {{"drift", rational_json(c.drift)},
            {"diffusion", rational_json(c.diffusion)},
            {"spread", rational_json(c.spread)},
            {"density", rational_json(c.density)},
            {"gaussian_coefficient", rational_json(c.gaussian_coefficient)}}},
          {"computed_prefactors", prefactors_json(d)}};
}

std::string cell(const theory::Rational& value) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%-9s %9.6f", theory::to_string(value).c_str(), theory::to_double(value));
  return buffer;
}

/// The computed prefactors of dimension d, one line per recording time, then their sources.
void print_prefactors(int d) {
  const std::vector<theory::ComputedPrefactor> all = theory::computed_prefactors(d);
  if (all.empty()) return;
  std::cout << "\n  impurity prefactors C = X / (the paper's estimate of X with its O(1) factor 1: R_imp = C lambda "
               "(R/lambda)^h_d,\n  Eq. (6); V_imp, Eq. (8); C_imp, Eq. (10)) computed by coldblast tracer (Monte Carlo "
               "of Eq. (36)), not\n  derived in the paper; +- block-jackknife standard error\n";
  char line[200];
  // The tracer's prefactor observables (R_imp, V_imp, C_imp), one column each.
  const std::vector<std::string> columns = theory::observable_names(theory::is_tracer_prefactor);
  if (columns.size() != 3) throw std::logic_error("coldblast theory: the prefactor table has 3 columns");
  std::snprintf(line, sizeof line, "  %-12s %-22s %-22s %-22s %s\n", "R/lambda", columns[0].c_str(), columns[1].c_str(),
                columns[2].c_str(), "source");
  std::cout << line;
  std::vector<double> times;
  for (const auto& p : all)
    if (std::find(times.begin(), times.end(), p.t) == times.end()) times.push_back(p.t);
  std::sort(times.begin(), times.end());
  std::vector<int> used;
  for (const double t : times) {
    std::string cells[3];
    double R_over_lambda = 0.0;
    int source = -1;
    for (const auto& p : all) {
      if (p.t != t) continue;
      const auto column =
          static_cast<std::size_t>(std::find(columns.begin(), columns.end(), p.observable) - columns.begin());
      if (column == columns.size())
        throw std::logic_error(std::string("computed prefactor of ") + p.observable + ", not a prefactor observable");
      // ASCII "+-" keeps printf's byte widths aligned.
      std::string text = common::format_measurement(p.value, p.error);
      const std::string plus_minus = " ± ";
      cells[column] = text.replace(text.find(plus_minus), plus_minus.size(), " +- ");
      R_over_lambda = p.R_over_lambda;
      source = p.source;
    }
    std::snprintf(line, sizeof line, "  %-12.5g %-22s %-22s %-22s [%d]\n", R_over_lambda, cells[0].c_str(),
                  cells[1].c_str(), cells[2].c_str(), source);
    std::cout << line;
    if (std::find(used.begin(), used.end(), source) == used.end()) used.push_back(source);
  }
  for (const int i : used) {
    const theory::PrefactorSource& s = theory::prefactor_sources().at(static_cast<std::size_t>(i));
    std::cout << "  [" << i << "] " << s.command << " (" << s.trajectories << " trajectories; " << s.description
              << ")\n";
  }
}

void print_detail(int d) {
  const theory::ScalingExponents s = theory::scaling_exponents(d);
  const theory::ConvectionDiffusionExponents c = theory::convection_diffusion_exponents(d);
  std::cout << "d = " << d << (s.pathological ? "  (pathological: no hydrodynamics in 1D, paper Sec. II)" : "")
            << "\n  h_d     = " << cell(s.h_d) << "\n  omega_d = " << cell(s.omega_d) << "\n\n"
            << "  quantity  time exponent         exponent in R/lambda\n";
  for (const auto& [name, e] : s.named()) {
    char line[160];
    std::snprintf(line, sizeof line, "  %-8s  %s   %s\n", name.c_str(), cell(e.in_time).c_str(),
                  cell(e.in_R_over_lambda).c_str());
    std::cout << line;
  }
  std::cout << "\n  convection-diffusion (Sec. IV): (d/dt + t^(" << theory::to_string(c.drift) << ") d/dr) P = t^("
            << theory::to_string(c.diffusion) << ") Laplacian P\n"
            << "    P = t^(-" << theory::to_string(c.density) << ") Pscaled(eta), eta = r t^(-"
            << theory::to_string(c.spread) << "), Pscaled ~ exp(-" << theory::to_string(c.gaussian_coefficient)
            << " eta^2)\n";
  print_prefactors(d);
}

void print_table(int d_first, int d_last) {
  // Column order of the paper's Table 2, then R, H and D0 (the catalogue's table2_column).
  const std::vector<std::string> names = theory::table2_names();
  std::cout << "time exponents t^alpha (paper Table 2 for any d)\n";
  char line[256];
  std::snprintf(line, sizeof line, "%-4s %-11s %-11s", "d", "h_d", "omega_d");
  std::cout << line;
  for (const std::string& name : names) {
    std::snprintf(line, sizeof line, "%-13s", name.c_str());
    std::cout << line;
  }
  std::cout << '\n';
  for (int d = d_first; d <= d_last; ++d) {
    const theory::ScalingExponents s = theory::scaling_exponents(d);
    std::snprintf(line, sizeof line, "%-4d %-11s %-11s", d, theory::to_string(s.h_d).c_str(),
                  theory::to_string(s.omega_d).c_str());
    std::cout << line;
    for (const std::string& name : names) {
      std::snprintf(line, sizeof line, "%-13s", theory::to_string(s.at(name).in_time).c_str());
      std::cout << line;
    }
    std::cout << (s.pathological ? "  (pathological)" : "") << '\n';
  }
}

void run(const TheoryOptions& options) {
  if (options.d_range.empty()) {
    common::require_integer_in_range("--d", options.d, theory::min_dimension, theory::max_dimension);
    if (options.format == Format::json)
      print_json(dimension_json(options.d));
    else
      print_detail(options.d);
    return;
  }
  const auto [first, last] = theory::parse_dimension_range(options.d_range);
  if (options.format == Format::json) {
    common::Json all = common::Json::array();
    for (int d = first; d <= last; ++d) all.push_back(dimension_json(d));
    print_json(all);
  } else {
    print_table(first, last);
  }
}

}  // namespace

void add_theory_command(CLI::App& app) {
  auto options = std::make_shared<TheoryOptions>();
  CLI::App* command = app.add_subcommand(
      "theory", "Exact rational scaling exponents of the paper (Table 2, Eqs. 4-12, 21-24, Sec. IV) for any d");
  auto* d_option =
      command->add_option("--d", options->d, "Spatial dimension d (integer, 1..10000)")->capture_default_str();
  command->add_option("--d-range", options->d_range, "Range of dimensions FIRST..LAST, e.g. 2..6")->excludes(d_option);
  add_format_option(*command, options->format);
  command->callback([options] { run(*options); });
}

}  // namespace coldblast::cli
