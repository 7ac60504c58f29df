#pragma once
// The tracer's background from an MD run's own mean fields (issue 32): the ensemble's profiles of
// density, radial flow and temperature in bins of x = r/R (R the moving-mass radius) at every
// recorded time (profiles.csv, docs/md-output.md), as the local Maxwellian of Eq. (36) [LB-full].
// In it the tracer/MD difference is Eq. (36)'s own error (molecular chaos, local equilibrium).
// Interpolation, its error bound and the range: docs/kinetic.md, "The MD's own fields".
#include <memory>
#include <string>
#include <vector>

#include "kinetic/background.hpp"

namespace coldblast::kinetic {

/// One recorded time of an MD run's profiles, as `md run` bins them (md/observers.cpp): per bin of
/// x = r/R_i (R_i each realization's moving-mass radius), over all realizations.
struct ProfileFrame {
  double t = 0.0;
  double R = 0.0;                   ///< the ensemble's mean moving-mass radius at t (observable `R`), > 0
  std::vector<double> density;      ///< n/n∞: the bin's volume average
  std::vector<double> velocity;     ///< radial flow: the bin's mass average Σ v_r / Σ 1
  std::vector<double> temperature;  ///< (Σ m v² / Σ 1 − u²)/d, ≥ 0
};

/// An MD run's measured mean fields: bins [edges[i], edges[i+1]) of x = r/R, the same at every time.
struct MeasuredProfiles {
  int d = 2;
  double n = 0.0;                    ///< ambient density n∞ of the MD's scene, > 0
  std::vector<double> edges;         ///< ascending, edges[0] = 0; profiles.csv: 0, 1.5/B, ..., 1.5
  std::vector<ProfileFrame> frames;  ///< ascending t, at least 2
  /// Throws std::invalid_argument naming the field and the frame (sizes, order, signs, finiteness).
  void validate() const;
};

/// A bin's volume centroid and the variance of x about it under the volume measure x^(d−1) dx.
struct BinMoments {
  double centroid = 0.0, variance = 0.0;
};
BinMoments bin_moments(int d, double lo, double hi);

/// The interpolation nodes of a background made from `profiles`: x = 0, then every bin's volume
/// centroid (where a volume average equals the field to second order in the bin width).
std::vector<double> measured_nodes(const MeasuredProfiles& profiles);

/// The background of Eq. (36) in the MD's mean fields: n = n∞ × density, u, T at the nodes of
/// measured_nodes (at x = 0: u = 0 by symmetry, n and T of the first bin), linear in x between
/// nodes, held from the last node to the last edge, and the ambient gas at rest (n∞, u = 0, T = 0)
/// beyond it; between recorded times linear in ln t with the scale R log-linear in t (a
/// GridBackground). No data before the first recorded time: bound() throws there; after the last
/// likewise, unless `self_similar_after` (then continued with the TvNS scaling of GridBackground:
/// for a run's end t_max, less than one recording interval after its last recorded time).
std::unique_ptr<GridBackground> make_md_background(const MeasuredProfiles& profiles, const ContactModel& contact,
                                                   std::string* description = nullptr, bool self_similar_after = false);

}  // namespace coldblast::kinetic
