// Tests of hydro/transport: the Chapman–Enskog prefactors of κ and μ (paper Eq. (15) [kappa-HS] with its
// prefactor) against the σ-formulas of Chapman & Cowling and Gass, and the local transport model.
#include <catch2/catch.hpp>
#include <cmath>

#include "hydro/transport.hpp"
#include "theory/prefactors.hpp"

using namespace coldblast;

TEST_CASE("Chapman-Enskog prefactors match the dilute hard-disc and hard-sphere formulas", "[fast]") {
  // κ written directly in σ = 2a (Chapman & Cowling; Gass 1971 for discs), then divided by n λ √T with
  // λ from theory::mean_free_path: an independent route to the same number.
  const double n = 0.37, a = 0.81, T = 2.3;
  const double sigma = 2 * a;
  const double kappa_2d = 2.0 / sigma * std::sqrt(T / M_PI);
  const double kappa_3d = 75.0 / (64.0 * sigma * sigma) * std::sqrt(T / M_PI);
  const double mu_2d = 1.0 / (2 * sigma) * std::sqrt(T / M_PI);
  const double mu_3d = 5.0 / (16.0 * sigma * sigma) * std::sqrt(T / M_PI);
  auto scale = [&](int d) { return n * theory::mean_free_path(d, n, a) * std::sqrt(T); };
  CHECK(hydro::chapman_enskog_kappa_prefactor(2) == Approx(kappa_2d / scale(2)).epsilon(1e-13));
  CHECK(hydro::chapman_enskog_kappa_prefactor(3) == Approx(kappa_3d / scale(3)).epsilon(1e-13));
  CHECK(hydro::chapman_enskog_viscosity_prefactor(2) == Approx(mu_2d / scale(2)).epsilon(1e-13));
  CHECK(hydro::chapman_enskog_viscosity_prefactor(3) == Approx(mu_3d / scale(3)).epsilon(1e-13));
  CHECK(hydro::chapman_enskog_kappa_prefactor(2) == Approx(2 / std::sqrt(M_PI)).epsilon(1e-14));
  CHECK(hydro::chapman_enskog_kappa_prefactor(3) == Approx(75 * std::sqrt(M_PI) / 256).epsilon(1e-14));
  CHECK_THROWS_AS(hydro::chapman_enskog_kappa_prefactor(0), std::invalid_argument);
}

TEST_CASE("the transport model: Fourier's law with kappa sqrt(T), a traceless dilute stress, Enskog's bulk part",
          "[fast]") {
  hydro::TransportModel dilute{2, 1.3, 0.4, false, hydro::Eos::ideal, 0.0, 1.0};
  const hydro::EnskogFactors none = dilute.factors_at(2.0);
  CHECK(none.shear == 1.0);
  CHECK(none.bulk == 0.0);
  CHECK(none.conductivity == 1.0);
  CHECK(dilute.heat_flux(4.0, 0.6, 0.2, none) == Approx(-1.3 * 2.0 * 3.0).epsilon(1e-15));
  // τ_rr + (d-1) τ_θθ = d ζ ∇·u: the shear part is traceless (strains ∂u/∂r and u/r sum to ∇·u)
  const double dudr = 0.7, u_over_r = -0.25, T = 1.7;
  for (int d : {2, 3}) {
    CAPTURE(d);
    const double divergence = dudr + (d - 1) * u_over_r;
    dilute.d = d;
    const double trace =
        dilute.normal_stress(T, dudr, divergence, none) + (d - 1) * dilute.normal_stress(T, u_over_r, divergence, none);
    CHECK(trace == Approx(0.0).margin(1e-15));
    hydro::TransportModel dense{d,     1.3, 0.4, true, d == 2 ? hydro::Eos::henderson : hydro::Eos::carnahan_starling,
                                0.118, 1.0};
    const hydro::EnskogFactors f = dense.factors_at(1.5);  // φ = 0.177
    const hydro::EnskogFactors expected =
        hydro::enskog_factors(d, 0.118 * 1.5, hydro::contact_value(dense.eos, 0.118 * 1.5));
    CHECK(f.shear == expected.shear);
    CHECK(f.bulk == expected.bulk);
    CHECK(dense.heat_flux(4.0, 0.6, 0.2, f) == Approx(-1.3 * 2.0 * 3.0 * f.conductivity).epsilon(1e-15));
    const double dense_trace =
        dense.normal_stress(T, dudr, divergence, f) + (d - 1) * dense.normal_stress(T, u_over_r, divergence, f);
    CHECK(dense_trace == Approx(d * 0.4 * std::sqrt(T) * f.bulk * divergence).epsilon(1e-13));
  }
}
