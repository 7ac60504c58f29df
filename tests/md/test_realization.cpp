// A realization (md/realization.cpp) whose moving particles reach the guard of its region starts
// again in a wider region holding the same gas inside: the same realization, up to the guard
// exactly as before, and then to t_max.
#include <catch2/catch.hpp>
#include <cmath>
#include <string>
#include <vector>

#include "md/event_queue.hpp"
#include "md/observers.hpp"
#include "md/realization.hpp"
#include "run/scene_file.hpp"

using namespace coldblast::md;
using coldblast::run::default_scene_toml;
using coldblast::run::parse_scene;

namespace {
/// The impurities' positions and the collision count after running realization `index`, grown
/// `growths` times, to t.
struct Snapshot {
  std::vector<Vec<3>> impurities;
  std::uint64_t collisions = 0;
};
Snapshot run_to(const ResolvedScene& scene, long long index, int growths, double t) {
  const InitialState<3> state = blast_initial_state<3>(scene, index, growths);
  Engine<3, CalendarEventQueue> engine(blast_engine_config<3>(scene, growths), state);
  engine.run_until(t);
  Snapshot s;
  for (std::size_t i = 0; i < state.size(); ++i)
    if (state.species[i] == impurity_species) s.impurities.push_back(engine.position(static_cast<std::int32_t>(i)));
  s.collisions = engine.collision_count();
  return s;
}

/// The first realization (index < 20) whose moving particles reach the guard of the unwidened
/// region before t_max, and the time they do (-1 if none does).
struct Trip {
  long long index = -1;
  double time = -1.0;
};
Trip first_trip(const ResolvedScene& scene) {
  for (long long index = 0; index < 20; ++index) try {
      run_to(scene, index, 0, scene.config.t_max);
    } catch (const GuardTripped& e) {
      return {index, e.time};
    }
  return {};
}

/// A lone impurity in 3D runs far ahead of Eq. (1) early on (it needed box_margin 5-6 before
/// regions grew, docs/stress.md): box_margin 3 × R(t_max) does not hold all its realizations.
ResolvedScene lone_impurity_scene(const std::vector<std::string>& extra = {}) {
  std::vector<std::string> keys = {"d=3",     "impurities.count=1", "t_max=20",
                                   "A_d=0.3", "box_margin=3",       "realizations=1"};
  keys.insert(keys.end(), extra.begin(), extra.end());
  return resolve_scene(parse_scene(default_scene_toml(), keys));
}
}  // namespace

TEST_CASE("a realization that reaches its region's guard grows the region and stays the same realization", "[fast]") {
  // The first realization of a lone impurity whose particles reach the guard of box_margin 3 × R(t_max).
  const ResolvedScene scene = lone_impurity_scene();
  const auto [index, tripped] = first_trip(scene);
  REQUIRE(tripped > 0.0);
  // Up to the guard no moving particle can touch the new shell: the same collisions, and the
  // impurity's position to round-off (a wider cell grid rounds its crossings differently).
  const Snapshot first = run_to(scene, index, 0, 0.999 * tripped), grown = run_to(scene, index, 1, 0.999 * tripped);
  CHECK(first.collisions > 0);
  CHECK(grown.collisions == first.collisions);
  REQUIRE(grown.impurities.size() == 1);
  CHECK((grown.impurities[0] - first.impurities[0]).norm() < 1e-9 * first.impurities[0].norm());

  // run_realization grows until the region holds it to t_max, energy conserved.
  const ObservableLayout layout(scene);
  const RealizationOutput out = run_realization(scene, layout, index);
  CHECK(out.growths >= 1);
  CHECK(out.region_radius == Approx(scene.region_radius * std::pow(region_growth, out.growths)).epsilon(1e-15));
  CHECK(out.particles == particles_within(scene, out.region_radius));
  CHECK(out.energy_error < 1e-12);
  // It ran in the first region that holds it: the one before trips its guard too.
  bool smaller_trips = false;
  try {
    run_to(scene, index, out.growths - 1, scene.config.t_max);
  } catch (const GuardTripped&) {
    smaller_trips = true;
  }
  CHECK(smaller_trips);
}

TEMPLATE_TEST_CASE("a region grown in place, between events, gives the run of the wider region from t = 0", "[fast]",
                   CalendarEventQueue, HeapEventQueue) {
  // The scene of the case above: its first realization that reaches the guard of box_margin 3; also
  // with a big impurity (radius 3a: wider stencils, md/big_particles.hpp, laid anew with the cells)
  // and with impurity recollisions off (the ghost bits, extended to the new particles).
  const std::vector<std::string> variant =
      GENERATE(std::vector<std::string>{}, std::vector<std::string>{"impurities.radius=1.5"},
               std::vector<std::string>{"impurities.recollide=false"});
  CAPTURE(variant);
  const ResolvedScene scene = lone_impurity_scene(variant);
  const long long index = first_trip(scene).index;
  REQUIRE(index >= 0);
  GrowingBlast<3, TestType> blast(scene, index);
  REQUIRE(blast.growths() == 0);  // it grows while it runs, not before
  blast.run_until(scene.config.t_max);
  const int growths = blast.growths();
  REQUIRE(growths >= 1);
  const Engine<3, TestType>& engine = blast.engine();
  CHECK(engine.size() == particles_within(scene, region_radius_after(scene, growths)));
  CHECK(engine.config().region_radius == region_radius_after(scene, growths));
  CHECK(std::abs(engine.kinetic_energy() - scene.config.E) < 1e-12 * scene.config.E);
  Vec<3> p0 = Vec<3>::Zero();  // the kick's momentum (one impurity: not zero), conserved
  for (std::size_t i = 0; i < blast.state().size(); ++i)
    p0 += engine.mass(static_cast<std::int32_t>(i)) * blast.state().velocity[i];
  CHECK((engine.momentum() - p0).norm() < 1e-12 * p0.norm());
  // The run in the region of `growths` growths from t = 0: the same collisions, the impurity at the
  // same place (a prediction is a function of two stored states; only the cell grids differ).
  const Snapshot wide = run_to(scene, index, growths, scene.config.t_max);
  CHECK(engine.collision_count() == wide.collisions);
  std::vector<Vec<3>> impurities;
  for (std::size_t i = 0; i < engine.size(); ++i)
    if (engine.species(static_cast<std::int32_t>(i)) == impurity_species)
      impurities.push_back(engine.position(static_cast<std::int32_t>(i)));
  REQUIRE(impurities.size() == 1);
  CHECK((impurities[0] - wide.impurities[0]).norm() < 1e-9 * wide.impurities[0].norm());
  // The particles added at rest sit where the state's shells put them.
  const InitialState<3>& state = blast.state();
  REQUIRE(state.size() == engine.size());
  for (std::size_t i = state.size() - 10; i < state.size(); ++i)
    if (!engine.is_moving(static_cast<std::int32_t>(i)))
      CHECK(engine.position(static_cast<std::int32_t>(i)) == state.position[i]);
}

TEST_CASE("Engine::grow refuses a closed box or a region that does not grow", "[fast]") {
  const ResolvedScene scene =
      resolve_scene(parse_scene(default_scene_toml(), {"d=3", "t_max=2", "A_d=0.3", "realizations=1"}));
  const InitialState<3> state = blast_initial_state<3>(scene, 0);
  Engine<3, CalendarEventQueue> engine(blast_engine_config<3>(scene), state);
  CHECK_THROWS_WITH(engine.grow(blast_engine_config<3>(scene), {}), Catch::Contains("must be open and grow"));
}

TEST_CASE("region_growths bounds the growth: 0 stops the run at the guard, naming the keys", "[fast]") {
  using Catch::Contains;
  CHECK_THROWS_WITH(resolve_scene(parse_scene(default_scene_toml(), {"region_growths=31", "A_d=0.3"})),
                    Contains("region_growths = 31 is outside [0, 30]"));
  const auto scene_text = coldblast::run::scene_toml(parse_scene(default_scene_toml(), {"region_growths=0"}));
  CHECK_THAT(scene_text, Contains("region_growths = 0"));  // written only when not the default 8
  CHECK(parse_scene(scene_text, {}).region_growths == 0);
  CHECK_THAT(coldblast::run::scene_toml(parse_scene(default_scene_toml(), {})), !Contains("region_growths"));
  // The scene of the case above, not allowed to grow: the first realization that reaches its guard.
  ResolvedScene scene = lone_impurity_scene({"region_growths=0"});
  const long long index = first_trip(scene).index;
  REQUIRE(index >= 0);
  CHECK(last_growth(scene, 0));
  CHECK_THROWS_AS(run_realization(scene, ObservableLayout(scene), index), GuardTripped);
  CHECK_THROWS_WITH(
      run_realization(scene, ObservableLayout(scene), index),
      Contains("a moving particle came within") && Contains("raise region_growths (now 0) or box_margin"));
  scene.config.region_growths = 8;
  CHECK(!last_growth(scene, 7));
  CHECK(last_growth(scene, 8));
}

TEST_CASE("the paper scenes never grow their region", "[fast]") {
  // box_margin × R(t_max) holds the blast: the realizations of docs/benchmarks.md's checksums run
  // in the region Eq. (1) gives (md_driver blast 2 1: 755ce49ab912484a).
  const ResolvedScene scene = resolve_scene(parse_scene(
      default_scene_toml(), {"n=0.15", "E=5.7", "A_d=0.22380034", "t_min=0.9765625", "box_margin=1.6", "t_max=4000"}));
  const ObservableLayout layout(scene);
  for (long long r = 0; r < 2; ++r) {
    const RealizationOutput out = run_realization(scene, layout, r);
    CHECK(out.growths == 0);
    CHECK(out.particles == scene.particle_count);
  }
}
