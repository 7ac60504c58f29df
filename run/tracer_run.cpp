#include "run/tracer_run.hpp"

#include <atomic>
#include <chrono>
#include <memory>
#include <mutex>
#include <vector>

#include "run/impurity_states.hpp"
#include "run/worker_pool.hpp"

namespace coldblast::run {

std::uint64_t TracerResult::collisions() const {
  return kinetic::total_collisions(blocks);
}
std::uint64_t TracerResult::candidates() const {
  return kinetic::total_candidates(blocks);
}
long long TracerResult::trajectories() const {
  return kinetic::total_trajectories(blocks);
}
double TracerResult::collision_rate() const {
  return kinetic::collision_rate(blocks, config.scene.t_max - start_time);
}
double TracerResult::collision_rate_error() const {
  return kinetic::collision_rate_error(blocks, config.scene.t_max - start_time);
}
double TracerResult::temperature_final() const {
  return kinetic::temperature_final(blocks, config.scene.impurities.mass, config.scene.d);
}
double TracerResult::temperature_final_error() const {
  return kinetic::temperature_final_error(blocks, config.scene.impurities.mass, config.scene.d);
}
double TracerResult::rejection_rate() const {
  return kinetic::rejection_rate(blocks);
}

kinetic::TracerConfig with_start_states(kinetic::TracerConfig config) {
  if (config.start != "states" || config.states || config.start_states.empty()) return config;
  config.states = std::make_shared<const md::ImpurityStates>(
      read_impurity_states(config.start_states, config.scene.d, "--start-states"));
  return config;
}

TracerResult tracer_result(const kinetic::TracerRunInfo& info, double wall_seconds, int ranks) {
  TracerResult result;
  result.config = info.config;
  result.ensemble.scene = info.scene;
  result.ensemble.threads = info.config.threads;
  result.ensemble.shard_index = info.config.shard_index;
  result.ensemble.shard_count = info.config.shard_count;
  result.ensemble.ranks = ranks;
  result.ensemble.wall_seconds = wall_seconds;
  result.background_description = info.background_description;
  result.background_frames = info.background_frames;
  result.kernel = info.kernel;
  result.n = info.n;
  result.chi = info.chi;
  result.start_time = info.start_time;
  result.wall_seconds = wall_seconds;
  return result;
}

TracerResult run_tracer(const kinetic::TracerConfig& config, const TracerProgress& progress) {
  const auto started = std::chrono::steady_clock::now();
  config.validate();  // before the states are read: a missing --start-states is named as such
  const kinetic::TracerRun run(with_start_states(config), progress.background);
  const std::vector<long long>& owned = run.blocks();
  std::vector<kinetic::TracerBlockSums> outputs(owned.size());
  std::mutex mutex;
  long long done = 0;
  run_slots_in_parallel(owned.size(), config.threads, [&](std::size_t slot, const std::atomic<bool>& stop) {
    outputs[slot] = run.run_block(owned[slot], stop);
    std::lock_guard<std::mutex> lock(mutex);
    ++done;
    if (progress.blocks) progress.blocks(done, static_cast<long long>(owned.size()));
  });
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  TracerResult result = tracer_result(run.info(), wall);
  for (std::size_t slot = 0; slot < owned.size(); ++slot) {
    result.ensemble.blocks[owned[slot]] = std::move(outputs[slot].sums);
    result.blocks[owned[slot]] = std::move(outputs[slot].tracer);
  }
  return result;
}

}  // namespace coldblast::run
