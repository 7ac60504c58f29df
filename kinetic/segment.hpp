#pragma once
// The straight-flight segments of the null-collision tracer (kinetic/trajectory.hpp): a segment's
// local majorant and its reuse after a collision. Shared by the scalar loop (trajectory.cpp) and
// the 8-lane kernel (batch.cpp), so that both sample the same process with the same bounds.
#include <algorithm>
#include <limits>

#include "kinetic/background.hpp"
#include "kinetic/trajectory.hpp"

namespace coldblast::kinetic::detail {

/// The current segment of straight flight: until `t_end` (the target, the window's end, or a
/// radial reach of a few grid bands) with one majorant over every radius reachable in it.
struct Segment {
  double t_end = 0.0;
  double majorant = 0.0;
  std::size_t cell = 0;  ///< grid cell near the segment's radii (TimeSlice::cell, a search hint)
  /// The local bound behind the majorant: A >= n chi and B >= n chi (|u| + c̄) at every radius in
  /// [r_lo, r_hi] and time in [t_open, bound_end] (bound_end >= t_end).
  double r_lo = 0.0, r_hi = 0.0, bound_end = 0.0, n_chi = 0.0, flux = 0.0;
};

template <int D>
inline Segment open_segment(const Background& background, const WindowBound& window, const TimeSlice& now, double S,
                            const TracerState<D>& s, double t_target) {
  const double speed = s.v.norm();
  Segment segment;
  segment.t_end = std::min(t_target, window.t_end);
  const double radius0 = s.r.norm();
  if (speed > 0.0) segment.t_end = std::min(segment.t_end, s.t + background.bound_length(now, radius0) / speed);
  const double reach = speed * (segment.t_end - s.t);
  segment.r_lo = std::max(0.0, radius0 - reach);
  segment.r_hi = radius0 + reach;
  segment.bound_end = segment.t_end;
  const WindowBound local = background.local_bound(window, now, segment.t_end, segment.r_lo, segment.r_hi);
  segment.n_chi = local.n_chi_max;
  segment.flux = local.flux_max;
  segment.majorant = S * (segment.n_chi * speed + segment.flux);
  segment.cell = local.cell;
  return segment;
}

/// After a collision at radius `radius` (inside [r_lo, r_hi]) the old segment's bound still holds
/// wherever the new straight path stays in that shell before bound_end: it stays there at least
/// until it could have covered the distance to the nearer edge (none below if r_lo = 0). So the
/// same A and B with the new speed make an exact majorant until that time, and no new bound is
/// needed. Returns false (open a fresh segment) when fewer than two candidates are expected
/// before that time.
template <int D>
inline bool reuse_segment(Segment& segment, double S, const TracerState<D>& s, double radius, double t_target) {
  const double speed = s.v.norm();
  const double margin = std::min(segment.r_lo > 0.0 ? radius - segment.r_lo : std::numeric_limits<double>::infinity(),
                                 segment.r_hi - radius);
  const double majorant = S * (segment.n_chi * speed + segment.flux);
  const double t_end = std::min({segment.bound_end, t_target, s.t + margin / speed});
  if (!(margin > 0.0) || !((t_end - s.t) * majorant >= 2.0)) return false;
  segment.majorant = majorant;
  segment.t_end = t_end;
  return true;
}

}  // namespace coldblast::kinetic::detail
