#pragma once
// Prefactor formulas of the paper (units m = 1, k_B = 1, a = particle radius): Omega_d and phi
// (Eq. 2), lambda (Eq. 5), R(t) given A_d (Eq. 1), H (Eq. 4), the impurity and core estimates of
// Eqs. (6)-(12), (21) without their unknown O(1) factors, and the Gaussian P(r,t) of Eq. (35).
#include <string>

namespace coldblast::theory {

/// Eq. (2) [phi:def]: volume of the unit ball in d >= 0 dimensions, π^(d/2)/Γ(d/2+1) (Ω_0 = 1).
double unit_ball_volume(int d);
/// Surface area of the unit sphere in R^d, d Ω_d (d = 1: 2, d = 2: 2π, d = 3: 4π).
double unit_sphere_area(int d);

/// Eq. (5) [eq:mfp]: λ = 1/(n Ω_{d-1} a^{d-1}); n > 0 (number density), a > 0 (radius).
double mean_free_path(int d, double n, double a);
/// Eq. (2) [phi:def]: φ = n Ω_d a^d.
double packing_fraction(int d, double n, double a);
/// Inverse of Eq. (2): n = φ/(Ω_d a^d).
double number_density(int d, double phi, double a);

/// Eq. (3) (unlabelled, after [phi:def]): the ideal-gas TvNS amplitudes for γ = 1 + 2/d, computed by
/// hydro::solve_tvns (A_2 ± 2.5e-14 matches the paper's 0.351 935 906...; A_3 ± 3.7e-14 does not match
/// the paper's 0.0724, see docs/verification.md). hydro's tests check these constants against the solver.
inline constexpr double ideal_gas_A_2 = 0.351935906848599;
inline constexpr double ideal_gas_A_3 = 0.493590149582568;
/// ideal_gas_A_2 or ideal_gas_A_3; throws std::invalid_argument for d outside [2, 3].
double ideal_gas_amplitude(int d);

/// An amplitude A_d of Eq. (1) chosen for a blast and where it came from (written to run outputs).
/// The project's one choice for MD boxes is hydro::md_amplitude (docs/ARCHITECTURE.md, "The A_d policy").
struct AmplitudeChoice {
  double A_d = 0.0;
  std::string source;
};

/// Physical parameters of a blast: dimension, ambient density n (1/length^d), radius a
/// (length), energy E (m = 1 units) and the TvNS amplitude A_d of Eq. (1).
struct BlastParameters {
  int d = 2;
  double n = 0.15;
  double a = 0.5;
  double E = 1.0;
  double A_d = ideal_gas_A_2;
  /// Throws std::invalid_argument naming the first parameter out of range.
  void validate() const;
};

/// Eq. (1) [R-shock]: R(t) = (E t²/(A_d n))^(1/(d+2)); E, n, A_d, t > 0 (std::invalid_argument
/// otherwise). The one definition of Eq. (1): every R(t), t(R), Ṙ and A_d-from-R calls these.
double shock_radius(int d, double E, double n, double A_d, double t);
/// Inverse of Eq. (1): the time t = (A_d n R^(d+2)/E)^(1/2) at which the shock reaches radius R > 0.
double shock_time(int d, double E, double n, double A_d, double R);
/// Eq. (1) solved for the amplitude: A_d = E t²/(n R^(d+2)) of a shock at radius R at time t.
double shock_amplitude(int d, double E, double n, double t, double R);
/// Ṙ = 2R/((d+2)t) of a shock at radius R at time t > 0 obeying Eq. (1)'s power law.
double shock_speed_at(int d, double R, double t);

/// Eq. (1) [R-shock] for a blast's parameters; t > 0.
double shock_radius(const BlastParameters& p, double t);
/// Inverse of Eq. (1): the time at which the shock reaches radius R > 0.
double shock_time(const BlastParameters& p, double R);
/// dR/dt = 2R/((d+2)t), from Eq. (1).
double shock_speed(const BlastParameters& p, double t);
/// Eq. (4) [size-dim]: H = λ (R/λ)^(h_d).
double core_radius(int d, double lambda, double R);

/// The paper's estimates at time t, with every omitted O(1) prefactor set to 1.
struct ScalingEstimates {
  double t, R, R_over_lambda, lambda, phi, H, R_imp, V_imp, u_imp, C_imp, n0, T0, D0;
};
/// Eqs. (1), (4), (6), (8), (9), (10), (11), (12), (21) evaluated at t > 0.
ScalingEstimates scaling_estimates(const BlastParameters& p, double t);

/// Eq. (35) [Prt-d]: P(r) = (2π R_imp²)^(-d/2) exp(-r²/(2 R_imp²)); r >= 0, R_imp > 0.
double gaussian_position_density(int d, double r, double R_imp);
/// Radial density of Eq. (35), S_d r^(d-1) P(r); in 2D this is Eq. (39) [eq:pr].
double radial_position_density(int d, double r, double R_imp);
/// Eqs. (31) [eq:2d-scal], (34) [3d-scal] for any d: 𝒫(η) = (c/π)^(d/2) exp(-c η²),
/// c the exact Gaussian coefficient of convection_diffusion_exponents(d).
double scaled_position_density(int d, double eta);

}  // namespace coldblast::theory
