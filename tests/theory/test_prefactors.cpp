// Prefactor formulas: known values of Omega_d, lambda and phi for the paper's scene, the inverse
// relations, and the Gaussian of Eq. (35) normalised in d dimensions.
#include <catch2/catch.hpp>
#include <cmath>

#include "theory/exponents.hpp"
#include "theory/prefactors.hpp"

using namespace coldblast::theory;
using Catch::Matchers::WithinRel;
constexpr double pi = 3.14159265358979323846;

TEST_CASE("unit ball volumes and sphere areas", "[fast]") {
  CHECK(unit_ball_volume(0) == 1.0);
  CHECK_THAT(unit_ball_volume(1), WithinRel(2.0, 1e-15));
  CHECK_THAT(unit_ball_volume(2), WithinRel(pi, 1e-15));
  CHECK_THAT(unit_ball_volume(3), WithinRel(4.0 * pi / 3.0, 1e-15));
  CHECK_THAT(unit_ball_volume(4), WithinRel(pi * pi / 2.0, 1e-15));
  CHECK_THAT(unit_sphere_area(1), WithinRel(2.0, 1e-15));
  CHECK_THAT(unit_sphere_area(3), WithinRel(4.0 * pi, 1e-15));
  // Recurrence Ω_d = (2π/d) Ω_{d-2}, independent of the Γ-function route.
  for (int d = 2; d <= 20; ++d)
    CHECK_THAT(unit_ball_volume(d), WithinRel(2.0 * pi / d * unit_ball_volume(d - 2), 1e-13));
}

TEST_CASE("the paper's 2D scene: n = 0.15, a = 1/2 gives phi = 0.118 and lambda = 20/3", "[fast]") {
  CHECK_THAT(packing_fraction(2, 0.15, 0.5), WithinRel(0.15 * pi / 4.0, 1e-15));  // 0.1178
  CHECK(std::abs(packing_fraction(2, 0.15, 0.5) - 0.118) < 5e-4);                 // Fig. 1 caption
  CHECK_THAT(mean_free_path(2, 0.15, 0.5), WithinRel(20.0 / 3.0, 1e-15));
  CHECK_THAT(mean_free_path(3, 0.2, 0.5), WithinRel(1.0 / (0.2 * pi * 0.25), 1e-15));
  CHECK_THAT(number_density(3, packing_fraction(3, 0.3, 0.7), 0.7), WithinRel(0.3, 1e-14));
  CHECK_THROWS_WITH(mean_free_path(2, -1.0, 0.5), Catch::Contains("n = -1"));
  CHECK_THROWS_WITH(packing_fraction(2, 0.1, 0.0), Catch::Contains("a = 0"));
}

TEST_CASE("shock radius, its inverse, its speed and the core radius", "[fast]") {
  const BlastParameters p{2, 0.15, 0.5, 4.0, 0.351935906};
  const double t = 4000.0;
  const double R = shock_radius(p, t);
  CHECK_THAT(std::pow(R, 4) * p.A_d * p.n / (p.E * t * t), WithinRel(1.0, 1e-14));  // Eq. (1)
  CHECK_THAT(shock_time(p, R), WithinRel(t, 1e-14));
  const double h = 1e-3 * t;
  const double numeric = (shock_radius(p, t + h) - shock_radius(p, t - h)) / (2 * h);
  CHECK_THAT(shock_speed(p, t), WithinRel(numeric, 1e-6));
  const double lambda = mean_free_path(2, p.n, p.a);
  CHECK_THAT(core_radius(2, lambda, R), WithinRel(lambda * std::pow(R / lambda, 0.8), 1e-15));
  CHECK_THROWS_WITH(shock_radius(p, 0.0), Catch::Contains("t = 0"));
  BlastParameters bad = p;
  bad.E = -1.0;
  CHECK_THROWS_WITH(shock_radius(bad, 1.0), Catch::Contains("E = -1"));
}

TEST_CASE("Eq. (1)'s forms agree with each other bit for bit and name bad arguments", "[fast]") {
  for (int d : {1, 2, 3, 7}) {
    const BlastParameters p{d, 0.2, 0.5, 3.0, 0.4};
    for (double t : {0.5, 10.0, 4000.0}) {
      const double R = shock_radius(d, p.E, p.n, p.A_d, t);
      CHECK(R == shock_radius(p, t));  // the BlastParameters form calls the free form
      CHECK(shock_speed_at(d, R, t) == shock_speed(p, t));
      CHECK_THAT(shock_time(d, p.E, p.n, p.A_d, R), WithinRel(t, 1e-14));
      CHECK_THAT(shock_amplitude(d, p.E, p.n, t, R), WithinRel(p.A_d, 1e-14));
    }
  }
  CHECK_THROWS_WITH(shock_radius(2, 1.0, 0.1, 0.3, -2.0), "t = -2 is outside (0, inf)");
  CHECK_THROWS_WITH(shock_amplitude(2, 1.0, 0.1, 1.0, 0.0), Catch::Contains("R = 0"));
  CHECK_THROWS_WITH(shock_speed_at(2, 1.0, std::nan("")), Catch::Contains("t = nan"));
}

TEST_CASE("the ideal-gas amplitudes: A_2 is the paper's 0.351935906..., A_3 exists only for d = 3", "[fast]") {
  CHECK(ideal_gas_amplitude(2) >= 0.351935906);
  CHECK(ideal_gas_amplitude(2) < 0.351935907);
  CHECK(ideal_gas_amplitude(3) == ideal_gas_A_3);
  CHECK(BlastParameters{}.A_d == ideal_gas_A_2);
  CHECK_THROWS_WITH(ideal_gas_amplitude(4), "d = 4 is outside [2, 3]");
}

TEST_CASE("scaling estimates follow their exponents in time", "[fast]") {
  for (int d : {2, 3}) {
    const BlastParameters p{d, 0.15, 0.5, 10.0, 0.5};
    const auto e = scaling_exponents(d);
    const auto a = scaling_estimates(p, 1000.0);
    const auto b = scaling_estimates(p, 2000.0);
    const double lg2 = std::log(2.0);
    CHECK_THAT(std::log(b.R_imp / a.R_imp) / lg2, WithinRel(to_double(e.R_imp.in_time), 1e-12));
    CHECK_THAT(std::log(b.V_imp / a.V_imp) / lg2, WithinRel(to_double(e.V_imp.in_time), 1e-12));
    CHECK_THAT(std::log(b.u_imp / a.u_imp) / lg2, WithinRel(to_double(e.u_imp.in_time), 1e-12));
    CHECK_THAT(std::log(b.C_imp / a.C_imp) / lg2, WithinRel(to_double(e.C_imp.in_time), 1e-12));
    CHECK_THAT(std::log(b.n0 / a.n0) / lg2, WithinRel(to_double(e.n0.in_time), 1e-12));
    CHECK_THAT(std::log(b.T0 / a.T0) / lg2, WithinRel(to_double(e.T0.in_time), 1e-12));
    CHECK_THAT(std::log(b.D0 / a.D0) / lg2, WithinRel(to_double(e.D0.in_time), 1e-12));
    // Eq. (21): D0 = λ (n/n0) V_imp with the same unit prefactors.
    CHECK_THAT(a.D0, WithinRel(a.lambda * p.n / a.n0 * a.V_imp, 1e-12));
  }
}

TEST_CASE("Gaussian position density of Eq. (35) is normalised; Eqs. (31), (34) reproduced", "[fast]") {
  for (int d : {1, 2, 3, 4}) {
    INFO("d = " << d);
    // ∫ S_d r^(d-1) P dr by composite Simpson on [0, 12 R_imp].
    const double R_imp = 1.7;
    const int steps = 4000;
    const double h = 12.0 * R_imp / steps;
    double sum = 0.0;
    for (int i = 0; i <= steps; ++i) {
      const double w = (i == 0 || i == steps) ? 1.0 : (i % 2 ? 4.0 : 2.0);
      sum += w * radial_position_density(d, i * h, R_imp);
    }
    CHECK_THAT(sum * h / 3.0, WithinRel(1.0, 1e-10));
  }
  CHECK_THAT(scaled_position_density(2, 0.0), WithinRel(1.0 / (5.0 * pi), 1e-15));
  CHECK_THAT(scaled_position_density(2, 2.0), WithinRel(std::exp(-4.0 / 5.0) / (5.0 * pi), 1e-14));
  CHECK_THAT(scaled_position_density(3, 1.0),
             WithinRel(std::pow(31.0 / (175.0 * pi), 1.5) * std::exp(-31.0 / 175.0), 1e-14));
  // Eq. (39) in 2D: p(r) = (r/R_imp²) exp(-r²/(2 R_imp²)).
  CHECK_THAT(radial_position_density(2, 3.0, 2.0), WithinRel(3.0 / 4.0 * std::exp(-9.0 / 8.0), 1e-14));
}
