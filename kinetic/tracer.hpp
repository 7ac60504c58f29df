#pragma once
// A tracer run prepared on one process: ensembles of impurity trajectories of the paper's
// Lorentz–Boltzmann equation, Eq. (36) [LB-full], in a Navier–Stokes, TvNS (Euler) or uniform
// equilibrium host background, by exact null-collision Monte Carlo (kinetic/trajectory.hpp).
// Trajectory i is seeded from (seed, i) and trajectories are summed in blocks in index order, so
// every number is bit-identical for any thread count, sharding or rank count. The orchestration
// (threads, shards, MPI, checkpoints) and the run directory, the one of `md run` that `coldblast
// compare` reads, are run/tracer_run.*'s. Method, start and error budget: docs/kinetic.md.
#include <atomic>
#include <cstddef>
#include <memory>
#include <string>
#include <vector>

#include "kinetic/tracer_config.hpp"
#include "kinetic/tracer_statistics.hpp"
#include "md/blast_config.hpp"

namespace coldblast::kinetic {

/// What a prepared run knows before any block runs, and what its run directory records.
struct TracerRunInfo {
  TracerConfig config;          ///< validated, with the scene as run (realizations = trajectories, block size)
  md::BlastConfig input_scene;  ///< the scene as given (A_d = 0 left to the policy)
  md::ResolvedScene scene;      ///< A_d, φ, λ, radii and recording times (no particle region)
  std::string background_description;
  std::size_t background_frames = 0;
  std::string kernel = "scalar";  ///< the kernel that runs: "scalar" or a vector kernel ("avx512", ...)
  double n = 0.0, chi = 1.0;      ///< ambient (equilibrium: bath) density and its contact value
  double start_time = 0.0;
};

/// A tracer run prepared on one process (validated config, resolved scene, background): what every
/// driver (run/tracer_run.hpp's threads, run/mpi_tracer.hpp's MPI ranks) shares. Blocks run on any
/// thread in any order, and each depends only on its index.
class TracerRun {
 public:
  /// Validates; builds the background (ns: solves NS, reporting to `progress`).
  explicit TracerRun(const TracerConfig& config, const BackgroundProgress& progress = {});
  ~TracerRun();
  TracerRun(const TracerRun&) = delete;
  TracerRun& operator=(const TracerRun&) = delete;
  const TracerRunInfo& info() const;
  /// This shard's blocks, ascending.
  const std::vector<long long>& blocks() const { return blocks_; }
  /// Runs the trajectories of block `block` in index order on the calling thread; returns early
  /// (partial sums, to be discarded) when `stop` becomes true.
  TracerBlockSums run_block(long long block, const std::atomic<bool>& stop) const;

 private:
  struct Context;
  std::unique_ptr<Context> context_;
  std::vector<long long> blocks_;
};

}  // namespace coldblast::kinetic
