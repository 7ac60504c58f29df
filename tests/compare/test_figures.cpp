// The figure data compare/ writes from recorded runs: MD radial profiles stop at the edge of the
// simulated ball (data/campaign3-3d: region radius 148.7 = 1.31 R at t_max), so empty bins beyond
// it are not drawn as vacuum.
#include <catch2/catch.hpp>
#include <cmath>
#include <fstream>
#include <iterator>
#include <sstream>
#include <string>

#include "compare/figures.hpp"
#include "compare/run_data.hpp"
#include "tests/temp_path.hpp"
#include "theory/observables.hpp"
#include "theory/prefactors.hpp"

using namespace coldblast::compare;
namespace fs = std::filesystem;

TEST_CASE("MD profile figure data stop at the simulated region's edge", "[fast]") {
  const RunData run = read_run(fs::path(COLDBLAST_SOURCE_DIR) / "data" / "campaign3-3d");
  const double region = run.summary["region_radius"].get<double>();
  const fs::path folder = coldblast::test::unique_temp_path("coldblast_test_figures");
  fs::remove_all(folder);
  fs::create_directories(folder);
  const ExtraFigures figures = write_extra_figures(run, std::nullopt, {}, folder);
  CHECK(figures.profiles == "profiles.png");

  // R at t_max from the run's own shock radius series.
  const BlockSeries& R_series = run.series.at("R");
  const double R = R_series.ensemble_values().back();
  REQUIRE(region / R == Approx(1.312).margin(0.01));

  std::ifstream in(folder / "profiles_md.dat");
  REQUIRE(in);
  std::string line;
  int rows = 0;
  double largest = 0;
  while (std::getline(in, line)) {
    std::istringstream fields(line);
    double r, density, velocity, temperature;
    REQUIRE(fields >> r >> density >> velocity >> temperature);
    largest = std::max(largest, r);
    CHECK(density > 0.0);  // every drawn bin lies inside the ball, which is filled with gas
    ++rows;
  }
  // 30 bins of width 0.05 R up to 1.5 R; those ending beyond 1.312 R (bins 27..30) are left out.
  CHECK(rows == 26);
  CHECK(largest < region / R);
  // The panels' labels are the catalogue's (theory/observables.hpp), not retyped.
  std::ifstream gp(folder / "profiles.gp");
  const std::string script((std::istreambuf_iterator<char>(gp)), std::istreambuf_iterator<char>());
  REQUIRE(coldblast::theory::profile_fields().size() == 3);
  for (const auto& field : coldblast::theory::profile_fields())
    CHECK(script.find(std::string("set ylabel '") + field.label + "'") != std::string::npos);
  fs::remove_all(folder);
}

namespace {
// A run folder holding only p_imp.csv at t = 1 (spread 2/5 makes t^spread = 1), 400 bins of width
// 0.02 on [0, 8), p = density(r), per-bin error 1e-3 sqrt(p) (counting statistics: 0 where empty).
template <class Density>
RunData histogram_run(const std::string& name, Density density) {
  const fs::path dir = coldblast::test::unique_temp_path(name);
  fs::create_directories(dir);
  std::ofstream csv(dir / "p_imp.csv");
  csv.precision(17);
  csv << "t,bin,r_lo,r_hi,r,p,p_stderr,count\n";
  for (int i = 0; i < 400; ++i) {
    const double lo = 0.02 * i, hi = lo + 0.02, r = 0.5 * (lo + hi);
    const double p = density(r);
    csv << "1," << i << ',' << lo << ',' << hi << ',' << r << ',' << p << ',' << 1e-3 * std::sqrt(p) << ",100\n";
  }
  RunData run;
  run.directory = dir;
  run.d = 2;
  return run;
}
}  // namespace

TEST_CASE("the impurity distribution's shape statistics: a Gaussian gives (d+2)/d, r exp(-r^4) gives pi/2", "[fast]") {
  // Eq. (39) with R_imp = 1.3: <r^4>/<r^2>^2 = 2 in 2D whatever the width, chi^2 = 0 at the fit
  const RunData gaussian = histogram_run(
      "coldblast_shape_gaussian", [](double r) { return coldblast::theory::radial_position_density(2, r, 1.3); });
  const auto g = fit_impurity_distribution(gaussian);
  REQUIRE(g);
  CHECK(g->b_fit == Approx(1.3).epsilon(1e-6));
  CHECK(g->moment_ratio_gaussian == 2.0);
  CHECK(g->moment_ratio == Approx(2.0).epsilon(1e-3));  // midpoint sums over bins of 0.02
  CHECK(g->chi2_per_dof < 1e-6);
  CHECK(g->weighted_bins == 400);
  // p ∝ r exp(-r^4): <r^k> ∝ Γ((k+2)/4), so <r^4>/<r^2>^2 = Γ(3/2) Γ(1/2) / Γ(1)^2 = π/2; the
  // best Gaussian misses it by far more than the errors
  const RunData quartic = histogram_run("coldblast_shape_quartic", [](double r) {
    const double p = 4.0 / std::sqrt(M_PI) * r * std::exp(-r * r * r * r);
    return p < 1e-300 ? 0.0 : p;  // no denormals in the CSV
  });
  const auto q = fit_impurity_distribution(quartic);
  REQUIRE(q);
  CHECK(q->moment_ratio == Approx(M_PI / 2).epsilon(1e-3));
  CHECK(q->moment_ratio_error > 0.0);
  CHECK(std::abs(q->moment_ratio - 2.0) > 100 * q->moment_ratio_error);
  CHECK(q->chi2_per_dof > 100.0);
  fs::remove_all(gaussian.directory);
  fs::remove_all(quartic.directory);
}
