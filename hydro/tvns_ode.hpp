#pragma once
// Self-similar Euler equations of the TvNS blast integrated from the shock inward with Boost.Odeint,
// for an ideal gas or hard discs/spheres (p = n T Z(phi), e = (d/2) T). Independent of the closed form:
// it shares only the jump conditions. Internal to hydro/: use TvnsSolution.
#include <array>
#include <vector>

#include "hydro/tvns.hpp"
#include "hydro/tvns_closed_form.hpp"

namespace coldblast::hydro::detail {

/// ODE state: W = V/x, ln G, ln P, and the kinetic and internal energy integrals accumulated so far
/// (vacuum branch: ln x instead of W, which is then the independent variable).
using OdeState = std::array<double, 5>;

/// Physics and numerics of one integration.
struct OdeSettings {
  int d = 2;
  double gamma = 2.0;  ///< ideal gas index (ignored for hard particles)
  Eos eos = Eos::ideal;
  double phi = 0.0;            ///< ambient packing fraction (hard particles)
  double tolerance = 1e-13;    ///< absolute and relative step tolerance
  bool check_stepper = false;  ///< Dormand-Prince 5(4) instead of Bulirsch-Stoer
};

/// Result of one integration: energy integrals, cavity edge and checkpoints for profiles.
struct OdeResult {
  EnergyIntegrals energy;
  double cavity_radius = 0.0;        ///< vacuum branch; NaN when the integration stopped before it (near gamma = 7)
  double shock_compression = 0.0;    ///< rho1/rho0
  std::vector<double> checkpoint_s;  ///< s = -ln(r/R) at accepted steps (standard branch)
  std::vector<OdeState> checkpoint_state;  ///< state there
  double centre_pressure = 0.0;            ///< P at r = 0 (standard branch)
  double end_s = 0.0;                      ///< last s integrated; beyond it the near-centre expansion below is used
  OdeState end_slope{};                    ///< d/ds of the state at end_s
  double centre_density_exponent = 0.0;    ///< k = d/(gamma0 - 1), gamma0 = kappa at G -> 0
  double centre_W = 0.0;                   ///< V/x at the centre, 1/gamma0
  double relaxation_rate = 0.0;            ///< rate r of the corrections exp(-r (s - end_s))
  double tolerance_used = 0.0;             ///< step tolerance actually used (see integrate_self_similar)
};

/// Integrates from r/R = 1 to the centre (standard) or the cavity edge (vacuum, ideal d = 3, gamma > 7).
OdeResult integrate_self_similar(const OdeSettings& settings);

/// Profile at r/R in [0, 1] from the checkpoints of a standard-branch result (short re-integration).
TvnsPoint ode_point(const OdeSettings& settings, const OdeResult& result, double r_over_R);

}  // namespace coldblast::hydro::detail
