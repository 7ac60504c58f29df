#include "md/ensemble.hpp"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <exception>
#include <mutex>
#include <sstream>
#include <stdexcept>
#include <thread>

#include "common/interrupt.hpp"
#include "common/validate.hpp"
#include "md/checkpoint.hpp"
#include "md/engine.hpp"
#include "md/extxyz.hpp"
#include "md/initial_state.hpp"
#include "md/observers.hpp"

namespace coldblast::md {

namespace {
using common::format_number;

struct RealizationOutput {
  std::vector<double> record;
  std::uint64_t collisions = 0;
  double energy_error = 0.0;
  std::vector<std::pair<std::string, std::string>> files;
};

template <int D, class Queue>
std::string snapshot_csv(const ResolvedScene& scene, const Engine<D, Queue>& engine) {
  std::ostringstream out;
  out << run_file_header(scene, {{"realization", "0"}, {"t", format_number(engine.now())}})
      << (D == 2 ? "id,x,y,moving,impurity\n" : "id,x,y,z,moving,impurity\n");
  for (std::size_t i = 0; i < engine.size(); ++i) {
    const auto id = static_cast<std::int32_t>(i);
    const Vec<D> x = engine.position(id);
    out << i;
    for (int k = 0; k < D; ++k) out << ',' << format_number(x[k]);
    out << ',' << (engine.is_moving(id) ? 1 : 0) << ',' << (engine.species(id) == impurity_species ? 1 : 0) << '\n';
  }
  return out.str();
}

/// trajectories.csv of realization 0: each impurity's start, its collisions, and its end, by id.
template <int D, class Queue>
std::string trajectories_csv(const ResolvedScene& scene, const Engine<D, Queue>& engine,
                             const std::vector<std::int32_t>& impurities, const std::vector<Vec<D>>& start) {
  std::vector<TrajectoryPoint<D>> points;
  for (std::size_t m = 0; m < start.size(); ++m) points.push_back({0.0, impurities[m], start[m]});
  for (const auto& p : engine.trajectories()) points.push_back(p);
  for (const std::int32_t id : impurities) points.push_back({engine.now(), id, engine.position(id)});
  std::stable_sort(points.begin(), points.end(), [](const auto& x, const auto& y) { return x.id < y.id; });
  std::ostringstream file;
  file << run_file_header(scene, {{"realization", "0"}}) << (D == 2 ? "id,t,x,y\n" : "id,t,x,y,z\n");
  for (const auto& p : points) {
    file << p.id << ',' << format_number(p.t);
    for (int k = 0; k < D; ++k) file << ',' << format_number(p.position[k]);
    file << '\n';
  }
  return file.str();
}

template <int D, class Queue>
RealizationOutput run_realization(const ResolvedScene& scene, const ObservableLayout& layout, long long index,
                                  const std::function<void(long long, double)>& realization_time) {
  const BlastConfig& c = scene.config;
  if (realization_time) realization_time(index, 0.0);
  const InitialState<D> state = blast_initial_state<D>(scene, index);

  const bool first = index == 0;
  EngineConfig<D> config = blast_engine_config<D>(scene);
  config.record_impurity_trajectories = first && scene.wants("trajectories");
  config.count_impurity_recollisions = scene.wants("C_re") || scene.wants("dE_first") || scene.wants("dE_re");
  Engine<D, Queue> engine(config, state);
  BlastObserver<D, Queue> observer(scene, layout, engine);

  RealizationOutput out;
  out.record.assign(layout.size(), 0.0);
  std::vector<std::pair<double, int>> stops;  // (time, k) with k = -1 for a snapshot
  for (std::size_t k = 0; k < scene.times.size(); ++k) stops.push_back({scene.times[k], static_cast<int>(k)});
  if (first && scene.wants("snapshots"))
    for (const double t : scene.snapshot_times) stops.push_back({t, -1});
  std::stable_sort(stops.begin(), stops.end(), [](const auto& x, const auto& y) { return x.first < y.first; });
  std::vector<Vec<D>> start;
  for (const std::int32_t id : observer.impurities()) start.push_back(engine.position(id));
  std::string extxyz;  // every snapshot as one frame of snapshots.extxyz (md/extxyz.hpp)
  for (const auto& [t, k] : stops) {
    engine.run_until(t);
    if (realization_time) realization_time(index, t);
    if (k >= 0) {
      observer.measure(k, out.record);
    } else {
      out.files.push_back({"snapshot_" + format_number(t) + ".csv", snapshot_csv(scene, engine)});
      extxyz += extxyz_frame(scene, engine);
    }
  }
  if (!extxyz.empty()) out.files.push_back({"snapshots.extxyz", extxyz});
  engine.run_until(c.t_max);
  out.collisions = engine.collision_count();
  out.energy_error = std::abs(engine.kinetic_energy() - c.E) / c.E;
  if (config.record_impurity_trajectories)
    out.files.push_back({"trajectories.csv", trajectories_csv(scene, engine, observer.impurities(), start)});
  for (const double v : out.record)
    if (!std::isfinite(v)) throw std::runtime_error("non-finite observable in realization " + std::to_string(index));
  return out;
}

/// What to do when a particle reached the guard at time `now`: the box_margin whose region would hold
/// it to t_max if every particle ahead of the blast kept its speed (in the cold gas they only slow
/// down, apart from hosts hit head-on by heavier impurities), the region scaled by t_max/now; above
/// box_margin's 100, lower t_max or E instead.
std::string guard_advice(const ResolvedScene& scene, double now) {
  const BlastConfig& c = scene.config;
  const double needed = scene.region_radius * c.t_max / std::max(now, 1e-300) / scene.shock_radius_at_t_max;
  const std::string margin = "raise box_margin (now " + format_number(c.box_margin) + ")";
  if (needed > 100.0)
    return margin + ": it would need " + format_number(needed) + ", above its maximum 100, so lower t_max or E";
  return margin + " to " + format_number(std::ceil(needed * 10.0) / 10.0) +
         " (the region scaled by t_max/t, enough if no particle ahead of the blast speeds up) or give a smaller A_d "
         "(now " +
         format_number(scene.A_d) + ")";
}

RealizationOutput dispatch(const ResolvedScene& scene, const ObservableLayout& layout, long long index,
                           const std::function<void(long long, double)>& time) {
  const bool heap = scene.config.queue == "heap";
  if (scene.config.d == 2)
    return heap ? run_realization<2, HeapEventQueue>(scene, layout, index, time)
                : run_realization<2, CalendarEventQueue>(scene, layout, index, time);
  return heap ? run_realization<3, HeapEventQueue>(scene, layout, index, time)
              : run_realization<3, CalendarEventQueue>(scene, layout, index, time);
}

}  // namespace

template <int D>
InitialState<D> blast_initial_state(const ResolvedScene& scene, long long index) {
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
  kick_impurities<D>(rng, state, static_cast<std::size_t>(c.impurities.count), c.E, scene.region_radius);
  return state;
}
template InitialState<2> blast_initial_state<2>(const ResolvedScene&, long long);
template InitialState<3> blast_initial_state<3>(const ResolvedScene&, long long);

template <int D>
EngineConfig<D> blast_engine_config(const ResolvedScene& scene) {
  const BlastConfig& c = scene.config;
  EngineConfig<D> config;
  config.periodic = false;
  config.region_radius = scene.region_radius;
  config.guard_radius = scene.guard_radius;
  config.guard_advice_at = [scene](double now) { return guard_advice(scene, now); };
  config.cell_width = c.cell_width;
  config.overlap_check = c.overlap_check;
  config.impurity_recollisions = c.impurities.recollide;
  return config;
}
template EngineConfig<2> blast_engine_config<2>(const ResolvedScene&);
template EngineConfig<3> blast_engine_config<3>(const ResolvedScene&);

std::pair<int, int> parse_shard(const std::string& text) {
  const auto slash = text.find('/');
  int i = -1, n = -1;
  try {
    std::size_t u1 = 0, u2 = 0;
    if (slash == std::string::npos) throw std::invalid_argument("");
    i = std::stoi(text.substr(0, slash), &u1);
    n = std::stoi(text.substr(slash + 1), &u2);
    if (u1 != slash || u2 != text.size() - slash - 1) throw std::invalid_argument("");
  } catch (const std::exception&) {
    throw std::invalid_argument("--shard = " + text + " is not of the form i/n (0 <= i < n)");
  }
  common::require_integer_in_range("--shard n", n, 1, 1000000);
  common::require_integer_in_range("--shard i", i, 0, n - 1, " (0 <= i < n; --shard = " + text + ")");
  return {i, n};
}

long long block_realizations(const BlastConfig& config, long long block) {
  const long long R = config.realizations, B = config.block_size;
  return std::max(0LL, std::min(R, (block + 1) * B) - block * B);
}

BlockSums run_block(const ResolvedScene& scene, long long block, NamedFiles* realization0_files,
                    const std::function<void()>& realization_done, const std::atomic<bool>* stop,
                    const std::function<void(long long, double)>& realization_time) {
  const ObservableLayout layout(scene);
  const long long B = scene.config.block_size;
  BlockSums s;
  s.sum.assign(layout.size(), 0.0);
  s.sum_squares.assign(layout.size(), 0.0);
  for (long long r = block * B; r < block * B + block_realizations(scene.config, block); ++r) {
    if (stop && *stop) break;
    common::throw_if_stop_requested();  // SIGINT/SIGTERM or a host's Ctrl-C: finished blocks stay saved
    RealizationOutput out = dispatch(scene, layout, r, realization_time);
    add_realization(s, out.record, out.collisions, out.energy_error);
    if (r == 0 && realization0_files) *realization0_files = std::move(out.files);
    if (realization_done) realization_done();
  }
  return s;
}

void run_slots_in_parallel(std::size_t count, int threads,
                           const std::function<void(std::size_t slot, const std::atomic<bool>& stop)>& work) {
  std::atomic<std::size_t> next{0};
  std::atomic<bool> failed{false};
  std::exception_ptr error;
  std::mutex mutex;
  auto worker = [&] {
    while (!failed) {
      const std::size_t slot = next++;
      if (slot >= count) return;
      try {
        common::throw_if_stop_requested();  // finished slots stay done (md: saved in the checkpoint)
        work(slot, failed);
      } catch (...) {
        std::lock_guard<std::mutex> lock(mutex);
        if (!error) error = std::current_exception();
        failed = true;
      }
    }
  };
  std::vector<std::thread> pool;
  for (int t = 1; t < threads; ++t) pool.emplace_back(worker);
  worker();
  for (auto& t : pool) t.join();
  if (error) std::rethrow_exception(error);
}

EnsemblePlan plan_ensemble(const BlastConfig& config, const RunOptions& options) {
  EnsemblePlan plan;
  BlastResult& result = plan.result;
  result.scene = resolve_scene(config, options.amplitude);
  result.threads = options.threads;
  result.shard_index = options.shard_index;
  result.shard_count = options.shard_count;
  const long long block_count = (config.realizations + config.block_size - 1) / config.block_size;
  if (!options.checkpoint.empty()) {
    if (options.resume) {
      Checkpoint saved = load_checkpoint(options.checkpoint, result.scene);
      for (auto& [b, s] : saved.blocks)
        if (b % options.shard_count == options.shard_index) {
          result.resumed_realizations += s.count;
          result.resumed_collisions += s.collisions;
          result.blocks[b] = std::move(s);
        }
      if (result.blocks.count(0)) result.realization0_files = std::move(saved.realization0_files);
    } else {
      start_checkpoint(options.checkpoint, result.scene);
    }
  }
  for (long long b = options.shard_index; b < block_count; b += options.shard_count)
    if (!result.blocks.count(b)) plan.pending.push_back(b);
  for (const long long b : plan.pending) plan.pending_realizations += block_realizations(config, b);
  return plan;
}

BlastResult run_blast(const BlastConfig& config, const RunOptions& options) {
  common::require_integer_in_range("threads", options.threads, 1, 1024);
  common::require_integer_in_range("shard_count", options.shard_count, 1, 1000000);
  common::require_integer_in_range("shard_index", options.shard_index, 0, options.shard_count - 1);
  const auto started = std::chrono::steady_clock::now();
  EnsemblePlan plan = plan_ensemble(config, options);
  BlastResult& result = plan.result;
  const ResolvedScene& scene = result.scene;
  const std::vector<long long>& owned = plan.pending;  // blocks still to run
  const long long total = plan.pending_realizations;

  std::vector<BlockSums> sums(owned.size());
  std::mutex mutex;
  long long done = 0;
  const auto realization_done = [&] {
    std::lock_guard<std::mutex> lock(mutex);
    ++done;
    if (options.progress) options.progress(done, total);
  };
  run_slots_in_parallel(owned.size(), options.threads, [&](std::size_t slot, const std::atomic<bool>& stop) {
    NamedFiles files;
    sums[slot] = run_block(scene, owned[slot], &files, realization_done, &stop, options.realization_time);
    if (stop) return;
    if (!options.checkpoint.empty())
      save_checkpoint_block(options.checkpoint, owned[slot], sums[slot], owned[slot] == 0 ? &files : nullptr);
    if (owned[slot] == 0) {
      std::lock_guard<std::mutex> lock(mutex);
      result.realization0_files = std::move(files);
    }
  });
  for (std::size_t slot = 0; slot < owned.size(); ++slot) result.blocks[owned[slot]] = std::move(sums[slot]);
  result.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  return std::move(plan.result);
}

}  // namespace coldblast::md
