// End to end on a tiny scale: every step runs, the files exist, and the numbers that have an
// exact reference (A_2, A_3, the NS exponents' approach, the MD's energy conservation) hold.
#include <catch2/catch.hpp>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <regex>
#include <string>

#include "compare/reproduce.hpp"
#include "tests/temp_path.hpp"

using namespace coldblast::compare;
namespace fs = std::filesystem;

namespace {
/// Digits after the decimal point of a quoted number ("0.0023": 4, "232": 0).
int decimals(const std::string& number) {
  const auto point = number.find('.');
  return point == std::string::npos ? 0 : static_cast<int>(number.size() - point - 1);
}

/// REPORT.md quotes each amplitude as "value ± error" with a two-digit error and the value to the
/// same decimal place, and the value is the verdict's, rounded there.
void check_amplitude_rows(const std::string& report, const std::vector<AmplitudeVerdict>& amplitudes) {
  for (const auto& a : amplitudes) {
    INFO(a.name << " = " << a.measured << " ± " << a.error);
    const std::regex row("\\| " + std::regex_replace(a.name, std::regex("[\\^/]"), "\\$&") +
                         " \\| (-?[0-9]+(\\.[0-9]+)?) ± ([0-9]+(\\.[0-9]+)?) \\|");
    std::smatch m;
    REQUIRE(std::regex_search(report, m, row));
    const std::string value = m[1], error = m[3];
    INFO("quoted " << value << " ± " << error);
    CHECK(decimals(value) == decimals(error));
    const std::string error_digits = std::regex_replace(error, std::regex("^[0.]+|\\."), "");
    CHECK(error_digits.size() == 2);  // "0.0023", "0.062", "12"
    const double unit = std::pow(10.0, -decimals(value));
    CHECK(std::abs(std::stod(value) - a.measured) <= 0.5 * unit * (1 + 1e-9));
    CHECK(std::abs(std::stod(error) - a.error) <= 0.5 * unit * (1 + 1e-9));
  }
}
}  // namespace

TEST_CASE("reproduce runs every step and writes the report", "[slow]") {
  ReproduceConfig config;
  config.out = coldblast::test::unique_temp_path("coldblast_test_reproduce");
  fs::remove_all(config.out);
  config.realizations = 4;
  config.hydro_until = 50;
  config.threads = 2;
  config.figures = false;
  const ReproduceResult r = run_reproduce(config);
  CHECK(r.A2 == Approx(0.351935906848599).epsilon(1e-13));
  CHECK(r.A3 == Approx(0.493590149582568).epsilon(1e-13));
  CHECK(r.A2_md < r.A2);  // hard discs are stiffer: the blast goes further for the same E
  CHECK(r.md["realizations"].get<long long>() == 4);
  CHECK(r.md["energy_error_max"].get<double>() < 1e-12);
  CHECK(std::abs(r.hydro["exponents"]["H"]["measured"].get<double>() - 0.4) < 0.05);
  CHECK(r.against_theory.observables.size() == 6);
  CHECK(r.against_paper.observables.size() == 6);
  CHECK(r.against_hydro.observables.size() == 6);
  // The flow speed is judged by u_flow except against the paper; hydro is the dense NS at the
  // scene's phi, solved once and shared by the three comparisons, with its amplitude verdicts.
  CHECK(r.against_hydro.observables.back().name == "u_flow");
  CHECK(r.against_paper.observables[3].name == "u_imp");
  CHECK(r.hydro["model"].get<std::string>().find("dense NS (henderson EOS at phi = 0.1178") == 0);
  REQUIRE(r.against_hydro.continuum);
  CHECK(r.against_theory.continuum == r.against_hydro.continuum);
  CHECK(r.against_hydro.continuum->ns_dilute.has_value());
  CHECK(r.against_hydro.continuum->profiles.size() == 4);
  CHECK(r.against_hydro.amplitudes.size() >= 3);  // H/R too unless 4 realizations leave no core edge
  for (const char* file : {"REPORT.md", "summary.json", "tvns.json", "hydro/core.json", "md/blocks.csv",
                           "report-theory/verdict.json", "report-paper/report.md", "report-hydro/exponents.csv"})
    CHECK(fs::exists(config.out / file));
  std::ifstream in(config.out / "REPORT.md");
  const std::string report((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  check_amplitude_rows(report, r.against_hydro.amplitudes);
  // Prose numbers at their meaningful digits, not 17 (R/λ, the energy error, the wall time).
  CHECK(std::regex_search(report, std::regex("Running time exponents at R/λ = [0-9.]{1,7} \\(relative energy "
                                             "error [0-9.]+(e-[0-9]+)?\\)")));
  CHECK(std::regex_search(report, std::regex("collisions in [0-9.]{1,5} s; largest relative energy error "
                                             "[0-9](\\.[0-9])?e-[0-9]+\\.")));
  fs::remove_all(config.out);
}

TEST_CASE("reproduce rejects bad options before running anything", "[fast]") {
  ReproduceConfig config;
  config.hydro_until = 5;
  CHECK_THROWS_WITH(run_reproduce(config), Catch::Contains("--hydro-until"));
  CHECK_THROWS_WITH(parse_scale("huge"), Catch::Contains("--scale"));
}
