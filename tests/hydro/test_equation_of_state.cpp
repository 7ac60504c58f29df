// Hard-particle equations of state and the strong-shock jump: known values of Z, Z' against a
// finite difference, the Hugoniot residual, the phi -> 0 (ideal, gamma = 1 + 2/d) limit and the
// close-packing bound.
#include <catch2/catch.hpp>
#include <cmath>
#include <limits>

#include "hydro/equation_of_state.hpp"

using namespace coldblast::hydro;
using Catch::Matchers::Contains;
using Catch::Matchers::WithinAbs;
using Catch::Matchers::WithinRel;

TEST_CASE("compressibility factors at known points", "[fast]") {
  CHECK(compressibility(Eos::ideal, 0.3) == 1.0);
  CHECK(compressibility(Eos::henderson, 0.0) == 1.0);
  CHECK(compressibility(Eos::carnahan_starling, 0.0) == 1.0);
  // Henderson: (1 + 1/32)/(1/4) = 4.125; Carnahan-Starling: (1 + 1/2 + 1/4 - 1/8)/(1/8) = 13.
  CHECK_THAT(compressibility(Eos::henderson, 0.5), WithinRel(4.125, 1e-15));
  CHECK_THAT(compressibility(Eos::carnahan_starling, 0.5), WithinRel(13.0, 1e-15));
  // Second virial coefficients: Z = 1 + 2 phi (discs) and 1 + 4 phi (spheres) to first order.
  const double phi = 1e-7;
  CHECK_THAT((compressibility(Eos::henderson, phi) - 1.0) / phi, WithinRel(2.0, 1e-6));
  CHECK_THAT((compressibility(Eos::carnahan_starling, phi) - 1.0) / phi, WithinRel(4.0, 1e-6));
}

TEST_CASE("dZ/dphi agrees with a central difference", "[fast]") {
  for (const Eos eos : {Eos::henderson, Eos::carnahan_starling}) {
    for (const double phi : {0.05, 0.118, 0.3, 0.6}) {
      const double h = 1e-5;
      const double difference = (compressibility(eos, phi + h) - compressibility(eos, phi - h)) / (2.0 * h);
      // Truncation error h^2 Z'''/6 with Z''' < 1e5 here, plus round-off eps Z/h.
      CHECK_THAT(compressibility_derivative(eos, phi), WithinAbs(difference, 1e-5 * difference));
    }
  }
}

TEST_CASE("strong-shock compression solves the Hugoniot and tends to d + 1 as phi -> 0", "[fast]") {
  for (const Eos eos : {Eos::henderson, Eos::carnahan_starling}) {
    const int d = eos_dimension(eos);
    CHECK_THAT(strong_shock_compression(eos, 1e-12), WithinRel(d + 1.0, 1e-10));
    double previous = d + 1.0;
    for (const double phi : {1e-3, 0.05, 0.118, 0.3, 0.5}) {
      const double c = strong_shock_compression(eos, phi);
      // Z(phi c)(1 - 1/c) = d/c, i.e. e1 = u1^2/2 with e = (d/2) T, p = n T Z.
      CHECK_THAT(compressibility(eos, phi * c) * (1.0 - 1.0 / c), WithinRel(d / c, 1e-13));
      CHECK(c < previous);  // denser gas is stiffer: less compression
      CHECK(phi * c < close_packing_fraction(eos));
      previous = c;
    }
  }
}

TEST_CASE("the largest ambient phi puts the shocked gas at close packing", "[fast]") {
  for (const Eos eos : {Eos::henderson, Eos::carnahan_starling}) {
    const double phi_max = max_ambient_packing_fraction(eos);
    const double phi = phi_max * (1.0 - 1e-9);
    CHECK_THAT(phi * strong_shock_compression(eos, phi), WithinRel(close_packing_fraction(eos), 1e-6));
    CHECK_THROWS_WITH(strong_shock_compression(eos, phi_max), Contains("phi = ") && Contains("close packing"));
    CHECK_THROWS_WITH(strong_shock_compression(eos, 0.0), Contains("phi = 0 is outside (0, "));
  }
  CHECK_THAT(max_ambient_packing_fraction(Eos::henderson), WithinAbs(0.89286, 5e-6));
  CHECK_THAT(max_ambient_packing_fraction(Eos::carnahan_starling), WithinAbs(0.72042, 5e-6));
}

TEST_CASE("adiabatic sound speed: gamma T in the dilute limit", "[fast]") {
  CHECK_THAT(sound_speed_squared_over_temperature(Eos::henderson, 0.0), WithinRel(2.0, 1e-15));
  CHECK_THAT(sound_speed_squared_over_temperature(Eos::carnahan_starling, 0.0), WithinRel(5.0 / 3.0, 1e-15));
}

TEST_CASE("EOS names round-trip and unknown names are rejected", "[fast]") {
  for (const Eos eos : {Eos::ideal, Eos::henderson, Eos::carnahan_starling})
    CHECK(eos_from_string(to_string(eos)) == eos);
  CHECK_THROWS_WITH(eos_from_string("van-der-waals", "--eos"), Contains("--eos = van-der-waals"));
}

TEST_CASE("contact value chi is consistent with the EOS: Z = 1 + 2^(d-1) phi chi", "[fast]") {
  for (const Eos eos : {Eos::henderson, Eos::carnahan_starling}) {
    const int d = eos_dimension(eos);
    CAPTURE(to_string(eos));
    CHECK(contact_value(eos, 0.0) == 1.0);
    for (double phi : {1e-8, 0.05, 0.118, 0.3, 0.5, 0.7}) {
      CAPTURE(phi);
      CHECK(compressibility(eos, phi) ==
            Approx(1.0 + std::pow(2.0, d - 1) * phi * contact_value(eos, phi)).epsilon(1e-14));
    }
    CHECK_THROWS_WITH(contact_value(eos, close_packing_fraction(eos)), Contains("phi"));
    CHECK_THROWS_AS(contact_value(eos, -0.1), std::invalid_argument);
  }
  // the textbook forms: Henderson chi = (1 - 7 phi/16)/(1 - phi)^2, Carnahan-Starling (1 - phi/2)/(1 - phi)^3
  CHECK(contact_value(Eos::henderson, 0.118) == Approx((1 - 7 * 0.118 / 16) / std::pow(1 - 0.118, 2)).epsilon(1e-15));
  CHECK(contact_value(Eos::carnahan_starling, 0.2) == Approx((1 - 0.1) / std::pow(0.8, 3)).epsilon(1e-15));
  CHECK(contact_value(Eos::ideal, 0.0) == 1.0);
}
