#pragma once
// Event-driven engine for elastic hard discs/spheres (paper Sec. V), after Smallenburg's EDMD:
// one event per particle (its earliest collision or cell crossing), lazy per-particle time,
// collision counters that expose stale predictions when they are popped, a cell list, and a
// choice of event calendar. At zero temperature a resting particle schedules nothing: the cost
// scales with the moving particles and the collisions, not with N. This file is the event loop;
// the pieces it drives: the cell scheme (md/cell_list.hpp), the neighbour scans
// (md/neighbour_scan.hpp), the big-particle stencils (md/big_particles.hpp), the event calendar
// (md/event_queue.hpp) and the observers that watch the collisions (md/collision_observer.hpp).
#include <cstdint>
#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

#include "common/bytes.hpp"
#include "md/big_particles.hpp"
#include "md/cell_list.hpp"
#include "md/collision.hpp"
#include "md/collision_observer.hpp"
#include "md/event_queue.hpp"
#include "md/huge_pages.hpp"
#include "md/neighbour_scan.hpp"
#include "md/particles.hpp"

namespace coldblast::md {

/// Geometry and checks of one engine.
template <int D>
struct EngineConfig {
  bool periodic = false;        ///< true: periodic box [0, box); false: open blast region
  Vec<D> box = Vec<D>::Ones();  ///< periodic box side lengths (length)
  double region_radius = 1.0;   ///< open: particles lie within this radius of the origin (length)
  double guard_radius = 1.0;    ///< open: a moving particle entering a cell reaching beyond it stops the run
  std::string guard_advice;     ///< open: what to raise when the guard trips (for the error message)
  /// open: the advice as a function of the time the guard tripped (used instead of guard_advice if set)
  std::function<std::string(double now)> guard_advice_at;
  /// Cell side (length); 0 = automatic. Never below the largest contact distance, except in open
  /// geometry with impurities larger than the host: then cells are as narrow as the host contact
  /// distance and the impurities are "big" (a wider stencil: md/big_particles.hpp). Automatic: the
  /// width at which a full scan holds 2.7 (2D) or 10 (3D) particles (md/cell_list.hpp, plan_cells).
  double cell_width = 0.0;
  /// Open geometry: keep cells as wide as the largest contact distance even for large impurities
  /// (the plain scheme; same trajectories bit for bit, much slower for radius ratios >> 1).
  bool wide_cells_for_big = false;
  /// The SIMD versions of the pair evaluator (md/pair_kernel.hpp): the SSE2 pair test and crossing
  /// time, and in 3D, where the CPU has AVX2, the crossing time's three axes at once and, with
  /// equal radii, candidates tested four at a time. false: the scalar definitions
  /// (md/collision.hpp). Trajectories are bitwise the same either way (tested).
  bool simd = true;
  bool overlap_check = false;  ///< verify after every event that the touched particles overlap nobody
  /// false: a numerical experiment, not hard-sphere dynamics. A pair with an impurity in it collides
  /// at most once: afterwards its two particles pass through each other. So no impurity has a
  /// recollision (Eq. (36) of the paper has none); host-host collisions are unchanged, and energy
  /// and momentum stay conserved. At most 64 impurities.
  bool impurity_recollisions = true;
};

/// A moving particle reached the guard of an open region (EngineConfig::guard_radius) at `time`.
class GuardTripped : public std::runtime_error {
 public:
  GuardTripped(const std::string& message, double time_) : std::runtime_error(message), time(time_) {}
  double time;
};

template <int D, class Queue>
class Engine {
 public:
  Engine(const EngineConfig<D>& config, const InitialState<D>& state);
  /// The engine that save() wrote into `saved`, which must come from an engine built from the same
  /// `config` and `state` (a grown engine: the config and state after its growths). Resting
  /// particles are taken from `state`, the rest from `saved`; the run goes on bit for bit as the
  /// saved engine's would have (tested). Throws std::runtime_error naming the mismatch when the
  /// saved engine had another dimension, particle count or cell grid, or the bytes are cut short.
  Engine(const EngineConfig<D>& config, const InitialState<D>& state, common::ByteReader& saved);
  Engine(const Engine&) = delete;  // the observers watch this engine
  Engine& operator=(const Engine&) = delete;

  /// Calls observer.collided after every collision from now on; the observer must outlive the
  /// engine or the runs it watches.
  void watch(CollisionObserver<D>& observer) { observers_.push_back(&observer); }

  /// Processes every event up to time t (>= now()), then sets now() = t and returns true; or stops
  /// after `max_events` events (now() is the last one's time) and returns false, so that a caller can
  /// save the engine between two slices of a long run (the slices change nothing: tested). Open
  /// geometry: throws GuardTripped after the event in which a moving particle reached the guard; the
  /// engine is whole then (now() is that event's time), and may grow (grow) and run on.
  bool run_until(double t, std::uint64_t max_events = UINT64_MAX);
  /// Processes events until `count` more collisions happened; now() is the last event's time.
  /// GuardTripped as run_until.
  void run_collisions(std::uint64_t count);
  /// Widens an open region between events: `wider` (region and guard radii larger; the other keys
  /// as before) and `resting` host particles at rest, which must lie where no moving particle
  /// reaches before it has crossed into their neighbour cells (beyond the old region: the guard
  /// keeps moving particles a cell diagonal inside it). The cells are laid anew over the wider
  /// region and every moving particle predicts afresh. A prediction is a function of the two
  /// particles' stored states alone, so the trajectory is the one the wider region would have given
  /// from the start, up to the calendar's order of events at equal times.
  void grow(const EngineConfig<D>& wider, const std::vector<Vec<D>>& resting);
  /// Appends the engine's state between two events to `out` (a mid-realization checkpoint): the
  /// moving particles, their predictions and events, the cell lists, the counters. Read back by the
  /// restoring constructor.
  void save(common::ByteWriter& out) const;

  double now() const { return now_; }
  /// The geometry it runs in (grow widens it).
  const EngineConfig<D>& config() const { return config_; }
  std::size_t size() const { return particles_.size(); }
  const Particle<D>& particle(std::int32_t id) const { return particles_[id]; }
  Vec<D> position(std::int32_t id) const { return particles_[id].position_at(now_); }
  const Vec<D>& velocity(std::int32_t id) const { return particles_[id].velocity; }
  std::uint8_t species(std::int32_t id) const { return species_[id]; }
  double mass(std::int32_t id) const { return mass_[species_[id]]; }
  bool is_moving(std::int32_t id) const { return moving_flag_[id] != 0; }
  /// Particles that have moved since t = 0, in the order they started moving.
  const std::vector<std::int32_t>& moving() const { return moving_; }
  std::uint64_t collision_count() const { return collision_count_; }
  std::uint64_t event_count() const { return event_count_; }
  /// Events that were cell crossings, and collision predictions found stale when popped.
  std::uint64_t crossing_count() const { return crossing_count_; }
  std::uint64_t stale_count() const { return stale_count_; }
  /// Σ over collisions of r_ij·Δp_i (mass length²/time), for the collisional virial pressure.
  double virial_sum() const { return virial_sum_; }
  double kinetic_energy() const;
  Vec<D> momentum() const;
  const CellList<D>& cells() const { return cells_; }

  /// Calls f(id, position) at time now() for each particle within `radius` of `centre` (open geometry).
  template <class F>
  void for_each_in_ball(const Vec<D>& centre, double radius, F&& f) const;
  /// Throws std::logic_error if any two particles overlap by more than `tolerance` (relative) now.
  void check_all_overlaps(double tolerance = 1e-9) const;
  /// Bytes held by the engine, per particle slot (memory budget).
  std::size_t bytes() const;

 private:
  void process(std::int32_t id, double t);
  // Starts loading the data of the event after the current one while the current one is processed.
  void prefetch_next() const {
    const std::int32_t next = queue_.second_hint();
    if (next < 0) return;
    __builtin_prefetch(&particles_[next]);
    __builtin_prefetch(&predictions_[next]);
  }
  void collide(std::int32_t i, std::int32_t j, double t);
  // Calls the observers with the collision of i and j (velocities before: before_i, before_j).
  [[gnu::noinline]] void notify(std::int32_t i, std::int32_t j, double t, const Vec<D>& before_i,
                                const Vec<D>& before_j);
  void cross(std::int32_t id, double t);
  using Scan = typename NeighbourScan<D>::Scan;
  NeighbourScan<D> scanner() const {
    return {particles_.data(), species_.data(), cells_, sigma2_, config_.simd, use_kernel_};
  }
  // Inlined like scan_cells: GCC's own choice depends on unrelated code (an out-of-line copy cost
  // 0.7 % of a 3D blast's instructions).
  [[gnu::always_inline]] Scan start_scan(std::int32_t id, bool same_radius) const {
    return scanner().start(id, predictions_[id], same_radius);
  }
  // The unwrapped cells base + delta for delta in [first, last) (`gather`: through the SIMD
  // kernel), then the result stored as the particle's prediction.
  [[gnu::always_inline]] void scan_cells(std::int32_t id, std::int32_t base, const std::int32_t* first,
                                         const std::int32_t* last, bool gather) {
    Scan s = start_scan(id, same_radius_);
    scanner().cells(s, base, first, last, gather);
    predictions_[id] = s.best;
  }
  void full_scan(std::int32_t id);
  // impurity_recollisions = false (else both empty): per particle, the bit of the impurity it is
  // (none for a host), and the bits of the impurities it has collided with. A pair with an impurity
  // that has collided is a "ghost" pair: never predicted again, never checked for overlap.
  bool ghost_involved(std::int32_t id) const { return ghosts_ && (ghost_mask_[id] != 0 || own_bit_[id] != 0); }
  bool ghost_pair(std::int32_t i, std::int32_t j) const {
    return ((ghost_mask_[i] & own_bit_[j]) | (ghost_mask_[j] & own_bit_[i])) != 0;
  }
  // The full scan of a particle in a ghost pair or an impurity: the plain pair evaluator over the
  // neighbour cells (or a big particle's stencil) and the big particles, skipping ghost pairs.
  [[gnu::noinline]] void ghost_scan(std::int32_t id);
  // Big particles (open geometry, impurities larger than the host: md/big_particles.hpp).
  bool is_big(std::int32_t id) const { return big_.any() && species_[id] != host_species; }
  [[gnu::noinline]] void scan_bigs(std::int32_t id);         // pair tests against every big particle
  void cross_big(std::int32_t id, int axis, int direction);  // a big particle's crossing
  void schedule(std::int32_t id);
  void start_moving(std::int32_t id);
  // The constructor's steps: the impurities' bits (impurity_recollisions = false), the guard's
  // trigger radius (open geometry), the particles into their cells, the first scans and events.
  void assign_impurity_bits();
  void set_guard_trigger();
  void place_particles(const InitialState<D>& state);
  void start_initial_motion(const InitialState<D>& state);
  // The one constructor: a fresh engine, or with `saved` the restored one (restore).
  Engine(const EngineConfig<D>& config, const InitialState<D>& state, common::ByteReader* saved);
  void restore(common::ByteReader& saved);
  // A moving particle beyond the guard's trigger: the event in hand completes (its scans, its
  // events, the observers), then run_until or run_collisions throws GuardTripped (guard_tripped).
  void check_guard(std::int32_t id) {
    if (!config_.periodic && particles_[id].position_at(now_).squaredNorm() > guard_trigger2_) guard_hit_ = true;
  }
  [[noreturn]] void guard_tripped();  // throws GuardTripped (and clears guard_hit_)
  CellPlan plan() const;              // the cell scheme for this region and these particles
  void place_big_particles();         // the big particles' stencils on the current cells
  void check_overlaps_of(std::int32_t id, double tolerance = 1e-9) const;
  // Throws std::logic_error if j (displaced by the periodic image `shift`) overlaps i, at x_i, now.
  void check_pair(std::int32_t i, const Vec<D>& x_i, std::int32_t j, const Vec<D>& shift, double tolerance) const;
  Vec<D> separation(std::int32_t i, std::int32_t j) const;  // r_j - r_i at now_, minimum image

  EngineConfig<D> config_;
  HugeVector<Particle<D>> particles_;
  HugeVector<Prediction> predictions_;
  std::vector<std::uint8_t> species_, moving_flag_;
  std::vector<std::uint8_t> crossing_;  // scheduled cell crossing: 2 axis + (direction > 0)
  std::vector<std::int32_t> moving_;
  // Per growth (grow): the first particle it added and the time, the resting particles' own time.
  std::vector<std::int32_t> shell_first_;
  std::vector<double> shell_time_;
  double radius_[2], mass_[2], sigma_[2][2], sigma2_[2][2];  // sigma2_ = sigma_²
  bool same_radius_ = true;      // host and impurity radii equal: the contact distance needs no species lookup
  bool simd_crossing_ = false;   // the SIMD crossing time (config.simd, D = 3, CPU with AVX2)
  bool use_kernel_ = false;      // the SIMD pair kernel (config.simd, D = 3, equal radii, CPU with AVX2)
  double guard_trigger2_ = 0.0;  // open: squared |x| beyond which a moving particle stops the run
  bool guard_hit_ = false;       // a moving particle passed the trigger during the event in hand
  CellList<D> cells_;
  BigParticles<D> big_;
  Queue queue_;
  double now_ = 0.0;
  std::uint64_t collision_count_ = 0, event_count_ = 0, crossing_count_ = 0, stale_count_ = 0;
  double virial_sum_ = 0.0;
  std::vector<CollisionObserver<D>*> observers_;
  bool ghosts_ = false;                              // config.impurity_recollisions = false
  std::vector<std::uint64_t> own_bit_, ghost_mask_;  // ghosts_: see ghost_pair
};

template <int D, class Queue>
template <class F>
void Engine<D, Queue>::for_each_in_ball(const Vec<D>& centre, double radius, F&& f) const {
  std::array<std::int32_t, D> lo, hi, c;
  const auto last = cells_.coordinates(cells_.cell_count() - 1);
  for (int k = 0; k < D; ++k) {
    // A particle may lie up to the margin outside its cell (md/cell_list.hpp).
    const double w = cells_.width(k), reach = radius + cells_.margin();
    lo[k] = static_cast<std::int32_t>(std::max(0.0, std::floor((centre[k] - reach - cells_.lower()[k]) / w)));
    hi[k] =
        static_cast<std::int32_t>(std::min<double>(last[k], std::floor((centre[k] + reach - cells_.lower()[k]) / w)));
    if (hi[k] < lo[k]) return;
  }
  c = lo;
  const double r2 = radius * radius;
  do {
    for (std::int32_t id = cells_.first(cells_.index(c)); id >= 0; id = cells_.next(id)) {
      const Vec<D> x = particles_[id].position_at(now_);
      if ((x - centre).squaredNorm() <= r2) f(id, x);
    }
  } while (next_multi_index(c, lo, hi));
}

}  // namespace coldblast::md
