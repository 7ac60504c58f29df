#include "compare/hydro_reference.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "theory/exponents.hpp"
#include "theory/observables.hpp"

namespace coldblast::compare {

HydroReference::HydroReference(hydro::NavierStokesResult result) : result_(std::move(result)) {
  if (result_.samples.size() < 3) throw std::invalid_argument("hydro reference: fewer than 3 samples");
  build_collision_exponents();
}

void HydroReference::build_collision_exponents() {
  // C(t) ∝ ∫_0^t n0 √T0 dt' (Eq. (24) [C-imp-long] argument with τ = 1/(n0 a^{d-1} √T0)). The
  // solver starts at R/λ = 2 from a hot central region whose early transient is not the MD's, so
  // the integral is anchored at the fixed R/λ = collision_anchor_R_over_lambda (the tracer's first
  // frame): the part before it is the asymptotic power law t_a f(t_a)/(1 + β), β the exact exponent
  // of f = n0 √T0 (2D: -3/5), with t_a and f(t_a) interpolated in ln t between the samples around
  // it; the rest is the trapezoid rule in ln t. The anchor does not depend on where the sample plan
  // puts its samples (that moves with the run's end, hydro/navier_stokes.cpp output_plan), so the
  // exponent at a given R/λ does not depend on how far the solver runs (docs/hydro.md).
  const auto& s = result_.samples;
  if (result_.config.physics.start == hydro::Start::hotspot) {
    build_hot_spot_collision_exponents();
    return;
  }
  const double anchor = std::log(collision_anchor_R_over_lambda);
  std::size_t k = 1;  // the samples k-1, k bracket the anchor
  while (k < s.size() && std::log(s[k].R_over_lambda) < anchor) ++k;
  if (k == s.size() || !(std::log(s[0].R_over_lambda) <= anchor))
    throw std::invalid_argument("hydro reference: the samples do not span R/lambda = " +
                                std::to_string(collision_anchor_R_over_lambda) + ", the collision integral's anchor");
  std::vector<double> g(s.size());  // ln(t f) = ln(t n0 √T0), interpolated linearly in ln(R/λ)
  for (std::size_t i = 0; i < s.size(); ++i) g[i] = std::log(s[i].t * s[i].n0 * std::sqrt(s[i].T0));
  const double x0 = std::log(s[k - 1].R_over_lambda), x1 = std::log(s[k].R_over_lambda);
  const double w = (anchor - x0) / (x1 - x0);
  const double ln_t_anchor = (1 - w) * std::log(s[k - 1].t) + w * std::log(s[k].t);
  const double g_anchor = (1 - w) * g[k - 1] + w * g[k];
  const auto exact = theory::scaling_exponents(result_.config.physics.d);
  const double beta = theory::to_double(exact.n0.in_time + exact.T0.in_time / 2);
  const double C_anchor = std::exp(g_anchor) / (1.0 + beta);
  // C at every sample: the trapezoid rule in ln t from the anchor, forward and backward.
  std::vector<double> C(s.size());
  C[k] = C_anchor + 0.5 * (std::log(s[k].t) - ln_t_anchor) * (std::exp(g_anchor) + std::exp(g[k]));
  C[k - 1] = C_anchor - 0.5 * (ln_t_anchor - std::log(s[k - 1].t)) * (std::exp(g[k - 1]) + std::exp(g_anchor));
  for (std::size_t i = k + 1; i < s.size(); ++i)
    C[i] = C[i - 1] + 0.5 * std::log(s[i].t / s[i - 1].t) * (std::exp(g[i]) + std::exp(g[i - 1]));
  for (std::size_t i = k - 1; i-- > 0;)
    C[i] = C[i + 1] - 0.5 * std::log(s[i + 1].t / s[i].t) * (std::exp(g[i + 1]) + std::exp(g[i]));
  log_R_over_lambda_.clear();
  collision_exponent_.clear();
  for (std::size_t i = 0; i < s.size(); ++i) {
    log_R_over_lambda_.push_back(std::log(s[i].R_over_lambda));
    collision_exponent_.push_back(std::exp(g[i]) / C[i]);  // d ln C / d ln t
  }
}

void HydroReference::build_hot_spot_collision_exponents() {
  // A hot spot's times count from the deposition, where its gas is at rest with a finite n0 √T0:
  // C(t) = ∫_0^t f dt' with f = n0 √T0 held at its first sample's value before it (first order in
  // that sample's t, a few 1e-3 of the grid's start time), then f a power law of t between samples
  // (exact for power laws; the samples' first interval spans a large ratio of t).
  const auto& s = result_.samples;
  std::vector<double> f(s.size()), C(s.size());
  for (std::size_t i = 0; i < s.size(); ++i) f[i] = s[i].n0 * std::sqrt(s[i].T0);
  C[0] = s[0].t * f[0];
  for (std::size_t i = 1; i < s.size(); ++i) {
    const double ratio = s[i].t / s[i - 1].t, p = std::log(f[i] / f[i - 1]) / std::log(ratio);
    const double growth = std::abs(p + 1) < 1e-12 ? std::log(ratio) : (std::pow(ratio, p + 1) - 1) / (p + 1);
    C[i] = C[i - 1] + s[i - 1].t * f[i - 1] * growth;
  }
  log_R_over_lambda_.clear();
  collision_exponent_.clear();
  for (std::size_t i = 0; i < s.size(); ++i) {
    log_R_over_lambda_.push_back(std::log(s[i].R_over_lambda));
    collision_exponent_.push_back(s[i].t * f[i] / C[i]);  // d ln C / d ln t
  }
}

double HydroReference::min_R_over_lambda() const {
  return std::max(result_.exponents.front().R_over_lambda, std::exp(log_R_over_lambda_.front()));
}

double HydroReference::max_R_over_lambda() const {
  return std::min(result_.exponents.back().R_over_lambda, std::exp(log_R_over_lambda_.back()));
}

double HydroReference::exponent(const std::string& observable, double R_over_lambda) const {
  if (!(R_over_lambda >= min_R_over_lambda() && R_over_lambda <= max_R_over_lambda()))
    throw std::invalid_argument("hydro reference: R/lambda = " + std::to_string(R_over_lambda) +
                                " is outside the solved range [" + std::to_string(min_R_over_lambda()) + ", " +
                                std::to_string(max_R_over_lambda()) + "]");
  const theory::ObservableInfo& info = theory::observable_info(observable);  // unknown: lists the catalogue
  const theory::HydroProxy& proxy = info.hydro;
  double alpha = 0.0;
  // The catalogue's proxies: R_imp ~ H (Eq. (6) [R-imp]), V_imp ~ √T0 (Sec. III), u_imp ~ R_imp/t
  // (Eq. (22)), C_imp from the collision integral (Eq. (10) [C-imp]), and n0, T0, R, H themselves.
  switch (proxy.quantity) {
    case theory::HydroQuantity::none:
      throw std::invalid_argument("observable = " + observable + " has no hydro prediction; allowed: " +
                                  theory::join_names(theory::observable_names([](const theory::ObservableInfo& o) {
                                    return o.hydro.quantity != theory::HydroQuantity::none;
                                  })));
    case theory::HydroQuantity::collisions:
      alpha = collision_exponent(R_over_lambda);
      break;
    case theory::HydroQuantity::H:
      alpha = result_.exponents_at(R_over_lambda).H;
      break;
    case theory::HydroQuantity::n0:
      alpha = result_.exponents_at(R_over_lambda).n0;
      break;
    case theory::HydroQuantity::T0:
      alpha = result_.exponents_at(R_over_lambda).T0;
      break;
    case theory::HydroQuantity::R:
      alpha = result_.exponents_at(R_over_lambda).R;
      break;
  }
  return proxy.scale * alpha + proxy.shift;
}

double HydroReference::collision_exponent(double R_over_lambda) const {
  // d ln C / d ln t interpolated linearly in ln(R/λ) between the samples.
  const double x = std::log(R_over_lambda);
  const auto upper = std::upper_bound(log_R_over_lambda_.begin(), log_R_over_lambda_.end(), x);
  const std::size_t i = std::min<std::size_t>(std::max<std::ptrdiff_t>(upper - log_R_over_lambda_.begin(), 1),
                                              log_R_over_lambda_.size() - 1);
  const double w = (x - log_R_over_lambda_[i - 1]) / (log_R_over_lambda_[i] - log_R_over_lambda_[i - 1]);
  return (1 - w) * collision_exponent_[i - 1] + w * collision_exponent_[i];
}

}  // namespace coldblast::compare
