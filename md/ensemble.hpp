#pragma once
// Running ensembles of blast realizations: threads, shards and checkpoints. Realization i is seeded
// from (seed, i); realizations are grouped in blocks (block = i / block_size) whose sums are
// accumulated in index order by one worker and totalled in block order, so every number is
// bit-identical for any thread count and sharding. Writing, reading and merging the run files is
// md/run_files.* (docs/md-output.md).
#include <atomic>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "common/output.hpp"
#include "md/engine.hpp"
#include "md/initial_state.hpp"
#include "md/run_files.hpp"
#include "md/scenes.hpp"

namespace coldblast::md {

/// How to run an ensemble (numerics only; the physics is in BlastConfig).
struct RunOptions {
  int threads = 1;      ///< worker threads, >= 1
  int shard_index = 0;  ///< this shard runs blocks shard_index, shard_index + shard_count, ...
  int shard_count = 1;  ///< number of shards, >= 1
  /// The amplitude that sizes the box when the scene gives A_d = 0 (md/scenes.hpp); `md run`,
  /// `reproduce` and the Python module pass hydro::md_amplitude. Empty: the scene must give A_d.
  AmplitudePolicy amplitude;
  /// Called after each realization with (done, total); may be empty. Called under a lock.
  std::function<void(long long, long long)> progress;
  /// Called with (realization, t) when a realization starts (t = 0, before its initial state is
  /// built: ~40 s for the 3D paper scene's region) and as it passes each recorded time t; may be
  /// empty. Called from the worker threads, concurrently: a 3D paper-scene realization runs for
  /// minutes, and this is its progress.
  std::function<void(long long, double)> realization_time;
  /// Folder where every finished block is saved at once (md/checkpoint.hpp); empty = no checkpoint.
  /// A fresh run clears the folder's old blocks.
  std::filesystem::path checkpoint;
  /// Load the blocks already saved in `checkpoint` (same resolved scene required, else
  /// std::invalid_argument naming --resume) and run only the missing ones.
  bool resume = false;
};

/// The initial state of realization `index` of a resolved blast scene (paper Sec. V): random
/// sequential addition at density n in the scene's region, then the impurities (the particles
/// nearest the origin) kicked with total energy E and zero momentum; seeded from (seed, index).
template <int D>
InitialState<D> blast_initial_state(const ResolvedScene& scene, long long index);

/// The engine settings of a blast realization (open region, guard and its advice, cell width,
/// overlap check): the one scene → EngineConfig mapping, shared by ensembles and benchmarks.
template <int D>
EngineConfig<D> blast_engine_config(const ResolvedScene& scene);

/// Runs the realizations of `config` owned by this shard. Throws std::invalid_argument for bad
/// options/scene and std::runtime_error when a realization fails (e.g. the guard trips).
BlastResult run_blast(const BlastConfig& config, const RunOptions& options = {});

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
EnsemblePlan plan_ensemble(const BlastConfig& config, const RunOptions& options);
/// Realizations in block `block` (the last block may be short).
long long block_realizations(const BlastConfig& config, long long block);
/// Runs the realizations of one block in index order on the calling thread: the unit of work of
/// threads, shards and MPI ranks. Fills `realization0_files` (if given) when the block holds
/// realization 0; calls `realization_done` after each realization (and `realization_time` at each
/// recorded time within one); stops early when `*stop` becomes true (the partial sums must then be
/// discarded). Throws like run_blast.
BlockSums run_block(const ResolvedScene& scene, long long block, NamedFiles* realization0_files = nullptr,
                    const std::function<void()>& realization_done = {}, const std::atomic<bool>* stop = nullptr,
                    const std::function<void(long long, double)>& realization_time = {});
/// The one worker pool of ensembles (md::run_blast, the tracer kinetic::run_tracer): runs
/// work(slot, stop) once for every slot in [0, count) on `threads` threads, the calling thread among
/// them, handing slots out in increasing order. A slot's work must write only its own results (and
/// merge them in slot order afterwards), so the outcome is bit-identical for any thread count. A
/// stop request (SIGINT/SIGTERM, common/interrupt.hpp) is checked before every slot; the first
/// exception sets `stop` (long work should poll it and return), no slot starts after it, and it is
/// rethrown once every thread has joined.
void run_slots_in_parallel(std::size_t count, int threads,
                           const std::function<void(std::size_t slot, const std::atomic<bool>& stop)>& work);
/// Parses "i/n" (0 <= i < n); throws std::invalid_argument naming --shard otherwise.
std::pair<int, int> parse_shard(const std::string& text);

}  // namespace coldblast::md
