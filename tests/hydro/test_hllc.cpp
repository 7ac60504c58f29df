// Tests of hydro/hllc: the HLLC flux through a moving face is consistent (equal states give the exact
// flux F(U) - wU), keeps a contact at rest and a reflecting wall exact, and is mirror-symmetric; van
// Leer's limiter is symmetric, vanishes at extrema and is bounded by twice the smaller slope.
#include <catch2/catch.hpp>
#include <cmath>

#include "hydro/hllc.hpp"

using namespace coldblast;
using hydro::components;
using hydro::State;

namespace {

/// Ideal monatomic gas in 2D (γ = 2): sound speed and total energy of a state.
State ideal(double n, double u, double p) {
  const double gamma = 2.0;
  State s{n, u, p};
  s.c = std::sqrt(gamma * p / n);
  s.total = p / (gamma - 1) + 0.5 * n * u * u;
  return s;
}

}  // namespace

TEST_CASE("HLLC: equal states give the exact flux F(U) - wU for any face speed", "[fast]") {
  const State s = ideal(1.3, 0.7, 2.1);
  for (double w : {-5.0, -0.3, 0.0, 0.9, 6.0}) {
    CAPTURE(w);
    double F[components];
    hydro::hllc_flux(s, s, w, F);
    CHECK(F[0] == Approx(s.n * s.u - w * s.n).epsilon(1e-14));
    CHECK(F[1] == Approx(s.n * s.u * s.u + s.p - w * s.n * s.u).epsilon(1e-14));
    CHECK(F[2] == Approx((s.total + s.p) * s.u - w * s.total).epsilon(1e-14));
  }
}

TEST_CASE("HLLC: a contact at rest and a reflecting wall are kept exactly", "[fast]") {
  // A density jump at equal pressure and zero velocity is a stationary contact: HLLC (unlike HLL)
  // resolves it, so no mass or energy crosses a fixed face and the momentum flux is the pressure.
  double F[components];
  hydro::hllc_flux(ideal(1.0, 0.0, 1.5), ideal(0.125, 0.0, 1.5), 0.0, F);
  CHECK(F[0] == Approx(0.0).margin(1e-14));
  CHECK(F[1] == Approx(1.5).epsilon(1e-14));
  CHECK(F[2] == Approx(0.0).margin(1e-14));
  // The ghost at r = 0 mirrors the state (u -> -u): the face carries no mass or energy.
  const State right = ideal(0.8, -0.4, 1.1);  // flowing into the wall
  hydro::hllc_flux(ideal(0.8, 0.4, 1.1), right, 0.0, F);
  CHECK(F[0] == Approx(0.0).margin(1e-15));
  CHECK(F[2] == Approx(0.0).margin(1e-15));
  CHECK(F[1] > right.p);  // the wall stops the inflow: the star pressure exceeds p
}

TEST_CASE("HLLC: the mirror image of a Riemann problem has the mirrored flux", "[fast]") {
  const State L = ideal(2.0, 0.3, 3.0), R = ideal(0.5, -0.2, 0.4);
  const State L_mirror = ideal(0.5, 0.2, 0.4), R_mirror = ideal(2.0, -0.3, 3.0);
  for (double w : {-1.0, 0.0, 0.35}) {
    CAPTURE(w);
    double F[components], G[components];
    hydro::hllc_flux(L, R, w, F);
    hydro::hllc_flux(L_mirror, R_mirror, -w, G);
    CHECK(G[0] == Approx(-F[0]).epsilon(1e-13));
    CHECK(G[1] == Approx(F[1]).epsilon(1e-13));
    CHECK(G[2] == Approx(-F[2]).epsilon(1e-13));
  }
}

TEST_CASE("van Leer's limiter: symmetric, zero at extrema, below twice the smaller slope", "[fast]") {
  CHECK(hydro::van_leer(1.0, 1.0) == 1.0);
  CHECK(hydro::van_leer(1.0, 3.0) == hydro::van_leer(3.0, 1.0));
  CHECK(hydro::van_leer(1.0, 3.0) == Approx(1.5).epsilon(1e-15));  // 2ab/(a+b)
  CHECK(hydro::van_leer(-1.0, 2.0) == 0.0);
  CHECK(hydro::van_leer(0.0, 2.0) == 0.0);
  CHECK(hydro::van_leer(-2.0, -6.0) == Approx(-3.0).epsilon(1e-15));
  CHECK(hydro::van_leer(0.1, 100.0) < 0.2);
}
