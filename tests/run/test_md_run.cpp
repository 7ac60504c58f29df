// The one A_d policy of the MD box (hydro::md_amplitude, docs/ARCHITECTURE.md), applied by run/:
// `md run`'s plan (run::plan_md_run) leaves A_d = 0 to it, and run_blast sizes the box that
// md::resolve_scene gives with the policy injected; the amplitude is hydro's hard-particle TvNS
// A_d(phi) (Henderson in 2D, Carnahan-Starling in 3D), not the ideal-gas value. The typed options
// --realizations and --seed: none keeps the scene's, every given value is checked.
#include <catch2/catch.hpp>
#include <cmath>
#include <filesystem>

#include "hydro/tvns.hpp"
#include "run/ensemble.hpp"
#include "run/md_run.hpp"
#include "run/scene_file.hpp"
#include "theory/prefactors.hpp"

using namespace coldblast;

TEST_CASE("md run's plan leaves A_d to the policy, and run_blast sizes md's box with hydro's amplitude", "[fast]") {
  run::MdRunRequest request;
  request.overrides = {"t_max=30", "block_size=1", R"(observables=["R_imp","n0","R"])"};
  request.realizations = 2;
  const run::MdRunPlan plan = run::plan_md_run(request);
  CHECK(plan.config.A_d == 0.0);  // left to the policy
  const run::BlastResult result = run::run_blast(plan.config, plan.options);
  const md::ResolvedScene& a = result.scene;
  const md::ResolvedScene b = md::resolve_scene(plan.config, hydro::md_amplitude);
  CHECK(a.A_d == b.A_d);
  CHECK(a.A_d_source == b.A_d_source);
  CHECK(a.region_radius == b.region_radius);
  CHECK(a.particle_count == b.particle_count);
  CHECK(run::scene_toml(a.config) == run::scene_toml(b.config));
  REQUIRE(result.blocks.size() == 2);
  // The amplitude is the hard-particle one at the scene's phi (Henderson, 2D), not the ideal gas's.
  CHECK(a.A_d == hydro::solve_tvns_for_md(2, a.phi).A());
  CHECK(a.A_d_source.find("henderson") != std::string::npos);
  CHECK(std::abs(a.A_d / theory::ideal_gas_A_2 - 1.0) > 0.05);
}

TEST_CASE("the paper's 3D scene gets the Carnahan-Starling A_3(phi) from md run's plan", "[fast]") {
  run::MdRunRequest request;
  request.scene_file = std::string(COLDBLAST_SOURCE_DIR) + "/scenes/paper-3d.toml";
  const run::MdRunPlan plan = run::plan_md_run(request);
  const md::ResolvedScene s = run::resolve_blast_scene(plan.config);
  CHECK(s.A_d == hydro::solve_tvns_for_md(3, s.phi).A());
  CHECK(s.A_d_source.find("carnahan-starling") != std::string::npos);
  // Without the policy, md refuses to guess an amplitude for A_d = 0.
  CHECK_THROWS_WITH(md::resolve_scene(plan.config), Catch::Contains("A_d = 0"));
}

TEST_CASE("md run's --realizations and --seed: none keeps the scene's, every given value is checked", "[fast]") {
  run::MdRunRequest request;
  CHECK(run::plan_md_run(request).config.realizations == run::parse_scene(run::default_scene_toml()).realizations);
  request.seed = 7;
  request.realizations = 3;
  const run::MdRunPlan plan = run::plan_md_run(request);
  CHECK(plan.config.seed == 7);
  CHECK(plan.config.realizations == 3);
  // A typed option wins over --set, as it did when it was appended to the overrides.
  request.overrides = {"realizations=5", "seed=2"};
  CHECK(run::plan_md_run(request).config.realizations == 3);
  CHECK(run::plan_md_run(request).config.seed == 7);
  // 0 and -1 were the "not given" sentinels; given, they are out of range like any other value.
  request.realizations = 0;
  CHECK_THROWS_WITH(run::plan_md_run(request), "--realizations = 0 is outside [1, 1000000000]");
  request.realizations = 3;
  request.seed = -1;
  CHECK_THROWS_WITH(run::plan_md_run(request), "--seed = -1 is outside [0, inf]");
}
