// Enskog transport factors (first Sonine order, elastic hard particles). With y = 2^(d-1) φ χ, the
// excess pressure Z - 1 of the EOS, the elastic limit (α = 1, no cooling, c = 0) of Garzó & Dufty,
// PRE 59, 5895 (1999), Sec. IV, reads
//   η/η0 = (1/χ) (1 + 2y/(d+2))² + d/(d+2) ζ/η0          (kinetic part × its collisional transfer)
//   ζ/η0 = 2^(2d+2)/(π (d+2)) φ² χ                        (bulk viscosity, purely collisional)
//   κ/κ0 = (1/χ) (1 + 3y/(d+2))² + 2^(2d+2)(d-1)/(π (d+2)²) φ² χ
// In 2D these are Gass (1971): η/η0 = 1/χ + 2φ + (1 + 8/π) φ²χ, κ/κ0 = 1/χ + 3φ + (9/4 + 4/π) φ²χ;
// in 3D, with bρ = 4φ, Chapman & Cowling's η/η0 = 1/χ + (4/5) bρ + (4/25 + 48/(25π)) (bρ)² χ and
// κ/κ0 = 1/χ + (6/5) bρ + (9/25 + 32/(25π)) (bρ)² χ (their 0.7614 and 0.7575 include the higher
// Sonine corrections of η0, κ0, which first Sonine order leaves out). tests/hydro/test_enskog.cpp
// recomputes the factors from those dimension-specific published forms.
#include "hydro/enskog.hpp"

#include <cmath>
#include <limits>
#include <stdexcept>

#include "common/validate.hpp"

namespace coldblast::hydro {

EnskogFactors enskog_factors(int d, double phi, double chi) {
  if (!(d >= 1 && d <= 100 && phi >= 0 && phi < 1 && chi > 0 && std::isfinite(chi))) {  // per face: cheap check first
    common::require_integer_in_range("d", d, 1, 100);
    common::require_in_range("phi", phi, 0.0, 1.0, common::Bound::closed, common::Bound::open);
    common::require_in_range("chi", chi, 0.0, std::numeric_limits<double>::infinity());
  }
  const double y = std::pow(2.0, d - 1) * phi * chi;  // Z - 1 (contact theorem)
  const double collisional = std::pow(2.0, 2 * d + 2) / M_PI * phi * phi * chi;
  EnskogFactors f;
  f.bulk = collisional / (d + 2);                                          // Garzó & Dufty 1999, bulk viscosity
  const double kinetic_shear = (1 + 2 * y / (d + 2)) / chi;                // η_k/η0 at α = 1
  f.shear = kinetic_shear * (1 + 2 * y / (d + 2)) + d * f.bulk / (d + 2);  // Garzó & Dufty 1999, η
  const double kinetic_conduction = (1 + 3 * y / (d + 2)) / chi;           // κ_k/κ0 at α = 1
  f.conductivity = kinetic_conduction * (1 + 3 * y / (d + 2)) + (d - 1) * collisional / ((d + 2) * (d + 2));  // κ
  return f;
}

EnskogFactors enskog_factors(Eos eos, double phi) {
  if (eos == Eos::ideal)
    throw std::invalid_argument("eos = ideal has no Enskog transport (it needs a hard-particle contact value chi)");
  return enskog_factors(eos_dimension(eos), phi, contact_value(eos, phi));
}

}  // namespace coldblast::hydro
