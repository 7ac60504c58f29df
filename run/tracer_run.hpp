#pragma once
// `coldblast tracer` as a run: a prepared kinetic::TracerRun (kinetic/tracer.hpp: the physics) run
// block by block on threads (the worker pool of ensembles) for this shard, its start states read
// from their file, and the finished ensemble in md's run-directory form (the files are
// run/tracer_files.hpp's; over MPI ranks, run/mpi_tracer.hpp).
#include <cstdint>
#include <functional>
#include <string>

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

/// The config with its start states read (start = "states" and none given yet: from
/// config.start_states, naming --start-states in errors); otherwise the config unchanged.
kinetic::TracerConfig with_start_states(kinetic::TracerConfig config);

/// The result of a prepared run with the blocks it finished, `wall_seconds` and `ranks` recorded.
TracerResult tracer_result(const kinetic::TracerRunInfo& info, double wall_seconds, int ranks = 1);

/// Runs the trajectories of this shard on config.threads threads (bit-identical for any count).
TracerResult run_tracer(const kinetic::TracerConfig& config, const TracerProgress& progress = {});

}  // namespace coldblast::run
