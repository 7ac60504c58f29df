// The blast's initial state: the impurity kick (exact E, zero momentum, the nearest particles), a
// single impurity's kick (all of E, a random direction), whose blast runs, and the other starts: the
// hot spot (exactly the particles within r0, a Maxwellian of exact E and zero momentum) and a single
// kicked host.
#include <catch2/catch.hpp>
#include <cmath>
#include <string>
#include <vector>

#include "md/initial_state.hpp"
#include "md/realization.hpp"
#include "run/ensemble.hpp"
#include "run/scene_file.hpp"

using namespace coldblast::md;
using coldblast::run::BlastResult;
using coldblast::run::default_scene_toml;
using coldblast::run::parse_scene;
using coldblast::run::run_blast;
using coldblast::run::RunOptions;

TEST_CASE("impurity kick: energy exactly E, momentum exactly zero, the nearest particles", "[fast]") {
  auto rng = realization_rng(11, 3);
  InitialState<3> s;
  s.host = {0.5, 1.0};
  s.impurity = {0.8, 2.5};
  s.position = random_sequential_addition<3>(rng, 3000, 0.5, 15.0);
  s.velocity.assign(3000, Vec<3>::Zero());
  s.species.assign(3000, host_species);
  kick_impurities<3>(rng, s, 5, 7.0, 15.0);
  double energy = 0.0, farthest_impurity = 0.0, nearest_host = 1e9;
  Vec<3> momentum = Vec<3>::Zero();
  int impurities = 0;
  for (std::size_t i = 0; i < s.size(); ++i) {
    if (s.species[i] == impurity_species) {
      ++impurities;
      energy += 0.5 * 2.5 * s.velocity[i].squaredNorm();
      momentum += 2.5 * s.velocity[i];
      farthest_impurity = std::max(farthest_impurity, s.position[i].norm());
    } else {
      nearest_host = std::min(nearest_host, s.position[i].norm());
      CHECK(s.velocity[i].norm() == 0.0);
    }
    for (std::size_t j = i + 1; j < s.size(); ++j) {
      const double sigma = (s.species[i] ? 0.8 : 0.5) + (s.species[j] ? 0.8 : 0.5);
      REQUIRE((s.position[i] - s.position[j]).norm() >= sigma);
    }
  }
  CHECK(impurities == 5);
  CHECK_THAT(energy, Catch::Matchers::WithinRel(7.0, 1e-14));
  CHECK(momentum.norm() < 1e-14 * std::sqrt(2.0 * 2.5 * 7.0));
  CHECK(farthest_impurity < nearest_host);
}

TEST_CASE("a single impurity gets energy E in a random direction and its blast runs", "[fast]") {
  // One impurity cannot have zero momentum: the kick gives it |p| = sqrt(2 m E) (all the energy),
  // in a direction that varies with the seed; the run conserves energy like any other.
  const double E = 3.5, mass = 2.0;
  std::vector<double> directions;
  for (std::uint64_t seed = 1; seed <= 3; ++seed) {
    auto rng = realization_rng(seed, 0);
    InitialState<3> s;
    s.host = {0.5, 1.0};
    s.impurity = {0.5, mass};
    s.position = random_sequential_addition<3>(rng, 200, 0.5, 10.0);
    s.velocity.assign(200, Vec<3>::Zero());
    s.species.assign(200, host_species);
    kick_impurities<3>(rng, s, 1, E, 10.0);
    int impurities = 0;
    for (std::size_t i = 0; i < s.size(); ++i) {
      if (s.species[i] != impurity_species) {
        CHECK(s.velocity[i].squaredNorm() == 0.0);
        continue;
      }
      ++impurities;
      CHECK(0.5 * mass * s.velocity[i].squaredNorm() == Approx(E).epsilon(1e-14));
      CHECK(mass * s.velocity[i].norm() == Approx(std::sqrt(2.0 * mass * E)).epsilon(1e-14));
      directions.push_back(s.velocity[i].x() / s.velocity[i].norm());
    }
    CHECK(impurities == 1);
  }
  REQUIRE(directions.size() == 3);
  CHECK(directions[0] != directions[1]);
  CHECK(directions[1] != directions[2]);
  for (const int d : {2, 3}) {
    INFO("d = " << d);
    // In 3D the lone fast impurity runs ahead of Eq. (1) early on, beyond box_margin 3 × R: the
    // region's early_reach_bound holds it (it needed box_margin 5-6 before).
    const BlastConfig scene = parse_scene(default_scene_toml(), {"d=" + std::to_string(d), "impurities.count=1",
                                                                 "t_max=20", "realizations=2", "A_d=0.3"});
    const BlastResult result = run_blast(scene, RunOptions{});
    CHECK(result.energy_error_max() < 1e-12);
    CHECK(result.collisions() > 10);
  }
}

namespace {
/// A 2D or 3D RSA state of `count` particles in a ball of radius `region` (hosts a = 0.5, mass 1).
template <int D>
InitialState<D> placed_state(std::mt19937_64& rng, std::size_t count, double region, const Species& impurity) {
  InitialState<D> s;
  s.host = {0.5, 1.0};
  s.impurity = impurity;
  s.position = random_sequential_addition<D>(rng, count, 0.5, region);
  s.velocity.assign(count, Vec<D>::Zero());
  s.species.assign(count, host_species);
  return s;
}

template <int D>
double kinetic_energy(const InitialState<D>& s) {
  double energy = 0.0;
  for (std::size_t i = 0; i < s.size(); ++i)
    energy += 0.5 * (s.species[i] == impurity_species ? s.impurity.mass : s.host.mass) * s.velocity[i].squaredNorm();
  return energy;
}

template <int D>
Vec<D> momentum(const InitialState<D>& s) {
  Vec<D> p = Vec<D>::Zero();
  for (std::size_t i = 0; i < s.size(); ++i)
    p += (s.species[i] == impurity_species ? s.impurity.mass : s.host.mass) * s.velocity[i];
  return p;
}

template <int D>
void check_hot_spot(std::uint64_t seed, const Species& impurity, double r0) {
  const double E = 5.7;
  auto rng = realization_rng(seed, 2);
  const double region = D == 2 ? 60.0 : 13.0;  // phi = 0.14 (2D), 0.11 (3D)
  InitialState<D> s = placed_state<D>(rng, 2000, region, impurity);
  const StartReport report = start_blast<D>(rng, s, {StartKind::hotspot, r0}, 4, E, region);
  // The hot set is exactly {i : |x_i| <= r0}, found here by a plain scan after the start; every
  // other particle rests; the four impurities (the nearest particles) are in it.
  std::vector<std::int32_t> inside;
  int impurities = 0;
  for (std::size_t i = 0; i < s.size(); ++i) {
    const bool in = s.position[i].norm() <= r0;
    if (in) inside.push_back(static_cast<std::int32_t>(i));
    if (!in) CHECK(s.velocity[i].squaredNorm() == 0.0);
    if (in) CHECK(s.velocity[i].squaredNorm() > 0.0);
    if (s.species[i] == impurity_species) {
      ++impurities;
      CHECK(in);
    }
  }
  CHECK(impurities == 4);
  CHECK(report.heated == inside);
  CHECK(inside.size() > 4);
  // Round-off bounds: E to 1e-12 relative, |P| to 1e-12 of the momentum scale sqrt(2 M E).
  CHECK_THAT(kinetic_energy(s), Catch::Matchers::WithinRel(E, 1e-12));
  double mass = 0.0;
  for (const std::int32_t id : inside) mass += s.species[id] == impurity_species ? impurity.mass : 1.0;
  CHECK(momentum(s).norm() < 1e-12 * std::sqrt(2.0 * mass * E));
}
}  // namespace

TEST_CASE("hot-spot start: exactly the particles within r0 share E with zero momentum", "[fast]") {
  for (std::uint64_t seed = 1; seed <= 3; ++seed) {
    INFO("seed " << seed);
    check_hot_spot<2>(seed, {0.5, 1.0}, 6.0);
    check_hot_spot<2>(seed, {0.5, 3.0}, 4.0);  // heavier impurities: the centre-of-mass velocity is mass-weighted
    check_hot_spot<3>(seed, {0.5, 1.0}, 3.0);
    check_hot_spot<3>(seed, {0.9, 0.2}, 3.5);  // larger, lighter impurities (hosts displaced first)
  }
  // A hot spot that misses an impurity or holds one particle names start.r0.
  auto rng = realization_rng(4, 0);
  InitialState<2> s = placed_state<2>(rng, 2000, 60.0, {0.5, 1.0});
  CHECK_THROWS_WITH(start_blast<2>(rng, s, {StartKind::hotspot, 0.2}, 4, 1.0, 60.0),
                    Catch::Contains("start.r0 = 0.2") && Catch::Contains("raise start.r0"));
}

TEST_CASE("hot-spot start: the velocities are a Maxwellian with equipartition between the species", "[fast]") {
  // Over many hot spots: each velocity component has kurtosis <v^4>/<v^2>^2 = 3 (Gaussian; a kick of
  // fixed speed would give 1.5 in 2D), and hosts and impurities of mass 3 carry the same mean
  // kinetic energy per particle (both within 4 standard errors, estimated from the samples). Fixing
  // the total momentum and energy of N ~ 30 particles biases both by O(1/N) (kurtosis 3 f/(f + 2) with
  // f ~ 2N degrees of freedom: -0.1; energies (1 - m/M): 5 %), below one standard error here.
  std::vector<double> v2, v4, host_energy, impurity_energy;
  for (std::uint64_t index = 0; index < 200; ++index) {
    auto rng = realization_rng(9, index);
    InitialState<2> s = placed_state<2>(rng, 800, 40.0, {0.5, 3.0});  // phi = 0.125; ~30 particles within r0
    const StartReport report = start_blast<2>(rng, s, {StartKind::hotspot, 8.0}, 4, 1.0, 40.0);
    const double per_particle = 1.0 / static_cast<double>(report.heated.size());  // mean energy
    for (const std::int32_t id : report.heated) {
      const double m = s.species[id] == impurity_species ? 3.0 : 1.0;
      const double scaled_x = std::sqrt(m / per_particle) * s.velocity[id].x();  // unit variance
      v2.push_back(scaled_x * scaled_x);
      v4.push_back(std::pow(scaled_x, 4));
      (m == 3.0 ? impurity_energy : host_energy).push_back(0.5 * m * s.velocity[id].squaredNorm() / per_particle);
    }
  }
  const auto mean = [](const std::vector<double>& x) {
    double sum = 0.0;
    for (const double v : x) sum += v;
    return sum / static_cast<double>(x.size());
  };
  const auto error = [&](const std::vector<double>& x) {
    const double m = mean(x);
    double sum = 0.0;
    for (const double v : x) sum += (v - m) * (v - m);
    return std::sqrt(sum / (x.size() - 1.0) / static_cast<double>(x.size()));
  };
  const double m2 = mean(v2), m4 = mean(v4);
  const double kurtosis = m4 / (m2 * m2);
  // Error of the ratio, to first order from the two means (kurtosis 3: sd(v^4) = sqrt(96), sd(v^2) = sqrt(2)).
  const double kurtosis_error = kurtosis * std::hypot(error(v4) / m4, 2.0 * error(v2) / m2);
  INFO("kurtosis " << kurtosis << " +- " << kurtosis_error << " from " << v2.size() << " velocities");
  CHECK(std::abs(kurtosis - 3.0) < 4.0 * kurtosis_error);
  const double difference = mean(impurity_energy) - mean(host_energy);
  const double difference_error = std::hypot(error(impurity_energy), error(host_energy));
  INFO("impurity - host energy per particle " << difference << " +- " << difference_error);
  CHECK(std::abs(difference) < 4.0 * difference_error);
}

TEST_CASE("single start: the host nearest the origin gets all of E; the impurities rest", "[fast]") {
  const double E = 2.5;
  for (std::uint64_t seed = 1; seed <= 3; ++seed) {
    auto rng = realization_rng(seed, 5);
    InitialState<3> s = placed_state<3>(rng, 1500, 12.0, {0.5, 2.0});
    const StartReport report = start_blast<3>(rng, s, {StartKind::single, 0.0}, 4, E, 12.0);
    std::int32_t nearest_host = -1;
    for (std::size_t i = 0; i < s.size(); ++i)
      if (s.species[i] == host_species && (nearest_host < 0 || s.position[i].norm() < s.position[nearest_host].norm()))
        nearest_host = static_cast<std::int32_t>(i);
    REQUIRE(report.heated == std::vector<std::int32_t>{nearest_host});
    for (std::size_t i = 0; i < s.size(); ++i)
      if (static_cast<std::int32_t>(i) != nearest_host) CHECK(s.velocity[i].squaredNorm() == 0.0);
    // One particle cannot have zero momentum: |P| = sqrt(2 m E) exactly (round-off), m = 1.
    CHECK_THAT(kinetic_energy(s), Catch::Matchers::WithinRel(E, 1e-12));
    CHECK_THAT(momentum(s).norm(), Catch::Matchers::WithinRel(std::sqrt(2.0 * E), 1e-12));
  }
}

TEST_CASE("kick start: start_blast is kick_impurities bit for bit", "[fast]") {
  // The kick scenes' trajectories (docs/benchmarks.md's checksums) must not change: the same draws
  // in the same order, for equal and unequal masses and for larger impurities.
  for (const Species impurity : {Species{0.5, 1.0}, Species{0.5, 10.0}, Species{1.5, 1.0}}) {
    auto first = realization_rng(21, 1), second = realization_rng(21, 1);
    InitialState<2> a = placed_state<2>(first, 3000, 60.0, impurity), b = placed_state<2>(second, 3000, 60.0, impurity);
    kick_impurities<2>(first, a, 4, 5.7, 60.0);
    const StartReport report = start_blast<2>(second, b, {StartKind::kick, 0.0}, 4, 5.7, 60.0);
    CHECK(report.heated.size() == 4);
    for (std::size_t i = 0; i < a.size(); ++i) {
      REQUIRE(a.position[i] == b.position[i]);
      REQUIRE(a.velocity[i] == b.velocity[i]);
      REQUIRE(a.species[i] == b.species[i]);
    }
    CHECK(first() == second());  // the generators are in the same state too
  }
}

TEST_CASE("hot-spot and single-host blasts start with E from their scene and conserve it", "[fast]") {
  for (const int d : {2, 3}) {
    for (const std::string kind : {"hotspot", "single"}) {
      INFO("d = " << d << ", start " << kind);
      std::vector<std::string> set = {"d=" + std::to_string(d), "t_max=30", "realizations=2", "A_d=0.3",
                                      "start.kind=" + kind};
      if (kind == "hotspot") set.push_back(d == 2 ? "start.r0=5" : "start.r0=3");
      const BlastConfig scene = parse_scene(default_scene_toml(), set);
      const ResolvedScene resolved = resolve_scene(scene);
      double energy = 0.0;
      std::size_t moving = 0;
      if (d == 2) {
        const InitialState<2> s = blast_initial_state<2>(resolved, 1);
        energy = kinetic_energy(s);
        for (const auto& v : s.velocity) moving += v.squaredNorm() > 0.0;
      } else {
        const InitialState<3> s = blast_initial_state<3>(resolved, 1);
        energy = kinetic_energy(s);
        for (const auto& v : s.velocity) moving += v.squaredNorm() > 0.0;
      }
      CHECK_THAT(energy, Catch::Matchers::WithinRel(scene.E, 1e-12));
      CHECK((kind == "single" ? moving == 1 : moving > 4));
      // The run keeps E to round-off (|E_kin(t_max) - E|/E, the engine's own check).
      const BlastResult result = run_blast(scene, RunOptions{});
      CHECK(result.energy_error_max() < 1e-12);
      CHECK(result.collisions() > 10);
    }
  }
}
