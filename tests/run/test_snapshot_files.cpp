// Snapshots (run/snapshot_files.*): snapshots.extxyz read back as a viewer reads it (one frame per
// snapshot time, the comment line's Lattice / Origin / Time / Properties / run_id, every particle
// once, the impurity count, z = 0 with a third cell vector in 2D, and the kinetic energy from the
// velocity and mass columns equal to E: elastic collisions conserve it exactly up to rounding); the
// default subset (the moving particles and the resting ones within the margin of the front: exactly
// those, a small share of a 3D region, near the size estimate), the stride, any realization, times
// as fractions of t_max, and the warning above 100 MB.
#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "common/validate.hpp"
#include "md/initial_state.hpp"
#include "md/realization.hpp"
#include "run/ensemble.hpp"
#include "run/run_files.hpp"
#include "run/scene_file.hpp"
#include "run/snapshot_files.hpp"
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
       "impurities.mass=" + std::to_string(mass), R"(observables=["R","snapshots"])", "snapshot_particles=\"all\""});
  const ResolvedScene resolved = resolve_scene(scene);
  const fs::path dir = coldblast::test::unique_temp_path("coldblast_test_extxyz_" + std::to_string(d));
  fs::remove_all(dir);
  const BlastResult result = run_blast(scene, RunOptions{});
  write_blast_outputs(result, dir);

  const std::vector<Frame> frames = read_frames(dir / "snapshots.extxyz");
  REQUIRE(frames.size() == 3);
  const double times[] = {5.0, 10.0, 20.0};
  const double L = 2.0 * resolved.region_radius;
  for (std::size_t f = 0; f < frames.size(); ++f) {
    const Frame& frame = frames[f];
    INFO("frame " << f << ": " << frame.comment);
    CHECK(std::stod(key(frame.comment, "Time")) == times[f]);
    CHECK(key(frame.comment, "Properties") ==
          "Z:I:1:type_name:S:1:typeid:I:1:id:I:1:pos:R:3:velo:R:3:momenta:R:3:masses:R:1:radius:R:1:moving:I:1:"
          "collisions:I:1");
    CHECK(key(frame.comment, "dimensions") == std::to_string(d));
    CHECK(key(frame.comment, "pbc") == "F F F");
    CHECK(key(frame.comment, "run_id") == result.run_id);
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
    std::vector<long> ids;
    for (const auto& row : frame.rows) {
      REQUIRE(row.size() == 17);
      CHECK(row[0] == "0");  // Z = 0: ASE's dummy atom, no element
      const bool impurity = row[1] == "impurity";
      CHECK((impurity || row[1] == "host"));
      CHECK(row[2] == (impurity ? "1" : "0"));
      ids.push_back(std::stol(row[3]));
      impurities += impurity;
      const double m = std::stod(row[13]);
      CHECK(m == (impurity ? mass : 1.0));
      double v2 = 0.0;
      for (int k = 0; k < 3; ++k) {
        const double x = std::stod(row[4 + k]), v = std::stod(row[7 + k]), p = std::stod(row[10 + k]);
        CHECK(std::abs(x) <= resolved.region_radius);  // inside the cell
        if (k >= d) CHECK((x == 0.0 && v == 0.0));     // 2D: z = 0
        CHECK(p == m * v);                             // momenta: ASE's get_velocities divides by masses
        v2 += v * v;
      }
      CHECK(std::stod(row[14]) == (impurity ? resolved.impurity_radius : scene.a));
      if (row[15] == "0") CHECK(v2 == 0.0);  // a resting particle has no velocity
      if (std::stol(row[16]) > 0) CHECK((row[15] == "1"));
      energy += 0.5 * m * v2;
    }
    // every particle once, ids ascending
    CHECK(std::is_sorted(ids.begin(), ids.end()));
    CHECK(std::adjacent_find(ids.begin(), ids.end()) == ids.end());
    CHECK(impurities == 3);
    CHECK(energy == Approx(E).epsilon(1e-12));
  }
  fs::remove_all(dir);
}

namespace {
/// The rows of a snapshot CSV: (id, position, moving).
struct Row {
  long long id;
  std::vector<double> x;
  bool moving;
};
std::vector<Row> snapshot_rows(const fs::path& file, int d) {
  std::ifstream in(file);
  std::vector<Row> rows;
  std::string line;
  bool header = false;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    if (!header) {
      header = true;
      continue;
    }
    std::istringstream fields(line);
    std::vector<double> values;
    for (std::string f; std::getline(fields, f, ',');) values.push_back(std::stod(f));
    REQUIRE(values.size() == static_cast<std::size_t>(d + 3));
    rows.push_back({static_cast<long long>(values[0]), std::vector<double>(values.begin() + 1, values.begin() + 1 + d),
                    values[static_cast<std::size_t>(d) + 1] != 0.0});
  }
  return rows;
}
double norm(const std::vector<double>& x) {
  double s = 0.0;
  for (const double v : x) s += v * v;
  return std::sqrt(s);
}
}  // namespace

TEST_CASE("a 3D snapshot by default holds the moving particles and the resting ones within the margin, exactly",
          "[slow]") {
  // The 3D paper scene's gas (n = 0.225, a = 1/2), small E and t_max: a region of 1.2e5 particles.
  const std::vector<std::string> keys = {"d=3",
                                         "n=0.225",
                                         "E=5.7",
                                         "A_d=0.2243",
                                         "t_max=40",
                                         "realizations=1",
                                         "box_margin=5",
                                         R"(observables=["R","snapshots"])",
                                         "snapshot_fractions=[1.0]"};
  const fs::path dir = coldblast::test::unique_temp_path("coldblast_test_snapshot_subset");
  fs::remove_all(dir);
  std::vector<std::string> all_keys = keys;
  all_keys.push_back("snapshot_particles=\"all\"");
  const BlastResult all = run_blast(parse_scene(default_scene_toml(), all_keys), {});
  const BlastResult front = run_blast(parse_scene(default_scene_toml(), keys), {});
  write_blast_outputs(all, dir / "all");
  write_blast_outputs(front, dir / "front");
  const std::vector<Row> every = snapshot_rows(dir / "all" / "snapshot_40.csv", 3);
  const std::vector<Row> subset = snapshot_rows(dir / "front" / "snapshot_40.csv", 3);
  // Every particle of the realization's region: the first one, or one grown from it (md/realization.hpp).
  bool whole_region = false;
  for (int g = 0; g < 8; ++g)
    whole_region =
        whole_region || every.size() == coldblast::md::particles_within(all.scene, region_radius_after(all.scene, g));
  REQUIRE(whole_region);
  // The selection, recomputed from the full gas: the moving particles, and the resting ones no
  // farther from the origin than the farthest moving particle plus 5 host diameters (the default).
  double reach = 0.0;
  for (const Row& r : every)
    if (r.moving) reach = std::max(reach, norm(r.x));
  std::vector<long long> expected;
  for (const Row& r : every)
    if (r.moving || norm(r.x) <= reach + 5.0 * 2.0 * 0.5) expected.push_back(r.id);
  std::vector<long long> got;
  for (const Row& r : subset) got.push_back(r.id);
  CHECK(got == expected);
  const double share = static_cast<double>(subset.size()) / static_cast<double>(every.size());
  INFO("subset " << subset.size() << " of " << every.size() << " particles, reach " << reach);
  // The region's radius is box_margin = 5 times R(t_max) of Eq. (1) (plus guard bands), the front
  // (the particles ahead of the blast) + 5 diameters: the subset is a small part of the gas.
  CHECK(share < 0.25);
  // The size estimate that the 100 MB warning uses errs high while the blast forms (its radius is
  // md::early_reach_bound's when that exceeds 1.2 R(t)), never below half the files written.
  const double bytes = static_cast<double>(fs::file_size(dir / "front" / "snapshot_40.csv") +
                                           fs::file_size(dir / "front" / "snapshots.extxyz"));
  const double estimate = snapshot_bytes_estimate(front.scene);
  CHECK(estimate / bytes > 0.5);
  CHECK(estimate / bytes < 4.0);
  CHECK(snapshot_size_warning(front.scene).empty());
  // A stride keeps every stride-th particle of the selection.
  std::vector<std::string> strided = keys;
  strided.push_back("snapshot_stride=7");
  write_blast_outputs(run_blast(parse_scene(default_scene_toml(), strided), {}), dir / "stride");
  const std::vector<Row> sparse = snapshot_rows(dir / "stride" / "snapshot_40.csv", 3);
  REQUIRE(sparse.size() == (expected.size() + 6) / 7);
  for (std::size_t i = 0; i < sparse.size(); ++i) CHECK(sparse[i].id == expected[7 * i]);
  fs::remove_all(dir);
}

TEST_CASE("snapshots of any realization, at fractions of t_max", "[fast]") {
  const std::vector<std::string> keys = {"t_max=40",
                                         "realizations=4",
                                         "block_size=2",
                                         "A_d=0.3",
                                         R"(observables=["R","snapshots","trajectories"])",
                                         "snapshot_fractions=[0.25, 1.0]",
                                         "snapshot_realizations=[0, 3]"};
  const BlastConfig scene = parse_scene(default_scene_toml(), keys);
  const BlastResult result = run_blast(scene, {});
  std::vector<std::string> names;
  for (const auto& [name, content] : result.realization_files) names.push_back(name);
  CHECK(names == std::vector<std::string>{"snapshot_10.csv", "snapshot_10_realization_3.csv", "snapshot_40.csv",
                                          "snapshot_40_realization_3.csv", "snapshots.extxyz",
                                          "snapshots_realization_3.extxyz", "trajectories.csv",
                                          "trajectories_realization_3.csv"});
  // Realization 3's path starts where md puts its impurities (its own initial state, not realization 0's).
  const InitialState<2> start = blast_initial_state<2>(result.scene, 3);
  std::string trajectories;
  for (const auto& [name, content] : result.realization_files)
    if (name == "trajectories_realization_3.csv") trajectories = content;
  CHECK(trajectories.find("# realization: 3") != std::string::npos);
  for (std::size_t i = 0; i < start.size(); ++i)
    if (start.species[i] == impurity_species)
      CHECK(trajectories.find(std::to_string(i) + ",0," + coldblast::common::format_number(start.position[i][0])) !=
            std::string::npos);
  // Fractions follow t_max; they and the other keys are checked.
  CHECK(resolve_scene(parse_scene(default_scene_toml(), {"snapshot_fractions=[0.5]", "t_max=30", "A_d=0.3"}))
            .snapshot_times == std::vector<double>{15.0});
  CHECK_THROWS_WITH(parse_scene(default_scene_toml(), {"snapshot_fractions=[1.5]"}),
                    Catch::Contains("snapshot_fractions = 1.5 is outside (0, 1]"));
  CHECK_THROWS_WITH(parse_scene(default_scene_toml(), {"snapshot_fractions=[0.5]", "snapshot_times=[10.0]"}),
                    Catch::Contains("give one"));
  CHECK_THROWS_WITH(parse_scene(default_scene_toml(), {"snapshot_realizations=[40]"}),
                    Catch::Contains("snapshot_realizations = 40 is outside [0, 31]"));
  CHECK_THROWS_WITH(parse_scene(default_scene_toml(), {"snapshot_particles=\"some\""}),
                    Catch::Contains("snapshot_particles = some is not one of: front, all"));
  CHECK_THROWS_WITH(parse_scene(default_scene_toml(), {"snapshot_stride=0"}), Catch::Contains("snapshot_stride = 0"));
  // The scene text keeps the keys that differ from their defaults, and reads back to the same scene.
  CHECK(scene_toml(parse_scene(scene_toml(scene))) == scene_toml(scene));
  CHECK(scene_toml(parse_scene(default_scene_toml())).find("snapshot_particles") == std::string::npos);
}

TEST_CASE("the snapshots of the 3D paper scene's whole gas warn, with their size, before the run", "[fast]") {
  std::ifstream file(std::string(COLDBLAST_SOURCE_DIR) + "/scenes/paper-3d.toml");
  std::stringstream text;
  text << file.rdbuf();
  const std::vector<std::string> keys = {"A_d=0.2243", R"(observables=["R","snapshots"])",
                                         "snapshot_fractions=[0.5, 1.0]"};
  std::vector<std::string> all = keys;
  all.push_back("snapshot_particles=\"all\"");
  const ResolvedScene whole = resolve_scene(parse_scene(text.str(), all));
  const std::string warning = snapshot_size_warning(whole);
  INFO(warning);
  // 2 x 1.5e7 particles at 170 bytes: about 5 GB; the issue's run wrote 690 MB with its 2 times.
  CHECK(snapshot_bytes_estimate(whole) > 1e9);
  CHECK(warning.find("the snapshots will take about") == 0);
  CHECK(warning.find("snapshot_particles = \"all\" writes every particle of the region") != std::string::npos);
  // The default subset of the same snapshots leaves out the resting gas ahead of the blast (the
  // region is 1.3 R(t_max), box_margin): about half of it, and it still warns.
  const ResolvedScene subset = resolve_scene(parse_scene(text.str(), keys));
  CHECK(snapshot_bytes_estimate(subset) < 0.6 * snapshot_bytes_estimate(whole));
  CHECK(snapshot_size_warning(subset).find("the snapshots will take about") == 0);
  CHECK(snapshot_size_warning(subset).find("writes every particle") == std::string::npos);
}
