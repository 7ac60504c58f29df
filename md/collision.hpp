#pragma once
// Pair evaluator for elastic hard spheres (the DynamO "pair rule" split): the contact time of two
// particles in straight-line flight, the time a particle takes to leave its cell, and the elastic
// collision rule for unequal masses. These scalar functions are the definitions: the engine's
// SIMD versions (md/pair_kernel.*: SSE2 and AVX2) do the same arithmetic operation for operation
// and are tested bit for bit against them (tests/md/test_pair_kernel.cpp); with
// EngineConfig::simd = false the engine runs these.
// Contact: |Δr + Δv τ| = σ_ij; the smallest root uses the cancellation-free form c/(-b + √disc).
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>

#include "md/particles.hpp"

namespace coldblast::md {

inline constexpr double never = std::numeric_limits<double>::infinity();

/// The terms of the contact condition |dr + dv τ|² = sigma2, a quadratic v2 τ² + 2 b τ + c = 0:
/// b = dr·dv, v2 = |dv|², c = |dr|² - sigma2 and the quarter discriminant disc = b² - v2 c
/// (each sum in Eigen's order: (x + y) + z).
struct ContactTerms {
  double b, v2, c, disc;
};

template <int D>
inline ContactTerms contact_terms(const Vec<D>& dr, const Vec<D>& dv, double sigma2) {
  const double b = dr.dot(dv);
  const double v2 = dv.squaredNorm();
  const double c = dr.squaredNorm() - sigma2;
  return {b, v2, c, b * b - v2 * c};
}

/// Time until contact τ >= 0 of two particles separated by dr = r_j - r_i with relative velocity
/// dv = v_j - v_i and squared contact distance sigma2 (sum of radii, squared); `never` if they do
/// not approach. Slightly overlapping approaching pairs (round-off) collide at once (τ = 0).
template <int D>
inline double contact_time_squared(const Vec<D>& dr, const Vec<D>& dv, double sigma2) {
  const ContactTerms q = contact_terms<D>(dr, dv, sigma2);
  if (q.b >= 0.0) return never;    // receding or at rest relative to each other
  if (q.disc < 0.0) return never;  // passing each other without touching
  const double tau = q.c / (-q.b + std::sqrt(q.disc));
  return tau > 0.0 ? tau : 0.0;
}

/// The same with the contact distance sigma (length).
template <int D>
inline double contact_time(const Vec<D>& dr, const Vec<D>& dv, double sigma) {
  return contact_time_squared<D>(dr, dv, sigma * sigma);
}

/// Time until a particle at coordinate x with velocity component v leaves the cell span
/// [lower, lower + width) along one axis: through the upper wall if v > 0, the lower one if v < 0,
/// `never` if v = 0; 0 if round-off put it a hair outside already.
inline double axis_crossing_time(double x, double v, double lower, double width) {
  const double wall = v > 0.0 ? lower + width : lower;
  return v == 0.0 ? never : std::max(0.0, (wall - x) / v);
}

/// Time until a particle (position, velocity) leaves its cell, spanning [lower_k, lower_k + width_k)
/// per axis, and the face it leaves by, code = 2 axis + (v_axis > 0): the earliest axis, the lower
/// axis among equal times; `never` with code 0 for a particle at rest.
template <int D>
inline double cell_crossing_time(const Vec<D>& position, const Vec<D>& velocity, const double* lower,
                                 const double* width, std::uint8_t& code) {
  double best = never;
  code = 0;
  for (int k = 0; k < D; ++k) {
    const double dt = axis_crossing_time(position[k], velocity[k], lower[k], width[k]);
    if (dt < best) {
      best = dt;
      code = static_cast<std::uint8_t>(2 * k + (velocity[k] > 0.0 ? 1 : 0));
    }
  }
  return best;
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
