// The blast's initial state: the impurity kick (exact E, zero momentum, the nearest particles), and
// a single impurity's kick (all of E, a random direction), whose blast runs.
#include <catch2/catch.hpp>
#include <cmath>
#include <string>
#include <vector>

#include "md/initial_state.hpp"
#include "run/ensemble.hpp"
#include "run/scene_file.hpp"

using namespace coldblast::md;
using coldblast::run::BlastResult;
using coldblast::run::default_scene_toml;
using coldblast::run::parse_scene;
using coldblast::run::run_blast;
using coldblast::run::RunOptions;

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
