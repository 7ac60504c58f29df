// The paper's Fig. 1 from a synthetic run folder whose every drawn quantity is known: which
// particles fall in the frame and (3D) the slab, the impurity paths cut at each snapshot time and
// ending at the impurity's snapshot position, R_imp interpolated in (ln t, ln R_imp) and the shock
// radius of Eq. (1).
#include <catch2/catch.hpp>
#include <cmath>
#include <fstream>
#include <string>

#include "common/input.hpp"
#include "common/output.hpp"
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

TEST_CASE("blast figure already drawn for the same run is copied, not drawn again; another script is drawn", "[fast]") {
  if (std::system("gnuplot --version > /dev/null 2>&1") != 0) {
    WARN("gnuplot is not installed: the copy is not checked");
    return;
  }
  const fs::path root = fresh_folder("coldblast_test_figure_blast_drawn");
  const fs::path first = root / "first", second = root / "second", third = root / "third";
  for (const fs::path& dir : {first, second, third}) fs::create_directories(dir);
  const RunData run = synthetic_run(root);
  blast_figure(run, first);
  // Markers in place of the drawn figures: a copy carries them, a drawing would not.
  coldblast::common::write_file_atomic(first / "fig1.png", "marker png");
  coldblast::common::write_file_atomic(first / "fig1.pdf", "marker pdf");
  CHECK(blast_figure(run, second, true, first).file == "fig1.png");
  CHECK(coldblast::common::read_text(second / "fig1.png") == "marker png");
  CHECK(coldblast::common::read_text(second / "fig1.pdf") == "marker pdf");
  CHECK(coldblast::common::read_text(second / "fig1.gp") == coldblast::common::read_text(first / "fig1.gp"));
  // The same script over other data there (a particle moved): this one is drawn.
  const fs::path fourth = root / "fourth";
  fs::create_directories(fourth);
  std::string particles = coldblast::common::read_text(first / "fig1_particles_0.dat");
  particles[0] = particles[0] == '9' ? '8' : '9';
  coldblast::common::write_file_atomic(first / "fig1_particles_0.dat", particles);
  blast_figure(run, fourth, true, first);
  CHECK(coldblast::common::read_text(fourth / "fig1.png").substr(1, 3) == "PNG");
  // Another run's script there (another E: another title and shock radius): this one is drawn.
  RunData other = run;
  other.summary["E"] = 9.0;
  blast_figure(other, first, false);
  REQUIRE(coldblast::common::read_text(first / "fig1.gp") != coldblast::common::read_text(second / "fig1.gp"));
  blast_figure(run, third, true, first);
  CHECK(coldblast::common::read_text(third / "fig1.png").substr(1, 3) == "PNG");
  CHECK(coldblast::common::read_text(third / "fig1.pdf").substr(0, 5) == "%PDF-");
  fs::remove_all(root);
}

TEST_CASE("blast figure's PDF draws each particle as a point of its disc's size in the frame", "[fast]") {
  const fs::path dir = fresh_folder("coldblast_test_figure_blast_pdf_points");
  const BlastFigure figure = blast_figure(synthetic_run(dir), dir, false);
  REQUIRE(figure.panels.size() == 2);
  // Two panels side by side on 1440 x 820 pixels (10 x 5.69 in): each plot box is 0.42 of the width
  // (margins 0.06 and 0.98, spacing 0.08) = 4.2 in, less than its height (0.76 of 5.69 in), so the
  // square frame of 2 half_width spans 4.2 in. A disc of radius r is 2 r 4.2 / (2 half_width) inches
  // across, and pdfcairo's point type 7 is 0.0834 ps + 0.003 inches across.
  const double slope = 2.0 * 4.2 / (2.0 * figure.half_width) / 0.0834, offset = 0.003 / 0.0834;
  const std::string script = coldblast::common::read_text(dir / "fig1.gp");
  const std::string key = "disc_ps(r) = (r * ";
  const std::size_t at = script.find(key);
  REQUIRE(at != std::string::npos);
  CHECK(std::stod(script.substr(at + key.size())) == Approx(slope).epsilon(1e-5));
  const std::string minus = " - ";
  const std::size_t off = script.find(minus, at);
  REQUIRE(off != std::string::npos);
  CHECK(std::stod(script.substr(off + minus.size())) == Approx(offset).epsilon(1e-3));
  // The PNG keeps circles of the radius in data units; the PDF's points come from disc_ps.
  CHECK(script.find("u 1:2:3:($4 > 0 ? 0xd62728 : 0x8fb0e8) w circles") != std::string::npos);
  CHECK(script.find("u 1:2:(disc_ps($3)):($4 > 0 ? 0xd62728 : 0x8fb0e8) w p pt 7 ps variable lw 0.01") !=
        std::string::npos);
  fs::remove_all(dir);
}
