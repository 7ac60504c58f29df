#pragma once
// One realization of a blast scene (paper Sec. V): its initial state (random sequential addition,
// then the impurities and the scene's start), its engine settings, and its run to t_max with the observers measuring
// at the recording times, returning the realization's record and, when asked, its snapshots and its
// impurities' paths as data. Ensembles, files and checkpoints are run/'s (run/ensemble.hpp).
#include <array>
#include <cstdint>
#include <functional>
#include <vector>

#include "md/blast_config.hpp"
#include "md/engine.hpp"
#include "md/initial_state.hpp"
#include "md/observers.hpp"

namespace coldblast::md {

/// The initial state of realization `index` of a resolved blast scene (paper Sec. V): random
/// sequential addition at density n in the scene's region, then the impurities (the particles
/// nearest the origin) and the energy E as the scene's start says (start_blast: the impurities'
/// kick, a hot spot or a single kicked host); seeded from (seed, index). After `growths` growths
/// (run_realization) the same, plus one RSA shell per growth out to region_radius_after(scene,
/// growths), each from its own stream of (seed, index, growth) (add_rsa_shell): the gas inside an
/// earlier region is the same particles at the same places, with the same indices.
template <int D>
InitialState<D> blast_initial_state(const ResolvedScene& scene, long long index, int growths = 0);
/// The state of realization `index` after growth `growth` (>= 1) from its state after growth - 1:
/// blast_initial_state's last step, for a realization that grows (std::logic_error if `state` does
/// not hold the particles of region_radius_after(scene, growth - 1)).
template <int D>
void grow_initial_state(const ResolvedScene& scene, long long index, InitialState<D>& state, int growth);

/// Whether a region grown `growths` times may grow no further (config.region_growths, max_region_radius).
bool last_growth(const ResolvedScene& scene, int growths);

/// Calls attempt(growths) for growths = 0, 1, ... until a call returns without md::GuardTripped,
/// and returns its result: a realization in a region grown until it holds the moving particles
/// (run_realization). Beyond config.region_growths growths, or a region wider than
/// scene.max_region_radius, is not tried: the last guard's error is rethrown.
template <class Attempt>
auto with_growing_region(const ResolvedScene& scene, Attempt attempt) {
  for (int growths = 0;; ++growths) {
    try {
      return attempt(growths);
    } catch (const GuardTripped&) {
      if (last_growth(scene, growths)) throw;
    }
  }
}

/// The engine settings of a blast realization (open region grown `growths` times, guard and its
/// advice, cell width, overlap check): the one scene → EngineConfig mapping, shared by ensembles and
/// benchmarks.
template <int D>
EngineConfig<D> blast_engine_config(const ResolvedScene& scene, int growths = 0);

/// Which particles a snapshot holds (run/ chooses; the scene's snapshot_* keys).
struct SnapshotSelection {
  /// false: every particle; true: the moving ones and the resting ones closer to the origin than
  /// the farthest moving particle plus `margin`.
  bool front_only = false;
  double margin = 0.0;  ///< length, >= 0
  int stride = 1;       ///< keep every stride-th particle of the selection (by index), >= 1
};

/// The selected particles of a realization at time t, as data (run/snapshot_files.* writes them).
struct SnapshotFrame {
  double t = 0.0;
  std::vector<std::int32_t> id;            ///< particle index, ascending
  std::vector<double> position, velocity;  ///< d entries per particle
  std::vector<std::uint8_t> impurity, moving;
  std::vector<std::uint32_t> collisions;  ///< per particle, since t = 0
  double region_radius = 0.0;             ///< the realization's region (length): particles lie within it
  std::size_t size() const { return id.size(); }
};

/// One point of an impurity's path (its start, each of its collisions, its end at t_max).
struct PathPoint {
  std::int32_t id = 0;
  double t = 0.0;
  std::array<double, 3> position{};  ///< d entries used
};

/// What a realization records beyond its observables.
struct RealizationExtras {
  std::vector<double> snapshot_times;  ///< times of snapshots, ascending, in (0, t_max]; empty = none
  SnapshotSelection selection;
  bool paths = false;  ///< the impurities' paths (trajectories.csv)
};

/// A finished realization.
struct RealizationOutput {
  std::vector<double> record;  ///< ObservableLayout order
  std::uint64_t collisions = 0;
  double energy_error = 0.0;   ///< |E_kin(t_max) - E|/E
  int growths = 0;             ///< times the region grew (run_realization)
  double region_radius = 0.0;  ///< the region it ran in (length)
  std::size_t particles = 0;   ///< the particles of that region
  std::vector<SnapshotFrame> snapshots;
  std::vector<PathPoint> paths;  ///< by impurity id, then time (empty unless extras.paths)
};

/// Runs realization `index` to t_max: the observers' record at each recording time, the extras
/// asked for. The gas is filled where the blast reaches: the realization starts in the scene's
/// region; if a moving particle reaches its guard (md::GuardTripped), it starts again from t = 0 in
/// a region region_growth times wider that holds the same gas inside (blast_initial_state), and so
/// on up to max_region_radius. The realization is the same: up to the guard, no moving particle
/// could touch the new shell (round-off aside: the cell grid is wider). `time(index, t)` (may be
/// empty) is called at the start of each attempt (t = 0, before the initial state is built) and as
/// the realization passes each recorded time. Throws std::invalid_argument for a scene whose region
/// does not hold its particles, std::runtime_error (md::GuardTripped) when a particle reaches the
/// guard of the widest region, or an observable is not finite.
RealizationOutput run_realization(const ResolvedScene& scene, const ObservableLayout& layout, long long index,
                                  const RealizationExtras& extras = {},
                                  const std::function<void(long long, double)>& time = {});

}  // namespace coldblast::md
