// The hydro reference maps Navier–Stokes core exponents onto the MD observables (Sec. III):
// checked on a synthetic Navier–Stokes result with exact 2D power laws, where every mapped
// exponent must equal the theory's rational (C_imp through the ∫ n0 √T0 dt quadrature).
#include <catch2/catch.hpp>
#include <cmath>

#include "compare/hydro_reference.hpp"
#include "theory/exponents.hpp"

using namespace coldblast;

namespace {
hydro::NavierStokesResult synthetic_power_laws() {
  hydro::NavierStokesResult result;
  result.config.physics.d = 2;
  for (int i = 0; i <= 120; ++i) {
    const double t = std::pow(10.0, 0.05 * i);
    hydro::NavierStokesSample s;
    s.t = t;
    s.R = std::sqrt(t);
    s.R_over_lambda = s.R;
    s.H = std::pow(t, 0.4);
    s.n0 = std::pow(t, -0.2);
    s.T0 = std::pow(t, -0.8);
    result.samples.push_back(s);
    hydro::RunningExponents e;
    e.t = t;
    e.R_over_lambda = s.R_over_lambda;
    e.R = 0.5;
    e.H = 0.4;
    e.n0 = -0.2;
    e.T0 = -0.8;
    result.exponents.push_back(e);
  }
  return result;
}
}  // namespace

TEST_CASE("hydro reference maps H, n0, T0 onto the six MD observables", "[fast]") {
  const compare::HydroReference reference(synthetic_power_laws());
  const auto exact = theory::scaling_exponents(2);
  for (const char* name : {"R_imp", "V_imp", "u_imp", "n0", "T0", "C_imp"}) {
    INFO(name);
    // Trapezoid rule in ln t with 20 points per decade: relative error ~1e-4 on C.
    CHECK(reference.exponent(name, 100.0) == Approx(theory::to_double(exact.at(name).in_time)).margin(1e-3));
  }
  CHECK_THROWS_WITH(reference.exponent("R_imp", 1e9), Catch::Contains("outside the solved range"));
  CHECK_THROWS_WITH(reference.exponent("speed", 100.0), Catch::Contains("speed"));
}
