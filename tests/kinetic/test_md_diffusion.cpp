// coldblast's MD self-diffusion (md::run_equilibrium's mean squared displacement) against the
// kinetic theory of kinetic/kinetic_theory.hpp: in a dilute 3D hard-sphere fluid the MD's D,
// corrected to the infinite box (Yeh & Hummer), lies above the first Sonine Enskog value by the
// higher Sonine orders (about +2 % for equal spheres: the tracer's exact Monte Carlo of the linear
// Boltzmann–Enskog equation gives 1.019 ± 0.001, docs/verification.md) and by the correlated
// collisions that Enskog's theory leaves out (a few per cent at low density: Alder, Gass &
// Wainwright, J. Chem. Phys. 53, 3813 (1970)), and by at most 8 %.
#include <catch2/catch.hpp>
#include <cmath>

#include "hydro/enskog.hpp"
#include "hydro/navier_stokes.hpp"
#include "kinetic/kinetic_theory.hpp"
#include "md/equilibrium.hpp"
#include "theory/prefactors.hpp"

using namespace coldblast;

TEST_CASE("periodic-box diffusion correction: xi T/(6 pi eta L)") {
  CHECK(kinetic::periodic_box_diffusion_correction(2.0, 0.5, 10.0) == Approx(2.837297 * 2 / (6 * M_PI * 5)));
  CHECK_THROWS_WITH(kinetic::periodic_box_diffusion_correction(1.0, 0.0, 10.0), Catch::Contains("eta"));
}

TEST_CASE("MD self-diffusion of dilute hard spheres against the first Sonine Enskog value", "[slow]") {
  md::EquilibriumConfig c;
  c.d = 3;
  c.phi = 0.05;
  c.particles = 4000;
  c.collisions = 100000;
  c.seed = 41;
  const double a = c.a, n = theory::number_density(3, c.phi, a);
  const double chi = kinetic::pair_contact_value(3, c.phi, a, a);
  const double D1 = kinetic::first_sonine_tracer_diffusion(3, n, chi, 2 * a, 1.0, 1.0);
  c.diffusion_lag = 10.0 * D1;  // ten velocity relaxation times D/T: the estimator's offset is e^-10
  c.diffusion_windows = 20;
  const md::EquilibriumResult r = md::run_equilibrium(c);
  const double eta = hydro::chapman_enskog_viscosity_prefactor(3) * n * theory::mean_free_path(3, n, a) *
                     hydro::enskog_factors(3, c.phi, chi).shear;
  const double D = r.diffusion + kinetic::periodic_box_diffusion_correction(r.temperature, eta, r.box_side);
  INFO("D_MD = " << r.diffusion << " ± " << r.diffusion_error << ", box-corrected " << D << ", D1 = " << D1
                 << ", ratio " << D / D1);
  CHECK(r.diffusion_error < 0.01 * r.diffusion);
  CHECK(D > D1 - 4 * r.diffusion_error);
  CHECK(D < 1.08 * D1 + 4 * r.diffusion_error);
}
