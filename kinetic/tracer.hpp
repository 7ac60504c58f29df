#pragma once
// `coldblast tracer`: ensembles of impurity trajectories of the paper's Lorentz–Boltzmann equation,
// Eq. (36) [LB-full], in a Navier–Stokes, TvNS (Euler) or uniform equilibrium host background, by
// exact null-collision Monte Carlo (kinetic/trajectory.hpp). Trajectory i is seeded from (seed, i)
// and trajectories are summed in blocks in index order, so every number is bit-identical for any
// thread count and sharding; the run directory is the one of `md run` (docs/md-output.md), so
// `coldblast compare` reads it unchanged. Method, start and error budget: docs/kinetic.md.
#include <atomic>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "common/output.hpp"
#include "kinetic/background.hpp"
#include "md/ensemble.hpp"
#include "md/scenes.hpp"
#include "md/states.hpp"

namespace coldblast::kinetic {

/// One tracer run: the MD scene (d, n, a, E, impurities.*, t_min, t_max, seed, block_size,
/// p_imp_bins) plus the background and the Monte Carlo options.
struct TracerConfig {
  md::BlastConfig scene;
  std::string background = "ns";         ///< "ns" (Navier–Stokes core), "tvns" (exact Euler) or "equilibrium"
  std::string transport = "dilute";      ///< "dilute" (chi = 1) or "enskog" (chi(n) at contact; ns: the dense NS)
  long long trajectories = 0;            ///< impurity trajectories, >= 1; 0 = scene realizations × impurities.count
  int threads = 1;                       ///< worker threads, [1, 1024]
  int shard_index = 0, shard_count = 1;  ///< this shard runs blocks shard_index, shard_index + shard_count, ...
  double T = 1.0;                        ///< equilibrium: bath temperature, > 0
  std::optional<double> phi;  ///< equilibrium: packing fraction (default: the scene's), (0, 0.7) 2D, (0, 0.5) 3D
  /// "kick" (the MD's kick: E shared by k impurities), "thermal", or "states": trajectory i starts
  /// from state i of start_states (the MD's own impurities, `md states`) at the file's time.
  std::string start = "kick";
  double start_time = 0.0;     ///< start time, >= 0 (> 0 for ns/tvns); 0 = scene t_min (ns, tvns); 0 for states
  std::string start_states;    ///< start = "states": an impurity_states.csv of the same scene (md/states.hpp)
  int frames_per_decade = 40;  ///< ns: stored background frames per decade of R/λ, [4, 400]
  int cells = 256;             ///< ns: finite-volume cells, [64, 4096]; tvns: x samples = 8 × cells
  /// "auto" (the 8-lane AVX-512 kernel of kinetic/batch.hpp where the CPU has it and the background
  /// is a grid, else the scalar loop), "avx512" or "scalar". The kernels sample the same process
  /// with different deviates: the same laws, other sample paths (a run records its kernel).
  std::string kernel = "auto";
  /// Throws std::invalid_argument naming the option, its value and the allowed range.
  void validate() const;
  /// start_time with 0 resolved.
  double resolved_start_time() const;
};

/// Sums over the trajectories of one block beyond the md layout: per recording time k the sums of
/// |Δr|², |Δr|⁴, |v|², |v|⁴ (moments[4k + 0..3]); the end state at t_max; work counters.
struct TracerBlock {
  std::vector<double> moments;
  double collisions_squares = 0.0;  ///< Σ (collisions of the trajectory in [start, t_max])²
  double v2_final = 0.0, v2_final_squares = 0.0;
  std::uint64_t candidates = 0, collisions = 0;
  long long count = 0;
};

/// A finished tracer ensemble.
struct TracerResult {
  TracerConfig config;
  md::BlastResult ensemble;  ///< scene and md-layout block sums (R_imp, V_imp, C_imp, u_imp, p_imp)
  std::map<long long, TracerBlock> blocks;
  std::string background_description;
  std::size_t background_frames = 0;
  std::string kernel = "scalar";  ///< the kernel that ran: "avx512" or "scalar"
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

/// The scene of a tracer run: md::parse_scene of `toml_text` with `overrides`, except that the
/// scene's snapshot_times (particle snapshots, an md key that must lie within t_max) are dropped
/// first: the tracer records none, and they would refuse a shorter t_max. An override of them
/// still applies (and is checked).
md::BlastConfig parse_tracer_scene(const std::string& toml_text, const std::vector<std::string>& overrides,
                                   const std::string& source);

/// Progress of the `ns` background's Navier–Stokes solve: called with the shock's R/λ at each of its
/// diagnostics' samples (20 per decade; the solve ends just after t_max).
using BackgroundProgress = std::function<void(double R_over_lambda)>;

/// Progress of a run: the background's solve, then blocks(done, total) after each block. Either may
/// be empty.
struct TracerProgress {
  BackgroundProgress background;
  std::function<void(long long, long long)> blocks;
};

/// The background of a config (built once per run; `ns` integrates the Navier–Stokes blast).
std::unique_ptr<Background> make_background(const TracerConfig& config, std::string* description = nullptr,
                                            const BackgroundProgress& progress = {});

/// Runs the trajectories of this shard on config.threads threads (md::run_slots_in_parallel).
TracerResult run_tracer(const TracerConfig& config, const TracerProgress& progress = {});

/// One block's sums: md's layout (R_imp, V_imp, C_imp, u_imp, p_imp) and the tracer's own.
struct TracerBlockSums {
  md::BlockSums sums;
  TracerBlock tracer;
};

/// A tracer run prepared on one process (validated config, resolved scene, background): what every
/// driver (run_tracer's threads, kinetic/mpi_tracer.hpp's MPI ranks) shares. Blocks run on any
/// thread in any order; `add` collects them, and the result depends only on the blocks.
class TracerRun {
 public:
  /// Validates; builds the background (ns: solves NS, reporting to `progress`).
  explicit TracerRun(const TracerConfig& config, const BackgroundProgress& progress = {});
  ~TracerRun();
  TracerRun(const TracerRun&) = delete;
  TracerRun& operator=(const TracerRun&) = delete;
  /// This shard's blocks, ascending.
  const std::vector<long long>& blocks() const { return blocks_; }
  /// Runs the trajectories of block `block` in index order on the calling thread; returns early
  /// (partial sums, to be discarded) when `stop` becomes true.
  TracerBlockSums run_block(long long block, const std::atomic<bool>& stop) const;
  /// Keeps a finished block (not thread-safe: callers lock).
  void add(long long block, TracerBlockSums&& sums);
  /// The result so far, with the wall time since construction and `ranks` MPI ranks recorded.
  TracerResult result(int ranks = 1) const;

 private:
  struct Context;
  std::unique_ptr<Context> context_;
  std::vector<long long> blocks_;
};

/// Rows of moments.csv: at each recording time ⟨r²⟩, ⟨r⁴⟩/⟨r²⟩², ⟨v²⟩, ⟨v⁴⟩/⟨v²⟩² with block
/// jackknife errors (r = displacement from the start).
struct MomentRow {
  double t;
  double r2, r2_error, r_ratio, r_ratio_error, v2, v2_error, v_ratio, v_ratio_error;
};
std::vector<MomentRow> moment_rows(const TracerResult& result);

/// summary.json: md::blast_summary's keys plus the tracer's (docs/kinetic.md).
common::Json tracer_summary(const TracerResult& result);
/// Writes the run directory: the md files (observables.csv, blocks.csv, p_imp.csv, ...), then
/// moments.csv, prefactors.csv, the tracer's exact block sums (tracer_blocks.csv, read back by
/// merge_tracer_outputs) and the tracer's summary.json.
void write_tracer_outputs(const TracerResult& result, const std::filesystem::path& directory);

/// True when `directory`'s summary.json was written by the tracer (its "engine" key).
bool is_tracer_run(const std::filesystem::path& directory);
/// Reads tracer shard directories (`coldblast tracer --shard i/n`) and combines them exactly: md's
/// files through md::merge_blast_outputs, the tracer's block sums from tracer_blocks.csv, and the
/// run-wide summary keys (background, transport, start, chi, ...), which must agree across shards
/// (else std::invalid_argument naming the key). write_tracer_outputs of the result gives the files
/// of one run of every block, moments.csv and the tracer's summary keys included.
TracerResult merge_tracer_outputs(const std::vector<std::filesystem::path>& directories);

}  // namespace coldblast::kinetic
