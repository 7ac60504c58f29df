// snapshots.extxyz (md/extxyz.hpp) read back as a viewer reads it: one frame per snapshot time,
// the comment line's Lattice / Origin / Time / Properties, every particle once, the impurity count,
// z = 0 with a third cell vector in 2D, and the kinetic energy from the velocity and mass columns
// equal to E (elastic collisions conserve it exactly up to rounding).
#include <catch2/catch.hpp>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "run/ensemble.hpp"
#include "run/run_files.hpp"
#include "run/scene_file.hpp"
#include "tests/temp_path.hpp"

using namespace coldblast::md;
using namespace coldblast::run;
namespace fs = std::filesystem;

namespace {

struct Frame {
  std::string comment;
  std::vector<std::vector<std::string>> rows;
};

std::vector<Frame> read_frames(const fs::path& file) {
  std::ifstream in(file);
  std::vector<Frame> frames;
  std::string line;
  while (std::getline(in, line)) {
    const std::size_t n = std::stoul(line);
    Frame frame;
    REQUIRE(std::getline(in, frame.comment));
    for (std::size_t i = 0; i < n; ++i) {
      REQUIRE(std::getline(in, line));
      std::istringstream fields(line);
      std::vector<std::string> row;
      for (std::string f; fields >> f;) row.push_back(f);
      frame.rows.push_back(row);
    }
    frames.push_back(frame);
  }
  return frames;
}

std::string key(const std::string& comment, const std::string& name) {
  std::smatch m;
  const std::regex quoted(name + "=\"([^\"]*)\""), bare(name + "=(\\S+)");
  if (std::regex_search(comment, m, quoted) || std::regex_search(comment, m, bare)) return m[1];
  FAIL("no " << name << " in " << comment);
  return "";
}

std::vector<double> numbers(const std::string& text) {
  std::istringstream in(text);
  std::vector<double> out;
  for (double x; in >> x;) out.push_back(x);
  return out;
}

}  // namespace

TEST_CASE("snapshots.extxyz parses back: frames, particles, impurities, cell, energy = E", "[fast]") {
  const int d = GENERATE(2, 3);
  const double E = d == 2 ? 10.0 : 6.0, mass = d == 2 ? 1.0 : 3.0;
  INFO("d = " << d);
  const BlastConfig scene = parse_scene(
      default_scene_toml(),
      {"d=" + std::to_string(d), "E=" + std::to_string(E), "t_max=20", "realizations=1", d == 2 ? "n=0.15" : "n=0.1",
       "box_margin=6", "A_d=0.3", "snapshot_times=[5.0, 10.0, 20.0]", "impurities.count=3",
       "impurities.mass=" + std::to_string(mass), R"(observables=["R","snapshots"])"});
  const ResolvedScene resolved = resolve_scene(scene);
  const fs::path dir = coldblast::test::unique_temp_path("coldblast_test_extxyz_" + std::to_string(d));
  fs::remove_all(dir);
  write_blast_outputs(run_blast(scene, RunOptions{}), dir);

  const std::vector<Frame> frames = read_frames(dir / "snapshots.extxyz");
  REQUIRE(frames.size() == 3);
  const double times[] = {5.0, 10.0, 20.0};
  const double L = 2.0 * resolved.region_radius;
  for (std::size_t f = 0; f < frames.size(); ++f) {
    const Frame& frame = frames[f];
    INFO("frame " << f << ": " << frame.comment);
    CHECK(std::stod(key(frame.comment, "Time")) == times[f]);
    CHECK(key(frame.comment, "Properties") ==
          "species:S:1:pos:R:3:velo:R:3:mass:R:1:radius:R:1:moving:I:1:collisions:I:1");
    CHECK(key(frame.comment, "pbc") == "F F F");
    // Lattice: three vectors, diagonal; the d region sides 2 R_region, in 2D a third of length 2a.
    const std::vector<double> lattice = numbers(key(frame.comment, "Lattice"));
    REQUIRE(lattice.size() == 9);
    CHECK(lattice == std::vector<double>{L, 0, 0, 0, L, 0, 0, 0, d == 3 ? L : 2.0 * scene.a});
    const std::vector<double> origin = numbers(key(frame.comment, "Origin"));
    REQUIRE(origin.size() == 3);
    CHECK(origin[0] == -resolved.region_radius);
    CHECK(origin[2] == (d == 3 ? -resolved.region_radius : -scene.a));

    REQUIRE(frame.rows.size() == resolved.particle_count);
    int impurities = 0;
    double energy = 0.0;
    for (const auto& row : frame.rows) {
      REQUIRE(row.size() == 11);
      const bool impurity = row[0] == "I";
      CHECK((impurity || row[0] == "H"));
      impurities += impurity;
      double v2 = 0.0;
      for (int k = 0; k < 3; ++k) {
        const double x = std::stod(row[1 + k]), v = std::stod(row[4 + k]);
        CHECK(std::abs(x) <= resolved.region_radius);  // inside the cell
        if (k >= d) CHECK((x == 0.0 && v == 0.0));     // 2D: z = 0
        v2 += v * v;
      }
      const double m = std::stod(row[7]);
      CHECK(m == (impurity ? mass : 1.0));
      CHECK(std::stod(row[8]) == (impurity ? resolved.impurity_radius : scene.a));
      if (row[9] == "0") CHECK(v2 == 0.0);  // a resting particle has no velocity
      if (std::stol(row[10]) > 0) CHECK((row[9] == "1"));
      energy += 0.5 * m * v2;
    }
    CHECK(impurities == 3);
    CHECK(energy == Approx(E).epsilon(1e-12));
  }
  fs::remove_all(dir);
}
