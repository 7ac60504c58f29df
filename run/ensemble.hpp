#pragma once
// Running ensembles of blast realizations: threads, shards and checkpoints. Realization i is seeded
// from (seed, i); realizations are grouped in blocks (block = i / block_size) whose sums are
// accumulated in index order by one worker and totalled in block order, so every number is
// bit-identical for any thread count and sharding. A scene that leaves A_d = 0 is sized with the
// project's one A_d policy, hydro::md_amplitude (docs/ARCHITECTURE.md). Writing, reading and
// merging the run files is run/run_files.* (docs/md-output.md); one realization is md/realization.hpp's.
#include <atomic>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "md/blast_config.hpp"
#include "md/block_sums.hpp"
#include "run/run_files.hpp"

namespace coldblast::run {

/// How to run an ensemble (numerics only; the physics is in BlastConfig).
struct RunOptions {
  int threads = 1;      ///< worker threads, >= 1
  int shard_index = 0;  ///< this shard runs blocks shard_index, shard_index + shard_count, ...
  int shard_count = 1;  ///< number of shards, >= 1
  /// Called after each realization with (done, total); may be empty. Called under a lock.
  std::function<void(long long, long long)> progress;
  /// Called with (realization, t) when a realization starts (t = 0, before its initial state is
  /// built: ~40 s for the 3D paper scene's region) and as it passes each recorded time t; may be
  /// empty. Called from the worker threads, concurrently: a 3D paper-scene realization runs for
  /// minutes, and this is its progress.
  std::function<void(long long, double)> realization_time;
  /// Folder where every finished block is saved at once (run/checkpoint.hpp); empty = no checkpoint.
  /// A fresh run clears the folder's old blocks.
  std::filesystem::path checkpoint;
  /// Load the blocks already saved in `checkpoint` (same resolved scene required, else
  /// std::invalid_argument naming --resume) and run only the missing ones.
  bool resume = false;
};

/// The scene resolved with the project's A_d policy (hydro::md_amplitude for A_d = 0).
md::ResolvedScene resolve_blast_scene(const md::BlastConfig& config);

/// Runs the realizations of `config` owned by this shard. Throws std::invalid_argument for bad
/// options/scene and std::runtime_error when a realization fails (e.g. the guard trips).
BlastResult run_blast(const md::BlastConfig& config, const RunOptions& options = {});

/// What is known before any realization of an ensemble runs (shared by the threaded and the MPI
/// drivers): the resolved scene and options, the blocks loaded from a checkpoint when resuming,
/// and the blocks of this shard still to run.
struct EnsemblePlan {
  BlastResult result;                  ///< scene, thread/shard settings, already finished blocks
  std::vector<long long> pending;      ///< blocks still to run, ascending
  long long pending_realizations = 0;  ///< realizations in `pending`
};
/// Resolves the scene, loads (resume) or starts the checkpoint in options.checkpoint, and lists
/// the pending blocks. Throws std::invalid_argument for a bad scene or checkpoint.
EnsemblePlan plan_ensemble(const md::BlastConfig& config, const RunOptions& options);
/// Runs the realizations of one block in index order on the calling thread: the unit of work of
/// threads, shards and MPI ranks. Fills `realization0_files` (if given) when the block holds
/// realization 0; calls `realization_done` after each realization (and `realization_time` at each
/// recorded time within one); stops early when `*stop` becomes true (the partial sums must then be
/// discarded). Throws like run_blast.
md::BlockSums run_block(const md::ResolvedScene& scene, long long block, NamedFiles* realization0_files = nullptr,
                        const std::function<void()>& realization_done = {}, const std::atomic<bool>* stop = nullptr,
                        const std::function<void(long long, double)>& realization_time = {});
/// Parses "i/n" (0 <= i < n); throws std::invalid_argument naming --shard otherwise.
std::pair<int, int> parse_shard(const std::string& text);

}  // namespace coldblast::run
