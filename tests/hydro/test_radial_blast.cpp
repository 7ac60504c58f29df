// Tests of hydro/radial_blast (the right-hand side): the conduction operator against the
// Barenblatt–Pattle heat wave at second order.
#include <catch2/catch.hpp>
#include <cmath>

#include "hydro/navier_stokes.hpp"
#include "tests/hydro/blast_configs.hpp"
#include "theory/prefactors.hpp"

using namespace coldblast;
using hydro::NavierStokesConfig;
using hydro::run_navier_stokes;
using test::core_config;

namespace {

/// Barenblatt–Pattle / Zel'dovich–Raizer point-source heat wave for ∂t T = a ∇·(T^(1/2) ∇T) in d
/// dimensions with ∫ T dV = M: with τ = (2a/3)(t - t_origin) it is u_τ = Δ(u^m), m = 3/2, whose
/// self-similar solution is T = τ^(-α) (C - k r² τ^(-2β))₊², α = 2d/(d+4), β = 2/(d+4),
/// k = 1/(3(d+4)), C = (M k^(d/2)/(S_d I_d))^(2/(d+4)), I_d = ∫0^1 (1-x²)² x^(d-1) dx = 8/(d(d+2)(d+4)).
/// (Zel'dovich & Raizer, "Physics of Shock Waves and High-Temperature Hydrodynamic Phenomena",
/// Ch. X §4; Barenblatt, Prikl. Mat. Mekh. 16, 67 (1952); Pattle, Q. J. Mech. Appl. Math. 12, 407 (1959).)
struct HeatWave {
  int d;
  double M, C, k, alpha, beta;
  HeatWave(int d_, double M_) : d(d_), M(M_) {
    k = 1.0 / (3.0 * (d + 4));
    alpha = 2.0 * d / (d + 4);
    beta = 2.0 / (d + 4);
    const double I = 8.0 / (d * (d + 2.0) * (d + 4.0));
    C = std::pow(M * std::pow(k, 0.5 * d) / (theory::unit_sphere_area(d) * I), 2.0 / (d + 4));
  }
  double front(double tau) const { return std::sqrt(C / k) * std::pow(tau, beta); }
  double tau_at_front(double r_f) const { return std::pow(r_f / std::sqrt(C / k), 1.0 / beta); }
  double temperature(double r, double tau) const {
    const double x = C - k * r * r * std::pow(tau, -2 * beta);
    return x > 0 ? std::pow(tau, -alpha) * x * x : 0.0;
  }
};

struct HeatWaveError {
  double front_error, profile_L1;
};

/// Frozen-flow run (pure conduction, κ = c_κ n∞ λ √T) started from the solver's own initial hot region,
/// whose (1 - r²/w²)² shape is the heat wave's at the time its front is at w; compared at R_ref/λ = until.
HeatWaveError heat_wave_error(int d, int cells, double until) {
  NavierStokesConfig config = core_config(d, until, cells);
  config.physics.frozen_flow = true;
  config.numerics.shock_band_fraction = 0.0;  // no shock
  config.numerics.core_resolution = 0.05;
  config.numerics.start_R_over_lambda = until / 3;
  config.numerics.temperature_floor = 1e-9;
  config.numerics.relative_tolerance = 1e-9;
  const auto result = run_navier_stokes(config);
  const auto& physics = result.config.physics;
  const double lambda = result.lambda, start = config.numerics.start_R_over_lambda;
  const double t0 = theory::shock_time(d, physics.E, physics.n_inf, result.A_reference, start * lambda);
  const double a = 2.0 * result.kappa_prefactor * lambda / d;  // (d/2) n ∂t T = ∇·(c_κ n λ √T ∇T)
  const HeatWave wave(d, physics.E / (0.5 * d * physics.n_inf));
  const double w = config.numerics.initial_width * start * lambda;
  const auto& profile = result.profiles.back();
  const double tau = wave.tau_at_front(w) + 2.0 * a / 3.0 * (profile.t - t0);
  // faces from the centres (each centre is the midpoint of its faces), r_0 = 0
  double r_in = 0, error = 0, norm = 0, moment = 0, total = 0;
  for (std::size_t i = 0; i < profile.r.size(); ++i) {
    const double r_out = 2 * profile.r[i] - r_in;
    const double volume = std::pow(r_out, d) - std::pow(r_in, d);  // ∝ cell volume
    const double T = profile.temperature[i], exact = wave.temperature(profile.r[i], tau);
    error += std::abs(T - exact) * volume;
    norm += exact * volume;
    moment += T * profile.r[i] * profile.r[i] * volume;
    total += T * volume;
    r_in = r_out;
  }
  // <r²> = r_f² d/(d+6) for the (1 - r²/r_f²)² profile
  const double front = std::sqrt((d + 6.0) / d * moment / total);
  return {front / wave.front(tau) - 1, error / norm};
}

}  // namespace

TEST_CASE("conduction alone reproduces the Barenblatt-Pattle heat wave, at second order", "[slow]") {
  // R_ref/λ from 10 to 30: the front grows from 0.2 R_ref to about half the grid (τ grows 240-1100x).
  // docs/hydro.md: errors at 64, 128, 256, 512 cells fall at order 2.0-2.1 in d = 1, 2, 3.
  for (int d : {1, 2, 3}) {
    CAPTURE(d);
    const HeatWaveError coarse = heat_wave_error(d, 64, 30);
    const HeatWaveError fine = heat_wave_error(d, 128, 30);
    INFO("front " << coarse.front_error << " -> " << fine.front_error << ", L1 " << coarse.profile_L1 << " -> "
                  << fine.profile_L1);
    CHECK(std::abs(fine.front_error) < 1e-3);
    CHECK(fine.profile_L1 < 2.5e-3);
    CHECK(std::log2(coarse.front_error / fine.front_error) > 1.8);
    CHECK(std::log2(coarse.profile_L1 / fine.profile_L1) > 1.8);
  }
}
