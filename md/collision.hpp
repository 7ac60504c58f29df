#pragma once
// Pair evaluator for elastic hard spheres (the DynamO "pair rule" split): the contact time of two
// particles in straight-line flight, and the elastic collision rule for unequal masses.
// Contact: |Δr + Δv τ| = σ_ij; the smallest root uses the cancellation-free form c/(-b + √disc).
#include <cmath>
#include <limits>

#include "md/particles.hpp"

namespace coldblast::md {

inline constexpr double never = std::numeric_limits<double>::infinity();

/// Time until contact τ >= 0 of two particles separated by dr = r_j - r_i with relative velocity
/// dv = v_j - v_i and squared contact distance sigma2 (sum of radii, squared); `never` if they do
/// not approach. Slightly overlapping approaching pairs (round-off) collide at once (τ = 0).
template <int D>
inline double contact_time_squared(const Vec<D>& dr, const Vec<D>& dv, double sigma2) {
  const double b = dr.dot(dv);
  if (b >= 0.0) return never;
  const double v2 = dv.squaredNorm();
  const double c = dr.squaredNorm() - sigma2;
  const double disc = b * b - v2 * c;
  if (disc < 0.0) return never;
  const double tau = c / (-b + std::sqrt(disc));
  return tau > 0.0 ? tau : 0.0;
}

/// The same with the contact distance sigma (length).
template <int D>
inline double contact_time(const Vec<D>& dr, const Vec<D>& dv, double sigma) {
  return contact_time_squared<D>(dr, dv, sigma * sigma);
}

/// Result of one elastic collision: the impulse on j is -impulse on i.
template <int D>
struct CollisionOutcome {
  Vec<D> impulse_on_i;  ///< momentum change of particle i (mass × length/time)
  double virial;        ///< r_ij · Δp_i = -2 μ (Δr·Δv) >= 0 (r_ij = r_i - r_j): the collisional virial
};

/// Elastic collision of i and j at contact; dr = r_j - r_i, velocities updated in place.
/// Momentum is exchanged along dr: Δv_i = (2 m_j/(m_i+m_j)) (dr·dv/|dr|²) dr.
template <int D>
inline CollisionOutcome<D> collide(const Vec<D>& dr, Vec<D>& v_i, Vec<D>& v_j, double m_i, double m_j) {
  const Vec<D> dv = v_j - v_i;
  const double b = dr.dot(dv);
  const double reduced_mass = m_i * m_j / (m_i + m_j);
  const Vec<D> impulse = (2.0 * reduced_mass * b / dr.squaredNorm()) * dr;
  v_i += impulse / m_i;
  v_j -= impulse / m_j;
  return {impulse, -2.0 * reduced_mass * b};
}

}  // namespace coldblast::md
