#pragma once
// The Navier–Stokes prediction of the MD's running exponents at the MD's own R/λ (issue 5,
// `--against hydro`): n0 and T0 directly, R_imp from H, V_imp from √T0, u_imp from H/t and C_imp
// from ∫ n0 √T0 dt (the paper's Sec. III arguments: R_imp ~ H, V_imp ~ √T0, u_imp ~ R_imp/t,
// C_imp = t/τ with τ = 1/(n0 a^{d-1} V_imp)). No parameter is fitted: κ is the Chapman–Enskog one.
#include <string>
#include <vector>

#include "hydro/navier_stokes.hpp"

namespace coldblast::compare {

/// R/λ at which the collision integral ∫ n0 √T0 dt is anchored to its asymptotic power law: the
/// tracer's first frame (kinetic/), independent of the NS sample plan.
constexpr double collision_anchor_R_over_lambda = 2.5;

class HydroReference {
 public:
  /// Wraps an existing Navier–Stokes result (its samples must span the R/λ asked for).
  explicit HydroReference(hydro::NavierStokesResult result);

  /// Time exponent of `observable` at R/λ from its catalogue hydro proxy (theory::HydroProxy: R_imp,
  /// V_imp, C_imp, u_imp, u_flow, n0, T0, R, H); throws std::invalid_argument outside the solved range,
  /// for an unknown observable or one without a proxy, naming the observables allowed.
  double exponent(const std::string& observable, double R_over_lambda) const;
  /// Smallest and largest R/λ at which exponents are available.
  double min_R_over_lambda() const;
  double max_R_over_lambda() const;
  const hydro::NavierStokesResult& result() const { return result_; }

 private:
  void build_collision_exponents();
  /// The same for a hot-spot start: the integral from the deposition (t = 0).
  void build_hot_spot_collision_exponents();
  /// d ln C / d ln t at R/λ, C the collision integral (HydroQuantity::collisions).
  double collision_exponent(double R_over_lambda) const;
  hydro::NavierStokesResult result_;
  std::vector<double> log_R_over_lambda_, collision_exponent_;  // d ln C / d ln t at the samples
};

}  // namespace coldblast::compare
