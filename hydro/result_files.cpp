#include "hydro/result_files.hpp"

#include <cstdio>

#include "hydro/euler_check.hpp"
#include "theory/exponents.hpp"

namespace coldblast::hydro {

namespace {

/// `value` with `digits` significant digits (printf %g: the files' format since their first version).
std::string number(double value, int digits = 17) {
  char buffer[48];
  std::snprintf(buffer, sizeof buffer, "%.*g", digits, value);
  return buffer;
}

/// The column `name` of `rows`' `member`.
template <class Row>
Column column(const char* name, const std::vector<Row>& rows, double Row::*member, int digits = 17) {
  Column c{name, {}, digits};
  c.values.reserve(rows.size());
  for (const Row& row : rows) c.values.push_back(row.*member);
  return c;
}

bool is_euler(const NavierStokesResult& r) {
  return !r.config.physics.heat_conduction;
}

/// model: the physics actually solved (phi resolved by the library) and how E entered.
common::Json model_json(const NavierStokesResult& r) {
  const NavierStokesPhysics& p = r.config.physics;
  return {{"eos", to_string(p.eos)},
          {"phi", p.phi},
          {"transport", to_string(p.transport)},
          {"start", to_string(p.start)},
          {"r0_over_lambda", p.r0_over_lambda},
          {"start_R_over_lambda", *r.config.numerics.start_R_over_lambda}};
}

/// The Euler check's keys: A against the exact TvNS amplitude and the profiles' L1 errors.
void add_tvns_comparison(const NavierStokesResult& r, common::Json& summary) {
  const TvnsComparison c = compare_to_tvns(r);
  summary["A_exact"] = c.A_exact;
  summary["A_relative_error"] = c.A_relative_error;
  summary["profile_L1_error"] = {{"density", c.L1_density}, {"velocity", c.L1_velocity}, {"pressure", c.L1_pressure}};
  summary["R_over_initial_width"] =
      r.config.until_R_over_lambda / (*r.config.numerics.start_R_over_lambda * r.config.numerics.initial_width);
}

}  // namespace

common::Json exponents_json(const NavierStokesResult& r) {
  const theory::ScalingExponents theory_exponents = theory::scaling_exponents(r.config.physics.d);
  const RunningExponents e = r.final_exponents();
  common::Json exponents = common::Json::object();
  for (const CoreExponent& q : core_exponents) {
    const theory::Rational law = theory_exponents.at(q.name).in_time;
    exponents[q.name] = {{"measured", e.*q.time_exponent},
                         {"theory", theory::to_double(law)},
                         {"theory_rational", theory::to_string(law)}};
  }
  return exponents;
}

Table sample_table(const NavierStokesResult& r) {
  using S = NavierStokesSample;
  const auto& s = r.samples;
  return {column("t", s, &S::t),
          column("R_over_lambda", s, &S::R_over_lambda),
          column("R", s, &S::R),
          column("H", s, &S::H),
          column("H_density", s, &S::H_density),
          column("n0", s, &S::n0),
          column("T0", s, &S::T0),
          column("p0", s, &S::p0),
          column("energy", s, &S::energy),
          column("mass", s, &S::mass),
          column("energy_error", s, &S::energy_error, 3),
          column("H_prefactor", s, &S::H_prefactor),
          column("n0_prefactor", s, &S::n0_prefactor),
          column("T0_prefactor", s, &S::T0_prefactor),
          column("p0_scaled", s, &S::p0_scaled)};
}

Table exponent_table(const NavierStokesResult& r) {
  using E = RunningExponents;
  const auto& e = r.exponents;
  return {column("t", e, &E::t),
          column("R_over_lambda", e, &E::R_over_lambda),
          column("R", e, &E::R),
          column("H", e, &E::H),
          column("H_density", e, &E::H_density),
          column("n0", e, &E::n0),
          column("T0", e, &E::T0),
          column("H_in_R", e, &E::H_in_R),
          column("H_density_in_R", e, &E::H_density_in_R),
          column("n0_in_R", e, &E::n0_in_R),
          column("T0_in_R", e, &E::T0_in_R)};
}

Table profile_table(const NavierStokesProfile& p) {
  return {{"r", p.r},
          {"r_over_R", p.r_over_R},
          {"density", p.density},
          {"velocity", p.velocity},
          {"temperature", p.temperature},
          {"pressure", p.pressure},
          {"heat_flux", p.heat_flux}};
}

common::Json result_summary(const NavierStokesResult& r) {
  const NavierStokesSample& s = r.final_sample();
  common::Json summary = {{"d", r.config.physics.d}, {"R_over_lambda", s.R_over_lambda}};
  if (!is_euler(r)) summary["exponents"] = exponents_json(r);
  summary["prefactors"] = {{"H", s.H_prefactor}, {"n0", s.n0_prefactor}, {"T0", s.T0_prefactor}};
  summary["p0_scaled"] = s.p0_scaled;
  summary["model"] = model_json(r);
  summary["lambda"] = r.lambda;
  summary["kappa_prefactor"] = r.kappa_prefactor;
  summary["viscosity_prefactor"] = r.viscosity_prefactor;
  summary["A_reference"] = r.A_reference;
  summary["A_measured"] = r.A_measured;
  if (is_euler(r)) add_tvns_comparison(r, summary);
  summary["energy_error"] = r.max_energy_error;
  summary["energy_drift_before_projection"] = r.energy_projected;
  summary["cells"] = r.config.numerics.cells;
  summary["wall_seconds"] = r.statistics.wall_seconds;
  summary["rhs_evaluations"] = r.statistics.rhs_evaluations;
  return summary;
}

std::string table_csv(const std::string& header, const Table& table) {
  std::string text = header;
  for (std::size_t c = 0; c < table.size(); ++c) text += (c ? "," : "") + table[c].name;
  text += '\n';
  const std::size_t rows = table.empty() ? 0 : table.front().values.size();
  for (std::size_t i = 0; i < rows; ++i) {
    for (std::size_t c = 0; c < table.size(); ++c) text += (c ? "," : "") + number(table[c].values[i], table[c].digits);
    text += '\n';
  }
  return text;
}

std::string result_file_header(const NavierStokesResult& r) {
  const NavierStokesConfig& c = r.config;
  return common::provenance_header(
      {{"d", std::to_string(c.physics.d)},
       {"E", number(c.physics.E)},
       {"n_inf", number(c.physics.n_inf)},
       {"a", number(c.physics.a)},
       {"eos", to_string(c.physics.eos)},
       {"phi", number(c.physics.phi)},
       {"transport", to_string(c.physics.transport)},
       {"lambda", number(r.lambda)},
       {"kappa_prefactor", number(r.kappa_prefactor)},
       {"viscosity_prefactor", number(r.viscosity_prefactor)},
       {"until_R_over_lambda", number(c.until_R_over_lambda)},
       {"cells", std::to_string(c.numerics.cells)},
       {"start", to_string(c.physics.start)},
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

void write_result_files(const NavierStokesResult& r, const std::filesystem::path& directory) {
  const std::string header = result_file_header(r);
  common::write_file_atomic(directory / "samples.csv", table_csv(header, sample_table(r)));
  common::write_file_atomic(directory / "exponents.csv", table_csv(header, exponent_table(r)));
  const NavierStokesProfile& p = r.profiles.back();
  common::write_file_atomic(
      directory / "profile.csv",
      table_csv(header + "# t: " + number(p.t) + "\n# R: " + number(p.R) + "\n", profile_table(p)));
}

}  // namespace coldblast::hydro
