#pragma once
// The semi-discrete radial blast, the right-hand side CVODE integrates (paper Sec. III, Eqs. (13)-(16)
// in docs/hydro.md's total-energy form): cell totals of mass, radial momentum and total energy on faces
// r = ξ R_ref(t) that grow with the blast, HLLC fluxes (hydro/hllc.hpp) of states reconstructed from
// (ln n, u, ln p), heat flux and viscous stresses (hydro/transport.hpp), and the two starts.
#include <cmath>
#include <vector>

#include "hydro/hllc.hpp"
#include "hydro/navier_stokes_config.hpp"
#include "hydro/transport.hpp"

namespace coldblast::hydro {

/// Geometry, parameters and scratch space of the right-hand side. Times t count from the start's origin
/// (the hot spot's deposition, or the virtual point explosion of R_ref for the self-similar start); the
/// grid scale R_ref runs on t + time_shift, so that it holds the hot spot at the start.
class RadialBlast {
 public:
  /// `config` with its defaults resolved (resolve_defaults); c_κ, c_μ (0: off) and the TvNS A_d of R_ref.
  RadialBlast(const NavierStokesConfig& config, double c_kappa, double c_mu, double A_reference);

  int cells() const { return cells_; }
  double lambda() const { return lambda_; }
  /// Time of the initial state: 0 for the hot spot, t(R_ref = start_R_over_lambda λ) for the self-similar start.
  double start_time() const { return t_start_; }
  /// Temperature of the cold gas entering the grid at time t: floor Ṙ_ref(t)², so that the shock's
  /// Mach number stays 1/√(γ floor) at all times (the gas of the paper is at T = 0).
  double T_inf(double t) const;
  double internal_energy_inf(double t) const { return 0.5 * d_ * n_inf_ * T_inf(t); }
  /// Pressure of the cold gas: n∞ T∞ Z(φ∞) (Z = 1 for the ideal gas, written so that its bits are unchanged).
  double pressure_inf(double t) const;
  /// Local packing fraction φ = φ∞ n/n∞.
  double packing_fraction(double n) const { return phi_inf_ * n / n_inf_; }
  /// Largest φ met by the last failed primitives() (0 if none): > close packing means the flow tried to pack the gas.
  double packing_exceeded() const { return packing_exceeded_; }
  double close_packing() const { return phi_close_packing_; }

  /// Eq. (1) [R-shock] with the reference amplitude: R_ref = (E τ²/(A n∞))^(1/(d+2)) at τ = t + time_shift,
  /// its inverse (the t at which R_ref = R) and the grid's speed Ṙ_ref.
  double reference_radius(double t) const;
  double time_of(double R) const;
  double shock_speed(double t) const;
  /// Outer grid edge L(t) = margin R_ref(t); faces sit at r = ξ L(t).
  double outer_radius(double t) const { return margin_ * reference_radius(t); }
  double ball_volume(double r) const { return omega_ * std::pow(r, d_); }
  double face_area(double r) const { return d_ * omega_ * std::pow(r, d_ - 1); }
  /// Expected totals: E plus the cold gas energy swept in; n∞ times the grid volume.
  double expected_energy(double t) const;
  double expected_mass(double t) const { return n_inf_ * ball_volume(outer_radius(t)); }
  /// Face radii r_j = ξ_j R_ref(t), j = 0..cells, ξ_cells = outer_margin.
  void faces(double t, std::vector<double>& r) const;

  /// Cell totals (mass, momentum, energy per cell) at start_time(): cold gas at rest plus E as heat.
  void initial_state(double* y) const;
  /// d/dt of the cell totals; returns 1 (recoverable) when a trial state is not positive or packs
  /// the gas beyond close packing.
  int rhs(double t, const double* y, double* ydot);

  const std::vector<double>& radii() const { return r_; }
  const std::vector<double>& density() const { return n_; }
  const std::vector<double>& velocity() const { return u_; }
  const std::vector<double>& temperature() const { return T_; }
  const std::vector<double>& pressure() const { return p_; }
  /// Heat flux at cell centres (average of the two face fluxes), valid after rhs().
  double heat_flux(int i) const { return 0.5 * (heat_[i] + heat_[i + 1]); }
  bool frozen_flow() const { return frozen_; }

 private:
  // The right-hand side's steps (inline in radial_blast.cpp, where the hot loop lives).
  /// Sound speed and total energy of a face state: ideal c² = γ p/n, e = p/(γ-1) + n u²/2; hard particles
  /// c² = T (Z + φ Z' + (2/d) Z²) (hydro/equation_of_state.hpp) and internal energy (d/2) n T = (d/2) p/Z.
  bool complete_state(State& s) const;
  void self_similar_state(double* y) const;
  void hotspot_state(double* y) const;
  bool primitives(double t, const double* y);
  double q(double t, int i, int k) const;
  void reconstruct(double t);
  State face_state(double t, int i, double r) const;
  bool hydrodynamic_fluxes(double t);
  void transport_fluxes();
  double hoop_stress(int i, double u_in, double u_out) const;
  void assemble(double* ydot) const;

  int d_;
  double gamma_, E_, n_inf_;
  Eos eos_;
  bool frozen_;
  double phi_inf_, phi_close_packing_, Z_inf_;
  double lambda_, A_ref_, margin_, omega_;
  TransportModel transport_;
  Start start_;
  double hot_radius_ = 0;  ///< initial_width R_ref(t_start) (self-similar) or r0 (hotspot)
  int cells_ = 0;
  double floor_ = 0, time_shift_ = 0, t_start_ = 0;
  double packing_exceeded_ = 0;
  std::vector<double> xi_, r_, centre_, n_, u_, T_, p_, slope_, flux_, heat_, stress_;
};

}  // namespace coldblast::hydro
