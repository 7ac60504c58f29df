#pragma once
// Equations of state for the TvNS blast: ideal gas of index gamma, Henderson's hard discs
// (Mol. Phys. 30, 971 (1975), doi:10.1080/00268977500102511) and Carnahan-Starling hard spheres
// (J. Chem. Phys. 51, 635 (1969), doi:10.1063/1.1672048): p = n T Z(phi), internal energy (d/2) n T,
// and the strong-shock (cold, pressureless upstream) Rankine-Hugoniot compression.
#include <cmath>
#include <limits>
#include <string>

namespace coldblast::hydro {

enum class Eos { ideal, henderson, carnahan_starling };

/// "ideal", "henderson" or "carnahan-starling".
std::string to_string(Eos eos);
/// Inverse of to_string (also accepts "carnahan_starling"); throws std::invalid_argument naming `option`.
Eos eos_from_string(const std::string& text, const std::string& option = "eos");

/// The dimension an EOS is defined for: henderson 2, carnahan_starling 3, ideal 0 (any d).
int eos_dimension(Eos eos);

namespace detail {
/// Throws std::logic_error for an Eos value outside the enum (`where` names the caller).
[[noreturn]] void unknown_eos(const char* where);
/// Throws std::invalid_argument naming phi and its range [0, close packing) for `eos`.
[[noreturn]] void reject_contact_phi(Eos eos, double phi);
}  // namespace detail

/// Close packing: π/(2√3) = 0.9069 (discs, d = 2), π/(3√2) = 0.7405 (spheres, d = 3). Inline, as
/// contact_value: the tracer evaluates it at every candidate collision.
inline double close_packing_fraction(Eos eos) {
  constexpr double pi = 3.14159265358979323846;
  switch (eos) {
    case Eos::ideal:
      return std::numeric_limits<double>::infinity();
    case Eos::henderson:
      return pi / (2.0 * std::sqrt(3.0));
    case Eos::carnahan_starling:
      return pi / (3.0 * std::sqrt(2.0));
  }
  detail::unknown_eos("close_packing_fraction");
}

/// Compressibility factor Z = p/(n T) at packing fraction phi in [0, 1); 1 for the ideal gas.
double compressibility(Eos eos, double phi);
/// dZ/dphi.
double compressibility_derivative(Eos eos, double phi);

/// Largest ambient phi whose strong-shock state stays below close packing:
/// phi_max = phi_cp Z(phi_cp)/(Z(phi_cp) + d) (henderson 0.89286, carnahan_starling 0.72042).
double max_ambient_packing_fraction(Eos eos);

/// Strong-shock compression rho1/rho0 > 1 for a hard-particle gas at ambient phi in (0, phi_max):
/// the root of Z(phi rho1/rho0)(1 - rho0/rho1) = d rho0/rho1 (GSL Brent); (d+1) when phi -> 0.
double strong_shock_compression(Eos eos, double phi);

/// Squared adiabatic sound speed over T for hard particles: c^2/T = Z + phi Z' + (2/d) Z^2.
double sound_speed_squared_over_temperature(Eos eos, double phi);

/// Pair correlation at contact chi(phi) consistent with the EOS through the virial (contact) theorem
/// Z = 1 + 2^(d-1) phi chi: henderson (1 - 7 phi/16)/(1 - phi)^2, carnahan_starling
/// (1 - phi/2)/(1 - phi)^3; chi = 1 at phi = 0. The ideal gas (no excluded volume) returns 1, the
/// Boltzmann limit. Throws std::invalid_argument naming phi outside [0, close_packing_fraction(eos)).
/// Inline: the Navier–Stokes solver calls it per face and the tracer per candidate collision.
inline double contact_value(Eos eos, double phi) {
  if (eos == Eos::ideal) return 1.0;
  if (!(phi >= 0.0 && phi < close_packing_fraction(eos))) detail::reject_contact_phi(eos, phi);
  const double one_minus = 1.0 - phi;
  // (Z - 1)/(2^(d-1) phi) of the two closed forms of compressibility(), simplified so that phi = 0
  // is regular: Henderson Z - 1 = (2 phi - 7 phi^2/8)/(1 - phi)^2; Carnahan-Starling
  // Z - 1 = (4 phi - 2 phi^2)/(1 - phi)^3.
  if (eos == Eos::henderson) return (1.0 - 7.0 * phi / 16.0) / (one_minus * one_minus);
  return (1.0 - 0.5 * phi) / (one_minus * one_minus * one_minus);
}

}  // namespace coldblast::hydro
