// The one A_d policy of the MD box (hydro::md_amplitude, docs/ARCHITECTURE.md): `md run` (through
// compare::plan_md_run) and a library call of md::run_blast with the policy injected size the same
// box for the same scene and give the same block sums bit for bit; the amplitude is hydro's
// hard-particle TvNS A_d(phi) (Henderson in 2D, Carnahan-Starling in 3D), not the ideal-gas value.
#include <catch2/catch.hpp>
#include <filesystem>

#include "compare/md_run.hpp"
#include "hydro/tvns.hpp"
#include "md/ensemble.hpp"
#include "theory/prefactors.hpp"

using namespace coldblast;

TEST_CASE("md run and md::run_blast size the same box for the same scene", "[fast]") {
  const std::vector<std::string> set = {"t_max=30", "block_size=1", R"(observables=["R_imp","n0","R"])"};
  compare::MdRunRequest request;
  request.overrides = set;
  request.realizations = 2;
  const compare::MdRunPlan plan = compare::plan_md_run(request);
  CHECK(plan.config.A_d == 0.0);  // left to the policy
  const md::BlastResult via_md_run = md::run_blast(plan.config, plan.options);

  md::BlastConfig scene = md::parse_scene(md::default_scene_toml(), set);
  scene.realizations = 2;
  md::RunOptions options;
  options.amplitude = hydro::md_amplitude;
  const md::BlastResult via_library = md::run_blast(scene, options);

  const md::ResolvedScene &a = via_md_run.scene, &b = via_library.scene;
  CHECK(a.A_d == b.A_d);
  CHECK(a.A_d_source == b.A_d_source);
  CHECK(a.region_radius == b.region_radius);
  CHECK(a.particle_count == b.particle_count);
  CHECK(a.config.to_toml() == b.config.to_toml());
  REQUIRE(via_md_run.blocks.size() == 2);
  for (const auto& [block, sums] : via_md_run.blocks) {
    CHECK(sums.sum == via_library.blocks.at(block).sum);
    CHECK(sums.collisions == via_library.blocks.at(block).collisions);
  }
  // The amplitude is the hard-particle one at the scene's phi (Henderson, 2D), not the ideal gas's.
  CHECK(a.A_d == hydro::solve_tvns_for_md(2, a.phi).A());
  CHECK(a.A_d_source.find("henderson") != std::string::npos);
  CHECK(std::abs(a.A_d / theory::ideal_gas_A_2 - 1.0) > 0.05);
}

TEST_CASE("the paper's 3D scene gets the Carnahan-Starling A_3(phi) from md run's plan", "[fast]") {
  compare::MdRunRequest request;
  request.scene_file = std::string(COLDBLAST_SOURCE_DIR) + "/scenes/paper-3d.toml";
  const compare::MdRunPlan plan = compare::plan_md_run(request);
  const md::ResolvedScene s = md::resolve_scene(plan.config, plan.options.amplitude);
  CHECK(s.A_d == hydro::solve_tvns_for_md(3, s.phi).A());
  CHECK(s.A_d_source.find("carnahan-starling") != std::string::npos);
  // Without the policy, md refuses to guess an amplitude for A_d = 0.
  CHECK_THROWS_WITH(md::resolve_scene(plan.config), Catch::Contains("A_d = 0"));
}

TEST_CASE("md run's --realizations and --seed: none keeps the scene's, every given value is checked", "[fast]") {
  compare::MdRunRequest request;
  CHECK(compare::plan_md_run(request).config.realizations == md::parse_scene(md::default_scene_toml()).realizations);
  request.seed = 7;
  request.realizations = 3;
  const compare::MdRunPlan plan = compare::plan_md_run(request);
  CHECK(plan.config.seed == 7);
  CHECK(plan.config.realizations == 3);
  // 0 and -1 were the "not given" sentinels; given, they are out of range like any other value.
  request.realizations = 0;
  CHECK_THROWS_WITH(compare::plan_md_run(request), "--realizations = 0 is outside [1, 1000000000]");
  request.realizations = 3;
  request.seed = -1;
  CHECK_THROWS_WITH(compare::plan_md_run(request), "--seed = -1 is outside [0, inf]");
  std::vector<std::string> overrides;
  md::add_seed_override(overrides, std::nullopt);
  CHECK(overrides.empty());
  md::add_seed_override(overrides, 0);
  CHECK(overrides == std::vector<std::string>{"seed=0"});
}
