#pragma once
// Closed-form (parametric) TvNS solution of an ideal gas in a uniform cold medium: Kamm & Timmes,
// "On efficient generation of numerically robust Sedov solutions", LA-UR-07-2849 (2007), Eqs. 29-47
// with omega = 0, rewritten so that gamma = 2 (their omega3 case) is not special and gamma -> 7 in
// d = 3 stays well conditioned. Internal to hydro/: use TvnsSolution.
#include <cmath>
#include <limits>
#include <vector>

#include "hydro/tvns.hpp"

namespace coldblast::hydro::detail {

/// Self-similar energy integrals ∫0^1 [G V^2/2] x^(d-1) dx and ∫0^1 [P/(gamma-1)] x^(d-1) dx
/// (G = rho/rho0, V = u/Rdot, P = p/(rho0 Rdot^2), x = r/R) with their absolute error estimates.
struct EnergyIntegrals {
  double kinetic = 0.0, internal = 0.0;
  double error = 0.0;    ///< absolute error estimate of kinetic + internal
  long evaluations = 0;  ///< integrand evaluations
  double total() const { return kinetic + internal; }
};

/// Kamm & Timmes' functions of the similarity variable for the standard and vacuum branches.
/// The parameter p in [0, 1] runs from the centre (standard) or the cavity edge (vacuum), p = 0,
/// to the shock, p = 1; in the standard branch V - V0 = (V2 - V0) p^m, m = 1/(d beta), which makes
/// the centre's integrable singularity of the energy integrand disappear.
class ClosedForm {
 public:
  /// d in {1, 2, 3}, gamma > 1, not the singular case (d = 3, gamma = 7).
  ClosedForm(int d, double gamma);

  /// The parameter as the pair (p, q = 1 - p); whichever is below 1/2 is exact, so that both the centre
  /// (p -> 0) and the shock (q -> 0) are resolved to full relative precision.
  struct Parameter {
    double p, q;
    double ln_p() const {
      if (p <= 0.0) return -std::numeric_limits<double>::infinity();
      return p < 0.5 ? std::log(p) : std::log1p(-q);
    }
  };
  /// Fields at a parameter: x = r/R and G, V, P as in EnergyIntegrals.
  struct State {
    double x, density, velocity, pressure;
  };
  State state(Parameter t) const;

  /// Energy integrals by GSL QAGS in p with relative tolerance `tolerance`.
  EnergyIntegrals energy_integrals(double tolerance) const;

  /// Profile at x = r/R in [0, 1] (GSL Brent root of x(p) = r/R).
  TvnsPoint at(double r_over_R) const;

  /// x of the cavity edge (vacuum branch), 0 otherwise.
  double cavity_radius() const { return cavity_radius_; }

 private:
  struct Logs {
    double ln_x, ln_g, ln_h, ln_x1;
  };
  Logs logs(Parameter t) const;
  double velocity_offset(Parameter t) const;
  /// alpha5 ln(x4/x3) of the standard case, without cancellation near gamma = 7 (d = 3).
  double shock_ratio(double dV, double x4) const;
  double energy_integrand(Parameter t, bool kinetic) const;
  Parameter parameter_at(double r_over_R) const;
  std::vector<double> break_points(bool shock_side) const;

  int d_;
  double gamma_;
  bool vacuum_;
  // Kamm & Timmes' constants a, b, c, d, e (d renamed k3), y = (d+2)/2, and exponents alpha0..alpha5.
  double a_, b_, c_, k3_, e_, y_;
  double alpha0_, alpha1_, alpha3_, alpha4_, alpha5_, beta_, sum45_;
  double V2_, Vend_, span_, m_;  // shock V, V at p = 0, span_ = V2 - Vend, m = 1/(d beta)
  double cavity_radius_ = 0.0;
};

/// Exact energy integrals of the singular case (d = 3, gamma = 7): G = 4x/3, V = x/4, P = x^3/4.
EnergyIntegrals singular_energy_integrals();
/// Exact profile of the singular case.
TvnsPoint singular_point(double r_over_R);

}  // namespace coldblast::hydro::detail
