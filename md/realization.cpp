#include "md/realization.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <utility>

#include "common/validate.hpp"
#include "md/event_queue.hpp"

namespace coldblast::md {

namespace {
using common::format_number;

/// The particles `selection` keeps of the engine's, at engine.now().
template <int D, class Queue>
SnapshotFrame capture(const Engine<D, Queue>& engine, const SnapshotSelection& selection) {
  double reach = -1.0;  // the farthest moving particle's distance from the origin
  if (selection.front_only)
    for (const std::int32_t id : engine.moving()) reach = std::max(reach, engine.position(id).norm());
  SnapshotFrame frame;
  frame.t = engine.now();
  long long kept = 0;
  for (std::size_t i = 0; i < engine.size(); ++i) {
    const auto id = static_cast<std::int32_t>(i);
    const Vec<D> x = engine.position(id);
    if (selection.front_only && !engine.is_moving(id) && !(x.norm() <= reach + selection.margin)) continue;
    if (kept++ % selection.stride != 0) continue;
    const Vec<D>& v = engine.velocity(id);
    frame.id.push_back(id);
    for (int k = 0; k < D; ++k) {
      frame.position.push_back(x[k]);
      frame.velocity.push_back(v[k]);
    }
    frame.impurity.push_back(engine.species(id) == impurity_species ? 1 : 0);
    frame.moving.push_back(engine.is_moving(id) ? 1 : 0);
    frame.collisions.push_back(engine.particle(id).collisions);
  }
  return frame;
}

/// Each impurity's start, its collisions and its end, by id (stable in time).
template <int D, class Queue>
std::vector<PathPoint> impurity_paths(const Engine<D, Queue>& engine, const std::vector<std::int32_t>& impurities,
                                      const std::vector<Vec<D>>& start,
                                      const std::vector<TrajectoryPoint<D>>& collisions) {
  std::vector<PathPoint> points;
  const auto add = [&points](std::int32_t id, double t, const Vec<D>& x) {
    PathPoint p;
    p.id = id;
    p.t = t;
    for (int k = 0; k < D; ++k) p.position[static_cast<std::size_t>(k)] = x[k];
    points.push_back(p);
  };
  for (std::size_t m = 0; m < start.size(); ++m) add(impurities[m], 0.0, start[m]);
  for (const auto& p : collisions) add(p.id, p.t, p.position);
  for (const std::int32_t id : impurities) add(id, engine.now(), engine.position(id));
  std::stable_sort(points.begin(), points.end(), [](const auto& x, const auto& y) { return x.id < y.id; });
  return points;
}

/// Realization `index` in a region that grows where the blast reaches (GrowingBlast), to t_max.
template <int D, class Queue>
RealizationOutput run_realization_in(const ResolvedScene& scene, const ObservableLayout& layout, long long index,
                                     const RealizationExtras& extras,
                                     const std::function<void(long long, double)>& realization_time) {
  const BlastConfig& c = scene.config;
  if (realization_time) realization_time(index, 0.0);
  GrowingBlast<D, Queue> blast(scene, index);
  Engine<D, Queue>& engine = blast.engine();
  BlastObserver<D, Queue> observer(scene, layout, engine, extras.paths);

  RealizationOutput out;
  out.record.assign(layout.size(), 0.0);
  std::vector<std::pair<double, int>> stops;  // (time, k) with k = -1 for a snapshot
  for (std::size_t k = 0; k < scene.times.size(); ++k) stops.push_back({scene.times[k], static_cast<int>(k)});
  for (const double t : extras.snapshot_times) stops.push_back({t, -1});
  std::stable_sort(stops.begin(), stops.end(), [](const auto& x, const auto& y) { return x.first < y.first; });
  std::vector<Vec<D>> start;
  for (const std::int32_t id : observer.impurities()) start.push_back(engine.position(id));
  for (const auto& [t, k] : stops) {
    blast.run_until(t);
    if (realization_time) realization_time(index, t);
    if (k >= 0)
      observer.measure(k, out.record);
    else {
      out.snapshots.push_back(capture(engine, extras.selection));
      out.snapshots.back().region_radius = engine.config().region_radius;
    }
  }
  blast.run_until(c.t_max);
  out.growths = blast.growths();
  out.region_radius = engine.config().region_radius;
  out.particles = engine.size();
  out.collisions = engine.collision_count();
  out.energy_error = std::abs(engine.kinetic_energy() - c.E) / c.E;
  if (observer.trajectories())
    out.paths = impurity_paths(engine, observer.impurities(), start, observer.trajectories()->points());
  for (const double v : out.record)
    if (!std::isfinite(v)) throw std::runtime_error("non-finite observable in realization " + std::to_string(index));
  return out;
}

/// What to do when a particle reached the guard of the last region a realization may grow to
/// (last_growth), at time `now`. Below the particle cap: more growths, or a first region that holds
/// the particles to t_max if every particle ahead of the blast kept its speed (in the cold gas they
/// only slow down, apart from hosts hit head-on by heavier impurities), scaled by t_max/now.
std::string guard_advice(const ResolvedScene& scene, int growths, double now) {
  const BlastConfig& c = scene.config;
  const std::string grew = growths == 0 ? "" : "(the region grew " + std::to_string(growths) + " times) ";
  if (region_radius_after(scene, growths + 1) > scene.max_region_radius)
    return grew + "a wider region would hold more than 1.5e9 particles; lower t_max or E";
  const double needed =
      region_radius_after(scene, growths) * c.t_max / std::max(now, 1e-300) / scene.shock_radius_at_t_max;
  const std::string margin = grew + "raise region_growths (now " + std::to_string(c.region_growths) +
                             ") or box_margin (now " + format_number(c.box_margin) + ")";
  if (needed > 100.0) return margin + ", or lower t_max or E";
  return margin + " to " + format_number(std::ceil(needed * 10.0) / 10.0) +
         " (the region scaled by t_max/t, enough if no particle ahead of the blast speeds up), or give a smaller A_d "
         "(now " +
         format_number(scene.A_d) + ")";
}

/// The generator of shell k >= 1 of a grown region: a stream of its own, so that the first region
/// and the start draw what they draw in a region that never grows.
std::mt19937_64 shell_rng(std::uint64_t seed, long long index, int k) {
  return realization_rng(common::splitmix64(seed ^ (0x9e3779b97f4a7c15ULL * static_cast<std::uint64_t>(k))),
                         static_cast<std::uint64_t>(index));
}

}  // namespace

template <int D>
InitialState<D> blast_initial_state(const ResolvedScene& scene, long long index, int growths) {
  const BlastConfig& c = scene.config;
  auto rng = realization_rng(c.seed, static_cast<std::uint64_t>(index));
  InitialState<D> state;
  state.host = {c.a, 1.0};
  state.impurity = {scene.impurity_radius, c.impurities.mass};
  try {
    state.position = random_sequential_addition<D>(rng, scene.particle_count, c.a, scene.region_radius);
  } catch (const RsaSaturated& e) {
    // Possible only just below jamming (a finite ball saturates above the bulk value, docs/md-output.md).
    throw std::invalid_argument(
        "phi = " + format_number(scene.phi) + " (n = " + format_number(c.n) + ", a = " + format_number(c.a) +
        ") does not fit: random sequential addition saturated the region of realization " + std::to_string(index) +
        " at phi = " + format_number(e.fraction_reached) + " (" + std::to_string(e.placed) + " of " +
        std::to_string(e.requested) + " particles); allowed: phi in (0, " + format_number(rsa_jamming_fraction(D)) +
        ") for d = " + std::to_string(D) + " and below the region's saturation; lower n or a");
  }
  state.velocity.assign(scene.particle_count, Vec<D>::Zero());
  state.species.assign(scene.particle_count, host_species);
  start_blast<D>(rng, state, c.start, static_cast<std::size_t>(c.impurities.count), c.E, scene.region_radius);
  for (int k = 1; k <= growths; ++k) grow_initial_state<D>(scene, index, state, k);
  return state;
}
template InitialState<2> blast_initial_state<2>(const ResolvedScene&, long long, int);
template InitialState<3> blast_initial_state<3>(const ResolvedScene&, long long, int);

bool last_growth(const ResolvedScene& scene, int growths) {
  return growths >= scene.config.region_growths || region_radius_after(scene, growths + 1) > scene.max_region_radius;
}

template <int D>
void grow_initial_state(const ResolvedScene& scene, long long index, InitialState<D>& state, int growth) {
  const double r_in = region_radius_after(scene, growth - 1), r_out = region_radius_after(scene, growth);
  if (growth < 1 || state.size() != particles_within(scene, r_in))
    throw std::logic_error("grow_initial_state: growth " + std::to_string(growth) +
                           " needs the state after growth - 1 (" + std::to_string(particles_within(scene, r_in)) +
                           " particles), not " + std::to_string(state.size()));
  auto shell = shell_rng(scene.config.seed, index, growth);
  add_rsa_shell<D>(shell, state, particles_within(scene, r_out) - state.size(), r_in, r_out);
}
template void grow_initial_state<2>(const ResolvedScene&, long long, InitialState<2>&, int);
template void grow_initial_state<3>(const ResolvedScene&, long long, InitialState<3>&, int);

template <int D>
EngineConfig<D> blast_engine_config(const ResolvedScene& scene, int growths) {
  const BlastConfig& c = scene.config;
  EngineConfig<D> config;
  config.periodic = false;
  config.region_radius = region_radius_after(scene, growths);
  config.guard_radius = config.region_radius - (scene.region_radius - scene.guard_radius);
  config.guard_advice_at = [scene, growths](double now) { return guard_advice(scene, growths, now); };
  config.cell_width = c.cell_width;
  config.overlap_check = c.overlap_check;
  config.impurity_recollisions = c.impurities.recollide;
  return config;
}
template EngineConfig<2> blast_engine_config<2>(const ResolvedScene&, int);
template EngineConfig<3> blast_engine_config<3>(const ResolvedScene&, int);

RealizationOutput run_realization(const ResolvedScene& scene, const ObservableLayout& layout, long long index,
                                  const RealizationExtras& extras, const std::function<void(long long, double)>& time) {
  common::require_integer_in_range("snapshot stride", extras.selection.stride, 1, 1000000000);
  const bool heap = scene.config.queue == "heap";
  if (scene.config.d == 2)
    return heap ? run_realization_in<2, HeapEventQueue>(scene, layout, index, extras, time)
                : run_realization_in<2, CalendarEventQueue>(scene, layout, index, extras, time);
  return heap ? run_realization_in<3, HeapEventQueue>(scene, layout, index, extras, time)
              : run_realization_in<3, CalendarEventQueue>(scene, layout, index, extras, time);
}

}  // namespace coldblast::md
