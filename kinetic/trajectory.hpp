#pragma once
// One impurity trajectory of the linear Lorentz–Boltzmann equation, paper Eq. (36) [LB-full], by
// exact null-collision (majorant, "thinning") sampling: free flight between collisions; candidate
// collisions at the majorant rate Λ = S (A |v| + B), S the total cross-section, A >= n chi and
// B >= n chi (|u| + c̄(T)) over the radii the impurity can reach in the current segment (a few
// radial bands of the background grid, inside one time window, along the segment's straight path;
// recomputed when the velocity changes or the segment ends, so Λ is predictable and the thinning
// exact); a candidate at
// (r, t) is accepted with probability ν(r, v, t)/Λ, ν = n chi S E_w|v − w| the exact local rate of
// the kernel |(w − v)·e|, and the host velocity w is then distributed as |v − w| F(w) and the impact
// direction e as (g·e)_+ (g = v − w). No time step: exact in time (docs/kinetic.md).
#include <cstdint>

#include "kinetic/background.hpp"
#include "kinetic/random.hpp"
#include "md/particles.hpp"

namespace coldblast::kinetic {

/// The impurity: mass M (host mass 1) and contact distance sigma_c = a + a_imp.
struct ImpurityModel {
  int d = 2;
  double M = 1.0;
  double sigma_c = 1.0;
  double cross_section() const;  ///< total cross-section S (kinetic_theory.hpp)
};

/// Position (from the blast centre), velocity, time and collision count of one impurity.
template <int D>
struct TracerState {
  md::Vec<D> r = md::Vec<D>::Zero();
  md::Vec<D> v = md::Vec<D>::Zero();
  double t = 0.0;
  std::uint64_t collisions = 0;
};

/// Work counters: candidate (majorant) events, accepted collisions and segments (fresh local
/// bounds of the majorant; a collision keeps the old bound where it can).
struct TracerCounters {
  std::uint64_t candidates = 0, collisions = 0, segments = 0;
};

/// Impact direction e for relative velocity direction g_hat (unit): density ∝ (g_hat·e)_+ on the
/// unit sphere, i.e. impact parameter uniform on the unit (d-1)-ball perpendicular to g_hat.
template <int D>
md::Vec<D> sample_impact_direction(const md::Vec<D>& g_hat, Random& rng);

/// Elastic hard-sphere collision of the impurity (velocity v, mass M) with a host (w, mass 1) at
/// contact along e (unit, impurity → host) with (v − w)·e > 0: exact unequal-mass rule of
/// md::collide, v' = v − 2/(M+1) ((v−w)·e) e, w' = w + 2M/(M+1) ((v−w)·e) e.
template <int D>
void binary_collision(const md::Vec<D>& e, md::Vec<D>& v, md::Vec<D>& w, double M);

/// Advances `state` to t_target (>= state.t) through every collision on the way.
/// Throws std::runtime_error if an acceptance probability exceeds 1 (a majorant violated).
template <int D>
void advance(const Background& background, const ImpurityModel& impurity, TracerState<D>& state, double t_target,
             Random& rng, TracerCounters& counters);

}  // namespace coldblast::kinetic
