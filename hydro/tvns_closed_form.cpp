// Kamm & Timmes' closed-form TvNS solution (LA-UR-07-2849, Eqs. 29-47, 80-85, omega = 0) evaluated
// in logarithms, parametrised so that every x_i is computed without cancellation, with the energy
// integrals by GSL QAGS and the inverse x(p) = r/R by GSL Brent.
#include "hydro/tvns_closed_form.hpp"

#include <gsl/gsl_errno.h>
#include <gsl/gsl_integration.h>
#include <gsl/gsl_roots.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "common/validate.hpp"
#include "hydro/gsl_status.hpp"

namespace coldblast::hydro::detail {

namespace {

constexpr double infinity = std::numeric_limits<double>::infinity();

void check_gsl(int status, const std::string& context) {
  if (status != GSL_SUCCESS)
    throw std::runtime_error("GSL error in TvNS closed form, " + context + ": " + gsl_strerror(status));
}

/// log1p(epsilon A)/epsilon, continuous through epsilon = 0 (where it equals A).
double log1p_over(double epsilon, double A) {
  const double z = epsilon * A;
  if (std::abs(z) < 1e-8) return A * (1.0 - z / 2.0 + z * z / 3.0);
  return A * std::log1p(z) / z;
}

}  // namespace

ClosedForm::ClosedForm(int d, double gamma) : d_(d), gamma_(gamma) {
  disable_gsl_abort();
  if (tvns_case(d, gamma) == TvnsCase::singular)
    throw std::logic_error("ClosedForm: the singular case has its own exact solution");
  vacuum_ = tvns_case(d, gamma) == TvnsCase::vacuum;
  const double j = d, g = gamma, j2 = j + 2.0;
  // Kamm & Timmes Eqs. 33-37 (omega = 0).
  a_ = j2 * (g + 1.0) / 4.0;
  b_ = (g + 1.0) / (g - 1.0);
  c_ = j2 * g / 2.0;
  e_ = (2.0 + j * (g - 1.0)) / 2.0;
  y_ = j2 / 2.0;
  // k3 = 1/(1 - e V2) in exact form. Its denominator g (2 - j) + 3j - 2 vanishes at d = 3, gamma = 7;
  // written as (3j - 2) - g (j - 2) it is 7 - g there, exact in floating point (Sterbenz), so that
  // k3 keeps full relative precision at gamma = 7 - 1e-9 (the other order lost 7 digits).
  k3_ = j2 * (g + 1.0) / ((3.0 * j - 2.0) - g * (j - 2.0));
  // Eqs. 42-47: the exponents; alpha2 = -beta.
  alpha0_ = 2.0 / j2;
  beta_ = (g - 1.0) / (2.0 * (g - 1.0) + j);
  alpha1_ = j2 * g / (2.0 + j * (g - 1.0)) * (2.0 * j * (2.0 - g) / (g * j2 * j2) + beta_);
  alpha3_ = j / (2.0 * (g - 1.0) + j);
  // alpha4 and alpha5 are infinite at gamma = 2 (Kamm & Timmes' omega3 case) but their sum is not:
  // (j+2) alpha1 - 2 vanishes at gamma = 2 and sum45 below is that ratio simplified.
  const double q = 2.0 + j * (g - 1.0), r = 2.0 * (g - 1.0) + j;
  sum45_ = 2.0 * j / q - ((j * j + 4.0) * g - (j - 2.0) * (j - 2.0)) / (q * r);
  alpha4_ = vacuum_ ? j2 * alpha1_ / (2.0 - g) : 0.0;
  alpha5_ = vacuum_ ? -2.0 / (2.0 - g) : 0.0;
  V2_ = 4.0 / (j2 * (g + 1.0));
  Vend_ = vacuum_ ? alpha0_ : 2.0 / (j2 * g);  // cavity edge or centre
  span_ = V2_ - Vend_;
  m_ = 1.0 / (j * beta_);
  if (vacuum_) cavity_radius_ = std::exp(logs({0.0, 1.0}).ln_x);
}

double ClosedForm::shock_ratio(double dV, double x4) const {  // x4 = 1 - b y dV
  const double j = d_, epsilon = 2.0 - gamma_;
  if (std::abs(epsilon) < 0.5) {  // near gamma = 2: 1 + eps A stays near 1; log1p_over is exact at eps = 0
    const double V = V2_ + dV;
    return 2.0 * (log1p_over(epsilon, j * b_ * V / (2.0 * x4)) - log1p_over(epsilon, j * b_ * V2_ / 2.0));
  }
  // Elsewhere 1 + eps A can approach 0 (at d = 3, gamma -> 7: 1 + eps A2 = b/k3 -> 0), where
  // log1p(eps A) - log1p(eps A2) cancels. Exactly: x4 (1 + eps A) = N2 + dV b (eps j/2 - y) with
  // N2 = 1 + eps A2 = b/k3, so L(A) - L(A2) = [log1p(dV b (eps j/2 - y)/N2) - ln x4]/eps, every term
  // to full relative precision.
  const double N2 = b_ / k3_;
  return 2.0 * (std::log1p(dV * b_ * (epsilon * j / 2.0 - y_) / N2) - std::log1p(-b_ * y_ * dV)) / epsilon;
}

double ClosedForm::velocity_offset(Parameter t) const {
  if (vacuum_) return -span_ * t.q;
  return span_ * std::expm1(m_ * t.ln_p());
}

ClosedForm::Logs ClosedForm::logs(Parameter t) const {
  const double j = d_;
  Logs out{};
  const double dV = velocity_offset(t);  // V - V2, accurate near the shock since q is exact there
  if (!vacuum_) {
    const double ln_p = t.ln_p();
    const double ln_x2 = std::log(b_ * c_ * span_) + m_ * ln_p;  // x2 = b c (V - V0), accurate near the centre
    const double x1 = 1.0 + a_ * dV, x3 = 1.0 - k3_ * e_ * dV, x4 = 1.0 - b_ * y_ * dV;
    const double ln_x1 = std::log(x1), ln_x3 = std::log(x3);
    // x3^alpha4 x4^alpha5 = x3^(alpha4+alpha5) (x4/x3)^alpha5, and alpha5 ln(x4/x3) =
    // 2 [L(A) - L(A2)] with L = log1p(eps A)/eps, eps = 2 - gamma, A = j b V/(2 x4).
    const double ratio = shock_ratio(dV, x4);
    out.ln_x = -alpha0_ * ln_x1 + beta_ * ln_x2 - alpha1_ * ln_x3;
    out.ln_g = alpha3_ * ln_x2 + sum45_ * ln_x3 + ratio;
    out.ln_h = j * alpha0_ * ln_x1 + std::log(x4) - 2.0 * alpha1_ * ln_x3 + sum45_ * ln_x3 + ratio;
    out.ln_x1 = ln_x1;
  } else {
    const double x1 = 1.0 + a_ * dV, x2 = 1.0 + b_ * c_ * dV, x3 = 1.0 - k3_ * e_ * dV;
    const double ln_x4 = std::log(-b_ * y_ * span_) + t.ln_p();
    const double ln_x1 = std::log(x1), ln_x2 = std::log(x2), ln_x3 = std::log(x3);
    out.ln_x = -alpha0_ * ln_x1 + beta_ * ln_x2 - alpha1_ * ln_x3;
    out.ln_g = alpha3_ * ln_x2 + alpha4_ * ln_x3 + alpha5_ * ln_x4;
    out.ln_h = j * alpha0_ * ln_x1 + (alpha4_ - 2.0 * alpha1_) * ln_x3 + (1.0 + alpha5_) * ln_x4;
    out.ln_x1 = ln_x1;
  }
  return out;
}

ClosedForm::State ClosedForm::state(Parameter t) const {
  const Logs l = logs(t);
  const double x = std::exp(l.ln_x);
  // rho2 = b rho0, u2 = 2 Rdot/(gamma+1), p2 = 2 rho0 Rdot^2/(gamma+1) (Kamm & Timmes Eqs. 13-18);
  // u = u2 f with f = x1 x.
  return {x, b_ * std::exp(l.ln_g), 2.0 / (gamma_ + 1.0) * std::exp(l.ln_x1 + l.ln_x),
          2.0 / (gamma_ + 1.0) * std::exp(l.ln_h)};
}

double ClosedForm::energy_integrand(Parameter t, bool kinetic) const {
  const double j = d_;
  const Logs l = logs(t);
  const double dV = velocity_offset(t);
  // x^(d-1) dx/dp, without the 0 * inf of the centre: x^d dln x/dp.
  double jacobian = 0.0;
  if (!vacuum_) {
    const double p_m = std::exp(m_ * t.ln_p());
    const double x1 = 1.0 + a_ * dV, x3 = 1.0 - k3_ * e_ * dV;
    // x^d = p exp(j(-alpha0 ln x1 - alpha1 ln x3) + j beta ln(b c span)) since j beta m = 1.
    const double x_d_over_p =
        std::exp(j * (-alpha0_ * std::log(x1) - alpha1_ * std::log(x3)) + j * beta_ * std::log(b_ * c_ * span_));
    // dln x/dV dV/dp = (-alpha0 a/x1 + alpha1 k3 e/x3) m span p^(m-1) + beta m/p.
    jacobian = x_d_over_p * (p_m * m_ * span_ * (-alpha0_ * a_ / x1 + alpha1_ * k3_ * e_ / x3) + beta_ * m_);
  } else {
    const double x1 = 1.0 + a_ * dV, x2 = 1.0 + b_ * c_ * dV, x3 = 1.0 - k3_ * e_ * dV;
    const double dln_x_dV = -alpha0_ * a_ / x1 + beta_ * b_ * c_ / x2 + alpha1_ * k3_ * e_ / x3;
    jacobian = std::exp(j * l.ln_x) * dln_x_dV * span_;
  }
  const double g = gamma_;
  if (kinetic)  // G V^2/2 = 2 b g f^2/(gamma+1)^2
    return 2.0 * b_ / ((g + 1.0) * (g + 1.0)) * std::exp(l.ln_g + 2.0 * (l.ln_x1 + l.ln_x)) * jacobian;
  return 2.0 / ((g + 1.0) * (g - 1.0)) * std::exp(l.ln_h) * jacobian;  // P/(gamma-1)
}

EnergyIntegrals ClosedForm::energy_integrals(double tolerance) const {
  constexpr std::size_t workspace_size = 2000;
  std::unique_ptr<gsl_integration_workspace, decltype(&gsl_integration_workspace_free)> workspace(
      gsl_integration_workspace_alloc(workspace_size), &gsl_integration_workspace_free);
  if (!workspace) throw std::runtime_error("TvNS closed form: cannot allocate the GSL workspace");
  EnergyIntegrals out;
  // GSL's QAG family refuses epsrel below 50 DBL_EPSILON (= 1.1e-14).
  const double relative = std::max(tolerance, 51.0 * std::numeric_limits<double>::epsilon());
  for (const bool kinetic : {true, false}) {
    // [0, 1/2] in p (centre side) and [0, 1/2] in q = 1 - p (shock side), so that each half is sampled
    // where floating point is dense.
    for (const bool shock_side : {false, true}) {
      struct Parameters {
        const ClosedForm* self;
        bool kinetic, shock_side;
        long* evaluations;
      } parameters{this, kinetic, shock_side, &out.evaluations};
      gsl_function F;
      F.function = [](double u, void* raw) {
        auto* params = static_cast<Parameters*>(raw);
        ++*params->evaluations;
        const Parameter t = params->shock_side ? Parameter{1.0 - u, u} : Parameter{u, 1.0 - u};
        return params->self->energy_integrand(t, params->kinetic);
      };
      F.params = &parameters;
      double result = 0.0, error = 0.0;
      std::vector<double> points = break_points(shock_side);
      const int status = gsl_integration_qagp(&F, points.data(), points.size(), 0.0, relative, workspace_size,
                                              workspace.get(), &result, &error);
      // GSL_EROUND (round-off stops the bisection short of the request, which happens within ~1e-5 of
      // d = 3, gamma = 7) is accepted when the error estimate is below 1e-10 relative: that estimate is
      // reported in EnergyIntegrals::error and hence in A_error.
      if (!(status == GSL_EROUND && error <= 1e-10 * std::abs(result)))
        check_gsl(status, std::string(kinetic ? "kinetic" : "internal") + " energy integral (QAGP, d = " +
                              std::to_string(d_) + ", gamma = " + common::format_number(gamma_) + ")");
      if (!std::isfinite(result) || !(result > 0.0))
        throw std::runtime_error("TvNS closed form: energy integral is not finite and positive for gamma = " +
                                 common::format_number(gamma_));
      (kinetic ? out.kinetic : out.internal) += result;
      out.error += error;
    }
  }
  return out;
}

std::vector<double> ClosedForm::break_points(bool shock_side) const {
  // Near d = 3, gamma = 7 the factor x3 = 1 + K (V2 - V)/(V2 - Vend) spans many decades (K = k3 e span
  // diverges) and the profile lives where x3 = O(1), i.e. q = 1 - p within ~1/K of the shock: one break
  // point per decade of x3 lets QAGP bisect there directly.
  std::vector<double> points{0.0};
  const double K = k3_ * e_ * span_;
  if (shock_side) {
    std::vector<double> reversed;
    for (double fraction = 0.1; K * fraction > 1.0 && fraction > 1e-15; fraction *= 0.1) {
      const double q = vacuum_ ? fraction : -std::expm1(std::log1p(-fraction) / m_);
      if (q < 0.5) reversed.push_back(q);
    }
    points.insert(points.end(), reversed.rbegin(), reversed.rend());
  }
  points.push_back(0.5);
  return points;
}

ClosedForm::Parameter ClosedForm::parameter_at(double r_over_R) const {
  if (r_over_R >= 1.0) return {1.0, 0.0};
  const double target = std::log(r_over_R);
  // x increases with p; solve in q near the shock and in p near the centre or cavity.
  const bool shock_side = logs({0.5, 0.5}).ln_x <= target;
  struct Parameters {
    const ClosedForm* self;
    double target;
    bool shock_side;
  } parameters{this, target, shock_side};
  gsl_function F;
  F.function = [](double u, void* raw) {
    const auto* params = static_cast<const Parameters*>(raw);
    const Parameter t = params->shock_side ? Parameter{1.0 - u, u} : Parameter{u, 1.0 - u};
    return params->self->logs(t).ln_x - params->target;
  };
  F.params = &parameters;
  double lower = 0.0, upper = 0.5;
  if (!shock_side && !vacuum_) {  // x ∝ p^(1/d) near the centre: bracket away from p = 0
    upper = 0.5;
    lower = 0.5;
    while (logs({lower, 1.0 - lower}).ln_x > target) {
      upper = lower;
      lower *= 1e-4;
      if (lower < 1e-300) return {0.0, 1.0};
    }
  }
  std::unique_ptr<gsl_root_fsolver, decltype(&gsl_root_fsolver_free)> solver(
      gsl_root_fsolver_alloc(gsl_root_fsolver_brent), &gsl_root_fsolver_free);
  if (!solver) throw std::runtime_error("TvNS closed form: cannot allocate the GSL root solver");
  check_gsl(gsl_root_fsolver_set(solver.get(), &F, lower, upper),
            "bracketing r/R = " + common::format_number(r_over_R));
  for (int iteration = 0; iteration < 400; ++iteration) {
    check_gsl(gsl_root_fsolver_iterate(solver.get()), "Brent iteration for r/R = " + common::format_number(r_over_R));
    lower = gsl_root_fsolver_x_lower(solver.get());
    upper = gsl_root_fsolver_x_upper(solver.get());
    if (gsl_root_test_interval(lower, upper, 1e-300, 4.0 * std::numeric_limits<double>::epsilon()) == GSL_SUCCESS) {
      const double u = gsl_root_fsolver_root(solver.get());
      return shock_side ? Parameter{1.0 - u, u} : Parameter{u, 1.0 - u};
    }
  }
  throw std::runtime_error("TvNS closed form: Brent iteration did not converge for r/R = " +
                           common::format_number(r_over_R));
}

TvnsPoint ClosedForm::at(double r_over_R) const {
  if (vacuum_ && r_over_R <= cavity_radius_) return {r_over_R, 0.0, 0.0, 0.0, 0.0};
  const Parameter t = parameter_at(r_over_R);
  const State s = state(t);
  const double temperature = s.density > 0.0 ? s.pressure / s.density : infinity;
  return {r_over_R, s.density, s.velocity, s.pressure, vacuum_ && t.p == 0.0 ? 0.0 : temperature};
}

EnergyIntegrals singular_energy_integrals() {
  // ∫0^1 (4x/3)(x/4)^2/2 x^2 dx = 1/144 and ∫0^1 (x^3/4)/6 x^2 dx = 1/144 (Kamm & Timmes Eq. 80-85).
  EnergyIntegrals out;
  out.kinetic = 1.0 / 144.0;
  out.internal = 1.0 / 144.0;
  out.error = 2.0 * std::numeric_limits<double>::epsilon() / 72.0;
  return out;
}

TvnsPoint singular_point(double r_over_R) {
  const double x = r_over_R;
  return {x, 4.0 * x / 3.0, x / 4.0, x * x * x / 4.0, 3.0 * x * x / 16.0};
}

}  // namespace coldblast::hydro::detail
