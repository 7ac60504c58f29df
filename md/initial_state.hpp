#pragma once
// Initial configurations (paper Sec. V): random sequential addition (RSA) of non-overlapping
// discs/spheres in a ball (blast) and lattice starts for periodic equilibrium runs; the impurity
// kick with total energy exactly E and total momentum exactly zero; Maxwellian velocities.
// Random numbers: one std::mt19937_64 per realization seeded by splitmix64 from (seed, index), so
// a realization does not depend on which thread or shard runs it.
#include <cstdint>
#include <random>

#include "md/particles.hpp"

namespace coldblast::md {

/// splitmix64 step (Steele, Lea & Flood 2014): a well-mixed 64-bit hash of x.
std::uint64_t splitmix64(std::uint64_t x);
/// The generator of realization `index` of a run with master seed `seed`.
std::mt19937_64 realization_rng(std::uint64_t seed, std::uint64_t index);
/// Uniform double in [0, 1) from the top 53 bits (portable, unlike std::uniform_real_distribution).
double uniform01(std::mt19937_64& rng);
/// Standard normal deviate (Box-Muller, portable).
double standard_normal(std::mt19937_64& rng);

/// Largest packing fraction random sequential addition reaches (jamming): 0.547 (d = 2), 0.3841 (d = 3).
double rsa_jamming_fraction(int d);

/// RSA of `count` spheres of radius `radius` with centres uniform in the ball |x| < region_radius;
/// the result is ordered along a coarse grid (memory locality). Throws std::runtime_error if the
/// placement stalls (packing too close to jamming).
template <int D>
std::vector<Vec<D>> random_sequential_addition(std::mt19937_64& rng, std::size_t count, double radius,
                                               double region_radius);

/// Blast set-up: the `impurity_count` particles nearest the origin become impurities (their own
/// radius and mass; host particles that would overlap a larger impurity are moved to new random
/// places) with random momenta: total kinetic energy exactly E, total momentum exactly zero.
template <int D>
void kick_impurities(std::mt19937_64& rng, InitialState<D>& state, std::size_t impurity_count, double E,
                     double region_radius);

/// Periodic box start: `count` spheres on a simple cubic (square) lattice filling the box row by row,
/// Maxwellian velocities at temperature T with zero total momentum, rescaled so that the kinetic
/// energy is exactly (d/2) (count - 1) T.
template <int D>
InitialState<D> lattice_start(std::mt19937_64& rng, std::size_t count, double radius, const Vec<D>& box, double T);

}  // namespace coldblast::md
