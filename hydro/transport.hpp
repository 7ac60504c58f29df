#pragma once
// Transport of the Navier–Stokes blast: heat conduction κ = c_κ n∞ λ √T (paper Eq. (15) [kappa-HS],
// with the Chapman–Enskog prefactor c_κ the paper drops) and shear viscosity μ = c_μ n∞ λ √T, dilute or
// times Enskog's dense-gas factors at the local φ (hydro/enskog.hpp). Sources of c_κ, c_μ: Chapman &
// Cowling (spheres), Gass, J. Chem. Phys. 54, 1898 (1971) (discs); docs/hydro.md.
#include <cmath>
#include <string>

#include "hydro/enskog.hpp"
#include "hydro/equation_of_state.hpp"

namespace coldblast::hydro {

/// Transport coefficients: dilute Chapman–Enskog (κ = c_κ n∞ λ √T, μ = c_μ n∞ λ √T, no bulk viscosity),
/// or Enskog's dense gas (the same times the factors of hydro/enskog.hpp at the local φ, with bulk viscosity).
enum class Transport { dilute, enskog };

/// "dilute" or "enskog".
std::string to_string(Transport transport);
/// Inverse of to_string; throws std::invalid_argument naming `option` and the allowed values.
Transport transport_from_string(const std::string& text, const std::string& option = "transport");

/// Default c_κ: dilute Chapman–Enskog (first Sonine order) conductivity of hard discs (2D: 2/√π)
/// and spheres (3D: 75√π/256) in units n∞ λ √T; d = 1 has no such limit and uses 1 (Eq. (15) as written).
double chapman_enskog_kappa_prefactor(int d);
/// Default c_μ: Chapman–Enskog shear viscosity (2D: 1/(2√π), 3D: 5√π/64); d = 1: c_κ/4 (no effect, see docs).
double chapman_enskog_viscosity_prefactor(int d);

/// The local transport of one blast: heat flux and viscous stresses from the cell values (units:
/// m = k_B = 1; kappa = c_κ n∞ λ and mu = c_μ n∞ λ, 0 when switched off).
struct TransportModel {
  int d = 2;
  double kappa = 0, mu = 0;
  bool enskog = false;
  Eos eos = Eos::ideal;
  double phi_inf = 0, n_inf = 1;  ///< φ = phi_inf n/n_inf

  // Inline: called per face in the right-hand side's loop (hydro/radial_blast.cpp).
  /// Enskog's factors at density n with the EOS's contact value; {1, 0, 1} for dilute transport.
  EnskogFactors factors_at(double n) const {
    if (!enskog) return EnskogFactors{};
    const double phi = phi_inf * n / n_inf;
    return enskog_factors(d, phi, contact_value(eos, phi));
  }
  /// Heat flux q = -κ(T) ∂T/∂r through a face at temperature T_face, ∂T/∂r ≈ dT/dr (Eq. (15)).
  double heat_flux(double T_face, double dT, double dr, const EnskogFactors& f) const {
    double q = -kappa * std::sqrt(T_face) * dT / dr;
    if (enskog) q *= f.conductivity;
    return q;
  }
  /// Viscous normal stress μ(T) (2 s - (2/d) ∇·u) + ζ(T) ∇·u, s = ∂u/∂r (τ_rr) or u/r (τ_θθ), ζ = 0 when dilute.
  double normal_stress(double T, double strain, double divergence, const EnskogFactors& f) const {
    if (!enskog) return mu * std::sqrt(T) * (2 * strain - 2.0 / d * divergence);
    return mu * std::sqrt(T) * (f.shear * (2 * strain - 2.0 / d * divergence) + f.bulk * divergence);
  }
};

}  // namespace coldblast::hydro
