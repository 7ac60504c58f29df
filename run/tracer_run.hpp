#pragma once
// `coldblast tracer` as a run: a prepared kinetic::TracerRun (kinetic/tracer.hpp: the physics) run
// block by block on threads (the worker pool of ensembles) for this shard, its start states read
// from their file, every finished block kept in OUT/checkpoint (--resume OUT continues with the
// checkpoint's scene and options), and the finished ensemble in md's run-directory form (the files
// are run/tracer_files.hpp's; over MPI ranks, run/mpi_tracer.hpp).
#include <cstdint>
#include <filesystem>
#include <functional>
#include <map>
#include <string>
#include <vector>

#include "kinetic/tracer.hpp"
#include "kinetic/tracer_config.hpp"
#include "kinetic/tracer_statistics.hpp"
#include "run/run_files.hpp"

namespace coldblast::run {

/// A finished tracer ensemble.
struct TracerResult {
  kinetic::TracerConfig config;
  BlastResult ensemble;  ///< scene and md-layout block sums (R_imp, V_imp, C_imp, u_imp, p_imp)
  kinetic::TracerBlocks blocks;
  std::string background_description;
  std::size_t background_frames = 0;
  std::string kernel = "scalar";  ///< the kernel that ran: "scalar" or a vector kernel ("avx512", ...)
  double n = 0.0, chi = 1.0;      ///< ambient (equilibrium: bath) density and its contact value
  double start_time = 0.0;
  double wall_seconds = 0.0;

  std::uint64_t collisions() const;
  std::uint64_t candidates() const;
  long long trajectories() const;
  /// Collisions per unit time per impurity over [start_time, t_max] and its standard error.
  double collision_rate() const;
  double collision_rate_error() const;
  /// M ⟨v²⟩/d of the impurity at t_max and its standard error.
  double temperature_final() const;
  double temperature_final_error() const;
  /// Share of majorant candidates that were not collisions.
  double rejection_rate() const;
};

/// Progress of a run: the background's solve, then blocks(done, total) after each block. Either may
/// be empty.
struct TracerProgress {
  kinetic::BackgroundProgress background;
  std::function<void(long long, long long)> blocks;
};

/// Where a tracer run keeps its files: as RunOptions' out, resume, overwrite (run/ensemble.hpp).
/// Without `out` nothing is written; the caller writes the outputs (write_tracer_outputs).
struct TracerRunFiles {
  std::filesystem::path out;
  std::string out_option = "--out";
  bool resume = false, overwrite = false;
  std::string resume_hint;  ///< how to continue a stopped run, e.g. "coldblast tracer --resume OUT"
};

/// The options a checkpoint records and --resume OUT alone restores: flag name → value text
/// (--background, --transport, --trajectories, --T, --phi, --start, --start-time, --start-states,
/// --md-run (md_run_path's form) and md_run_id, --frames-per-decade, --cells, --kernel, --shard).
std::map<std::string, std::string> tracer_option_values(const kinetic::TracerConfig& config);
/// --resume OUT: the config of OUT's checkpoint (its scene as given and its options), with
/// `requested`'s threads. Each flag in `given` (e.g. "--background", or "SCENE" and "--set" for the
/// scene) must agree with the checkpoint, else std::invalid_argument naming the flag and both values.
kinetic::TracerConfig resume_tracer_config(const std::filesystem::path& out, const kinetic::TracerConfig& requested,
                                           const std::vector<std::string>& given);

/// The config with the files it names read, once: its start states (start = "states": from
/// config.start_states, naming --start-states in errors) and its MD fields (background = "md": from
/// config.md_run, made absolute; the MD's scene must have the tracer's physics, and a recorded
/// md_run_id, e.g. a checkpoint's, must be the folder's run), otherwise the config unchanged.
kinetic::TracerConfig with_input_files(kinetic::TracerConfig config);
/// --md-run's folder as the run records it: absolute, normalised, without a trailing separator.
std::string md_run_path(const std::string& md_run);

/// The result of a prepared run with the blocks it finished, `wall_seconds` and `ranks` recorded.
TracerResult tracer_result(const kinetic::TracerRunInfo& info, double wall_seconds, int ranks = 1);

/// What a run knows before its blocks run (shared by the threaded and the MPI drivers): the result
/// so far (with the blocks of a resumed checkpoint) and the blocks still to run. Claims OUT and
/// starts its checkpoint, or loads it (resume).
struct TracerPlan {
  TracerResult result;
  std::vector<long long> pending;
};
TracerPlan plan_tracer(const kinetic::TracerRun& run, const TracerRunFiles& files);
/// Saves a finished block in OUT/checkpoint (nothing without OUT).
void save_tracer_block(const TracerRunFiles& files, long long block, const kinetic::TracerBlockSums& sums);

/// Runs the trajectories of this shard on config.threads threads (bit-identical for any count),
/// keeping every finished block in files.out's checkpoint.
TracerResult run_tracer(const kinetic::TracerConfig& config, const TracerProgress& progress = {},
                        const TracerRunFiles& files = {});
/// The end of a run with an output folder: its files and manifest.json, then the checkpoint removed.
void finish_tracer_run(const TracerResult& result, const std::filesystem::path& out);

}  // namespace coldblast::run
