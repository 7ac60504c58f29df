#include "md/realization.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <memory>
#include <stdexcept>
#include <string>
#include <string_view>
#include <type_traits>
#include <utility>

#include "common/bytes.hpp"
#include "common/interrupt.hpp"
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

constexpr char in_flight_magic[] = "coldblast in-flight realization";
constexpr std::uint64_t in_flight_version = 1;

void save_frame(common::ByteWriter& out, const SnapshotFrame& f) {
  out.put(f.t);
  out.put(f.region_radius);
  out.put_vector(f.id);
  out.put_vector(f.position);
  out.put_vector(f.velocity);
  out.put_vector(f.impurity);
  out.put_vector(f.moving);
  out.put_vector(f.collisions);
}

SnapshotFrame read_frame(common::ByteReader& in) {
  SnapshotFrame f;
  f.t = in.get<double>();
  f.region_radius = in.get<double>();
  f.id = in.get_vector<std::int32_t>();
  f.position = in.get_vector<double>();
  f.velocity = in.get_vector<double>();
  f.impurity = in.get_vector<std::uint8_t>();
  f.moving = in.get_vector<std::uint8_t>();
  f.collisions = in.get_vector<std::uint32_t>();
  return f;
}

/// One realization in a region that grows where the blast reaches (GrowingBlast), from t = 0 or
/// from a mid-run checkpoint (InFlight), through its stops (recording and snapshot times) to t_max.
template <int D, class Queue>
class RealizationRun {
 public:
  RealizationRun(const ResolvedScene& scene, const ObservableLayout& layout, long long index,
                 const RealizationExtras& extras, const InFlight* in_flight)
      : scene_(scene), layout_(layout), index_(index), extras_(extras), in_flight_(in_flight) {
    for (std::size_t k = 0; k < scene.times.size(); ++k) stops_.push_back({scene.times[k], static_cast<int>(k)});
    for (const double t : extras.snapshot_times) stops_.push_back({t, -1});
    std::stable_sort(stops_.begin(), stops_.end(), [](const auto& x, const auto& y) { return x.first < y.first; });
    if (in_flight && !in_flight->resume.empty()) {
      resume(in_flight->resume);
      return;
    }
    blast_ = std::make_unique<GrowingBlast<D, Queue>>(scene, index);
    observer_ = std::make_unique<BlastObserver<D, Queue>>(scene, layout, blast_->engine(), extras.paths);
    out_.record.assign(layout.size(), 0.0);
    for (const std::int32_t id : observer_->impurities()) start_.push_back(blast_->engine().position(id));
  }

  RealizationOutput finish(const std::function<void(long long, double)>& realization_time) {
    Engine<D, Queue>& engine = blast_->engine();
    for (; next_stop_ < stops_.size(); ++next_stop_) {
      const auto [t, k] = stops_[next_stop_];
      run_to(t);
      if (realization_time) realization_time(index_, t);
      if (k >= 0) {
        observer_->measure(k, out_.record);
      } else {
        out_.snapshots.push_back(capture(engine, extras_.selection));
        out_.snapshots.back().region_radius = engine.config().region_radius;
      }
    }
    run_to(scene_.config.t_max);
    out_.growths = blast_->growths();
    out_.region_radius = engine.config().region_radius;
    out_.particles = engine.size();
    out_.collisions = engine.collision_count();
    out_.energy_error = std::abs(engine.kinetic_energy() - scene_.config.E) / scene_.config.E;
    if (observer_->trajectories())
      out_.paths = impurity_paths(engine, observer_->impurities(), start_, observer_->trajectories()->points());
    return std::move(out_);
  }

 private:
  // Runs to t; with in_flight_, in slices, saving when due and before a requested stop.
  void run_to(double t) {
    if (!in_flight_) {
      blast_->run_until(t);
      return;
    }
    while (!blast_->run_until(t, std::max<std::uint64_t>(in_flight_->slice_events, 1))) {
      if (common::stop_requested()) {
        in_flight_->save(save());
        common::throw_if_stop_requested();
      }
      if (in_flight_->due && in_flight_->due()) in_flight_->save(save());
    }
  }

  void put_header(common::ByteWriter& out) const {
    out.put_string(in_flight_magic);
    out.put(in_flight_version);
    out.put<std::int32_t>(D);
    out.put<std::uint8_t>(std::is_same_v<Queue, HeapEventQueue>);
    out.put<std::int64_t>(index_);
    out.put<std::uint64_t>(scene_.config.seed);
    out.put<std::uint64_t>(stops_.size());
  }

  std::string save() const {
    common::ByteWriter out;
    put_header(out);
    out.put<std::uint64_t>(next_stop_);
    out.put<std::int32_t>(blast_->growths());
    out.put_vector(out_.record);
    out.put<std::uint64_t>(out_.snapshots.size());
    for (const SnapshotFrame& f : out_.snapshots) save_frame(out, f);
    std::vector<double> start;
    for (const Vec<D>& x : start_) start.insert(start.end(), x.data(), x.data() + D);
    out.put_vector(start);
    blast_->engine().save(out);
    observer_->save(out);
    std::string bytes = out.take();
    const std::uint64_t check = common::fnv1a64(bytes.data(), bytes.size());
    bytes.append(reinterpret_cast<const char*>(&check), sizeof check);
    return bytes;
  }

  void resume(const std::string& bytes) {
    try {
      read(bytes);
    } catch (const std::runtime_error& e) {  // the reader's and the restoring constructors' refusals
      throw SavedStateRefused(e.what());
    }
  }

  void read(const std::string& bytes) {
    const std::string source = "the saved state of realization " + std::to_string(index_);
    std::uint64_t check = 0;
    if (bytes.size() < sizeof check) throw std::runtime_error(source + ": truncated");
    std::memcpy(&check, bytes.data() + bytes.size() - sizeof check, sizeof check);
    if (check != common::fnv1a64(bytes.data(), bytes.size() - sizeof check))
      throw std::runtime_error(source + ": its checksum does not match (truncated or altered)");
    common::ByteReader in(std::string_view(bytes).substr(0, bytes.size() - sizeof check), source);
    common::ByteWriter expected;
    put_header(expected);
    for (const char c : expected.bytes())
      if (in.get<char>() != c) in.fail("of another realization, scene, dimension, calendar or format");
    next_stop_ = static_cast<std::size_t>(in.get<std::uint64_t>());
    const int growths = in.get<std::int32_t>();
    out_.record = in.get_vector<double>();
    if (next_stop_ > stops_.size() || growths < 0 || out_.record.size() != layout_.size())
      in.fail("a stop, growth count or record size this scene does not have");
    const auto frames = in.get<std::uint64_t>();
    if (frames > stops_.size()) in.fail("more snapshots than the scene has stops");
    for (std::uint64_t k = 0; k < frames; ++k) out_.snapshots.push_back(read_frame(in));
    const auto start = in.get_vector<double>();
    for (std::size_t m = 0; m + D <= start.size(); m += D) start_.push_back(Eigen::Map<const Vec<D>>(start.data() + m));
    blast_ = std::make_unique<GrowingBlast<D, Queue>>(scene_, index_, growths, in);
    observer_ = std::make_unique<BlastObserver<D, Queue>>(scene_, layout_, blast_->engine(), extras_.paths, in);
    if (in.remaining() != 0) in.fail("bytes left over");
    out_.resumed_collisions = blast_->engine().collision_count();
  }

  const ResolvedScene& scene_;
  const ObservableLayout& layout_;
  long long index_;
  const RealizationExtras& extras_;
  const InFlight* in_flight_;
  std::vector<std::pair<double, int>> stops_;  // (time, k) with k = -1 for a snapshot
  std::size_t next_stop_ = 0;
  std::unique_ptr<GrowingBlast<D, Queue>> blast_;
  std::unique_ptr<BlastObserver<D, Queue>> observer_;
  RealizationOutput out_;
  std::vector<Vec<D>> start_;  // the impurities at t = 0
};

template <int D, class Queue>
RealizationOutput run_realization_in(const ResolvedScene& scene, const ObservableLayout& layout, long long index,
                                     const RealizationExtras& extras,
                                     const std::function<void(long long, double)>& realization_time,
                                     const InFlight* in_flight) {
  if (realization_time) realization_time(index, 0.0);
  RealizationOutput out = RealizationRun<D, Queue>(scene, layout, index, extras, in_flight).finish(realization_time);
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
                                  const RealizationExtras& extras, const std::function<void(long long, double)>& time,
                                  const InFlight* in_flight) {
  common::require_integer_in_range("snapshot stride", extras.selection.stride, 1, 1000000000);
  const bool heap = scene.config.queue == "heap";
  if (scene.config.d == 2)
    return heap ? run_realization_in<2, HeapEventQueue>(scene, layout, index, extras, time, in_flight)
                : run_realization_in<2, CalendarEventQueue>(scene, layout, index, extras, time, in_flight);
  return heap ? run_realization_in<3, HeapEventQueue>(scene, layout, index, extras, time, in_flight)
              : run_realization_in<3, CalendarEventQueue>(scene, layout, index, extras, time, in_flight);
}

}  // namespace coldblast::md
