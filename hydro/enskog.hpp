#pragma once
// Enskog transport of elastic hard particles (discs, spheres, any d) at first Sonine order: the
// shear viscosity η, bulk viscosity ζ and thermal conductivity κ of the dense gas as multiples of the
// dilute Chapman–Enskog values η0, κ0 at the same temperature (hydro/navier_stokes.hpp's c_μ, c_κ),
// with the pair correlation at contact χ taken from the equation of state (hydro/equation_of_state.hpp).
// Sources: discs, Gass, J. Chem. Phys. 54, 1898 (1971); spheres, Chapman & Cowling, "The
// Mathematical Theory of Non-uniform Gases", 3rd ed. (1970), Ch. 16 (Enskog's dense-gas theory);
// any d, the elastic limit α = 1 of Garzó & Dufty, Phys. Rev. E 59, 5895 (1999), Sec. IV.
#include "hydro/equation_of_state.hpp"

namespace coldblast::hydro {

/// Dense-gas transport over the dilute coefficients: η/η0, ζ/η0 (ζ: bulk viscosity) and κ/κ0.
struct EnskogFactors {
  double shear = 1, bulk = 0, conductivity = 1;
};

/// Enskog factors in d >= 1 dimensions at packing fraction phi >= 0 with contact value chi > 0
/// (elastic limit of Garzó & Dufty 1999; see enskog.cpp for each term). phi = 0, chi = 1 gives
/// {1, 0, 1}. Throws std::invalid_argument naming d, phi or chi out of range.
EnskogFactors enskog_factors(int d, double phi, double chi);

/// The same with chi = contact_value(eos, phi) and d = eos_dimension(eos) (hard particles only).
EnskogFactors enskog_factors(Eos eos, double phi);

}  // namespace coldblast::hydro
