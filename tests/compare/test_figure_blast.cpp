// The paper's Fig. 1 from a synthetic run folder whose every drawn quantity is known: which
// particles fall in the frame and (3D) the slab, the impurity paths cut at each snapshot time and
// ending at the impurity's snapshot position, R_imp interpolated in (ln t, ln R_imp) and the shock
// radius of Eq. (1).
#include <catch2/catch.hpp>
#include <cmath>
#include <fstream>
#include <string>

#include "compare/figure_blast.hpp"
#include "tests/temp_path.hpp"
#include "theory/prefactors.hpp"

using namespace coldblast::compare;
namespace fs = std::filesystem;

namespace {

fs::path fresh_folder(const std::string& name) {
  const fs::path dir = coldblast::test::unique_temp_path(name);
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

// A 3D run: n = 0.2, a = 0.5, E = 8, A_d = 0.5; snapshots at t = 4 and 16; impurity 7 with
// collisions at t = 1, 3, 10; R_imp^2 means 1 at t = 1 and 16 at t = 16 (so R_imp = 1 and 4).
RunData synthetic_run(const fs::path& dir) {
  RunData run;
  run.directory = dir;
  run.d = 3;
  run.summary = {{"a", 0.5}, {"n", 0.2}, {"E", 8.0}, {"A_d", 0.5}, {"lambda", 1.0}, {"region_radius", 100.0}};
  BlockSeries r_imp;
  r_imp.observable = "R_imp";
  r_imp.transform = transform_for("R_imp");
  r_imp.t = {1.0, 16.0};
  r_imp.sums = {{1.0, 16.0}};
  r_imp.counts = {{1.0, 1.0}};
  run.series["R_imp"] = r_imp;
  for (const double t : {4.0, 16.0}) {
    std::ofstream csv(dir / ("snapshot_" + std::to_string(static_cast<int>(t)) + ".csv"));
    csv << "# a comment line\nid,x,y,z,moving,impurity\n"
        << "0,0.5,0.5,0.0,1,0\n"            // in the slab, moving
        << "1,-1.0,2.0,0.9,0,0\n"           // in the slab (|z| < 2a = 1), resting
        << "2,1.0,1.0,1.5,1,0\n"            // outside the slab
        << "3,1000.0,0.0,0.0,0,0\n"         // outside the frame
        << "7," << t << ",-2.0,0.0,1,1\n";  // the impurity, in the slab, moving
  }
  std::ofstream trajectories(dir / "trajectories.csv");
  trajectories << "id,t,x,y,z\n7,0,0,0,0\n7,1,1,0,0\n7,3,2,1,0\n7,10,3,-1,0\n7,16,16,-2,0\n";
  return run;
}

}  // namespace

TEST_CASE("blast figure panels: at most four snapshot times, spread from the first to the last", "[fast]") {
  CHECK(blast_panel_times({3.0, 1.0}) == std::vector<double>{1.0, 3.0});
  CHECK(blast_panel_times({1, 2, 3, 4, 5, 6}) == std::vector<double>{1, 3, 4, 6});
  CHECK(blast_panel_times({}).empty());
}

TEST_CASE("blast figure of a 3D run: slab, frame, paths cut at each time, R_imp and Eq. (1)", "[fast]") {
  const fs::path dir = fresh_folder("coldblast_test_figure_blast");
  const RunData run = synthetic_run(dir);
  const BlastFigure figure = blast_figure(run, dir, /*draw=*/false);
  REQUIRE(figure.file == "fig1.png");
  REQUIRE(figure.panels.size() == 2);
  CHECK(figure.slab == 1.0);
  const coldblast::theory::BlastParameters blast{3, 0.2, 0.5, 8.0, 0.5};
  CHECK(figure.half_width == Approx(1.1 * coldblast::theory::shock_radius(blast, 16.0)).epsilon(1e-14));
  const BlastPanel& early = figure.panels[0];
  CHECK(early.t == 4.0);
  CHECK(early.moving == 2);                          // particle 0 and the impurity
  CHECK(early.resting == 1);                         // particle 1; particle 2 is outside the slab, 3 outside the frame
  CHECK(early.R_imp == Approx(2.0).epsilon(1e-14));  // sqrt(1 * 4): halfway in ln t between 1 and 16
  CHECK(early.R_shock == Approx(coldblast::theory::shock_radius(blast, 4.0)).epsilon(1e-14));
  REQUIRE(early.paths.size() == 1);
  // the start and the collisions at t = 1 and 3, then the snapshot position (x = t)
  const std::vector<std::array<double, 2>> path_4{{0, 0}, {1, 0}, {2, 1}, {4, -2}};
  CHECK(early.paths[0] == path_4);
  const BlastPanel& late = figure.panels[1];
  CHECK(late.R_imp == Approx(4.0).epsilon(1e-14));
  REQUIRE(late.paths.size() == 1);
  CHECK(late.paths[0].size() == 6);  // 0, 1, 3, 10, 16 (the end point) and the snapshot position
  CHECK(late.paths[0].back() == std::array<double, 2>{16, -2});
  for (const char* name : {"fig1.gp", "fig1_particles_0.dat", "fig1_lines_1.dat"}) CHECK(fs::exists(dir / name));
  fs::remove_all(dir);
}

TEST_CASE("blast figure: nothing without snapshots, a clear error for a misnamed one", "[fast]") {
  const fs::path dir = fresh_folder("coldblast_test_figure_blast_empty");
  RunData run;
  run.directory = dir;
  run.d = 2;
  CHECK(blast_figure(run, dir, false).file.empty());
  CHECK(fs::is_empty(dir));
  std::ofstream(dir / "snapshot_late.csv") << "id,x,y,moving,impurity\n";
  CHECK_THROWS_WITH(blast_figure(run, dir, false), Catch::Contains("snapshot_late.csv") && Catch::Contains("number t"));
  fs::remove_all(dir);
}

TEST_CASE("blast figure is drawn as a PNG and a PDF of two panels side by side", "[fast]") {
  if (std::system("gnuplot --version > /dev/null 2>&1") != 0) {
    WARN("gnuplot is not installed: the PNG is not checked");
    return;
  }
  const fs::path dir = fresh_folder("coldblast_test_figure_blast_png");
  const BlastFigure figure = blast_figure(synthetic_run(dir), dir);
  std::ifstream png(dir / figure.file, std::ios::binary);
  unsigned char header[24] = {};
  REQUIRE(png.read(reinterpret_cast<char*>(header), 24));
  CHECK(std::string(reinterpret_cast<char*>(header) + 1, 3) == "PNG");
  const auto be32 = [&](int k) {
    return (header[k] << 24) | (header[k + 1] << 16) | (header[k + 2] << 8) | header[k + 3];
  };
  CHECK(be32(16) == 2 * 720);   // width: two columns
  CHECK(be32(20) == 740 + 80);  // height: one row and the legend's strip below it
  std::ifstream pdf(dir / "fig1.pdf", std::ios::binary);
  std::string magic(5, '\0');
  REQUIRE(pdf.read(magic.data(), 5));
  CHECK(magic == "%PDF-");
  fs::remove_all(dir);
}
