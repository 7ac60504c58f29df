// End to end on a tiny scale: every step runs, the files exist, and the numbers that have an
// exact reference (A_2, A_3, the NS exponents' approach, the MD's energy conservation, the
// tracer's Enskog factor) hold.
#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <regex>
#include <string>

#include "common/validate.hpp"
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
    const std::regex row("\\| " + std::regex_replace(a.name, std::regex("[\\^/()]"), "\\$&") +
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

/// Step 4: the tracer of the paper scene in the dense NS background, against the MD at t = 4000.
void check_tracer(const ReproduceResult& r, const std::string& report) {
  CHECK(r.tracer["trajectories"].get<long long>() == 600);
  CHECK(r.tracer["background"].get<std::string>() == "ns");
  CHECK(r.tracer["transport"].get<std::string>() == "enskog");
  // Henderson's contact value (1 − 7φ/16)/(1 − φ)² at the MD's φ: the Enskog factor of the collisions.
  const double phi = r.phi_md;
  CHECK(r.tracer["chi"].get<double>() == Approx((1 - 7 * phi / 16) / ((1 - phi) * (1 - phi))).epsilon(1e-12));
  REQUIRE(r.tracer_vs_md.tracer_md);
  const TracerMdComparison& c = *r.tracer_vs_md.tracer_md;
  REQUIRE(c.series.size() == 3);
  CHECK(c.distribution.has_value());
  for (const auto& s : c.series) {
    const TracerMdPoint& p = s.points.back();
    INFO(s.observable << ": tracer " << p.tracer << " ± " << p.tracer_error << ", MD " << p.md << " ± " << p.md_error);
    CHECK(p.t == 4000);
    CHECK(p.tracer_error > 0);
    // R_imp and V_imp agree with the MD within a few % at 1e5 trajectories and 384 realizations
    // (docs/verification.md); with 600 and 4 they agree within the errors.
    if (s.observable != "C_imp") CHECK(std::abs(p.ratio) < 4 * p.ratio_error);
    const std::string row =
        "| " + s.observable + " | " + coldblast::common::format_measurement(p.tracer, p.tracer_error) + " | " +
        coldblast::common::format_measurement(p.md, p.md_error) + " | " + format_ratio_percent(p) + " |";
    CHECK(report.find(row) != std::string::npos);
  }
  CHECK(report.find("600 trajectories of the Lorentz–Boltzmann equation in the Navier-Stokes core (dense: henderson "
                    "EOS at phi = 0.1178, Enskog transport") != std::string::npos);
}
}  // namespace

TEST_CASE("reproduce runs every step and writes the report", "[slow]") {
  ReproduceConfig config;
  config.out = coldblast::test::unique_temp_path("coldblast_test_reproduce");
  fs::remove_all(config.out);
  config.realizations = 4;
  config.hydro_until = 50;
  config.tracer_trajectories = 600;
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
                           "tracer/summary.json", "tracer/moments.csv", "report-theory/verdict.json",
                           "report-paper/report.md", "report-hydro/exponents.csv", "report-tracer/tracer_vs_md.csv"})
    CHECK(fs::exists(config.out / file));
  std::ifstream in(config.out / "REPORT.md");
  const std::string report((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  check_amplitude_rows(report, r.against_hydro.amplitudes);
  check_tracer(r, report);
  // The summary comes first: each comparison's word, then one line per verdict that is not a pass
  // saying why, then its warnings (4 realizations: 4 jackknife blocks, fewer than 8).
  CHECK(report.find("# coldblast reproduce\n\n## Summary\n\n- A_2 = 0.351935906848599 ± 2.5e-14, A_3 = ") == 0);
  const std::pair<std::string, const CompareResult*> summaries[] = {
      {"- MD (4 realizations) against theory: ", &r.against_theory},
      {"- against the paper's Table 1: ", &r.against_paper},
      {"- against the Navier–Stokes prediction: ", &r.against_hydro}};
  for (const auto& [head, result] : summaries) {
    std::string lines = head + verdict_word(*result) + "\n";
    const std::vector<std::string> reasons = verdict_reasons(*result);
    for (const auto& reason : reasons) lines += "  - " + reason + "\n";
    for (const auto& warning : result->warnings) lines += "  - warning: " + warning + "\n";
    INFO(head);
    CHECK(report.find(lines) != std::string::npos);
    CHECK(reasons.size() ==
          static_cast<std::size_t>(std::count_if(result->observables.begin(), result->observables.end(),
                                                 [](const ObservableVerdict& v) { return !v.pass; }) +
                                   std::count_if(result->amplitudes.begin(), result->amplitudes.end(),
                                                 [](const AmplitudeVerdict& a) { return !a.pass; })));
    CHECK_THAT(result->warnings.at(0), Catch::StartsWith("only 4 jackknife blocks"));
  }
  CHECK(r.tracer_vs_md.continuum == r.against_hydro.continuum);  // one solve for the scene
  CHECK(report.find("- kinetic tracer (Eq. (36), 600 trajectories, nothing fitted) against the MD at t = 4000: R_imp " +
                    format_ratio_percent(r.tracer_vs_md.tracer_md->series[0].points.back())) != std::string::npos);
  CHECK(report.find(".png") == std::string::npos);  // figures = false: no links to figures not drawn
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
  config.hydro_until = 0;
  config.tracer_trajectories = 1;
  CHECK_THROWS_WITH(run_reproduce(config), Catch::Contains("--tracer-trajectories = 1"));
  config.tracer_trajectories = 0;
  // --md-run must be an MD run of the paper's 2D scene: checked before any step runs.
  const fs::path data = fs::path(COLDBLAST_SOURCE_DIR) / "data";
  config.md_run = data / "campaign3-3d";
  CHECK_THROWS_WITH(run_reproduce(config), Catch::Contains("--md-run = ") &&
                                               Catch::Contains("is not a run of the paper's 2D scene: its d is 3, "
                                                               "the paper scene's 2"));
  // Campaigns 2 and 4 share d, n, a and E but not t_max or the impurity.
  CHECK_THROWS_WITH(check_paper_md_run(data / "campaign2-2d-long"), Catch::Contains("its t_min is 0.6103515625"));
  CHECK_THROWS_WITH(check_paper_md_run(data / "campaign4-heavy"),
                    Catch::Contains("its impurities.mass is 10, the paper scene's 1"));
  CHECK_THROWS_WITH(check_paper_md_run(data / "campaign4-large"),
                    Catch::Contains("its impurities.radius is 2.5, the paper scene's 0"));
  config.md_run = "/nonexistent";
  CHECK_THROWS_WITH(run_reproduce(config), Catch::StartsWith("--md-run: "));
  CHECK_NOTHROW(check_paper_md_run(data / "campaign1-paper-2d"));
  CHECK_NOTHROW(check_paper_md_run(data / "paper-2d"));
  // The paper scene with recollisions switched off is a numerical experiment, not the paper's MD.
  CHECK_NOTHROW(check_paper_md_run(data / "recollisions" / "unit"));
  CHECK_THROWS_WITH(check_paper_md_run(data / "recollisions" / "unit-no-recollisions"),
                    Catch::Contains("its impurities.recollide is false, the paper scene's true"));
}
