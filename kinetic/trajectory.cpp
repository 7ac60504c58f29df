#include "kinetic/trajectory.hpp"

#include <Eigen/Geometry>
#include <cmath>
#include <stdexcept>
#include <string>

#include "common/validate.hpp"
#include "kinetic/kinetic_theory.hpp"
#include "kinetic/segment.hpp"
#include "md/collision.hpp"

namespace coldblast::kinetic {

namespace {
constexpr double two_pi = 6.283185307179586476925;

template <int D>
md::Vec<D> normal_vector(Random& rng) {
  md::Vec<D> x;
  for (int k = 0; k < D; ++k) x[k] = rng.normal();
  return x;
}

/// Thermal velocity c = w − u of the host partner from the mixture (|v−u| F + |c| F)/(|v−u| + c̄):
/// with probability |v−u|/(|v−u| + c̄) Maxwellian, else speed-biased Maxwellian (density ∝ |c| F:
/// speed ~ chi with d+1 degrees of freedom, uniform direction). The biased speed reuses the
/// direction's normals: for a standard normal vector z in R^d, |z|² (chi² with d degrees of
/// freedom) is independent of z/|z|, so |z|² + z_{d+1}² is chi² with d+1, independent of z/|z|.
template <int D>
md::Vec<D> mixture_velocity(double relative_speed, double mean_speed, double T, Random& rng) {
  const double sqrt_T = std::sqrt(T);
  if (rng.uniform() * (relative_speed + mean_speed) < relative_speed) return sqrt_T * normal_vector<D>(rng);
  md::Vec<D> direction = normal_vector<D>(rng);
  double norm2 = direction.squaredNorm();
  while (norm2 == 0.0) {
    direction = normal_vector<D>(rng);
    norm2 = direction.squaredNorm();
  }
  const double z = rng.normal();
  return (sqrt_T * std::sqrt((norm2 + z * z) / norm2)) * direction;
}
}  // namespace

double ImpurityModel::cross_section() const {
  return total_cross_section(d, sigma_c);
}

template <int D>
md::Vec<D> sample_impact_direction(const md::Vec<D>& g_hat, Random& rng) {
  if constexpr (D == 2) {
    const double b = 2.0 * rng.uniform() - 1.0;
    const md::Vec<2> perpendicular(-g_hat[1], g_hat[0]);
    return std::sqrt(1.0 - b * b) * g_hat + b * perpendicular;
  } else {
    const double b2 = rng.uniform();
    const double b = std::sqrt(b2), angle = two_pi * rng.uniform();
    // Orthonormal pair perpendicular to g_hat (Frisvad-style choice of the helper axis).
    const md::Vec<3> helper = std::abs(g_hat[0]) < 0.6 ? md::Vec<3>(1, 0, 0) : md::Vec<3>(0, 1, 0);
    const md::Vec<3> e1 = g_hat.cross(helper).normalized();
    const md::Vec<3> e2 = g_hat.cross(e1);
    return std::sqrt(1.0 - b2) * g_hat + b * (std::cos(angle) * e1 + std::sin(angle) * e2);
  }
}

template <int D>
void binary_collision(const md::Vec<D>& e, md::Vec<D>& v, md::Vec<D>& w, double M) {
  md::collide<D>(e, v, w, M, 1.0);  // dr = r_host − r_impurity ∥ e
}

namespace {
[[noreturn, gnu::cold, gnu::noinline]] void majorant_violated(double t, double radius, double rate, double majorant) {
  throw std::runtime_error("null-collision majorant violated at t = " + common::format_number(t) +
                           ", r = " + common::format_number(radius) + ": rate " + common::format_number(rate) + " > " +
                           common::format_number(majorant));
}

/// The last two steps of the thinning for a candidate the dominating rate accepted (host flow u,
/// |v − u| and c̄(T) given): the partner's thermal velocity c from the mixture, accepted with
/// probability |v − u − c|/(|v − u| + |c|); then the binary collision changes v. Returns whether the
/// impurity collided.
template <int D>
inline bool collide_with_host(const md::Vec<D>& u, double relative_speed, double mean_speed, double T, double M,
                              md::Vec<D>& v, Random& rng) {
  const md::Vec<D> c = mixture_velocity<D>(relative_speed, mean_speed, T, rng);
  md::Vec<D> w = u + c;
  const md::Vec<D> g = v - w;
  const double g_norm = g.norm();
  if (rng.uniform() * (relative_speed + c.norm()) >= g_norm) return false;
  const md::Vec<D> e = sample_impact_direction<D>(g / g_norm, rng);
  binary_collision<D>(e, v, w, M);
  return true;
}
}  // namespace

template <int D>
void advance(const Background& background, const ImpurityModel& impurity, TracerState<D>& s, double t_target,
             Random& rng, TracerCounters& counters) {
  using detail::open_segment;
  using detail::reuse_segment;
  using detail::Segment;
  const double S = impurity.cross_section();
  WindowBound window = background.bound(s.t);
  TimeSlice anchor = background.slice(window, s.t);  // the slices of nearby times derive from it
  Segment segment = open_segment(background, window, anchor, S, s, t_target);
  ++counters.segments;
  // Every time slice carries the segment's grid cell as its search hint (same results, fewer comparisons).
  const auto slice_at = [&](double t) {
    TimeSlice slice = background.slice_near(window, anchor, t);
    slice.cell = segment.cell;
    return slice;
  };
  while (true) {
    // The majorant bounds the rate along the whole straight path of the segment, so it stays valid
    // after a rejected candidate (the path is unchanged, the process memoryless) and is recomputed
    // only when the velocity changes or the segment ends: the thinning stays exact.
    const double majorant = segment.majorant;
    const double dt = majorant > 0.0 ? rng.exponential() / majorant : std::numeric_limits<double>::infinity();
    if (s.t + dt >= segment.t_end) {  // memoryless: stop at the segment's end and redraw there
      s.r += s.v * (segment.t_end - s.t);
      s.t = segment.t_end;
      if (s.t >= t_target) return;
      if (s.t >= window.t_end) window = background.bound(s.t);
      segment = open_segment(background, window, slice_at(s.t), S, s, t_target);
      ++counters.segments;
      continue;
    }
    s.t += dt;
    s.r += s.v * dt;
    ++counters.candidates;
    const double radius = s.r.norm();
    const TimeSlice now = slice_at(s.t);
    const HostState h = background.at(radius, now);
    const md::Vec<D> u = radius > 0.0 ? md::Vec<D>((h.u / radius) * s.r) : md::Vec<D>::Zero();
    const double relative_speed = (s.v - u).norm();
    const double mean_speed = host_mean_speed(D, h.T);
    const double dominating = S * h.n * h.chi * (relative_speed + mean_speed);
    if (dominating > majorant * (1.0 + 1e-12)) majorant_violated(s.t, radius, dominating, majorant);
    if (rng.uniform() * majorant >= dominating) continue;
    if (!collide_with_host<D>(u, relative_speed, mean_speed, h.T, impurity.M, s.v, rng)) continue;
    ++s.collisions;
    ++counters.collisions;
    if (!reuse_segment(segment, S, s, radius, t_target)) {
      segment = open_segment(background, window, now, S, s, t_target);
      ++counters.segments;
    }
  }
}

template md::Vec<2> sample_impact_direction<2>(const md::Vec<2>&, Random&);
template md::Vec<3> sample_impact_direction<3>(const md::Vec<3>&, Random&);
template void binary_collision<2>(const md::Vec<2>&, md::Vec<2>&, md::Vec<2>&, double);
template void binary_collision<3>(const md::Vec<3>&, md::Vec<3>&, md::Vec<3>&, double);
template void advance<2>(const Background&, const ImpurityModel&, TracerState<2>&, double, Random&, TracerCounters&);
template void advance<3>(const Background&, const ImpurityModel&, TracerState<3>&, double, Random&, TracerCounters&);

}  // namespace coldblast::kinetic
