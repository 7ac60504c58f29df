#pragma once
// The options of a tracer run (`coldblast tracer`, docs/kinetic.md): the MD scene, the host
// background and the Monte Carlo's numerics, their validation with the CLI's option names, and the
// background they describe (built once per run).
#include <functional>
#include <memory>
#include <optional>
#include <string>

#include "hydro/navier_stokes_config.hpp"
#include "kinetic/background.hpp"
#include "kinetic/md_background.hpp"
#include "md/blast_config.hpp"
#include "md/impurity_state.hpp"

namespace coldblast::kinetic {

/// One tracer run: the MD scene (d, n, a, E, impurities.*, t_min, t_max, seed, block_size,
/// p_imp_bins) plus the background and the Monte Carlo options.
struct TracerConfig {
  md::BlastConfig scene;
  /// "ns" (Navier–Stokes core), "tvns" (exact Euler), "equilibrium" or "md" (an MD run's own
  /// measured profiles: md_run)
  std::string background = "ns";
  std::string md_run;     ///< background = "md": the `md run` folder (recorded, and in messages)
  std::string md_run_id;  ///< background = "md": that run's id (recorded; empty for a run before run ids)
  /// background = "md": the profiles read from md_run (run::with_input_files).
  std::shared_ptr<const MeasuredProfiles> md_profiles;
  std::string transport = "dilute";      ///< "dilute" (chi = 1) or "enskog" (chi(n) at contact; ns: the dense NS)
  long long trajectories = 0;            ///< impurity trajectories, >= 1; 0 = scene realizations × impurities.count
  int threads = 1;                       ///< worker threads, [1, 1024]
  int shard_index = 0, shard_count = 1;  ///< this shard runs blocks shard_index, shard_index + shard_count, ...
  double T = 1.0;                        ///< equilibrium: bath temperature, > 0
  std::optional<double> phi;  ///< equilibrium: packing fraction (default: the scene's), (0, 0.7) 2D, (0, 0.5) 3D
  /// "kick" (the MD's kick: E shared by k impurities), "hotspot" (the MD's hot spot of radius r0:
  /// the impurity among the particles nearest the centre, E shared as a Maxwellian by every particle
  /// within r0, the background the Navier–Stokes hot spot; kinetic/hot_spot_start.hpp), "single"
  /// (the MD's single kicked host: the impurity at rest where the MD puts it, near the centre, until
  /// the blast's background picks it up), "thermal", or
  /// "states": trajectory i starts from state i of `states` (the MD's own impurities, `md states`) at
  /// their time.
  std::string start = "kick";
  /// start = "hotspot": the hot spot's radius (length, the scene's start.r0), in
  /// [md::hot_spot_min_radius, R(t_max)]; 0 = the scene's start.r0 if its [start] is a hot spot.
  /// Must stay 0 for the other starts.
  double r0 = 0.0;
  /// start time, >= 0 (> 0 for ns/tvns); 0 = scene t_min (ns, tvns), t_min/1024 for hotspot (the
  /// deposition, to 0.1 % of t_min); 0 for states
  double start_time = 0.0;
  std::string start_states;  ///< start = "states": the impurity_states.csv they came from (recorded, and in messages)
  /// start = "states": the states read from start_states (run::read_impurity_states).
  std::shared_ptr<const md::ImpurityStates> states;
  int frames_per_decade = 40;             ///< ns: stored background frames per decade of R/λ, [4, 400]
  int cells = hydro::default_core_cells;  ///< ns: finite-volume cells, [64, 4096]; tvns: x samples = 8 × cells
  /// "auto" (the widest vector kernel of kinetic/batch.hpp this CPU runs where the background is a
  /// grid, else the scalar loop), "avx512", "avx2", "sse4", "neon" or "scalar" (resolve_kernel). The
  /// kernels sample the same process with different deviates: the same laws, other sample paths (a
  /// run records its kernel).
  std::string kernel = "auto";
  /// Throws std::invalid_argument naming the option, its value and the allowed range.
  void validate() const;
  /// start_time with 0 resolved.
  double resolved_start_time() const;
  /// start = "hotspot": r0, or the scene's start.r0 when r0 = 0 and the scene starts from a hot spot;
  /// 0 for the other starts.
  double hot_spot_radius() const;
};

/// Progress of the `ns` background's Navier–Stokes solve: called with the shock's R/λ at each of its
/// diagnostics' samples (20 per decade; the solve ends just after t_max).
using BackgroundProgress = std::function<void(double R_over_lambda)>;

/// The background of a config (built once per run; `ns` integrates the Navier–Stokes blast).
std::unique_ptr<Background> make_background(const TracerConfig& config, std::string* description = nullptr,
                                            const BackgroundProgress& progress = {});

}  // namespace coldblast::kinetic
