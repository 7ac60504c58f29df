// Enskog transport factors against the published dimension-specific forms (Gass 1971 for discs,
// Chapman & Cowling for spheres), the dilute limit, and the EOS-consistent contact value.
#include <catch2/catch.hpp>
#include <cmath>
#include <stdexcept>

#include "hydro/enskog.hpp"

using namespace coldblast::hydro;

TEST_CASE("Enskog factors reproduce Gass's hard-disc forms (d = 2)", "[fast]") {
  // Gass, J. Chem. Phys. 54, 1898 (1971): η/η0 = 1/χ + 2φ + (1 + 8/π) φ²χ,
  // κ/κ0 = 1/χ + 3φ + (9/4 + 4/π) φ²χ, bulk viscosity ζ/η0 = (16/π) φ²χ.
  for (double phi : {1e-4, 0.118, 0.3, 0.6}) {
    CAPTURE(phi);
    const double chi = contact_value(Eos::henderson, phi);
    const EnskogFactors f = enskog_factors(Eos::henderson, phi);
    CHECK(f.shear == Approx(1 / chi + 2 * phi + (1 + 8 / M_PI) * phi * phi * chi).epsilon(1e-14));
    CHECK(f.conductivity == Approx(1 / chi + 3 * phi + (9.0 / 4 + 4 / M_PI) * phi * phi * chi).epsilon(1e-14));
    CHECK(f.bulk == Approx(16 / M_PI * phi * phi * chi).epsilon(1e-14));
  }
}

TEST_CASE("Enskog factors reproduce Chapman and Cowling's hard-sphere forms (d = 3)", "[fast]") {
  // Chapman & Cowling Ch. 16 with bρ = (2π/3) n σ³ = 4φ and y = bρχ, first Sonine order:
  // η/η0 = 1/χ + (4/5) bρ + (4/25 + 48/(25π)) (bρ)²χ, κ/κ0 = 1/χ + (6/5) bρ + (9/25 + 32/(25π)) (bρ)²χ,
  // ζ/η0 = (16/(5π)) (bρ)²χ.
  for (double phi : {1e-4, 0.118, 0.3, 0.45}) {
    CAPTURE(phi);
    const double chi = contact_value(Eos::carnahan_starling, phi);
    const double b_rho = 4 * phi;
    const EnskogFactors f = enskog_factors(Eos::carnahan_starling, phi);
    CHECK(f.shear ==
          Approx(1 / chi + 0.8 * b_rho + (4.0 / 25 + 48 / (25 * M_PI)) * b_rho * b_rho * chi).epsilon(1e-14));
    CHECK(f.conductivity ==
          Approx(1 / chi + 1.2 * b_rho + (9.0 / 25 + 32 / (25 * M_PI)) * b_rho * b_rho * chi).epsilon(1e-14));
    CHECK(f.bulk == Approx(16 / (5 * M_PI) * b_rho * b_rho * chi).epsilon(1e-14));
  }
}

TEST_CASE("Enskog factors: dilute limit and bad input", "[fast]") {
  for (int d : {1, 2, 3, 4}) {
    const EnskogFactors f = enskog_factors(d, 0.0, 1.0);
    CHECK(f.shear == 1.0);
    CHECK(f.conductivity == 1.0);
    CHECK(f.bulk == 0.0);
    // at χ ≡ 1, η/η0 = (1 + 2y/(d+2))² + O(φ²) with y = 2^(d-1) φ: slope 2^(d+1)/(d+2) at φ = 0
    const double h = 1e-7;
    CHECK((enskog_factors(d, h, 1.0).shear - 1) / h == Approx(std::pow(2.0, d + 1) / (d + 2)).epsilon(1e-5));
  }
  CHECK_THROWS_AS(enskog_factors(2, -0.1, 1.0), std::invalid_argument);
  CHECK_THROWS_AS(enskog_factors(2, 0.1, 0.0), std::invalid_argument);
  CHECK_THROWS_AS(enskog_factors(Eos::ideal, 0.0), std::invalid_argument);
}
