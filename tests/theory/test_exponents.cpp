// Exact exponents: the paper's Table 2 for d = 2, 3, two independent routes for d = 2..10, and
// the consistency identities of Sec. III.
#include <catch2/catch.hpp>

#include "theory/exponents.hpp"

using namespace coldblast::theory;

TEST_CASE("Table 2 of the paper, d = 2 and d = 3, exactly", "[fast]") {
  const auto two = scaling_exponents(2);
  CHECK(two.C_imp.in_time == Rational(2, 5));
  CHECK(two.R_imp.in_time == Rational(2, 5));
  CHECK(two.V_imp.in_time == Rational(-2, 5));
  CHECK(two.u_imp.in_time == Rational(-3, 5));
  CHECK(two.n0.in_time == Rational(-1, 5));
  CHECK(two.T0.in_time == Rational(-4, 5));
  CHECK(two.h_d == Rational(4, 5));
  CHECK(two.R.in_time == Rational(1, 2));

  const auto three = scaling_exponents(3);
  CHECK(three.C_imp.in_time == Rational(52, 175));
  CHECK(three.R_imp.in_time == Rational(62, 175));
  CHECK(three.V_imp.in_time == Rational(-87, 175));
  CHECK(three.u_imp.in_time == Rational(-113, 175));
  CHECK(three.n0.in_time == Rational(-36, 175));
  CHECK(three.T0.in_time == Rational(-174, 175));
  CHECK(three.h_d == Rational(31, 35));
  CHECK(three.omega_d == Rational(87, 70));
}

TEST_CASE("Sec. IV convection-diffusion exponents, d = 2 and 3", "[fast]") {
  const auto two = convection_diffusion_exponents(2);
  CHECK(two.drift == Rational(-3, 5));                // Eq. (26)
  CHECK(two.diffusion == Rational(-1, 5));            // Eq. (26)
  CHECK(two.spread == Rational(2, 5));                // Eq. (27)
  CHECK(two.density == Rational(4, 5));               // Eq. (27)
  CHECK(two.gaussian_coefficient == Rational(1, 5));  // Eq. (31)
  const auto three = convection_diffusion_exponents(3);
  CHECK(three.drift == Rational(-113, 175));               // Eq. (32)
  CHECK(three.diffusion == Rational(-51, 175));            // Eq. (32)
  CHECK(three.spread == Rational(62, 175));                // Eq. (33)
  CHECK(three.density == Rational(186, 175));              // Eq. (33)
  CHECK(three.gaussian_coefficient == Rational(31, 175));  // Eq. (34)
}

TEST_CASE("each exponent by two independent routes, d = 2..10", "[fast]") {
  for (long long d = 2; d <= 10; ++d) {
    INFO("d = " << d);
    const auto s = scaling_exponents(static_cast<int>(d));
    const long long q = 8 + 3 * d * d;
    // Abstract and Eq. (23) [RVu-HS], (24) [C-imp-long], written directly in t.
    CHECK(s.V_imp.in_time == Rational(-d * (8 - 2 * d + 3 * d * d), (2 + d) * q));
    CHECK(s.C_imp.in_time == Rational(4 * (4 + d * d), (2 + d) * q));
    CHECK(s.R_imp.in_time == Rational(2, d + 2) - Rational(8, (d + 2) * q));
    CHECK(s.u_imp.in_time == Rational(-d, d + 2) - Rational(8, (d + 2) * q));
    // Core from the TvNS near-centre laws (18a,b) evaluated at r = H: n0 = n (H/R)^(d²/2),
    // T0 = (R/t)² (H/R)^(-d²/2), with H/R ∝ (R/λ)^(h_d - 1).
    const Rational core = (s.h_d - 1) * Rational(d * d, 2);
    CHECK(s.n0.in_R_over_lambda == core);
    CHECK(s.T0.in_time == 2 * (Rational(2, d + 2) - 1) - core * Rational(2, d + 2));
    // H from the balance (17) [H-est] solved for H: H^(3d²/4 + 2) ∝ λ R^(3d²/4 + 1).
    CHECK(s.H.in_R_over_lambda == Rational(3 * d * d + 4, 3 * d * d + 8));
  }
}

TEST_CASE("consistency identities of Sec. III hold exactly, d = 1..50", "[fast]") {
  for (int d = 1; d <= 50; ++d) {
    INFO("d = " << d);
    const auto s = scaling_exponents(d);
    CHECK(2 * s.R_imp.in_time == s.D0.in_time + 1);                // R_imp² ∝ D0 t
    CHECK(s.C_imp.in_time == 1 + s.n0.in_time + s.V_imp.in_time);  // C = t n0 V_imp (Boltzmann cylinder)
    CHECK(2 * s.V_imp.in_time == s.T0.in_time);                    // V_imp² ∝ T0
    CHECK(s.u_imp.in_time == s.R_imp.in_time - 1);                 // u_imp ∝ R_imp/t
    CHECK(s.D0.in_time == s.V_imp.in_time - s.n0.in_time);         // D0 = λ (n/n0) V_imp, Eq. (21)
    CHECK(s.R_imp.in_time == s.H.in_time);                         // the impurity stays in the core
    for (const auto& [name, e] : s.named()) CHECK(e.in_time == e.in_R_over_lambda * Rational(2, d + 2));
  }
}

TEST_CASE("d = 1 is computed but flagged pathological; bad d throws", "[fast]") {
  CHECK(scaling_exponents(1).pathological);
  CHECK_FALSE(scaling_exponents(2).pathological);
  CHECK(h_d(1) == Rational(7, 11));
  CHECK_THROWS_AS(scaling_exponents(0), std::invalid_argument);
  CHECK_THROWS_WITH(scaling_exponents(-3), Catch::Contains("d = -3"));
  CHECK_THROWS_AS(scaling_exponents(max_dimension + 1), std::invalid_argument);
  CHECK_NOTHROW(scaling_exponents(max_dimension));
  CHECK_THROWS_WITH(scaling_exponents(2).at("speed"), Catch::Contains("speed"));
}

TEST_CASE("to_string and to_double", "[fast]") {
  CHECK(to_string(Rational(-174, 175)) == "-174/175");
  CHECK(to_string(Rational(4, 2)) == "2");
  CHECK(to_double(Rational(2, 5)) == 0.4);
}
