#include "hydro/euler_check.hpp"

#include <cmath>
#include <stdexcept>

#include "common/validate.hpp"
#include "hydro/navier_stokes.hpp"
#include "hydro/tvns.hpp"
#include "theory/prefactors.hpp"

namespace coldblast::hydro {

namespace {

/// Σ|numerical - exact| Δx and Σ|exact| Δx of ρ/n∞, u/Ṙ, p/(n∞Ṙ²) over x = r/R in [x_min, 1).
void accumulate_profile_errors(const NavierStokesProfile& profile, const TvnsSolution& exact, double n_inf, double R,
                               double shock_speed, double x_min, double error[3], double norm[3]) {
  const std::size_t cells = profile.r.size();
  for (std::size_t i = 0; i < cells; ++i) {
    const double x = profile.r[i] / R;
    if (x < x_min) continue;
    if (x >= 1) break;
    // cell width in x from the neighbouring centres (cells are contiguous)
    const double left = i == 0 ? 0.0 : 0.5 * (profile.r[i - 1] + profile.r[i]);
    const double right = i + 1 == cells ? profile.r[i] : 0.5 * (profile.r[i] + profile.r[i + 1]);
    const double dx = (right - left) / R;
    const TvnsPoint point = exact.at(x);
    const double numerical[3] = {profile.density[i] / n_inf, profile.velocity[i] / shock_speed,
                                 profile.pressure[i] / (n_inf * shock_speed * shock_speed)};
    const double reference[3] = {point.density, point.velocity, point.pressure};
    for (int k = 0; k < 3; ++k) {
      error[k] += std::abs(numerical[k] - reference[k]) * dx;
      norm[k] += std::abs(reference[k]) * dx;
    }
  }
}

}  // namespace

TvnsComparison compare_to_tvns(const NavierStokesResult& result, double x_min) {
  common::require_in_range("x_min", x_min, 0.0, 1.0, common::Bound::closed, common::Bound::open);
  if (result.profiles.empty()) throw std::invalid_argument("compare_to_tvns: the result has no profile");
  const NavierStokesPhysics& physics = result.config.physics;
  const int d = physics.d;
  TvnsConfig tvns_config;
  tvns_config.d = d;
  tvns_config.eos = physics.eos;
  tvns_config.phi = physics.resolved_phi();
  const TvnsSolution exact = solve_tvns(tvns_config);
  const NavierStokesProfile& profile = result.profiles.back();
  TvnsComparison comparison;
  comparison.x_min = x_min;
  comparison.A_exact = exact.A();
  comparison.A_measured = theory::shock_amplitude(d, physics.E, physics.n_inf, profile.t, profile.R);
  comparison.A_relative_error = comparison.A_measured / comparison.A_exact - 1;
  // Eq. (1) [R-shock] with the exact amplitude
  const double R = theory::shock_radius(d, physics.E, physics.n_inf, exact.A(), profile.t);
  const double shock_speed = theory::shock_speed_at(d, R, profile.t);
  double error[3] = {0, 0, 0}, norm[3] = {0, 0, 0};
  accumulate_profile_errors(profile, exact, physics.n_inf, R, shock_speed, x_min, error, norm);
  if (!(norm[0] > 0)) throw std::invalid_argument("compare_to_tvns: no cell with x_min <= r/R < 1");
  comparison.L1_density = error[0] / norm[0];
  comparison.L1_velocity = error[1] / norm[1];
  comparison.L1_pressure = error[2] / norm[2];
  return comparison;
}

NavierStokesResult run_hydro_euler(int d, double until_R_over_lambda, int cells,
                                   const std::optional<NavierStokesPhysics>& physics) {
  NavierStokesConfig config;
  if (physics) {
    config.physics.eos = physics->eos;
    config.physics.phi = physics->phi;
  }
  config.physics.d = d;
  config.physics.heat_conduction = false;
  config.physics.viscosity = false;
  config.numerics.cells = cells;
  config.until_R_over_lambda = until_R_over_lambda;
  return run_navier_stokes(config);
}

}  // namespace coldblast::hydro
