// Collision observers: a recollision counter watching an engine counts an impurity's recollisions
// and its energy losses exactly in a hand-computable periodic run, sees nothing when not watching,
// and the trajectory recorder holds every collision of the impurities and nothing else.
#include <catch2/catch.hpp>

#include "md/collision_observer.hpp"
#include "md/engine.hpp"

using namespace coldblast::md;
using Catch::Matchers::WithinAbs;

namespace {
InitialState<2> impurity_and_host() {
  // Equal discs on one line in a periodic box of side 10: the impurity moves at v = 1 towards the
  // resting host 4 away; equal masses exchange velocities, the host runs round the box (gap 8) and
  // hits it from behind, and so on: collisions at t = 3, 11, 19, ...; every one after the first is
  // a recollision.
  InitialState<2> s;
  s.host = {0.5, 1.0};
  s.impurity = s.host;
  s.position = {Vec<2>(2.0, 5.0), Vec<2>(6.0, 5.0)};
  s.velocity = {Vec<2>(1.0, 0.0), Vec<2>::Zero()};
  s.species = {impurity_species, host_species};
  return s;
}
EngineConfig<2> periodic_box() {
  EngineConfig<2> config;
  config.periodic = true;
  config.box = Vec<2>::Constant(10.0);
  return config;
}
}  // namespace

TEST_CASE("recollisions: an impurity and one host in a periodic box meet again and again", "[fast]") {
  for (const bool watching : {true, false}) {
    Engine<2, CalendarEventQueue> engine(periodic_box(), impurity_and_host());
    RecollisionCounter<2> counter({0});
    if (watching) engine.watch(counter);
    engine.run_until(60.0);  // collisions at 3, 11, ..., 59
    REQUIRE(engine.collision_count() == 8);
    CHECK(engine.particle(0).collisions == 8);
    const RecollisionStats stats = counter.stats(0);
    CHECK(stats.recollisions == (watching ? 7u : 0u));
    // The impurity gives its energy 1/2 away in the first collision, then gets it back and gives it
    // away in turn: +1/2 -1/2 +1/2 -1/2 +1/2 -1/2 +1/2 after it, and it moves at 1 again at t = 60.
    CHECK(stats.loss_first == (watching ? 0.5 : 0.0));
    CHECK_THAT(stats.loss_re, WithinAbs(watching ? -0.5 : 0.0, 1e-15));
    CHECK_THAT(engine.velocity(0)[0], WithinAbs(1.0, 1e-15));
    CHECK(counter.stats(1).recollisions == 0);  // a host: not watched
  }
}

TEST_CASE("impurity trajectories: every collision of an impurity, at contact, in order", "[fast]") {
  Engine<2, CalendarEventQueue> engine(periodic_box(), impurity_and_host());
  ImpurityTrajectories<2> trajectories;
  engine.watch(trajectories);
  engine.run_until(60.0);
  const auto& points = trajectories.points();
  REQUIRE(points.size() == 8);  // the host's collisions are all with the impurity: one point each
  for (std::size_t k = 0; k < points.size(); ++k) {
    CHECK(points[k].id == 0);
    CHECK_THAT(points[k].t, WithinAbs(3.0 + 8.0 * static_cast<double>(k), 1e-12));
    CHECK_THAT(points[k].position[1], WithinAbs(5.0, 1e-15));  // on the line y = 5
  }
  // The first contact is at x = 5 (the host at 6); the impurity rests there until hit from behind.
  CHECK_THAT(points[0].position[0], WithinAbs(5.0, 1e-12));
  CHECK_THAT(points[1].position[0], WithinAbs(5.0, 1e-12));
}
