// Regression against the reference ensembles in data/paper-2d/ and data/recollisions/ (with and
// without recollisions, and the contact shells): a small
// fresh MD ensemble of the paper's scene (different seed) must agree with the reference means
// within the combined statistical error at every recorded time from t = 256 on. The bound is 4.5 sigma per point; with
// ~70 points the chance of a false alarm is ~5e-4. A change of physics, seeding or observable
// definition moves the means by many sigma.
#include <catch2/catch.hpp>
#include <cmath>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "hydro/tvns.hpp"
#include "run/ensemble.hpp"
#include "run/scene_file.hpp"

using namespace coldblast;
namespace fs = std::filesystem;

namespace {
/// Compares the fresh ensemble's estimates with every row of a reference observables.csv at
/// t >= 256 (the names the fresh run records): each within 4.5 combined standard errors. Returns
/// the number of points compared.
int agreeing_points(const fs::path& reference_csv, const run::BlastResult& fresh, unsigned seed) {
  std::map<std::pair<double, std::string>, run::ObservableEstimate> fresh_by_key;
  for (const auto& e : run::estimate_observables(fresh)) fresh_by_key[{e.t, e.observable}] = e;
  // observables.csv stores the names as text, so match rows by (t, name) from the raw file.
  std::ifstream in(reference_csv);
  REQUIRE(in);
  std::string line;
  int compared = 0;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#' || line.rfind("t,", 0) == 0) continue;
    std::stringstream row(line);
    std::string t_text, name, mean_text, stderr_text;
    std::getline(row, t_text, ',');
    std::getline(row, name, ',');
    std::getline(row, mean_text, ',');
    std::getline(row, stderr_text, ',');
    const double t = std::stod(t_text);
    const auto found = fresh_by_key.find({t, name});
    if (t < 256 || found == fresh_by_key.end()) continue;
    const double combined = std::hypot(std::stod(stderr_text), found->second.stderr_);
    INFO("seed " << seed << ", t = " << t << ", " << name << ": reference " << mean_text << " ± " << stderr_text
                 << ", fresh " << found->second.mean << " ± " << found->second.stderr_);
    CHECK(std::abs(found->second.mean - std::stod(mean_text)) < 4.5 * combined);
    ++compared;
  }
  return compared;
}
}  // namespace

TEST_CASE("a fresh small ensemble of the paper scene is consistent with data/paper-2d", "[slow]") {
  const fs::path reference_dir = fs::path(COLDBLAST_SOURCE_DIR) / "data" / "paper-2d";
  // The reference scene, read back from the reference's own scene file, with a new seed.
  std::ifstream scene_file(reference_dir / "scene.toml");
  std::stringstream scene_text;
  scene_text << scene_file.rdbuf();
  const unsigned seed = 20261121;
  md::BlastConfig scene =
      run::parse_scene(scene_text.str(), {"realizations=48", "block_size=4", "seed=" + std::to_string(seed),
                                          "observables=[\"R_imp\",\"V_imp\",\"C_imp\",\"n0\",\"T0\",\"R\"]"});
  run::RunOptions options;
  options.threads = 2;
  const run::BlastResult fresh = run::run_blast(scene, options);
  std::map<std::pair<double, std::string>, run::ObservableEstimate> fresh_by_key;
  for (const auto& e : run::estimate_observables(fresh)) fresh_by_key[{e.t, e.observable}] = e;

  CHECK(agreeing_points(reference_dir / "observables.csv", fresh, seed) >= 40);
}

namespace {
/// 24 fresh realizations of the paper scene with the heavy impurity (mass 10), seed `seed`, the
/// extra scene keys and `md run`'s box and p_imp bins (A_d(phi)).
run::BlastResult fresh_heavy_ensemble(unsigned seed, std::vector<std::string> keys) {
  std::ifstream scene_file(fs::path(COLDBLAST_SOURCE_DIR) / "scenes" / "paper-2d.toml");
  std::stringstream scene_text;
  scene_text << scene_file.rdbuf();
  keys.insert(keys.end(), {"realizations=24", "block_size=2", "seed=" + std::to_string(seed), "impurities.mass=10"});
  run::RunOptions options;
  options.threads = 2;
  return run::run_blast(run::parse_scene(scene_text.str(), keys), options);
}
}  // namespace

TEST_CASE("a fresh heavy-impurity ensemble has data/recollisions' C_imp, C_re, dE_first and dE_re", "[slow]") {
  // The recollisions (C_re) and the energy lost in them and in first collisions are definitions: a
  // change of them (or of the engine's partner bookkeeping) moves them by many sigma. 24 realizations against the 256
  // of the reference.
  const unsigned seed = 20261124;
  const run::BlastResult fresh =
      fresh_heavy_ensemble(seed, {"observables=[\"C_imp\",\"C_re\",\"dE_first\",\"dE_re\"]"});
  CHECK(agreeing_points(fs::path(COLDBLAST_SOURCE_DIR) / "data" / "recollisions" / "heavy" / "observables.csv", fresh,
                        seed) >= 4 * 10);
}

TEST_CASE("a fresh heavy-impurity ensemble without recollisions has data/recollisions/heavy-no-recollisions' means",
          "[slow]") {
  // impurities.recollide = false (a pair with an impurity collides once): R_imp, V_imp and C_imp of
  // 24 fresh realizations against the 256 of the reference. A change of the switch's rule (say,
  // letting impurity pairs recollide, or ghosting host pairs) moves C_imp by many sigma.
  const unsigned seed = 20261125;
  const run::BlastResult fresh =
      fresh_heavy_ensemble(seed, {"impurities.recollide=false", "observables=[\"R_imp\",\"V_imp\",\"C_imp\"]"});
  const fs::path reference = fs::path(COLDBLAST_SOURCE_DIR) / "data" / "recollisions" / "heavy-no-recollisions";
  CHECK(agreeing_points(reference / "observables.csv", fresh, seed) >= 4 * 10);
}

TEST_CASE("a fresh heavy-impurity ensemble has data/recollisions/heavy-shells' contact-shell densities and drift",
          "[slow]") {
  // g_front, g_back, u_front are definitions (the shell, its sides, the units): a change of them
  // moves the bow's numbers of docs/verification.md by many sigma.
  const unsigned seed = 20261126;
  const run::BlastResult fresh = fresh_heavy_ensemble(seed, {"observables=[\"g_front\",\"g_back\",\"u_front\"]"});
  const fs::path reference = fs::path(COLDBLAST_SOURCE_DIR) / "data" / "recollisions" / "heavy-shells";
  CHECK(agreeing_points(reference / "observables.csv", fresh, seed) >= 3 * 10);
}
