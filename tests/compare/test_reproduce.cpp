// End to end on a tiny scale: every step runs, the files exist, and the numbers that have an
// exact reference (A_2, A_3, the NS exponents' approach, the MD's energy conservation) hold.
#include <catch2/catch.hpp>
#include <cmath>
#include <filesystem>

#include "compare/reproduce.hpp"
#include "tests/temp_path.hpp"

using namespace coldblast::compare;
namespace fs = std::filesystem;

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
  fs::remove_all(config.out);
}

TEST_CASE("reproduce rejects bad options before running anything", "[fast]") {
  ReproduceConfig config;
  config.hydro_until = 5;
  CHECK_THROWS_WITH(run_reproduce(config), Catch::Contains("--hydro-until"));
  CHECK_THROWS_WITH(parse_scale("huge"), Catch::Contains("--scale"));
}
