#pragma once
// The tracer's hot-spot and single-host starts (docs/kinetic.md, "Start"): one impurity as the MD's
// start leaves it (md::start_blast): the impurities are the particles nearest the centre; in a hot
// spot every particle within r0 shares E as a Maxwellian with zero total momentum, from a single
// host the impurities stay at rest. The
// configuration is random sequential addition at the scene's density in a ball of radius
// hot_spot_neighbourhood(r0) around the centre, not the MD's whole region.
#include <cstdint>

#include "md/blast_config.hpp"
#include "md/particles.hpp"

namespace coldblast::kinetic {

/// Radius of the ball whose particles the hot-spot start places: 3 r0, and at least r0 plus four
/// contact diameters, so that the count within r0 fluctuates nearly as in the MD's large region.
double hot_spot_neighbourhood(const md::BlastConfig& scene, double r0);

/// One impurity of a hot-spot start and the hot spot it came from.
template <int D>
struct HotSpotImpurity {
  md::Vec<D> r = md::Vec<D>::Zero();  ///< position (length, from the blast centre)
  md::Vec<D> v = md::Vec<D>::Zero();  ///< velocity
  int heated = 0;                     ///< particles within r0 (they share E), impurities included
  double heated_mass = 0.0;           ///< their total mass
};

/// Impurity `which` (in [0, impurities.count), by ascending particle index) of one hot-spot start of
/// radius r0 (length, > 0) for `scene` (d, n, a, E, impurities.*), from the generator seeded with
/// `seed`. Throws std::invalid_argument naming --r0 if the hot spot holds fewer than two particles or
/// misses an impurity (as md::start_blast does, naming start.r0).
template <int D>
HotSpotImpurity<D> sample_hot_spot_impurity(const md::BlastConfig& scene, double r0, std::uint64_t seed, int which);

/// Impurity `which` of one single-host start (md::start_blast with start.kind = single) for `scene`,
/// from the generator seeded with `seed`: where the MD puts it (among the impurities.count particles
/// nearest the centre of an RSA neighbourhood of radius hot_spot_neighbourhood(scene, 0)), at rest.
template <int D>
md::Vec<D> sample_single_start_position(const md::BlastConfig& scene, std::uint64_t seed, int which);

}  // namespace coldblast::kinetic
