#pragma once
// Particle state of the event-driven engine (paper Sec. V): hard discs/spheres with lazy
// per-particle time (a particle's position is stored at its own last-update time; Smallenburg's
// EDMD idea), a collision counter that invalidates stale predictions, and two species (host, impurity).
#include <Eigen/Core>
#include <cstdint>
#include <vector>

namespace coldblast::md {

/// D-dimensional vector (length units, or length/time for velocities).
template <int D>
using Vec = Eigen::Matrix<double, D, 1>;

/// Hot per-particle data, one cache line in 3D (64 bytes) and 48 bytes in 2D.
template <int D>
struct alignas(D == 3 ? 64 : 16) Particle {
  Vec<D> position = Vec<D>::Zero();  ///< position at `time`
  Vec<D> velocity = Vec<D>::Zero();  ///< constant between collisions
  double time = 0.0;                 ///< time at which `position` is valid (lazy update)
  std::uint32_t collisions = 0;      ///< number of collisions so far; also the stale-event counter
  std::int32_t cell = -1;            ///< linear index of the cell holding the particle

  /// Position at time t >= time (straight-line flight).
  Vec<D> position_at(double t) const { return position + velocity * (t - time); }
  /// Moves the stored position to time t.
  void advance(double t) {
    position += velocity * (t - time);
    time = t;
  }
};

/// Radius and mass of one species (length, mass units; both > 0).
struct Species {
  double radius = 0.5;
  double mass = 1.0;
};

/// Species index stored per particle: the host gas is 0, impurities are 1.
inline constexpr std::uint8_t host_species = 0;
inline constexpr std::uint8_t impurity_species = 1;

/// Initial configuration handed to the engine.
template <int D>
struct InitialState {
  std::vector<Vec<D>> position;       ///< non-overlapping centres
  std::vector<Vec<D>> velocity;       ///< zero for resting particles
  std::vector<std::uint8_t> species;  ///< host_species or impurity_species per particle
  Species host, impurity;             ///< the two species' radius and mass
  std::size_t size() const { return position.size(); }
};

}  // namespace coldblast::md
