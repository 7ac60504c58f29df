#pragma once
// Event-driven engine for elastic hard discs/spheres (paper Sec. V), after Smallenburg's EDMD:
// one event per particle (its earliest collision or cell crossing), lazy per-particle time,
// collision counters that expose stale predictions when they are popped, a cell list, and a
// choice of event calendar. At zero temperature a resting particle schedules nothing: the cost
// scales with the moving particles and the collisions, not with N.
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "md/cell_list.hpp"
#include "md/collision.hpp"
#include "md/event_queue.hpp"
#include "md/huge_pages.hpp"
#include "md/pair_kernel.hpp"
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
  /// distance and the impurities are "big" (a wider stencil, see engine.cpp). Periodic geometry
  /// always uses the largest contact distance.
  double cell_width = 0.0;
  /// Open geometry: keep cells as wide as the largest contact distance even for large impurities
  /// (the plain scheme; same trajectories bit for bit, much slower for radius ratios >> 1).
  bool wide_cells_for_big = false;
  /// The SIMD versions of the pair evaluator (md/pair_kernel.hpp): the SSE2 pair test and crossing
  /// time, and in 3D, where the CPU has AVX2, the crossing time's three axes at once and, with
  /// equal radii, candidates tested four at a time. false: the scalar definitions
  /// (md/collision.hpp). Trajectories are bitwise the same either way (tested).
  bool simd = true;
  bool overlap_check = false;                 ///< verify after every event that the touched particles overlap nobody
  bool record_impurity_trajectories = false;  ///< store the impurities' positions at each of their collisions
  /// Count each impurity's recollisions: its collisions with a particle it had hit before, and the
  /// energy it loses in them and in first collisions (Engine::recollision_stats; observables C_re,
  /// dE_first, dE_re). Eq. (36) of the paper, the kinetic tracer's
  /// equation, draws every partner afresh and so has none.
  bool count_impurity_recollisions = false;
  /// false: a numerical experiment, not hard-sphere dynamics. A pair with an impurity in it collides
  /// at most once: afterwards its two particles pass through each other. So no impurity has a
  /// recollision (Eq. (36) of the paper has none); host-host collisions are unchanged, and energy
  /// and momentum stay conserved. At most 64 impurities.
  bool impurity_recollisions = true;
};

/// One point of an impurity trajectory.
template <int D>
struct TrajectoryPoint {
  double t;
  std::int32_t id;
  Vec<D> position;
};

template <int D, class Queue>
class Engine {
 public:
  Engine(const EngineConfig<D>& config, const InitialState<D>& state);

  /// Processes every event up to time t (>= now()), then sets now() = t.
  void run_until(double t);
  /// Processes events until `count` more collisions happened; now() is the last event's time.
  void run_collisions(std::uint64_t count);

  double now() const { return now_; }
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
  const std::vector<TrajectoryPoint<D>>& trajectories() const { return trajectories_; }
  /// What config.count_impurity_recollisions records of one impurity: its collisions with a
  /// particle it had already hit, and the kinetic energy it lost in its first collisions with a
  /// partner and in its recollisions (a gain counts as a negative loss).
  struct RecollisionStats {
    std::uint64_t recollisions = 0;
    double loss_first = 0.0, loss_re = 0.0;
  };
  /// The record of impurity `id`; zeros without count_impurity_recollisions (and for a host).
  RecollisionStats recollision_stats(std::int32_t id) const;
  const CellList<D>& cells() const { return cells_; }

  /// Calls f(id, position) at time now() for each particle within `radius` of `centre` (open geometry).
  template <class F>
  void for_each_in_ball(const Vec<D>& centre, double radius, F&& f) const;
  /// Throws std::logic_error if any two particles overlap by more than `tolerance` (relative) now.
  void check_all_overlaps(double tolerance = 1e-9) const;
  /// Bytes held by the engine, per particle slot (memory budget).
  std::size_t bytes() const;

 private:
  // 16 bytes; the scheduled cell crossing lives in crossing_ (one byte) to stay within the memory budget.
  struct Prediction {
    double time = never;                   // earliest predicted collision
    std::int32_t partner = -1;             // its partner
    std::uint32_t partner_collisions = 0;  // partner's counter when predicted
  };
  void process(std::int32_t id, double t);
  // Starts loading the data of the event after the current one while the current one is processed.
  void prefetch_next() const {
    const std::int32_t next = queue_.second_hint();
    if (next < 0) return;
    __builtin_prefetch(&particles_[next]);
    __builtin_prefetch(&predictions_[next]);
  }
  void collide(std::int32_t i, std::int32_t j, double t);
  void cross(std::int32_t id, double t);
  // One particle's search for its earliest contact: what the scan helpers share. The particle's
  // stored state, its row of squared contact distances (sigma2_[species]), whether every radius is
  // equal (then row[0] serves every partner, without a species lookup), and the earliest contact
  // found so far. A local copy: it stays in registers across the cells and is stored back once.
  struct Scan {
    std::int32_t id;
    Vec<D> position, velocity;
    double time;
    const double* sigma2_row;
    bool same_radius;
    Prediction best;
  };
  Scan start_scan(std::int32_t id, bool same_radius) const {
    const Particle<D>& p = particles_[id];
    return {id, p.position, p.velocity, p.time, sigma2_[species_[id]], same_radius, predictions_[id]};
  }
  // Scans the unwrapped cells base + delta for delta in [first, last) (no periodic image shift);
  // `gather`: through the SIMD kernel (requires use_kernel_).
  void scan_cells(std::int32_t id, std::int32_t base, const std::int32_t* first, const std::int32_t* last, bool gather);
  // Scans the cells base + deltas[m], m < count, each with its periodic image shift.
  void scan_wrapped_cells(std::int32_t id, std::int32_t base, const std::int32_t* deltas, const Vec<D>* shifts,
                          int count, bool gather);
  // The pair test both scans share: the scanning particle against every particle of `cell`, or
  // against particle j, displaced by `shift` when Shifted, keeping the earliest contact in s.best.
  // Simd: the SSE2 pair test (md/pair_kernel.hpp), else the scalar definition (md/collision.hpp).
  template <bool Shifted, bool Simd>
  void scan_list(Scan& s, std::int32_t cell, const Vec<D>& shift) const;
  template <bool Shifted, bool Simd>
  void test_pair(Scan& s, std::int32_t j, const Vec<D>& shift) const;
  // Both scans with the scalar pair evaluator (config.simd = false): the cells base + deltas[m],
  // m < count, with their image shifts unless `shifts` is null.
  void scan_plain(std::int32_t id, std::int32_t base, const std::int32_t* deltas, const Vec<D>* shifts, int count);
  // The gathered candidates ids[0, count) through the SIMD kernel (D = 3; ids has room to pad
  // count to a multiple of 4, and so have the image shift arrays sx, sy, sz when not null).
  void kernel_scan(Scan& s, std::int32_t* ids, int count, double* sx, double* sy, double* sz) const;
  // The D = 3 kernel path of both scans: gathers the cells base + deltas[m] (m < count; with their
  // image shifts when Shifted) and tests the candidates through kernel_scan.
  template <bool Shifted>
  void gather_scan(Scan& s, std::int32_t base, const std::int32_t* deltas, const Vec<D>* shifts, int count) const;
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
  // Big particles (open geometry, impurities larger than the host: see engine.cpp).
  bool is_big(std::int32_t id) const { return big_reach_ != 0 && species_[id] != host_species; }
  void scan_bigs(std::int32_t id);                                       // pair tests against every big particle
  void cross_big(std::int32_t id, int axis, int direction, bool stale);  // a big particle's crossing
  void cover(std::int32_t cell, const std::vector<std::int32_t>& deltas, int change);
  void schedule(std::int32_t id);
  // Time of the particle's next cell crossing (`never` at rest), and its crossing_ code.
  double crossing_time(const Particle<D>& p, std::uint8_t& code) const;
  void start_moving(std::int32_t id);
  void check_guard(std::int32_t id) const {
    if (!config_.periodic && particles_[id].position_at(now_).squaredNorm() > guard_trigger2_) guard_tripped();
  }
  [[noreturn]] void guard_tripped() const;
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
  double radius_[2], mass_[2], sigma_[2][2], sigma2_[2][2];  // sigma2_ = sigma_²
  bool same_radius_ = true;      // host and impurity radii equal: the contact distance needs no species lookup
  bool use_kernel_ = false;      // the SIMD pair kernel (config.simd, D = 3, equal radii, CPU with AVX2)
  bool simd_crossing_ = false;   // the SIMD crossing time (config.simd, D = 3, CPU with AVX2)
  double guard_trigger2_ = 0.0;  // open: squared |x| beyond which a moving particle stops the run
  CellList<D> cells_;
  int big_reach_ = 0;                      // k: cells per axis a big particle's stencil reaches; 0 = none
  std::vector<std::int32_t> big_;          // the big particles (a short list)
  std::vector<std::uint8_t> covered_;      // per cell: big particles whose stencil covers it
  std::vector<std::int32_t> big_stencil_;  // (2k+1)^D index offsets
  std::array<std::array<std::vector<std::int32_t>, 2>, D> big_slab_;  // per axis, direction: slab at offset ±k
  Queue queue_;
  double now_ = 0.0;
  std::uint64_t collision_count_ = 0, event_count_ = 0, crossing_count_ = 0, stale_count_ = 0;
  double virial_sum_ = 0.0;
  std::vector<TrajectoryPoint<D>> trajectories_;
  /// count_impurity_recollisions: per impurity, every particle it has hit and its record.
  struct PartnerMemory {
    std::int32_t id;
    std::vector<std::int32_t> partners;
    RecollisionStats stats;
  };
  std::vector<PartnerMemory> partner_memory_;  // a few impurities: searched linearly
  /// Records a collision of `id` with `partner` in which `id` lost kinetic energy `loss`.
  void remember_partner(std::int32_t id, std::int32_t partner, double loss);
  bool ghosts_ = false;                              // config.impurity_recollisions = false
  std::vector<std::uint64_t> own_bit_, ghost_mask_;  // ghosts_: see ghost_pair
};

template <int D, class Queue>
template <class F>
void Engine<D, Queue>::for_each_in_ball(const Vec<D>& centre, double radius, F&& f) const {
  std::array<std::int32_t, D> lo, hi, c;
  const auto last = cells_.coordinates(cells_.cell_count() - 1);
  for (int k = 0; k < D; ++k) {
    const double w = cells_.width(k);
    lo[k] = static_cast<std::int32_t>(std::max(0.0, std::floor((centre[k] - radius - cells_.lower()[k]) / w)));
    hi[k] =
        static_cast<std::int32_t>(std::min<double>(last[k], std::floor((centre[k] + radius - cells_.lower()[k]) / w)));
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
