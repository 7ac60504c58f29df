// md states (run/impurity_states.*): the impurities' states at a recorded time are those of md run's realizations
// (their R_imp, V_imp and C_imp reproduce the ensemble's to round-off), the same for any thread count, and
// impurity_states.csv reads back bit for bit; bad input names the option.
#include <catch2/catch.hpp>
#include <cmath>
#include <filesystem>

#include "common/output.hpp"
#include "run/ensemble.hpp"
#include "run/impurity_states.hpp"
#include "run/scene_file.hpp"
#include "tests/temp_path.hpp"

using namespace coldblast::md;
using namespace coldblast::run;
namespace fs = std::filesystem;

namespace {
BlastConfig small_scene(int d) {
  std::vector<std::string> keys{"t_max=100", "realizations=6", "seed=9", "block_size=2",
                                R"(observables=["R_imp","V_imp","C_imp"])"};
  if (d == 3)
    keys.insert(keys.end(), {"d=3", "n=0.225", "A_d=0.2243", "t_max=40"});
  else
    keys.push_back("A_d=0.2238");
  return parse_scene(default_scene_toml(), keys);
}
}  // namespace

TEST_CASE("md states: the ensemble's R_imp, V_imp and C_imp at a recorded time, for any thread count", "[fast]") {
  for (const int d : {2, 3}) {
    INFO("d = " << d);
    const BlastConfig config = small_scene(d);
    RunOptions options;
    options.threads = 2;
    const BlastResult run = run_blast(config, options);
    const double t = run.scene.times[run.scene.times.size() - 3];
    const auto states = impurity_states(run.scene, t, config.realizations, 2);
    REQUIRE(states.size() == static_cast<std::size_t>(config.realizations * config.impurities.count));
    double r2 = 0.0, v2 = 0.0, collisions = 0.0;
    for (const ImpurityState& s : states) {
      REQUIRE(s.r.size() == static_cast<std::size_t>(d));
      for (int k = 0; k < d; ++k) {
        r2 += 0.5 * (s.r[k] - s.r0[k]) * (s.r[k] - s.r0[k]);
        v2 += 0.5 * s.v[k] * s.v[k];
      }
      collisions += static_cast<double>(s.collisions);
    }
    const double count = static_cast<double>(states.size());
    for (const auto& e : estimate_observables(run)) {
      if (e.t != t) continue;
      INFO(e.observable);
      const double expected = e.observable == "R_imp"   ? std::sqrt(r2 / count)
                              : e.observable == "V_imp" ? std::sqrt(v2 / count)
                                                        : collisions / count;
      CHECK(e.mean == Approx(expected).epsilon(1e-12));
    }
    const auto one_thread = impurity_states(run.scene, t, config.realizations, 1);
    REQUIRE(one_thread.size() == states.size());
    for (std::size_t i = 0; i < states.size(); ++i) {
      CHECK(one_thread[i].realization == states[i].realization);
      CHECK(one_thread[i].r == states[i].r);
      CHECK(one_thread[i].v == states[i].v);
      CHECK(one_thread[i].collisions == states[i].collisions);
    }
  }
}

TEST_CASE("md states: impurity_states.csv reads back bit for bit, and bad input names the option", "[fast]") {
  const BlastConfig config = small_scene(2);
  const ResolvedScene scene = resolve_scene(config);
  const auto states = impurity_states(scene, 30.0, 3, 2);
  const fs::path dir = coldblast::test::unique_temp_path("coldblast_test_states");
  const fs::path file = dir / "impurity_states.csv";
  coldblast::common::write_file_atomic(file, impurity_states_csv(states, config, 30.0, "test-run"));
  const ImpurityStates read = read_impurity_states(file, 2, "--start-states");
  // md states' output directory stands for the file in it
  CHECK(read_impurity_states(dir, 2, "--start-states").states.size() == states.size());
  CHECK(read.t == 30.0);
  REQUIRE(read.states.size() == states.size());
  for (std::size_t i = 0; i < states.size(); ++i) {
    CHECK(read.states[i].realization == states[i].realization);
    CHECK(read.states[i].impurity == states[i].impurity);
    CHECK(read.states[i].collisions == states[i].collisions);
    CHECK(read.states[i].r == states[i].r);
    CHECK(read.states[i].v == states[i].v);
    CHECK(read.states[i].r0 == states[i].r0);
  }
  const auto keys = states_scene_keys(config);
  for (const auto& key : keys) CHECK(std::find(read.header.begin(), read.header.end(), key) != read.header.end());
  CHECK_THROWS_WITH(read_impurity_states(file, 3, "--start-states"),
                    Catch::Contains("--start-states = ") && Catch::Contains("a d = 3 state has 12"));
  CHECK_THROWS_WITH(read_impurity_states(dir / "missing.csv", 2, "--start-states"), Catch::Contains("cannot read"));
  coldblast::common::write_file_atomic(dir / "bad.csv",
                                       "# t: 5\nrealization,impurity,collisions,x,y,vx,vy,x0,y0\n"
                                       "0,0,1,2,3,4,x,6,7\n");
  CHECK_THROWS_WITH(read_impurity_states(dir / "bad.csv", 2, "--start-states"), Catch::Contains("'x' is not a number"));
  coldblast::common::write_file_atomic(dir / "empty.csv", "# t: 5\nrealization,impurity,collisions,x,y,vx,vy,x0,y0\n");
  CHECK_THROWS_WITH(read_impurity_states(dir / "empty.csv", 2, "--start-states"), Catch::Contains("no impurity state"));
  CHECK_THROWS_WITH(impurity_states(scene, 0.0, 3, 1), Catch::Contains("--time"));
  CHECK_THROWS_WITH(impurity_states(scene, 101.0, 3, 1), Catch::Contains("--time"));
  CHECK_THROWS_WITH(impurity_states(scene, 30.0, 0, 1), Catch::Contains("--realizations"));
  fs::remove_all(dir);
}
