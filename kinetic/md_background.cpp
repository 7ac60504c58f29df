#include "kinetic/md_background.hpp"

#include <cmath>
#include <limits>
#include <stdexcept>

#include "common/validate.hpp"

namespace coldblast::kinetic {

using common::format_number;

void MeasuredProfiles::validate() const {
  if (d != 2 && d != 3) throw std::invalid_argument("profiles: d = " + std::to_string(d) + " is not 2 or 3");
  common::require_in_range("profiles: n", n, 0.0, std::numeric_limits<double>::infinity());
  if (edges.size() < 2) throw std::invalid_argument("profiles: fewer than one bin of r/R");
  if (edges.front() != 0.0)
    throw std::invalid_argument("profiles: the first bin starts at r/R = " + format_number(edges.front()) +
                                ", not at the centre (0)");
  for (std::size_t i = 1; i < edges.size(); ++i)
    if (!(edges[i] > edges[i - 1]) || !std::isfinite(edges[i]))
      throw std::invalid_argument("profiles: the bin edges of r/R are not ascending at bin " + std::to_string(i - 1));
  if (frames.size() < 2)
    throw std::invalid_argument("profiles: " + std::to_string(frames.size()) +
                                " recorded times; at least 2 are needed to interpolate in time");
  const std::size_t bins = edges.size() - 1;
  for (std::size_t k = 0; k < frames.size(); ++k) {
    const ProfileFrame& f = frames[k];
    const std::string at = " at t = " + format_number(f.t);
    if (!(f.t > 0.0) || !std::isfinite(f.t) || (k > 0 && !(f.t > frames[k - 1].t)))
      throw std::invalid_argument("profiles: recorded times must be positive and ascending" + at);
    if (!(f.R > 0.0) || !std::isfinite(f.R))
      throw std::invalid_argument("profiles: the moving-mass radius R = " + format_number(f.R) + at +
                                  " is not positive");
    if (f.density.size() != bins || f.velocity.size() != bins || f.temperature.size() != bins)
      throw std::invalid_argument("profiles: " + std::to_string(bins) + " bins of r/R expected" + at);
    for (std::size_t i = 0; i < bins; ++i)
      if (!(f.density[i] >= 0.0) || !std::isfinite(f.density[i]) || !std::isfinite(f.velocity[i]) ||
          !(f.temperature[i] >= 0.0) || !std::isfinite(f.temperature[i]))
        throw std::invalid_argument("profiles: bin " + std::to_string(i) + at +
                                    " has a negative or non-finite density or temperature, or a non-finite flow");
  }
}

BinMoments bin_moments(int d, double lo, double hi) {
  // Moments of the volume measure x^(d−1) dx: ∫ x^(d−1+k) dx = (hi^(d+k) − lo^(d+k))/(d+k). The
  // variance is formed from the bin's own offsets, y = x − mid, so that it keeps its digits far
  // from the centre: ∫ (mid + y)^(d−1) y^j dy over [−h/2, h/2] in closed form.
  const double mid = 0.5 * (lo + hi), half = 0.5 * (hi - lo);
  const double h2 = half * half, h3 = h2 * half, h5 = h3 * h2;
  double m0, m1, m2;  // ∫ w(y) y^j dy, w = (mid + y)^(d−1)
  if (d == 2) {
    m0 = 2.0 * half * mid;
    m1 = 2.0 * h3 / 3.0;
    m2 = 2.0 * h3 * mid / 3.0;
  } else {
    m0 = 2.0 * half * mid * mid + 2.0 * h3 / 3.0;
    m1 = 4.0 * h3 * mid / 3.0;
    m2 = 2.0 * h3 * mid * mid / 3.0 + 2.0 * h5 / 5.0;
  }
  const double offset = m1 / m0;  // centroid − mid
  return {mid + offset, m2 / m0 - offset * offset};
}

std::vector<double> measured_nodes(const MeasuredProfiles& profiles) {
  std::vector<double> x{0.0};
  for (std::size_t i = 0; i + 1 < profiles.edges.size(); ++i)
    x.push_back(bin_moments(profiles.d, profiles.edges[i], profiles.edges[i + 1]).centroid);
  return x;
}

std::unique_ptr<GridBackground> make_md_background(const MeasuredProfiles& profiles, const ContactModel& contact,
                                                   std::string* description, bool self_similar_after) {
  profiles.validate();
  if (contact.d != profiles.d)
    throw std::invalid_argument("profiles: d = " + std::to_string(profiles.d) +
                                " but the impurity's d = " + std::to_string(contact.d));
  std::vector<double> x = measured_nodes(profiles);
  std::vector<BackgroundFrame> frames;
  for (const ProfileFrame& p : profiles.frames) {
    // x = 0: the first bin's density and temperature (their slope vanishes at the centre) and no
    // flow (u is odd in r); then the bins at their centroids.
    BackgroundFrame f{p.t, p.R, {profiles.n * p.density.front()}, {0.0}, {p.temperature.front()}};
    for (std::size_t i = 0; i < p.density.size(); ++i) {
      f.n.push_back(profiles.n * p.density[i]);
      f.u.push_back(p.velocity[i]);
      f.T.push_back(p.temperature[i]);
    }
    frames.push_back(std::move(f));
  }
  const double edge = profiles.edges.back();
  if (description)
    *description = "MD profiles: " + std::to_string(profiles.edges.size() - 1) + " bins of r/R from 0 to " +
                   common::format_significant(edge, 4) + ", " + std::to_string(frames.size()) +
                   " recorded times t from " + common::format_significant(frames.front().t, 4) + " to " +
                   common::format_significant(frames.back().t, 4) +
                   ", linear in r/R between the bins' volume centroids and in ln t; ambient gas at rest beyond" +
                   (self_similar_after ? "; self-similar (TvNS scaling) after the last time" : "");
  return std::make_unique<GridBackground>(profiles.d, std::move(x), edge, std::move(frames), profiles.n, contact,
                                          self_similar_after, false);
}

}  // namespace coldblast::kinetic
