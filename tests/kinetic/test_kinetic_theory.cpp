// Exact kinetic-theory references of kinetic/kinetic_theory.hpp against their textbook closed
// forms and an independent quadrature of the Chapman–Enskog collision integral.
#include <catch2/catch.hpp>
#include <cmath>

#include "hydro/equation_of_state.hpp"
#include "kinetic/kinetic_theory.hpp"
#include "md/equilibrium.hpp"

using namespace coldblast::kinetic;

namespace {
const double pi = std::acos(-1.0);

/// ⟨|g|^p⟩ of a d-dimensional Maxwellian with per-component variance s2, by the trapezoid rule.
double speed_moment(int d, double s2, int p) {
  const int steps = 200000;
  const double upper = 40.0 * std::sqrt(s2), h = upper / steps;
  double num = 0.0, den = 0.0;
  for (int i = 1; i < steps; ++i) {
    const double g = i * h, w = std::pow(g, d - 1) * std::exp(-g * g / (2 * s2));
    num += w * std::pow(g, p);
    den += w;
  }
  return num / den;
}
}  // namespace

TEST_CASE("equilibrium collision rate: the closed forms for equal discs and spheres") {
  const double n = 0.3, chi = 1.7, sigma = 1.3, T = 2.5;
  CHECK(equilibrium_collision_rate(2, n, chi, sigma, T, 1.0) ==
        Approx(2 * n * sigma * chi * std::sqrt(pi * T)).epsilon(1e-14));
  CHECK(equilibrium_collision_rate(3, n, chi, sigma, T, 1.0) ==
        Approx(4 * n * sigma * sigma * chi * std::sqrt(pi * T)).epsilon(1e-14));
  // Unequal masses: the mean relative speed at the reduced mass, by quadrature.
  for (const int d : {2, 3})
    for (const double M : {0.1, 3.0}) {
      const double mu = M / (M + 1);
      CHECK(mean_relative_speed(d, T, M) == Approx(speed_moment(d, T / mu, 1)).epsilon(1e-7));
    }
}

TEST_CASE("first Sonine tracer diffusion: Gass's equal-disc value and the general collision-integral form") {
  const double n = 0.2, chi = 1.3, sigma = 0.9, T = 1.7;
  CHECK(first_sonine_tracer_diffusion(2, n, chi, sigma, T, 1.0) ==
        Approx(1 / (2 * n * sigma * chi) * std::sqrt(T / pi)).epsilon(1e-14));
  CHECK(first_sonine_tracer_diffusion(3, n, chi, sigma, T, 1.0) ==
        Approx(3 / (8 * n * sigma * sigma * chi) * std::sqrt(T / pi)).epsilon(1e-14));
  // D_1 = d T² / (2 mu² n chi sigma^(d-1) K_d ⟨|g|³⟩), K_2 = 4/3, K_3 = π/2 (docs/kinetic.md).
  for (const int d : {2, 3})
    for (const double M : {0.2, 1.0, 7.0}) {
      const double mu = M / (M + 1), K = d == 2 ? 4.0 / 3.0 : pi / 2;
      const double D = d * T * T / (2 * mu * mu * n * chi * std::pow(sigma, d - 1) * K * speed_moment(d, T / mu, 3));
      CHECK(first_sonine_tracer_diffusion(d, n, chi, sigma, T, M) == Approx(D).epsilon(1e-7));
    }
}

TEST_CASE("pair contact value: Henderson and Carnahan-Starling through Z = 1 + 2^(d-1) phi chi") {
  for (const double phi : {0.05, 0.2, 0.4}) {
    CHECK(1 + 2 * phi * pair_contact_value(2, phi, 0.5, 0.5) == Approx(coldblast::md::henderson_Z(phi)).epsilon(1e-14));
    CHECK(1 + 4 * phi * pair_contact_value(3, phi, 0.5, 0.5) ==
          Approx(coldblast::md::carnahan_starling_Z(phi)).epsilon(1e-14));
    CHECK(pair_contact_value(2, phi, 0.5, 0.5) ==
          Approx(coldblast::hydro::contact_value(coldblast::hydro::Eos::henderson, phi)).epsilon(1e-14));
    CHECK(pair_contact_value(3, phi, 0.5, 0.5) ==
          Approx(coldblast::hydro::contact_value(coldblast::hydro::Eos::carnahan_starling, phi)).epsilon(1e-14));
    // A point impurity (a_imp -> 0) sees the wall contact value 1/(1-phi) of scaled-particle theory's first term.
    CHECK(pair_contact_value(3, phi, 0.5, 0.0) == Approx(1 / (1 - phi)).epsilon(1e-14));
    // Larger impurities see a larger contact value.
    CHECK(pair_contact_value(2, phi, 0.5, 2.5) > pair_contact_value(2, phi, 0.5, 0.5));
  }
  CHECK(pair_contact_value(2, 0.0, 0.5, 0.7) == 1.0);
  CHECK_THROWS_AS(pair_contact_value(2, 1.0, 0.5, 0.5), std::invalid_argument);
}
