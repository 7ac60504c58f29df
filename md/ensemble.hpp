#pragma once
// Ensembles of blast realizations: threads, shards and exact merges. Realization i is seeded from
// (seed, i); realizations are grouped in blocks (block = i / block_size) whose sums are accumulated
// in index order by one worker and totalled in block order, so every number is bit-identical for
// any thread count and sharding. Outputs (observables.csv, blocks.csv, summary.json, ...) are
// described in docs/md-output.md.
#include <atomic>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "common/output.hpp"
#include "md/initial_state.hpp"
#include "md/scenes.hpp"

namespace coldblast::md {

/// How to run an ensemble (numerics only; the physics is in BlastConfig).
struct RunOptions {
  int threads = 1;      ///< worker threads, >= 1
  int shard_index = 0;  ///< this shard runs blocks shard_index, shard_index + shard_count, ...
  int shard_count = 1;  ///< number of shards, >= 1
  /// Called after each realization with (done, total); may be empty. Called under a lock.
  std::function<void(long long, long long)> progress;
  /// Folder where every finished block is saved at once (md/checkpoint.hpp); empty = no checkpoint.
  /// A fresh run clears the folder's old blocks.
  std::filesystem::path checkpoint;
  /// Load the blocks already saved in `checkpoint` (same resolved scene required, else
  /// std::invalid_argument naming --resume) and run only the missing ones.
  bool resume = false;
};

/// Extra files of realization 0 (snapshot_<t>.csv, trajectories.csv): name → content.
using NamedFiles = std::vector<std::pair<std::string, std::string>>;

/// Sums over the realizations of one block.
struct BlockSums {
  std::vector<double> sum, sum_squares;  ///< per record entry
  long long count = 0;                   ///< realizations in the block
  std::uint64_t collisions = 0;
  double energy_error_max = 0.0;  ///< largest |E_kin(t_max) - E|/E in the block
};

/// A finished (or merged) ensemble.
struct BlastResult {
  ResolvedScene scene;
  std::map<long long, BlockSums> blocks;  ///< by block index
  double wall_seconds = 0.0;
  /// Realizations and collisions of blocks loaded from a checkpoint (`--resume`), not run in
  /// wall_seconds: the cost figures of the summary leave them out.
  long long resumed_realizations = 0;
  std::uint64_t resumed_collisions = 0;
  int threads = 1, shard_index = 0, shard_count = 1;
  int ranks = 1;  ///< MPI ranks that ran the ensemble (md/mpi_ensemble.hpp), each with `threads` threads
  /// Extra files of realization 0 (snapshot_<t>.csv, trajectories.csv): name → content.
  NamedFiles realization0_files;

  long long realizations() const;
  std::uint64_t collisions() const;
  double energy_error_max() const;
};

/// One row of observables.csv.
struct ObservableEstimate {
  double t;
  std::string observable;
  double mean, stderr_;
  long long count;
};

/// The initial state of realization `index` of a resolved blast scene (paper Sec. V): random
/// sequential addition at density n in the scene's region, then the impurities (the particles
/// nearest the origin) kicked with total energy E and zero momentum; seeded from (seed, index).
template <int D>
InitialState<D> blast_initial_state(const ResolvedScene& scene, long long index);

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
/// realization 0; calls `realization_done` after each realization; stops early when `*stop` becomes
/// true (the partial sums must then be discarded). Throws like run_blast.
BlockSums run_block(const ResolvedScene& scene, long long block, NamedFiles* realization0_files = nullptr,
                    const std::function<void()>& realization_done = {}, const std::atomic<bool>* stop = nullptr);
/// The ensemble estimates (mean, standard error) of the scalar observables, in output order.
std::vector<ObservableEstimate> estimate_observables(const BlastResult& result);
/// Writes every output file into `directory` (atomically, file by file).
void write_blast_outputs(const BlastResult& result, const std::filesystem::path& directory);
/// Reads shard directories written by write_blast_outputs and combines them exactly.
BlastResult merge_blast_outputs(const std::vector<std::filesystem::path>& directories);
/// Summary document (the content of summary.json).
common::Json blast_summary(const BlastResult& result);
/// Parses "i/n" (0 <= i < n); throws std::invalid_argument naming --shard otherwise.
std::pair<int, int> parse_shard(const std::string& text);

}  // namespace coldblast::md
