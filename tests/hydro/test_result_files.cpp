// hydro/result_files: the one schema of a Navier–Stokes result. Every table column is the struct's
// field, exactly; the CSV round-trips the numbers (17 digits) and keeps each column's digits; the
// summary holds the theory's rationals (core) or the exact TvNS check (Euler), and the model solved.
#include <catch2/catch.hpp>
#include <cstdlib>
#include <sstream>
#include <string>

#include "blast_configs.hpp"
#include "hydro/euler_check.hpp"
#include "hydro/navier_stokes.hpp"
#include "hydro/result_files.hpp"
#include "theory/exponents.hpp"

using namespace coldblast;

namespace {

const hydro::NavierStokesResult& core_result() {
  static const hydro::NavierStokesResult r = hydro::run_navier_stokes(test::core_config(2, 30, 64));
  return r;
}

const hydro::Column& find(const hydro::Table& table, const std::string& name) {
  for (const hydro::Column& c : table)
    if (c.name == name) return c;
  FAIL("no column " << name);
  throw;
}

/// The data lines of CSV text (no '#' lines, no header), each split at commas.
std::vector<std::vector<std::string>> data_rows(const std::string& text) {
  std::vector<std::vector<std::string>> rows;
  std::istringstream in(text);
  std::string line;
  bool header = true;
  while (std::getline(in, line)) {
    if (line.rfind('#', 0) == 0) continue;
    if (header) {
      header = false;
      continue;
    }
    std::vector<std::string> fields;
    std::istringstream cells(line);
    for (std::string f; std::getline(cells, f, ',');) fields.push_back(f);
    rows.push_back(fields);
  }
  return rows;
}

}  // namespace

TEST_CASE("hydro result tables: each column is its field, row for row") {
  const hydro::NavierStokesResult& r = core_result();
  const hydro::Table samples = hydro::sample_table(r);
  REQUIRE(samples.size() == 15);
  REQUIRE(find(samples, "t").values.size() == r.samples.size());
  for (std::size_t i = 0; i < r.samples.size(); ++i) {
    CHECK(find(samples, "n0").values[i] == r.samples[i].n0);
    CHECK(find(samples, "T0_prefactor").values[i] == r.samples[i].T0_prefactor);
    CHECK(find(samples, "p0").values[i] == r.samples[i].p0);
  }
  CHECK(find(samples, "energy_error").digits == 3);
  const hydro::Table exponents = hydro::exponent_table(r);
  REQUIRE(find(exponents, "T0_in_R").values.size() == r.exponents.size());
  CHECK(find(exponents, "T0_in_R").values.back() == r.exponents.back().T0_in_R);
  const hydro::Table profile = hydro::profile_table(r.profiles.back());
  CHECK(find(profile, "heat_flux").values == r.profiles.back().heat_flux);
}

TEST_CASE("hydro result CSV: the header names the columns, numbers round-trip exactly") {
  const hydro::NavierStokesResult& r = core_result();
  const std::string text = hydro::table_csv("# a header\n", hydro::sample_table(r));
  CHECK(text.rfind("# a header\nt,R_over_lambda,R,H,H_density,n0,T0,p0,", 0) == 0);
  const auto rows = data_rows(text);
  REQUIRE(rows.size() == r.samples.size());
  for (std::size_t i = 0; i < rows.size(); ++i) {
    REQUIRE(rows[i].size() == 15);
    CHECK(std::strtod(rows[i][5].c_str(), nullptr) == r.samples[i].n0);  // 17 digits: exact
    CHECK(std::strtod(rows[i][0].c_str(), nullptr) == r.samples[i].t);
  }
}

TEST_CASE("hydro result summary: the core's exponents beside the theory's rationals, the model solved") {
  const hydro::NavierStokesResult& r = core_result();
  const common::Json s = hydro::result_summary(r);
  const theory::ScalingExponents exact = theory::scaling_exponents(2);
  CHECK(s.at("exponents").at("T0").at("theory_rational") == theory::to_string(exact.T0.in_time));
  CHECK(s.at("exponents").at("T0").at("theory_rational") == "-4/5");
  CHECK(s.at("exponents").at("n0").at("measured").get<double>() == r.final_exponents().n0);
  CHECK(s.at("R_over_lambda").get<double>() == r.final_sample().R_over_lambda);
  CHECK(s.at("model").at("start") == "self-similar");
  CHECK(s.at("model").at("start_R_over_lambda").get<double>() == 2.0);
  CHECK(s.at("lambda").get<double>() == r.lambda);
  CHECK(s.at("cells").get<int>() == 64);
  CHECK_FALSE(s.contains("A_exact"));
}

TEST_CASE("hydro result summary of an Euler run: the exact TvNS check, no exponents") {
  const hydro::NavierStokesResult r = hydro::run_navier_stokes(test::euler_config(2, 10, 64));
  const common::Json s = hydro::result_summary(r);
  const hydro::TvnsComparison c = hydro::compare_to_tvns(r);
  CHECK_FALSE(s.contains("exponents"));
  CHECK(s.at("A_exact").get<double>() == c.A_exact);
  CHECK(s.at("A_exact").get<double>() == Approx(0.351935906848599).epsilon(1e-12));  // README's A_2
  CHECK(s.at("profile_L1_error").at("pressure").get<double>() == c.L1_pressure);
  CHECK(s.at("A_relative_error").get<double>() == c.A_measured / c.A_exact - 1);
}
