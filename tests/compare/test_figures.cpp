// The figure data compare/ writes from recorded runs: MD radial profiles stop at the edge of the
// simulated ball (data/campaign3-3d: region radius 148.7 = 1.31 R at t_max), so empty bins beyond
// it are not drawn as vacuum.
#include <cmath>
#include <fstream>
#include <sstream>

#include <catch2/catch.hpp>

#include "compare/figures.hpp"
#include "compare/run_data.hpp"

using namespace coldblast::compare;
namespace fs = std::filesystem;

TEST_CASE("MD profile figure data stop at the simulated region's edge", "[fast]") {
  const RunData run = read_run(fs::path(COLDBLAST_SOURCE_DIR) / "data" / "campaign3-3d");
  const double region = run.summary["region_radius"].get<double>();
  const fs::path folder = fs::temp_directory_path() / "coldblast_test_figures";
  fs::remove_all(folder);
  fs::create_directories(folder);
  const ExtraFigures figures = write_extra_figures(run, std::nullopt, folder);
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
  fs::remove_all(folder);
}
