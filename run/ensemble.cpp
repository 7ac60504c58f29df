#include "run/ensemble.hpp"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <mutex>
#include <stdexcept>

#include "common/interrupt.hpp"
#include "common/validate.hpp"
#include "hydro/tvns.hpp"
#include "md/observers.hpp"
#include "md/realization.hpp"
#include "run/checkpoint.hpp"
#include "run/snapshot_files.hpp"
#include "run/worker_pool.hpp"

namespace coldblast::run {

md::ResolvedScene resolve_blast_scene(const md::BlastConfig& config) {
  return md::resolve_scene(config, hydro::md_amplitude);
}

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

md::BlockSums run_block(const md::ResolvedScene& scene, long long block, NamedFiles* realization0_files,
                        const std::function<void()>& realization_done, const std::atomic<bool>* stop,
                        const std::function<void(long long, double)>& realization_time) {
  const md::ObservableLayout layout(scene);
  const long long B = scene.config.block_size;
  md::BlockSums s;
  s.sum.assign(layout.size(), 0.0);
  s.sum_squares.assign(layout.size(), 0.0);
  for (long long r = block * B; r < block * B + md::block_realizations(scene.config, block); ++r) {
    if (stop && *stop) break;
    common::throw_if_stop_requested();  // SIGINT/SIGTERM or a host's Ctrl-C: finished blocks stay saved
    const md::RealizationExtras extras = realization_extras(scene, r);
    const md::RealizationOutput out = md::run_realization(scene, layout, r, extras, realization_time);
    md::add_realization(s, out.record, out.collisions, out.energy_error);
    if (r == 0 && realization0_files) *realization0_files = realization_files(scene, r, out);
    if (realization_done) realization_done();
  }
  return s;
}

EnsemblePlan plan_ensemble(const md::BlastConfig& config, const RunOptions& options) {
  EnsemblePlan plan;
  BlastResult& result = plan.result;
  result.scene = resolve_blast_scene(config);
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
  for (const long long b : plan.pending) plan.pending_realizations += md::block_realizations(config, b);
  return plan;
}

BlastResult run_blast(const md::BlastConfig& config, const RunOptions& options) {
  common::require_integer_in_range("threads", options.threads, 1, 1024);
  common::require_integer_in_range("shard_count", options.shard_count, 1, 1000000);
  common::require_integer_in_range("shard_index", options.shard_index, 0, options.shard_count - 1);
  const auto started = std::chrono::steady_clock::now();
  EnsemblePlan plan = plan_ensemble(config, options);
  BlastResult& result = plan.result;
  const md::ResolvedScene& scene = result.scene;
  const std::vector<long long>& owned = plan.pending;  // blocks still to run
  const long long total = plan.pending_realizations;

  std::vector<md::BlockSums> sums(owned.size());
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

}  // namespace coldblast::run
