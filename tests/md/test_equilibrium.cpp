// Equilibrium hard discs and spheres: Z = βP/n from the collisional virial against Henderson (2D)
// and Carnahan-Starling (3D) within 4 standard errors plus the equations' own accuracy at
// φ <= 0.3 (0.3%: CS lies between the accurate Kolafa fit and the virial series to about that),
// and the exact kinetic-theory link Z - 1 = ν σ √(π m/(4 k_B T)) / d, which needs no equation of
// state: for Maxwellian velocities the collision-averaged normal speed is √(π k_B T/m) (σ = 2a).
#include <catch2/catch.hpp>
#include <cmath>
#include <string>
#include <vector>

#include "md/equilibrium.hpp"

using namespace coldblast::md;

namespace {
void check_equilibrium(int d, double phi, std::uint64_t seed) {
  EquilibriumConfig c;
  c.d = d;
  c.phi = phi;
  c.particles = 2000;
  c.collisions = 1000000;
  c.seed = seed;
  const EquilibriumResult r = run_equilibrium(c);
  INFO("d = " << d << ", phi = " << phi << ", seed = " << seed << ": Z = " << r.Z << " ± " << r.Z_error
              << ", Z(collision rate) = " << r.Z_from_collision_rate << " ± " << r.Z_from_collision_rate_error << ", "
              << r.reference_name << " " << r.Z_reference);
  constexpr double equation_accuracy = 0.003;
  CHECK(std::abs(r.Z - r.Z_reference) < 4.0 * r.Z_error + equation_accuracy * r.Z_reference);
  const double joint = std::hypot(r.Z_error, r.Z_from_collision_rate_error);
  CHECK(std::abs(r.Z - r.Z_from_collision_rate) < 4.0 * joint);
  CHECK(r.Z_error > 0.0);
  CHECK(r.Z_error < 0.01 * (r.Z - 1.0));  // the run is long enough to resolve Z - 1 to 1%
  CHECK(std::abs(r.temperature - 1.0) < 1e-10);
  CHECK(r.energy_error < 1e-12);
}
}  // namespace

TEST_CASE("2D equilibrium pressure: Henderson and the collision-rate identity", "[slow]") {
  check_equilibrium(2, 0.1, 21);
  check_equilibrium(2, 0.3, 22);
}

TEST_CASE("3D equilibrium pressure: Carnahan-Starling and the collision-rate identity", "[slow]") {
  check_equilibrium(3, 0.1, 31);
  check_equilibrium(3, 0.3, 32);
}

TEST_CASE("self-diffusion: unwrapped displacements keep the centre of mass and the ballistic limit", "[fast]") {
  // Over a lag of 60 the particles cross the box (L = 17.4) many times; the unwrapped
  // displacements must still sum to the centre of mass's motion, P t / (N m), to round-off.
  EquilibriumConfig c;
  c.d = 3;
  c.phi = 0.05;
  c.particles = 500;
  c.collisions = 20000;
  c.seed = 7;
  c.diffusion_lag = 60.0;
  c.diffusion_windows = 4;
  const EquilibriumResult r = run_equilibrium(c);
  INFO("L = " << r.box_side << ", <|dr(lag)|^2> = " << r.msd_lag << ", D = " << r.diffusion);
  CHECK(r.msd_lag > 2.0 * r.box_side * r.box_side);  // the images were crossed
  CHECK(r.center_of_mass_error < 1e-12 * r.box_side);
  CHECK(r.diffusion_sample_interval * std::sqrt(2.0 * 1.5 * (c.particles - 1)) <= 0.4 * r.box_side);
  // Far below the collision time 1/ν (ν ≈ 0.77), ⟨|Δr|²⟩ = Δ² Σv²/N = Δ² d T (N − 1)/N up to the
  // fraction νΔ = 8e-4 of particles that collide within the lag.
  c.diffusion_lag = 1e-3;
  c.diffusion_windows = 10;
  const EquilibriumResult b = run_equilibrium(c);
  const double ballistic = 3.0 * b.temperature * (c.particles - 1.0) / c.particles * 1e-6;
  CHECK(std::abs(b.msd_lag / ballistic - 1.0) < 1e-2);
}

TEST_CASE("equilibrium input is validated", "[fast]") {
  EquilibriumConfig c;
  c.phi = 0.6;
  CHECK_THROWS_WITH(run_equilibrium(c), Catch::Contains("phi = 0.6"));
  c = EquilibriumConfig{};
  c.d = 4;
  CHECK_THROWS_WITH(run_equilibrium(c), Catch::Contains("d = 4"));
  c = EquilibriumConfig{};
  c.collisions = 5;
  CHECK_THROWS_WITH(run_equilibrium(c), Catch::Contains("collisions"));
  c = EquilibriumConfig{};
  c.diffusion_lag = -1;
  CHECK_THROWS_WITH(run_equilibrium(c), Catch::Contains("diffusion_lag = -1"));
  c = EquilibriumConfig{};
  c.diffusion_windows = 1;
  CHECK_THROWS_WITH(run_equilibrium(c), Catch::Contains("diffusion_windows = 1"));
}

TEST_CASE("equilibrium progress reports every stage in order and does not change the run", "[fast]") {
  EquilibriumConfig c;
  c.d = 2;
  c.phi = 0.2;
  c.particles = 400;
  c.collisions = 20000;
  c.blocks = 4;
  c.diffusion_lag = 1.0;
  c.diffusion_windows = 3;
  std::vector<std::string> seen;
  const EquilibriumResult with = run_equilibrium(c, [&](const char* stage, long long done, long long total) {
    seen.push_back(std::string(stage) + " " + std::to_string(done) + "/" + std::to_string(total));
  });
  const std::vector<std::string> expected{"equilibration 0/1",
                                          "equilibration 1/1",
                                          "blocks 1/4",
                                          "blocks 2/4",
                                          "blocks 3/4",
                                          "blocks 4/4",
                                          "diffusion windows 1/3",
                                          "diffusion windows 2/3",
                                          "diffusion windows 3/3"};
  CHECK(seen == expected);
  const EquilibriumResult without = run_equilibrium(c);
  CHECK(with.Z == without.Z);
  CHECK(with.diffusion == without.diffusion);
  CHECK(with.collisions_total == without.collisions_total);
}
