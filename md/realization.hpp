#pragma once
// One realization of a blast scene (paper Sec. V): its initial state (random sequential addition,
// then the impurities and the scene's start), its engine settings, and its run to t_max with the observers measuring
// at the recording times, returning the realization's record and, when asked, its snapshots and its
// impurities' paths as data. Ensembles, files and checkpoints are run/'s (run/ensemble.hpp).
#include <array>
#include <cstdint>
#include <functional>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "common/bytes.hpp"
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

/// The engine settings of a blast realization (open region grown `growths` times, guard and its
/// advice, cell width, overlap check): the one scene → EngineConfig mapping, shared by ensembles and
/// benchmarks.
template <int D>
EngineConfig<D> blast_engine_config(const ResolvedScene& scene, int growths = 0);

/// The engine of realization `index`, its gas filled where the blast reaches: it starts in the
/// scene's region, and when a moving particle reaches the guard (md::GuardTripped) the state gains
/// the next RSA shell (grow_initial_state) and the engine takes its particles, at rest, between two
/// events (Engine::grow), and runs on: the trajectory of a run in the wider region from t = 0
/// (tested). A guard reached while the engine is built (an initial motion beyond it) builds it in
/// the next region. Beyond config.region_growths growths, or a region wider than
/// scene.max_region_radius, the guard's md::GuardTripped is rethrown.
template <int D, class Queue>
class GrowingBlast {
 public:
  /// The blast saved by a mid-realization checkpoint after `growths` growths: its initial state
  /// rebuilt (blast_initial_state), its engine restored from `saved` (Engine's restoring constructor).
  GrowingBlast(const ResolvedScene& scene, long long index, int growths, common::ByteReader& saved)
      : scene_(scene), index_(index), state_(blast_initial_state<D>(scene, index, growths)), growths_(growths) {
    engine_ = std::make_unique<Engine<D, Queue>>(blast_engine_config<D>(scene_, growths_), state_, saved);
  }
  GrowingBlast(const ResolvedScene& scene, long long index)
      : scene_(scene), index_(index), state_(blast_initial_state<D>(scene, index)) {
    for (;;) try {
        engine_ = std::make_unique<Engine<D, Queue>>(blast_engine_config<D>(scene_, growths_), state_);
        return;
      } catch (const GuardTripped&) {
        if (last_growth(scene_, growths_)) throw;
        grow_initial_state<D>(scene_, index_, state_, ++growths_);
      }
  }
  /// engine().run_until(t, max_events), growing the region whenever the guard trips (a growth
  /// starts a new count of max_events).
  bool run_until(double t, std::uint64_t max_events = UINT64_MAX) {
    for (;;) try {
        return engine_->run_until(t, max_events);
      } catch (const GuardTripped&) {
        if (last_growth(scene_, growths_)) throw;
        const std::size_t old = state_.size();
        grow_initial_state<D>(scene_, index_, state_, ++growths_);
        engine_->grow(
            blast_engine_config<D>(scene_, growths_),
            std::vector<Vec<D>>(state_.position.begin() + static_cast<std::ptrdiff_t>(old), state_.position.end()));
      }
  }
  Engine<D, Queue>& engine() { return *engine_; }
  /// The initial state of the region it runs in now (blast_initial_state(scene, index, growths())).
  const InitialState<D>& state() const { return state_; }
  int growths() const { return growths_; }

 private:
  const ResolvedScene& scene_;
  long long index_;
  InitialState<D> state_;
  int growths_ = 0;
  std::unique_ptr<Engine<D, Queue>> engine_;
};

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
  /// Of `collisions`, those of the mid-run state it resumed from (InFlight::resume; 0 from t = 0):
  /// done by an earlier process, so not counted in this one's rate.
  std::uint64_t resumed_collisions = 0;
  double energy_error = 0.0;   ///< |E_kin(t_max) - E|/E
  int growths = 0;             ///< times the region grew (run_realization)
  double region_radius = 0.0;  ///< the region it ran in (length)
  std::size_t particles = 0;   ///< the particles of that region
  std::vector<SnapshotFrame> snapshots;
  std::vector<PathPoint> paths;  ///< by impurity id, then time (empty unless extras.paths)
};

/// A realization's mid-run checkpoint (run/ keeps it in OUT/checkpoint: docs/md-output.md,
/// "Checkpoints"). The realization runs in slices of `slice_events` events; between two slices it
/// asks `due()` whether to hand its state to `save`, and when a stop was requested
/// (common::stop_requested: SIGINT, SIGTERM) it saves and throws common::Interrupted instead of running to
/// its end. The state holds the engine, the observers and what was recorded so far; given back as
/// `resume`, the realization goes on from there, and its output is bit for bit that of a run never
/// stopped (tested).
struct InFlight {
  std::string resume;         ///< bytes an earlier `save` gave for the same scene, index and extras; empty: t = 0
  std::function<bool()> due;  ///< may be empty (then saves happen only at a stop)
  std::function<void(std::string&&)> save;  ///< required
  std::uint64_t slice_events = 1ULL << 20;  ///< events between two polls (~0.3 s of a deep 2D blast), >= 1
};

/// A saved state (InFlight::resume) that is not the realization's, refused before it ran.
class SavedStateRefused : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// Runs realization `index` to t_max: the observers' record at each recording time, the extras
/// asked for. The gas is filled where the blast reaches (GrowingBlast): the realization starts in
/// the scene's region, which grows region_growth times wider, in place, whenever a moving particle
/// reaches its guard, up to max_region_radius. `time(index, t)` (may be empty) is called at the start
/// (t = 0, before the initial state is built) and as the realization passes each recorded time. Throws
/// std::invalid_argument for a scene whose region does not hold its particles, std::runtime_error (md::GuardTripped)
/// when a particle reaches the guard of the widest region, or an observable is not finite.
/// With `in_flight`, it can be saved mid-run and resumed (InFlight); a `resume` that is not this
/// realization's state (another scene, index, dimension or build, a truncated or altered file)
/// throws SavedStateRefused saying why.
RealizationOutput run_realization(const ResolvedScene& scene, const ObservableLayout& layout, long long index,
                                  const RealizationExtras& extras = {},
                                  const std::function<void(long long, double)>& time = {},
                                  const InFlight* in_flight = nullptr);

}  // namespace coldblast::md
