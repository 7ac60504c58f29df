#include "hydro/blast_measurements.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "common/validate.hpp"
#include "hydro/radial_blast.hpp"
#include "theory/exponents.hpp"
#include "theory/prefactors.hpp"

namespace coldblast::hydro {

namespace {

/// Shock radius from mass conservation ("equal areas"): the mass excess over the cold gas beyond the
/// outer face of cell b = peak - 3 equals that of a sharp shock at R behind which n continues the
/// smooth profile of cells b-1, b linearly. Sub-cell accurate; NaN if the peak is too close to r = 0.
double conservative_shock_radius(const RadialBlast& blast, const double* state, int peak, double n_inf) {
  const std::vector<double>& r = blast.radii();
  const std::vector<double>& n = blast.density();
  const int N = blast.cells(), b = peak - 3;
  if (b < 1) return std::numeric_limits<double>::quiet_NaN();
  double excess = 0;
  for (int i = b + 1; i < N; ++i)
    excess += state[components * i] - n_inf * (blast.ball_volume(r[i + 1]) - blast.ball_volume(r[i]));
  const double centre_b = 0.5 * (r[b] + r[b + 1]), centre_a = 0.5 * (r[b - 1] + r[b]);
  const double slope = (n[b] - n[b - 1]) / (centre_b - centre_a);
  // ∫_{r_{b+1}}^{R} (n_lin - n∞) A(r) dr; the integrand is a polynomial of degree <= 3, so the
  // 2-point Gauss-Legendre rule is exact.
  auto excess_of = [&](double R) {
    const double half = 0.5 * (R - r[b + 1]), middle = 0.5 * (R + r[b + 1]);
    double sum = 0;
    for (double node : {-1 / std::sqrt(3.0), 1 / std::sqrt(3.0)}) {
      const double x = middle + half * node;
      sum += (n[b] + slope * (x - centre_b) - n_inf) * blast.face_area(x);
    }
    return half * sum;
  };
  double lo = r[b + 1], hi = r[N];
  if (excess_of(hi) < excess) return std::numeric_limits<double>::quiet_NaN();
  for (int iteration = 0; iteration < 200 && hi - lo > 1e-15 * hi; ++iteration) {
    const double mid = 0.5 * (lo + hi);
    (excess_of(mid) < excess ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

/// Shock radius (conservative, with the half-height crossing as fallback and grid-exit check).
double measure_shock_radius(const RadialBlast& blast, const double* state, const std::vector<double>& centres,
                            double n_inf, double t) {
  const std::vector<double>& n = blast.density();
  const int N = blast.cells();
  const int peak = static_cast<int>(std::max_element(n.begin(), n.end()) - n.begin());
  const double R_crossing = crossing_radius(centres, n, peak, 0.5 * (n_inf + n[peak]), true);
  if (!std::isfinite(R_crossing) || R_crossing > 0.97 * blast.radii()[N])
    throw std::runtime_error("the shock left the grid at t = " + common::format_number(t) +
                             ", R_ref/lambda = " + common::format_number(blast.reference_radius(t) / blast.lambda()) +
                             " (heat conduction outruns the shock when R/lambda is ~1 or kappa is large, e.g. a "
                             "dense gas near close packing: raise outer_margin (--outer-margin, up to 2), or "
                             "start later)");
  const double R = conservative_shock_radius(blast, state, peak, n_inf);
  return std::isfinite(R) ? R : R_crossing;
}

/// The sample whose time is nearest to t_end in ln t.
template <class Item>
const Item& nearest_in_time(const std::vector<Item>& items, double t_end) {
  auto closest = std::min_element(items.begin(), items.end(), [t_end](const auto& x, const auto& y) {
    return std::abs(std::log(x.t / t_end)) < std::abs(std::log(y.t / t_end));
  });
  return *closest;
}

}  // namespace

double crossing_radius(const std::vector<double>& centres, const std::vector<double>& values, int first, double level,
                       bool falling) {
  for (std::size_t i = first + 1; i < values.size(); ++i) {
    const bool crossed = falling ? values[i] <= level : values[i] >= level;
    if (crossed) {
      const double f = (level - values[i - 1]) / (values[i] - values[i - 1]);
      return centres[i - 1] + f * (centres[i] - centres[i - 1]);
    }
  }
  return std::numeric_limits<double>::quiet_NaN();
}

NavierStokesSample measure_sample(const RadialBlast& blast, const double* state, const std::vector<double>& centres,
                                  const NavierStokesConfig& config, double t) {
  const int d = config.physics.d, N = blast.cells();
  const double lambda = blast.lambda(), n_inf = config.physics.n_inf;
  const std::vector<double>& n = blast.density();
  const std::vector<double>& T = blast.temperature();
  NavierStokesSample sample;
  sample.t = t;
  sample.R = blast.frozen_flow() ? blast.reference_radius(t) : measure_shock_radius(blast, state, centres, n_inf, t);
  sample.R_over_lambda = sample.R / lambda;
  sample.n0 = n[0];
  sample.T0 = T[0];
  sample.p0 = blast.pressure()[0];  // n0 T0 Z(φ0); n0 T0 for the ideal gas
  sample.H = crossing_radius(centres, T, 0, 0.5 * T[0], true);
  sample.H_density = crossing_radius(centres, n, 0, 2.0 * n[0], false);
  for (int i = 0; i < N; ++i) {
    sample.mass += state[components * i];
    sample.energy += state[components * i + 2];
  }
  const double x = sample.R_over_lambda, shock_speed = theory::shock_speed_at(d, sample.R, t);
  const theory::ScalingExponents laws = theory::scaling_exponents(d);
  // T0/Ṙ² with Ṙ² ∝ x^(-d): the exponent of Eq. (12) plus d, i.e. 2d²/(8+3d²)
  const double T0_over_Rdot2_exponent = theory::to_double(laws.T0.in_R_over_lambda + d);
  sample.H_prefactor = sample.H / theory::core_radius(d, lambda, sample.R);                              // Eq. (4)
  sample.n0_prefactor = sample.n0 / (n_inf * std::pow(x, theory::to_double(laws.n0.in_R_over_lambda)));  // Eq. (11)
  sample.T0_prefactor = sample.T0 / (shock_speed * shock_speed * std::pow(x, T0_over_Rdot2_exponent));   // Eq. (12)
  sample.p0_scaled = sample.p0 / (n_inf * shock_speed * shock_speed);
  sample.energy_error = std::abs(sample.energy - blast.expected_energy(t)) / config.physics.E;
  sample.mass_error = std::abs(sample.mass - blast.expected_mass(t)) / sample.mass;
  for (double value : {sample.R, sample.n0, sample.T0, sample.energy, sample.mass})
    if (!std::isfinite(value)) throw std::runtime_error("non-finite diagnostic at t = " + common::format_number(t));
  return sample;
}

NavierStokesProfile make_profile(const RadialBlast& blast, const std::vector<double>& centres, double t, double R) {
  NavierStokesProfile profile;
  profile.t = t;
  profile.R = R;
  for (int i = 0; i < blast.cells(); ++i) {
    profile.r.push_back(centres[i]);
    profile.r_over_R.push_back(centres[i] / R);
    profile.density.push_back(blast.density()[i]);
    profile.velocity.push_back(blast.velocity()[i]);
    profile.temperature.push_back(blast.temperature()[i]);
    profile.pressure.push_back(blast.pressure()[i]);
    profile.heat_flux.push_back(blast.heat_flux(i));
  }
  return profile;
}

std::vector<RunningExponents> running_exponents(const std::vector<NavierStokesSample>& s) {
  std::vector<RunningExponents> exponents;
  for (std::size_t k = 1; k + 1 < s.size(); ++k) {
    const double dlnt = std::log(s[k + 1].t / s[k - 1].t);
    const double dlnR = std::log(s[k + 1].R / s[k - 1].R);
    auto slope = [&](double a, double b) { return std::log(b / a) / dlnt; };
    RunningExponents e;
    e.t = s[k].t;
    e.R_over_lambda = s[k].R_over_lambda;
    e.R = dlnR / dlnt;
    e.H = slope(s[k - 1].H, s[k + 1].H);
    e.H_density = slope(s[k - 1].H_density, s[k + 1].H_density);
    e.n0 = slope(s[k - 1].n0, s[k + 1].n0);
    e.T0 = slope(s[k - 1].T0, s[k + 1].T0);
    e.H_in_R = e.H / e.R;
    e.H_density_in_R = e.H_density / e.R;
    e.n0_in_R = e.n0 / e.R;
    e.T0_in_R = e.T0 / e.R;
    exponents.push_back(e);
  }
  return exponents;
}

RunningExponents NavierStokesResult::exponents_at(double R_over_lambda) const {
  if (exponents.empty()) throw std::logic_error("NavierStokesResult::exponents_at: no exponents");
  const double front = exponents.front().R_over_lambda, back = exponents.back().R_over_lambda;
  common::require_in_range("R_over_lambda", R_over_lambda, front, back, common::Bound::closed, common::Bound::closed,
                           " (the sampled range of this run)");
  std::size_t k = 1;
  while (k + 1 < exponents.size() && exponents[k].R_over_lambda < R_over_lambda) ++k;
  const RunningExponents& a = exponents[k - 1];
  const RunningExponents& b = exponents[k];
  const double f = std::log(R_over_lambda / a.R_over_lambda) / std::log(b.R_over_lambda / a.R_over_lambda);
  auto mix = [f](double x, double y) { return x + f * (y - x); };
  return RunningExponents{mix(a.t, b.t),
                          R_over_lambda,
                          mix(a.R, b.R),
                          mix(a.H, b.H),
                          mix(a.H_density, b.H_density),
                          mix(a.n0, b.n0),
                          mix(a.T0, b.T0),
                          mix(a.H_in_R, b.H_in_R),
                          mix(a.H_density_in_R, b.H_density_in_R),
                          mix(a.n0_in_R, b.n0_in_R),
                          mix(a.T0_in_R, b.T0_in_R)};
}

const NavierStokesSample& NavierStokesResult::final_sample() const {
  if (samples.empty()) throw std::logic_error("NavierStokesResult::final_sample: no samples");
  return nearest_in_time(samples, profiles.back().t);
}

RunningExponents NavierStokesResult::final_exponents() const {
  if (exponents.empty()) throw std::logic_error("NavierStokesResult::final_exponents: no exponents");
  return nearest_in_time(exponents, profiles.back().t);
}

}  // namespace coldblast::hydro
