#pragma once
// Observers of the engine's collisions (DynamO's output plugins): bookkeeping that watches the
// events without steering them. The engine (md/engine.hpp) calls every watching observer after
// each collision with the pair's state before and after; with none watching, a collision costs
// one predicted branch more. Two observers of the impurities (paper Sec. V): their trajectories
// (Fig. 1's collision points) and their recollisions (observables C_re, dE_first, dE_re).
#include <cstdint>
#include <vector>

#include "common/bytes.hpp"
#include "md/particles.hpp"

namespace coldblast::md {

/// One collision as an observer sees it: particles i and j at contact at time t.
template <int D>
struct CollisionRecord {
  double t;
  std::int32_t i, j;
  std::uint8_t species_i, species_j;
  double mass_i, mass_j;
  const Vec<D>& position_i;  ///< at t
  const Vec<D>& position_j;
  const Vec<D>& velocity_i_before;
  const Vec<D>& velocity_j_before;
  const Vec<D>& velocity_i;  ///< after the collision
  const Vec<D>& velocity_j;
};

template <int D>
class CollisionObserver {
 public:
  virtual ~CollisionObserver() = default;
  virtual void collided(const CollisionRecord<D>& collision) = 0;
};

/// One point of an impurity trajectory.
template <int D>
struct TrajectoryPoint {
  double t;
  std::int32_t id;
  Vec<D> position;
};

/// The impurities' positions at each of their collisions (trajectories.csv).
template <int D>
class ImpurityTrajectories final : public CollisionObserver<D> {
 public:
  void collided(const CollisionRecord<D>& c) override {
    if (c.species_i == impurity_species) points_.push_back({c.t, c.i, c.position_i});
    if (c.species_j == impurity_species) points_.push_back({c.t, c.j, c.position_j});
  }
  /// In the order of the collisions.
  const std::vector<TrajectoryPoint<D>>& points() const { return points_; }
  /// The points so far, for a mid-realization checkpoint, and back.
  void save(common::ByteWriter& out) const;
  void restore(common::ByteReader& saved);

 private:
  std::vector<TrajectoryPoint<D>> points_;
};

/// What RecollisionCounter records of one impurity: its collisions with a particle it had already
/// hit, and the kinetic energy it lost in its first collisions with a partner and in its
/// recollisions (a gain counts as a negative loss).
struct RecollisionStats {
  std::uint64_t recollisions = 0;
  double loss_first = 0.0, loss_re = 0.0;
};

/// Each impurity's recollisions: its collisions with a particle it had hit before, and the energy
/// it loses in them and in first collisions (observables C_re, dE_first, dE_re). Eq. (36) of the
/// paper, the kinetic tracer's equation, draws every partner afresh and so has none.
template <int D>
class RecollisionCounter final : public CollisionObserver<D> {
 public:
  /// Watches the particles `impurities` (a few: searched linearly).
  explicit RecollisionCounter(const std::vector<std::int32_t>& impurities);
  void collided(const CollisionRecord<D>& c) override;
  /// The record of impurity `id`; zeros for a particle not watched.
  RecollisionStats stats(std::int32_t id) const;
  /// Every impurity's partners and record so far, for a mid-realization checkpoint, and back (the
  /// same impurities must be watched).
  void save(common::ByteWriter& out) const;
  void restore(common::ByteReader& saved);

 private:
  struct Memory {
    std::int32_t id;
    std::vector<std::int32_t> partners;  // every particle it has hit
    RecollisionStats stats;
  };
  // Records a collision of `id` with `partner` in which `id` lost kinetic energy `loss`.
  void remember(std::int32_t id, std::int32_t partner, double loss);
  std::vector<Memory> memory_;
};

}  // namespace coldblast::md
