// Blast scenes as md runs them: the A_d policy injected into resolve_scene, the early reach of the
// impurities that sizes small blasts' regions (and such blasts run), and the paper's scenes' regions
// from Eq. (1).
#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <string>
#include <vector>

#include "common/validate.hpp"
#include "md/blast_config.hpp"
#include "run/ensemble.hpp"
#include "run/scene_file.hpp"

using namespace coldblast::md;
using coldblast::run::default_scene_toml;
using coldblast::run::parse_scene;

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
    CHECK(resolved.region_radius >= margin_region(resolved));  // no early reach sizes it in advance
    const coldblast::run::BlastResult result = coldblast::run::run_blast(scene, {});
    CHECK(result.energy_error_max() < 1e-12);
  }
}

TEST_CASE("start keys: r0's range names start.r0, and the early reach takes the start's fastest particle", "[fast]") {
  using Catch::Contains;
  const auto scene = [](std::vector<std::string> set) {
    set.push_back("A_d=0.2238");
    return parse_scene(default_scene_toml(), set);
  };
  // The smallest hot spot holds max(2, impurities.count) particles on average: r0 = sqrt(4/(pi n)) in
  // 2D at n = 0.15, four impurities; the largest is Eq. (1)'s R(t_max).
  const double r_min = std::sqrt(4.0 / (M_PI * 0.15));
  CHECK(hot_spot_min_radius(2, 0.15, 4) == Approx(r_min).epsilon(1e-15));
  CHECK(hot_spot_min_radius(3, 0.15, 1) == Approx(std::cbrt(2.0 / (4.0 / 3.0 * M_PI * 0.15))).epsilon(1e-15));
  CHECK_THROWS_WITH(scene({"start.kind=hotspot", "start.r0=1"}),
                    Contains("start.r0 = 1 is outside [" + coldblast::common::format_number(r_min) + ", inf)"));
  CHECK_THROWS_WITH(scene({"start.kind=hotspot"}), Contains("start.r0 = 0 is outside"));
  const ResolvedScene base = resolve_scene(scene({}));
  CHECK_THROWS_WITH(resolve_scene(scene({"start.kind=hotspot", "start.r0=100"})),
                    Contains("start.r0 = 100 is outside [") &&
                        Contains(", " + coldblast::common::format_number(base.shock_radius_at_t_max) + "]") &&
                        Contains("R(t_max)"));
  CHECK_THROWS_WITH(scene({"start.r0=3"}), Contains("start.r0 = 3 is given for start.kind = kick"));
  CHECK_THROWS_WITH(scene({"start.kind=single", "start.r0=3"}), Contains("start.kind = single"));
  CHECK_THROWS_WITH(scene({"start.kind=blast"}), Contains("start.kind = blast is not one of: kick, hotspot, single"));
  CHECK_NOTHROW(resolve_scene(scene({"start.kind=hotspot", "start.r0=" + std::to_string(r_min * 1.0001)})));

  // The kick's reach is that of an impurity with E (k - 1)/k; a hot spot's and a single host's are
  // those of a particle with all of E (host or impurity, the larger), a hot spot's plus r0.
  const double R = base.shock_radius_at_t_max;
  BlastConfig all_of_E = base.config;
  all_of_E.impurities.count = 1;  // the kick bound with E1 = E
  const double with_E = early_reach_bound(all_of_E, 0.5, R);
  CHECK(early_reach_bound(base.config, 0.5, R) < with_E);
  CHECK(early_reach_bound(scene({"start.kind=single"}), 0.5, R) == with_E);
  CHECK(early_reach_bound(scene({"start.kind=hotspot", "start.r0=4"}), 0.5, R) == with_E + 4.0);
  // A light impurity outruns the host: the single host's blast is sized by the impurity it hits.
  BlastConfig light = scene({"start.kind=single", "impurities.mass=0.1"});
  BlastConfig light_kick = light;
  light_kick.start = StartConfig{};
  light_kick.impurities.count = 1;
  CHECK(early_reach_bound(light, 0.5, R) == early_reach_bound(light_kick, 0.5, R));
}

TEST_CASE("the paper scene with an MD-sized hot spot keeps Eq. (1)'s region", "[fast]") {
  // r0 = lambda = 20/3 (about 21 discs: docs/verification.md, "The start's memory"): the early reach
  // stays inside box_margin × R(t_max), so kick and hot spot run in the same region.
  const std::vector<std::string> paper = {"n=0.15",          "E=5.7",          "A_d=0.22380034",
                                          "t_min=0.9765625", "box_margin=1.6", "t_max=4000"};
  std::vector<std::string> hot = paper;
  hot.insert(hot.end(), {"start.kind=hotspot", "start.r0=6.666666666666667"});
  const ResolvedScene kick = resolve_scene(parse_scene(default_scene_toml(), paper));
  const ResolvedScene spot = resolve_scene(parse_scene(default_scene_toml(), hot));
  CHECK(spot.region_radius == margin_region(spot));
  CHECK(spot.region_radius == kick.region_radius);
  CHECK(spot.particle_count == kick.particle_count);
}
