#pragma once
// Initial configurations (paper Sec. V): random sequential addition (RSA) of non-overlapping
// discs/spheres in a ball (blast) and lattice starts for periodic equilibrium runs; the impurity
// kick with total energy exactly E and total momentum exactly zero, or the other starts (a hot spot,
// a single kicked host); Maxwellian velocities.
// Random numbers: one std::mt19937_64 per realization seeded by common::splitmix64 from (seed, index), so
// a realization does not depend on which thread or shard runs it.
#include <cstdint>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include "common/random_streams.hpp"
#include "md/particles.hpp"

namespace coldblast::md {

/// The generator of realization `index` of a run with master seed `seed`.
std::mt19937_64 realization_rng(std::uint64_t seed, std::uint64_t index);
/// Uniform double in [0, 1) from the top 53 bits (portable, unlike std::uniform_real_distribution).
double uniform01(std::mt19937_64& rng);
/// Standard normal deviate (Box-Muller, portable).
double standard_normal(std::mt19937_64& rng);

/// Largest packing fraction random sequential addition reaches (jamming): 0.547 (d = 2), 0.3841 (d = 3).
double rsa_jamming_fraction(int d);

/// Relative deficit of the density inside a ball of radius R filled by RSA with round(n Ω_d R^d)
/// spheres of diameter sigma, to first order in n: the free edge leaves candidates near it more room,
/// so a layer at the edge holds a surface excess Γ per area, taken from the interior. A candidate at
/// depth z < sigma misses the part V_out(z) of its exclusion ball beyond the edge while the density
/// grows from 0 to n, so Γ = (n²/2) ∫_0^sigma V_out(z) dz = n² sigma³/3 (d = 2), π n² sigma⁴/8 (d = 3)
/// (flat edge, R >> sigma), and the deficit is Γ S/(n V) = d Γ/(n R): 2 n sigma³/(3 R) and
/// 3π n sigma⁴/(8 R). Measured: tests/md/test_rsa.cpp; docs/md-output.md, "Region".
double rsa_interior_deficit(int d, double n, double sigma, double R);
/// That surface excess Γ per area (per length in 2D): n² sigma³/3 (d = 2), π n² sigma⁴/8 (d = 3).
double rsa_surface_excess(int d, double n, double sigma);

/// Consecutive failed random trials after which RSA switches to its voxel phase (below).
inline constexpr std::uint64_t rsa_voxel_switch_default = 1000;

/// How an RSA placement went: counts for tests, benchmarks and error messages.
struct RsaReport {
  std::size_t placed = 0;            ///< centres placed
  std::size_t placed_by_voxels = 0;  ///< of which in the voxel phase
  bool saturated = false;            ///< the voxel phase proved that no further centre fits
  int voxel_levels = 0;              ///< voxel subdivisions (0: the voxel phase was not used or never subdivided)
  std::size_t voxels_initial = 0;    ///< voxels left after the first coverage test
  std::uint64_t trials = 0;          ///< random trials, both phases
};

/// RSA of up to `count` spheres of radius `radius` with centres in the ball |x| < region_radius,
/// each new centre uniform over the space still available. Phase 1 draws centres uniformly in the
/// ball and rejects overlaps; after `switch_after` consecutive failures it switches to the voxel
/// method of Zhang & Torquato, Phys. Rev. E 88, 053312 (2013): it samples only voxels not yet
/// proven covered, so it reaches saturation. Stops at `count` or at saturation (report.saturated);
/// the result is ordered along a coarse grid (memory locality).
template <int D>
std::vector<Vec<D>> random_sequential_addition_report(std::mt19937_64& rng, std::size_t count, double radius,
                                                      double region_radius, RsaReport& report,
                                                      std::uint64_t switch_after = rsa_voxel_switch_default);

/// RSA saturated (no further centre fits anywhere in the region) before `requested` centres.
class RsaSaturated : public std::invalid_argument {
 public:
  RsaSaturated(std::size_t placed, std::size_t requested, double fraction_reached, double fraction_requested);
  std::size_t placed, requested;
  double fraction_reached, fraction_requested;  ///< placed (requested) sphere volume / region volume
};

/// random_sequential_addition_report for exactly `count` centres; throws RsaSaturated if the region
/// saturates first.
template <int D>
std::vector<Vec<D>> random_sequential_addition(std::mt19937_64& rng, std::size_t count, double radius,
                                               double region_radius);

/// Widens a placed configuration (a grown blast region, md/realization.hpp): `count` resting hosts by
/// RSA with centres in the shell r_in <= |x| < r_out, overlapping none of the particles already in
/// `state` (of either species), appended to it. The gas inside r_in is untouched, so a region grown
/// shell by shell holds the same particles whenever it grows. Throws RsaSaturated if the shell
/// saturates first.
template <int D>
void add_rsa_shell(std::mt19937_64& rng, InitialState<D>& state, std::size_t count, double r_in, double r_out);

/// How kick_impurities moved the host particles that a larger impurity would overlap.
struct KickReport {
  std::size_t displaced = 0;         ///< host particles moved
  std::size_t placed_by_voxels = 0;  ///< of which placed by RSA's voxel phase
  double inner_radius = 0.0;         ///< r_in = farthest impurity + a + r_imp: moved hosts lie at |x| >= r_in
};

/// Blast set-up, first step: the `impurity_count` particles nearest the origin become impurities (their own
/// radius and mass), returned in `impurities` by ascending index. Host particles that would overlap a
/// larger impurity move to new random places at |x| >= r_in (plain trials, then RSA's voxel phase
/// after rsa_voxel_switch_default failures in a row); if they provably do not fit,
/// std::invalid_argument naming impurities.radius.
template <int D>
KickReport place_impurities(std::mt19937_64& rng, InitialState<D>& state, std::size_t impurity_count,
                            double region_radius, std::vector<std::int32_t>& impurities);

/// Gives the particles `ids` (non-empty, any species) random velocities of total kinetic energy
/// exactly E: a Maxwellian (independent Gaussian components of variance ∝ 1/m), minus the
/// centre-of-mass velocity when there are two or more (total momentum zero to round-off), then
/// scaled to E. One particle gets E in a uniformly random direction (momentum sqrt(2 m E)).
template <int D>
void share_energy(std::mt19937_64& rng, InitialState<D>& state, const std::vector<std::int32_t>& ids, double E);

/// place_impurities, then share_energy among the impurities: the paper's kick (Sec. V).
template <int D>
KickReport kick_impurities(std::mt19937_64& rng, InitialState<D>& state, std::size_t impurity_count, double E,
                           double region_radius);

/// How the energy E enters a blast (the scene's [start] table; docs/md-output.md, "Starts"). In every
/// start the impurities are the same particles, the impurities.count nearest the origin
/// (place_impurities), so R_imp, V_imp, C_imp and p_imp follow the same tagged particles whatever
/// the start; only who gets E differs.
enum class StartKind {
  kick,     ///< the impurities share E (the paper's start, Sec. V)
  hotspot,  ///< every particle within r0 of the origin, impurities included, shares E (a Maxwellian)
  single,   ///< the host particle nearest the origin gets E; the impurities start at rest
};
/// "kick", "hotspot", "single".
const char* start_kind_name(StartKind kind);
/// The kind named `name`; std::invalid_argument naming start.kind and the allowed names otherwise.
StartKind start_kind_from_name(const std::string& name);

struct StartConfig {
  StartKind kind = StartKind::kick;
  /// hotspot: the hot spot's radius (length), in [hot_spot_min_radius, R(t_max) of Eq. (1)]; 0 for the others.
  double r0 = 0.0;
};

/// Smallest hot-spot radius (length): the ball that holds, on average at density n, max(2,
/// impurity_count) particles (zero momentum needs two; the impurities must lie in the hot spot).
double hot_spot_min_radius(int d, double n, int impurity_count);

/// What start_blast did.
struct StartReport {
  KickReport impurities;             ///< place_impurities' report
  std::vector<std::int32_t> heated;  ///< the particles that got E, by ascending index
};

/// Blast set-up: place_impurities, then E given as `start` says (share_energy over the impurities,
/// over every particle with |x| <= r0, or to the host nearest the origin). Draws from `rng` in that
/// order, so a kick is bit for bit kick_impurities. A hot spot that holds fewer than two particles
/// or misses an impurity throws std::invalid_argument naming start.r0.
template <int D>
StartReport start_blast(std::mt19937_64& rng, InitialState<D>& state, const StartConfig& start,
                        std::size_t impurity_count, double E, double region_radius);

/// Periodic box start: `count` spheres on a simple cubic (square) lattice filling the box row by row,
/// Maxwellian velocities at temperature T with zero total momentum, rescaled so that the kinetic
/// energy is exactly (d/2) (count - 1) T.
template <int D>
InitialState<D> lattice_start(std::mt19937_64& rng, std::size_t count, double radius, const Vec<D>& box, double T);

}  // namespace coldblast::md
