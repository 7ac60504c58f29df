// Scenes and ensembles: TOML parsing with overrides and rejected keys, the impurity kick (exact E,
// zero momentum), bit-identical results for 1 and 2 threads, and shards merged equal to the
// unsharded run.
#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <mutex>
#include <sstream>
#include <string>
#include <vector>

#include "md/ensemble.hpp"
#include "md/initial_state.hpp"
#include "md/scenes.hpp"
#include "tests/temp_path.hpp"

using namespace coldblast::md;
namespace fs = std::filesystem;

namespace {
BlastConfig small_scene() {
  return parse_scene(default_scene_toml(),
                     {"t_max=60", "realizations=7", "block_size=2", "A_d=0.351935906848599",
                      R"(observables=["R_imp","V_imp","C_imp","u_imp","n0","T0","R","profiles","p_imp"])"});
}
std::string data_lines(const fs::path& file) {
  std::ifstream in(file);
  std::string line, out;
  while (std::getline(in, line))
    if (!line.empty() && line[0] != '#') out += line + "\n";
  return out;
}
}  // namespace

TEST_CASE("scene parsing: overrides, dotted keys, unknown keys and ranges", "[fast]") {
  const BlastConfig c = parse_scene(default_scene_toml(), {"E=20", "impurities.count=3", "name=x"});
  CHECK(c.E == 20.0);
  CHECK(c.impurities.count == 3);
  CHECK(c.name == "x");
  CHECK(c.d == 2);
  CHECK_THROWS_WITH(parse_scene(default_scene_toml(), {"bogus=1"}), Catch::Contains("unknown scene key bogus"));
  CHECK_THROWS_WITH(parse_scene(default_scene_toml(), {"impurities.colour=1"}), Catch::Contains("impurities.colour"));
  CHECK_THROWS_WITH(parse_scene(default_scene_toml(), {"n=-1"}), Catch::Contains("n = -1"));
  CHECK_THROWS_WITH(parse_scene(default_scene_toml(), {"E=0"}), Catch::Contains("E = 0"));
  CHECK_THROWS_WITH(parse_scene(default_scene_toml(), {"n=0.8"}), Catch::Contains("phi"));
  CHECK_THROWS_WITH(parse_scene(default_scene_toml(), {"d=3", "n=0.8"}), Catch::Contains("0.3841"));
  CHECK_THROWS_WITH(parse_scene(default_scene_toml(), {R"(observables=["R_imp","magic"])"}), Catch::Contains("magic"));
  CHECK_THROWS_WITH(resolve_scene(parse_scene(default_scene_toml(), {"impurities.count=100000", "A_d=0.3"})),
                    Catch::Contains("impurities.count"));
  // The resolved TOML reads back to the same scene.
  const BlastConfig again = parse_scene(c.to_toml());
  CHECK(again.to_toml() == c.to_toml());
}

TEST_CASE("A_d = 0 takes the injected amplitude policy, written into the resolved scene; none is an error", "[fast]") {
  const BlastConfig c = parse_scene(default_scene_toml());
  REQUIRE(c.A_d == 0.0);
  CHECK_THROWS_WITH(resolve_scene(c), Catch::Contains("A_d = 0") && Catch::Contains("amplitude policy"));
  double phi_seen = 0.0;
  const AmplitudePolicy policy = [&](int d, double phi) {
    phi_seen = phi;
    return coldblast::theory::AmplitudeChoice{0.125 * d, "test policy"};
  };
  const ResolvedScene s = resolve_scene(c, policy);
  CHECK(phi_seen == s.phi);
  CHECK(s.A_d == 0.25);
  CHECK(s.config.A_d == 0.25);  // summary.json's scene carries it, so merges and resumes resolve alike
  CHECK(s.A_d_source == "test policy");
  const ResolvedScene given = resolve_scene(parse_scene(default_scene_toml(), {"A_d=0.25"}), policy);
  CHECK(given.A_d_source == "scene");
  CHECK(given.region_radius == s.region_radius);
  CHECK_THROWS_WITH(resolve_scene(c,
                                  [](int, double) {
                                    return coldblast::theory::AmplitudeChoice{-1.0, "bad"};
                                  }),
                    Catch::Contains("A_d = -1") && Catch::Contains("bad"));
}

TEST_CASE("impurity kick: energy exactly E, momentum exactly zero, the nearest particles", "[fast]") {
  auto rng = realization_rng(11, 3);
  InitialState<3> s;
  s.host = {0.5, 1.0};
  s.impurity = {0.8, 2.5};
  s.position = random_sequential_addition<3>(rng, 3000, 0.5, 15.0);
  s.velocity.assign(3000, Vec<3>::Zero());
  s.species.assign(3000, host_species);
  kick_impurities<3>(rng, s, 5, 7.0, 15.0);
  double energy = 0.0, farthest_impurity = 0.0, nearest_host = 1e9;
  Vec<3> momentum = Vec<3>::Zero();
  int impurities = 0;
  for (std::size_t i = 0; i < s.size(); ++i) {
    if (s.species[i] == impurity_species) {
      ++impurities;
      energy += 0.5 * 2.5 * s.velocity[i].squaredNorm();
      momentum += 2.5 * s.velocity[i];
      farthest_impurity = std::max(farthest_impurity, s.position[i].norm());
    } else {
      nearest_host = std::min(nearest_host, s.position[i].norm());
      CHECK(s.velocity[i].norm() == 0.0);
    }
    for (std::size_t j = i + 1; j < s.size(); ++j) {
      const double sigma = (s.species[i] ? 0.8 : 0.5) + (s.species[j] ? 0.8 : 0.5);
      REQUIRE((s.position[i] - s.position[j]).norm() >= sigma);
    }
  }
  CHECK(impurities == 5);
  CHECK_THAT(energy, Catch::Matchers::WithinRel(7.0, 1e-14));
  CHECK(momentum.norm() < 1e-14 * std::sqrt(2.0 * 2.5 * 7.0));
  CHECK(farthest_impurity < nearest_host);
}

TEST_CASE("1 thread and 2 threads give bit-identical block sums", "[slow]") {
  const BlastConfig scene = small_scene();
  RunOptions one, two;
  two.threads = 2;
  const BlastResult a = run_blast(scene, one), b = run_blast(scene, two);
  REQUIRE(a.blocks.size() == 4);
  REQUIRE(a.realizations() == 7);
  for (const auto& [block, sums] : a.blocks) {
    REQUIRE(b.blocks.at(block).sum == sums.sum);
    REQUIRE(b.blocks.at(block).sum_squares == sums.sum_squares);
    REQUIRE(b.blocks.at(block).collisions == sums.collisions);
  }
  CHECK(a.energy_error_max() < 1e-12);
  CHECK(a.collisions() > 1000);
}

TEST_CASE("shards merged equal the unsharded run", "[slow]") {
  const BlastConfig scene = small_scene();
  const fs::path root = coldblast::test::unique_temp_path("coldblast_test_shards");
  fs::remove_all(root);
  RunOptions all, first, second;
  first.shard_count = second.shard_count = 2;
  second.shard_index = 1;
  write_blast_outputs(run_blast(scene, all), root / "all");
  write_blast_outputs(run_blast(scene, first), root / "s0");
  write_blast_outputs(run_blast(scene, second), root / "s1");
  const BlastResult merged = merge_blast_outputs({root / "s1", root / "s0"});
  write_blast_outputs(merged, root / "merged");
  for (const char* file : {"observables.csv", "blocks.csv", "profiles.csv", "p_imp.csv", "accumulators.csv"}) {
    INFO(file);
    CHECK(data_lines(root / "all" / file) == data_lines(root / "merged" / file));
  }
  CHECK(data_lines(root / "all" / "observables.csv").size() > 100);
  CHECK_THROWS_WITH(merge_blast_outputs({root / "s0", root / "s0"}), Catch::Contains("appears twice"));
  // One shard alone merges (a progress check), with a note naming what is missing; both: none.
  CHECK(partial_merge_note(merged).empty());
  const BlastResult half = merge_blast_outputs({root / "s1"});
  REQUIRE((scene.realizations == 7 && scene.block_size == 2));  // blocks 0..3; shard 1/2 ran 1 and 3
  CHECK(half.realizations() == 3);
  CHECK(partial_merge_note(half) ==
        "md merge: 3 of the scene's 7 realizations (blocks 0, 2 missing): a partial ensemble");
  fs::remove_all(root);
}

TEST_CASE("shard specs are validated", "[fast]") {
  CHECK(parse_shard("1/3") == std::pair<int, int>{1, 3});
  CHECK_THROWS_WITH(parse_shard("3/2"), Catch::Contains("--shard"));
  CHECK_THROWS_WITH(parse_shard("x"), Catch::Contains("--shard"));
}

TEST_CASE("a single impurity gets energy E in a random direction and its blast runs", "[fast]") {
  // One impurity cannot have zero momentum: the kick gives it |p| = sqrt(2 m E) (all the energy),
  // in a direction that varies with the seed; the run conserves energy like any other.
  const double E = 3.5, mass = 2.0;
  std::vector<double> directions;
  for (std::uint64_t seed = 1; seed <= 3; ++seed) {
    auto rng = realization_rng(seed, 0);
    InitialState<3> s;
    s.host = {0.5, 1.0};
    s.impurity = {0.5, mass};
    s.position = random_sequential_addition<3>(rng, 200, 0.5, 10.0);
    s.velocity.assign(200, Vec<3>::Zero());
    s.species.assign(200, host_species);
    kick_impurities<3>(rng, s, 1, E, 10.0);
    int impurities = 0;
    for (std::size_t i = 0; i < s.size(); ++i) {
      if (s.species[i] != impurity_species) {
        CHECK(s.velocity[i].squaredNorm() == 0.0);
        continue;
      }
      ++impurities;
      CHECK(0.5 * mass * s.velocity[i].squaredNorm() == Approx(E).epsilon(1e-14));
      CHECK(mass * s.velocity[i].norm() == Approx(std::sqrt(2.0 * mass * E)).epsilon(1e-14));
      directions.push_back(s.velocity[i].x() / s.velocity[i].norm());
    }
    CHECK(impurities == 1);
  }
  REQUIRE(directions.size() == 3);
  CHECK(directions[0] != directions[1]);
  CHECK(directions[1] != directions[2]);
  for (const int d : {2, 3}) {
    INFO("d = " << d);
    // In 3D the lone fast impurity runs ahead of Eq. (1) early on, beyond box_margin 3 × R: the
    // region's early_reach_bound holds it (it needed box_margin 5-6 before).
    const BlastConfig scene = parse_scene(default_scene_toml(), {"d=" + std::to_string(d), "impurities.count=1",
                                                                 "t_max=20", "realizations=2", "A_d=0.3"});
    const BlastResult result = run_blast(scene, RunOptions{});
    CHECK(result.energy_error_max() < 1e-12);
    CHECK(result.collisions() > 10);
  }
}

namespace {
/// The region resolve_scene would give from Eq. (1)'s box_margin × R(t_max) alone (plus the guard bands).
double margin_region(const ResolvedScene& s) {
  const double contact = 2.0 * std::max(s.config.a, s.impurity_radius);
  return s.config.box_margin * s.shock_radius_at_t_max + 2.0 * contact + 2.0 * std::max(contact, s.config.cell_width);
}
}  // namespace

TEST_CASE("early_reach_bound: the ballistic cap, the slow-down and the mass dependence", "[fast]") {
  const BlastConfig base = parse_scene(default_scene_toml(), {"A_d=0.2238", "t_max=20"});
  const double R = resolve_scene(base).shock_radius_at_t_max;
  // A light impurity's short run is ballistic: the fastest of 4 (at most 3/4 of E) times t_max.
  BlastConfig quick = base;
  quick.impurities.mass = 1e-3;
  quick.t_max = 0.01;
  quick.t_min = 1e-4;
  const double R_quick = resolve_scene(quick).shock_radius_at_t_max;
  CHECK(early_reach_bound(quick, 0.5, R_quick) == Approx(std::sqrt(2.0 * 10.0 * 0.75 / 1e-3) * 0.01).epsilon(1e-14));
  quick.impurities.count = 1;  // all of E
  CHECK(early_reach_bound(quick, 0.5, R_quick) == Approx(std::sqrt(2.0 * 10.0 / 1e-3) * 0.01).epsilon(1e-14));
  // While Eq. (1)'s shock is faster than every particle (dR/dt >= v0), nothing runs ahead of it: 0,
  // and box_margin R(t_max) >= 2 v0 t_max covers the particles' reach.
  quick.impurities.mass = 1.0;
  quick.t_max = 1e-3;
  const double R_early = resolve_scene(quick).shock_radius_at_t_max;
  CHECK(early_reach_bound(quick, 0.5, R_early) == 0.0);
  CHECK(R_early > 2.0 * std::sqrt(2.0 * 10.0) * 1e-3);
  // Equal masses in 2D, by hand: λ_c = 1/(2 n (a + a)) = 10/3, v0 = sqrt(15), f = 2/3, g = 2/3,
  // N = 3 min(ln(1 + t_max/(3 τ0)), ln(v0/(dR/dt))), dR/dt = R/(2 t_max).
  const double lambda_c = 10.0 / 3.0, v0 = std::sqrt(15.0);
  const double N = 3.0 * std::min(std::log1p(20.0 / (3.0 * lambda_c / v0)), std::log(v0 / (R / 40.0)));
  CHECK(early_reach_bound(base, 0.5, R) == Approx(3.0 * lambda_c * std::sqrt(6.0 * N)).epsilon(1e-13));
  // A light impurity keeps its energy for ~1/f collisions and walks much further than an equal one.
  BlastConfig light = base;
  light.impurities.mass = 1e-3;
  CHECK(early_reach_bound(light, 0.5, R) > 5.0 * early_reach_bound(base, 0.5, R));
  // Long runs: the shock overtakes the impurity, so the reach stops growing with t_max (only through
  // ln(1/dR/dt)) while Eq. (1)'s R grows like t_max^(1/2).
  BlastConfig long_run = base;
  long_run.t_max = 4000;
  const double R_long = resolve_scene(long_run).shock_radius_at_t_max;
  CHECK(early_reach_bound(long_run, 0.5, R_long) < 1.5 * early_reach_bound(base, 0.5, R));
}

TEST_CASE("the paper's scenes keep the region of Eq. (1)'s box_margin × R(t_max)", "[fast]") {
  // bench/md_driver.cpp's scenes (whose trajectories docs/benchmarks.md pins by checksum),
  // scenes/paper-3d.toml (A_3(0.118) of docs/verification.md) and the default scene: the early reach
  // lies well inside box_margin × R, so the region is the one Eq. (1) gave before.
  const std::vector<std::vector<std::string>> scenes = {
      {"d=2", "n=0.15", "E=5.7", "A_d=0.22380034", "t_min=0.9765625", "box_margin=1.6", "t_max=4000"},
      {"d=3", "n=0.225", "E=5.7", "A_d=0.22429374246053257", "t_min=0.7505963", "box_margin=2.0", "t_max=1000"},
      {"d=3", "n=0.225", "E=5.7", "A_d=0.22401453913280", "t_min=0.7505963", "box_margin=1.3", "t_max=49191"},
      {"A_d=0.2238003370011654"}};
  for (const auto& set : scenes) {
    const ResolvedScene s = resolve_scene(parse_scene(default_scene_toml(), set));
    INFO(set[0] << " region " << s.region_radius);
    CHECK(s.region_radius == margin_region(s));
    CHECK(early_reach_bound(s.config, s.impurity_radius, s.shock_radius_at_t_max) <
          0.8 * s.config.box_margin * s.shock_radius_at_t_max);
  }
}

TEST_CASE("blasts that outrun Eq. (1) early run with the default box_margin", "[fast]") {
  // Each exited 1 ("raise box_margin") before the region held the early reach; they needed box_margin
  // 10, 6 and 5 (docs/stress.md). A_d is the hard-particle TvNS value md run would use (3D n = 0.01:
  // about hydro's A_3(0.0052)).
  const std::vector<std::vector<std::string>> scenes = {
      {"impurities.mass=1e-3", "A_d=0.2238"}, {"d=3", "n=0.01", "A_d=0.476"}, {"d=3", "impurities.count=1", "A_d=0.3"}};
  for (auto set : scenes) {
    set.insert(set.end(), {"t_max=20", "realizations=1", "box_margin=3"});
    const BlastConfig scene = parse_scene(default_scene_toml(), set);
    const ResolvedScene resolved = resolve_scene(scene);
    INFO(set[0] << " " << set[1] << ": region " << resolved.region_radius);
    CHECK(resolved.region_radius > margin_region(resolved));  // the early reach sizes it
    const BlastResult result = run_blast(scene, RunOptions{});
    CHECK(result.energy_error_max() < 1e-12);
  }
}

TEST_CASE("realization_time reports each realization's start and recorded times, and changes nothing", "[slow]") {
  const BlastConfig scene = small_scene();
  RunOptions quiet, watched;
  watched.threads = 2;
  std::mutex mutex;
  std::map<long long, std::vector<double>> seen;
  watched.realization_time = [&](long long realization, double t) {
    std::lock_guard<std::mutex> lock(mutex);
    seen[realization].push_back(t);
  };
  const BlastResult a = run_blast(scene, quiet), b = run_blast(scene, watched);
  REQUIRE(seen.size() == 7);
  for (const auto& [realization, times] : seen) {
    INFO("realization " << realization);
    REQUIRE(times.size() == b.scene.times.size() + 1);
    CHECK(times.front() == 0.0);  // the start, before the initial state is built
    CHECK(std::vector<double>(times.begin() + 1, times.end()) == b.scene.times);
  }
  for (const auto& [block, sums] : a.blocks) {
    CHECK(b.blocks.at(block).sum == sums.sum);
    CHECK(b.blocks.at(block).collisions == sums.collisions);
  }
}
