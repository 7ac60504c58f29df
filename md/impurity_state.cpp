#include "md/impurity_state.hpp"

#include <sstream>

#include "md/engine.hpp"
#include "md/event_queue.hpp"
#include "md/realization.hpp"

namespace coldblast::md {

namespace {
/// The impurities of realization `index` at time t, in the region `md run` grows to (GrowingBlast).
template <int D>
std::vector<ImpurityState> states_at(const ResolvedScene& scene, long long index, double t) {
  // The engine of `md run` (blast_engine_config; bucketed and heap calendars give the same
  // trajectories, tested), without observers: they do not change a trajectory.
  GrowingBlast<D, CalendarEventQueue> blast(scene, index);
  blast.run_until(t);
  const Engine<D, CalendarEventQueue>& engine = blast.engine();
  const InitialState<D>& state = blast.state();
  std::vector<ImpurityState> states;
  for (std::size_t id = 0; id < state.size(); ++id) {
    if (state.species[id] != impurity_species) continue;
    const auto i = static_cast<std::int32_t>(id);
    ImpurityState s;
    s.realization = index;
    s.impurity = static_cast<int>(states.size());
    s.collisions = engine.particle(i).collisions;
    const Vec<D> r = engine.position(i), v = engine.velocity(i);
    for (int k = 0; k < D; ++k) {
      s.r.push_back(r[k]);
      s.v.push_back(v[k]);
      s.r0.push_back(state.position[id][k]);
    }
    states.push_back(std::move(s));
  }
  return states;
}

std::string number_text(double x) {
  std::ostringstream out;
  out.precision(17);
  out << x;
  return out.str();
}
}  // namespace

std::vector<ImpurityState> realization_impurity_states(const ResolvedScene& scene, long long index, double t) {
  return scene.config.d == 2 ? states_at<2>(scene, index, t) : states_at<3>(scene, index, t);
}

std::vector<std::pair<std::string, std::string>> states_scene_keys(const BlastConfig& c) {
  return {{"d", std::to_string(c.d)},
          {"n", number_text(c.n)},
          {"a", number_text(c.a)},
          {"E", number_text(c.E)},
          {"impurities.count", std::to_string(c.impurities.count)},
          {"impurities.mass", number_text(c.impurities.mass)},
          {"impurities.radius", number_text(c.impurities.radius)},
          {"impurities.recollide", c.impurities.recollide ? "true" : "false"}};
}

}  // namespace coldblast::md
