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

/// How to run an ensemble (numerics and files; the physics is in md::BlastConfig).
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
  /// The run's output folder: claimed for this run before any work (run/run_directory.hpp), and its
  /// checkpoint, OUT/checkpoint (run/checkpoint.hpp), keeps every block as it ends and a block in
  /// progress with its finished realizations at a stop and every `checkpoint_seconds`. Empty: no
  /// files, no checkpoint (the caller writes the outputs with write_blast_outputs).
  std::filesystem::path out;
  std::string out_option = "--out";  ///< how errors name `out`
  /// Continue the checkpoint in OUT (same resolved scene required, else std::invalid_argument
  /// naming --resume) and run only the missing realizations.
  bool resume = false;
  /// A fresh run may replace another run's files in OUT (exactly those: run/run_directory.hpp).
  bool overwrite = false;
  /// How to continue a stopped run, for the error when OUT holds a checkpoint and the run is fresh.
  std::string resume_hint;
  /// Seconds between saves of a block in progress, besides the saves when it ends and at a stop;
  /// 0 saves after every realization. >= 0.
  double checkpoint_seconds = 60.0;
  /// A realization that runs longer than this (seconds, > 0) saves its state in OUT/checkpoint every
  /// `in_flight_seconds` (md::InFlight, run/checkpoint.hpp's in_flight_path), and at a stop (SIGINT,
  /// SIGTERM) saves it and ends at once instead of running to its end; `--resume` goes on from
  /// there, bit for bit. Without `out`, realizations in flight run to their end at a stop.
  double in_flight_seconds = 600.0;
  /// Events between two checks of the clock and the stop request (md::InFlight::slice_events), >= 1.
  std::uint64_t in_flight_slice_events = std::uint64_t{1} << 20;
  /// The run id (run/run_directory.hpp); empty = a new one, or the checkpoint's when resuming.
  std::string run_id;
  /// Called before any work with a warning for stderr (snapshots above ~100 MB:
  /// run/snapshot_files.hpp), and after a realization whose region grew (md::run_realization),
  /// from the thread that ran it, one call at a time; may be empty.
  std::function<void(const std::string&)> warning;
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
  BlastResult result;                          ///< run id, scene, thread/shard settings, finished blocks
  std::map<long long, md::BlockSums> partial;  ///< blocks in progress in the checkpoint
  std::vector<long long> pending;              ///< blocks still to run (finished or not), ascending
  long long pending_realizations = 0;          ///< realizations still to run in `pending`
};
/// Resolves the scene; with options.out, claims the folder and starts the checkpoint, or loads it
/// (resume); lists the pending blocks. Throws std::invalid_argument for a bad scene, folder or
/// checkpoint.
EnsemblePlan plan_ensemble(const md::BlastConfig& config, const RunOptions& options);

/// A block in progress: the sums of its first `sums.count` realizations and their files.
struct BlockProgress {
  md::BlockSums sums;
  NamedFiles files;             ///< the single realizations' files of those realizations
  std::size_t files_saved = 0;  ///< files[0, files_saved) are in the checkpoint
  /// The collisions of the mid-run states its realizations resumed from in this process (not run
  /// here: BlastResult::resumed_collisions); not saved in the checkpoint, whose finished
  /// realizations all count as resumed when the run resumes again.
  std::uint64_t resumed_in_flight = 0;
};
/// What a block reports as it runs; each may be empty.
struct BlockCallbacks {
  std::function<void()> realization_done;                   ///< after each realization
  std::function<void(long long, double)> realization_time;  ///< RunOptions::realization_time
  std::function<void(const std::string&)> note;             ///< RunOptions::warning
  /// Saves the block's progress (the checkpoint): every `save_seconds`, before a realization's
  /// mid-run state, and when the block ends (finished, or stopped early by a stop request, another
  /// thread's stop or failure, its own failure) with realizations not yet saved.
  std::function<void(BlockProgress&)> save;
  double save_seconds = 60.0;
  /// Mid-realization checkpoints (RunOptions::in_flight_seconds; all empty: none): the saved state
  /// of a realization (empty bytes: none), its save, and its removal once the block file counts it.
  std::function<std::string(long long)> load_in_flight;
  std::function<void(long long, const std::string&)> save_in_flight;
  std::function<void(long long)> drop_in_flight;
  double in_flight_seconds = 600.0;
  std::uint64_t in_flight_slice_events = std::uint64_t{1} << 20;
};
/// Runs the realizations of block `block` from `start` (its first start.sums.count realizations
/// done: a block in progress from a checkpoint; empty: from its first) in index order on the
/// calling thread: the unit of work of threads, shards and MPI ranks. Stops early, returning the
/// realizations done, when `*stop` becomes true; throws common::Interrupted at a stop request, and
/// like run_blast when a realization fails, after saving what it has (callbacks.save).
BlockProgress run_block(const md::ResolvedScene& scene, const std::string& run_id, long long block,
                        BlockProgress start = {}, const std::atomic<bool>* stop = nullptr,
                        const BlockCallbacks& callbacks = {});
/// The callbacks of block `block` of a run with `options`: its progress saved to OUT/checkpoint
/// (none without options.out) and options.realization_time; realization_done is the caller's.
BlockCallbacks checkpoint_callbacks(const RunOptions& options, long long block);
/// Runs pending block `block` of `plan` (from its realizations in the checkpoint, if any) with
/// checkpoint_callbacks, calling `realization_done` after each realization: the work of a thread
/// (run_blast) or of MPI rank 0 (run_blast_mpi).
BlockProgress run_planned_block(const EnsemblePlan& plan, const RunOptions& options, long long block,
                                const std::atomic<bool>& stop, std::function<void()> realization_done);
/// Parses "i/n" (0 <= i < n); throws std::invalid_argument naming --shard otherwise.
std::pair<int, int> parse_shard(const std::string& text);
/// Adds the single realizations' files of `more` to `files`, keeping name order, one file per name.
void add_files(NamedFiles& files, const NamedFiles& more);

}  // namespace coldblast::run
