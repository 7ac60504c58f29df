// The SIMD versions of the pair evaluator (md/pair_kernel.hpp) against its scalar definitions
// (md/collision.hpp): the AVX2 kernel gives the scalar pair test's earliest contact time bit for
// bit and the same partner (the first among equal times), with and without periodic image shifts;
// the SSE2 pair test gives contact_time_squared's time and decision bit for bit; the SSE2 and AVX2
// crossing times give cell_crossing_time's time and face, ties between axes included; and whole
// engines with simd = false (the scalar definitions) and true give bit-identical trajectories
// (a 3D periodic fluid, whose boundary cells use the shifts, a 3D blast and a 2D blast).
#include <catch2/catch.hpp>
#include <cmath>
#include <random>
#include <vector>

#include "md/collision.hpp"
#include "md/engine.hpp"
#include "md/initial_state.hpp"
#include "md/pair_kernel.hpp"
#include "tests/md/engine_checks.hpp"

using namespace coldblast::md;

namespace {
// The engine's pair test with the scalar definition (engine.cpp, test_pair), written out
// independently: evaluate the pair at the later of the two stored times, keep strictly earlier
// contacts.
EarliestContact scalar_earliest(const std::vector<Particle<3>>& particles, const std::vector<std::int32_t>& ids,
                                const std::vector<Vec<3>>* shifts, const Particle<3>& self, double sigma2,
                                double before) {
  EarliestContact best{before, -1};
  for (std::size_t k = 0; k < ids.size(); ++k) {
    const Particle<3>& q = particles[ids[k]];
    const double reference = std::max(self.time, q.time);
    const Vec<3> own = self.position + self.velocity * (reference - self.time);
    Vec<3> dr = q.position + q.velocity * (reference - q.time) - own;
    if (shifts != nullptr) dr = dr + (*shifts)[k];
    const double t = reference + contact_time_squared<3>(dr, q.velocity - self.velocity, sigma2);
    if (t < best.time) best = {t, static_cast<int>(k)};
  }
  return best;
}

// False (with a warning that says what is not compared) on a CPU without AVX2.
bool has_avx2_or_warn(const char* skipped) {
  if (pair_kernel_available()) return true;
  WARN("this CPU has no AVX2: " << skipped);
  return false;
}

Vec<3> random_vec(std::mt19937_64& rng, double scale) {
  std::uniform_real_distribution<double> u(-scale, scale);
  return Vec<3>(u(rng), u(rng), u(rng));
}
}  // namespace

TEST_CASE("the AVX2 pair kernel gives the scalar pair test's earliest contact bit for bit", "[fast]") {
  if (!has_avx2_or_warn("the engine uses the scalar pair test only, nothing to compare")) return;
  std::mt19937_64 rng(17);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const double sigma2 = 1.0;
  int hits = 0, ties = 0;
  for (int trial = 0; trial < 6000; ++trial) {
    // Particle 0 is the one scanning; candidates are particles 1.. at random states, some at rest,
    // some exactly at its own stored time, a few listed twice (equal times: the first must win).
    const int count = 1 + static_cast<int>(rng() % 40);
    std::vector<Particle<3>> particles(count + 1);
    for (auto& p : particles) {
      p.position = random_vec(rng, 3.0);
      p.velocity = u(rng) < 0.3 ? Vec<3>::Zero() : random_vec(rng, 2.0);
      p.time = u(rng) < 0.3 ? 5.0 : 5.0 * u(rng);
      p.collisions = static_cast<std::uint32_t>(rng() % 100);
    }
    std::vector<std::int32_t> ids;
    for (int j = 1; j <= count; ++j) {
      ids.push_back(j);
      if (u(rng) < 0.1) ids.push_back(j);
    }
    const bool shifted = trial % 2 == 1;
    std::vector<Vec<3>> shifts(ids.size(), Vec<3>::Zero());
    if (shifted)
      for (auto& s : shifts)
        for (int k = 0; k < 3; ++k) s[k] = (static_cast<int>(rng() % 3) - 1) * 0.5;  // small, so pairs still meet
    const double before = u(rng) < 0.2 ? 5.0 + u(rng) : never;
    const EarliestContact expected =
        scalar_earliest(particles, ids, shifted ? &shifts : nullptr, particles[0], sigma2, before);
    // The engine's call: padded to a multiple of 4 with the scanning particle itself.
    std::vector<std::int32_t> padded = ids;
    std::vector<double> sx, sy, sz;
    for (const auto& s : shifts) {
      sx.push_back(s[0]);
      sy.push_back(s[1]);
      sz.push_back(s[2]);
    }
    while (padded.size() % 4 != 0) {
      padded.push_back(0);
      sx.push_back(0.0);
      sy.push_back(0.0);
      sz.push_back(0.0);
    }
    const CandidateShifts candidate_shifts =
        shifted ? CandidateShifts{sx.data(), sy.data(), sz.data()} : CandidateShifts{};
    const EarliestContact got =
        earliest_contact(particles.data(), padded.data(), static_cast<int>(padded.size()), candidate_shifts,
                         particles[0].position, particles[0].velocity, particles[0].time, sigma2, before);
    INFO("trial " << trial);
    REQUIRE(got.index == expected.index);
    REQUIRE(got.time == expected.time);  // bitwise: exact equality of doubles
    hits += expected.index >= 0;
    if (expected.index >= 0 && expected.index + 1 < static_cast<int>(ids.size()) &&
        ids[expected.index + 1] == ids[expected.index])
      ++ties;
  }
  REQUIRE(hits > 1000);  // the comparison covered many real contacts
  REQUIRE(ties > 10);    // and equal times, where the first candidate must win
}

TEST_CASE("the kernel needs a multiple of 4 candidates", "[fast]") {
  if (!pair_kernel_available()) return;
  std::vector<Particle<3>> particles(2);
  const std::int32_t ids[3] = {1, 1, 1};
  REQUIRE_THROWS_AS(earliest_contact(particles.data(), ids, 3, {}, Vec<3>::Zero(), Vec<3>::Zero(), 0.0, 1.0, never),
                    std::invalid_argument);
}

namespace {
template <class Make>
void require_kernel_invariant(const InitialState<3>& s, EngineConfig<3> config, Make&& run,
                              std::uint64_t min_collisions) {
  config.simd = false;
  Engine<3, CalendarEventQueue> scalar(config, s);
  config.simd = true;
  Engine<3, CalendarEventQueue> simd(config, s);
  run(scalar);
  run(simd);
  testing::require_same_trajectory(scalar, simd, min_collisions);
  REQUIRE(scalar.stale_count() == simd.stale_count());  // the same events, too
}

// A periodic box of `count` spheres (radius 1/2) at packing fraction phi, from a lattice at T = 1,
// run `collisions` collisions with and without the kernel (cell_width 0 = automatic).
void require_kernel_invariant_in_box(std::uint64_t seed, std::size_t count, double phi, double cell_width,
                                     std::uint64_t collisions) {
  auto rng = realization_rng(seed, 0);
  EngineConfig<3> config;
  config.periodic = true;
  config.box = Vec<3>::Constant(std::cbrt(count * (M_PI / 6.0) / phi));
  config.cell_width = cell_width;
  const InitialState<3> s = lattice_start<3>(rng, count, 0.5, config.box, 1.0);
  require_kernel_invariant(
      s, config, [collisions](auto& engine) { engine.run_collisions(collisions); }, collisions);
}
}  // namespace

TEST_CASE("engines with and without the SIMD pair kernel give bit-identical trajectories (3D)", "[fast]") {
  has_avx2_or_warn("both engines run the scalar pair test");
  SECTION("periodic fluid at phi = 0.3 (boundary cells scan with image shifts)") {
    require_kernel_invariant_in_box(3, 2000, 0.3, 0.0, 200000);
  }
  SECTION("wide periodic cells: scans of more candidates than one gathered batch holds") {
    // Cells 2 sigma wide at phi = 0.2 hold up to 8 lattice sites each, so a full scan's 27 cells
    // gather more than gather_capacity candidates and the batches must be flushed in between.
    require_kernel_invariant_in_box(5, 4000, 0.2, 2.0, 50000);
  }
  SECTION("blast (open geometry, mostly resting candidates)") {
    auto rng = realization_rng(4, 0);
    const double radius = 22.0;
    InitialState<3> s;
    s.host = s.impurity = {0.5, 1.0};
    const auto count = static_cast<std::size_t>(0.225 * (4.0 / 3.0) * M_PI * radius * radius * radius);
    s.position = random_sequential_addition<3>(rng, count, 0.5, radius);
    s.velocity.assign(count, Vec<3>::Zero());
    s.species.assign(count, host_species);
    kick_impurities<3>(rng, s, 4, 5.7, radius);
    EngineConfig<3> config;
    config.region_radius = 40.0;  // room for the few fast particles that leave the filled ball
    config.guard_radius = 38.0;
    require_kernel_invariant(
        s, config, [](auto& engine) { engine.run_until(100.0); }, 5000);
  }
}

namespace {
// A random cell and a particle in it for the crossing-time comparisons: some axes at rest, every
// 50th particle at rest, and every 7th with axes 0 and 1 reaching their walls at exactly the
// same time (a tie: the lower axis wins).
template <int D>
void crossing_case(std::mt19937_64& rng, int trial, double (&lower)[D], double (&width)[D], Vec<D>& x, Vec<D>& v) {
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (int k = 0; k < D; ++k) {
    lower[k] = -3.0 + 4.0 * u(rng);
    width[k] = 1.0 + 0.1 * u(rng);
    x[k] = lower[k] + width[k] * u(rng);
    v[k] = u(rng) < 0.15 ? 0.0 : 2.0 * u(rng) - 1.0;
  }
  if (trial % 50 == 0) v = Vec<D>::Zero();
  if (trial % 7 == 0) {
    v[0] = v[1] = -0.5;
    x[1] = lower[1] + (x[0] - lower[0]);
  }
}

// Requires `crossing` (a SIMD version) to give cell_crossing_time's time and face code bit for
// bit over many random cases, ties and particles at rest among them.
template <int D, class Crossing>
void require_scalar_crossing(Crossing&& crossing) {
  std::mt19937_64 rng(23);
  int ties = 0, resting = 0;
  for (int trial = 0; trial < 20000; ++trial) {
    double lower[D], width[D];
    Vec<D> x, v;
    crossing_case<D>(rng, trial, lower, width, x, v);
    std::uint8_t expected_code = 255;
    const double best = cell_crossing_time<D>(x, v, lower, width, expected_code);
    std::uint8_t code = 255;
    const double got = crossing(x, v, lower, width, code);
    INFO("trial " << trial);
    REQUIRE(got == best);
    REQUIRE(code == expected_code);
    resting += best == never;
    if (v[0] == v[1] && v[0] != 0.0 && (lower[0] - x[0]) / v[0] == (lower[1] - x[1]) / v[1] && expected_code <= 1)
      ++ties;
  }
  REQUIRE(resting >= 300);  // particles at rest: never, code 0
  REQUIRE(ties > 100);
}
}  // namespace

TEST_CASE("the AVX2 crossing time gives the scalar crossing time and face bit for bit", "[fast]") {
  if (!has_avx2_or_warn("the engine uses the scalar crossing time only, nothing to compare")) return;
  require_scalar_crossing<3>([](const Vec<3>& x, const Vec<3>& v, const double* lower, const double* width,
                                std::uint8_t& code) { return earliest_crossing(x, v, lower, width, code); });
}

TEST_CASE("the SSE2 crossing time gives the scalar crossing time and face bit for bit (2D, 3D)", "[fast]") {
  if constexpr (simd_built) {
    require_scalar_crossing<2>([](const Vec<2>& x, const Vec<2>& v, const double* lower, const double* width,
                                  std::uint8_t& code) { return cell_crossing_time_sse2<2>(x, v, lower, width, code); });
    require_scalar_crossing<3>([](const Vec<3>& x, const Vec<3>& v, const double* lower, const double* width,
                                  std::uint8_t& code) { return cell_crossing_time_sse2<3>(x, v, lower, width, code); });
  } else {
    WARN("this build has no SSE2: the engine runs the scalar definitions only, nothing to compare");
  }
}

TEST_CASE("the SSE2 pair test gives contact_time_squared's contact time and decision bit for bit", "[fast]") {
  if constexpr (simd_built) {
    std::mt19937_64 rng(29);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    int hits = 0, later = 0, overlapping = 0;
    for (int trial = 0; trial < 50000; ++trial) {
      // Pairs at random separations (some overlapping by round-off or more), approaching,
      // receding, at rest relative to each other or passing without touching.
      const Vec<3> dr = random_vec(rng, 3.0);
      const Vec<3> dv = u(rng) < 0.05 ? Vec<3>::Zero() : random_vec(rng, 2.0);
      const double sigma2 = trial % 10 == 0 ? dr.squaredNorm() * (1.0 + 1e-15 * u(rng)) : 0.5 + u(rng);
      const double reference = 5.0 * u(rng);
      const double before = u(rng) < 0.3 ? never : reference + 4.0 * u(rng);
      const double t = reference + contact_time_squared<3>(dr, dv, sigma2);
      double best = before;
      const std::uint32_t keep = earlier_contact_sse2(contact_terms<3>(dr, dv, sigma2), reference, best);
      INFO("trial " << trial);
      REQUIRE(keep == (t < before ? 0u : ~0u));
      REQUIRE(best == (t < before ? t : before));  // bitwise: exact equality of doubles
      hits += t < before;
      later += t < never && t >= before;
      overlapping += t == reference && t < before;
    }
    REQUIRE(hits > 3000);        // many real contacts
    REQUIRE(later > 200);        // contacts after the best so far, which must not replace it
    REQUIRE(overlapping > 100);  // round-off overlaps that collide at once (τ = 0)
  } else {
    WARN("this build has no SSE2: the engine runs the scalar definitions only, nothing to compare");
  }
}

TEST_CASE("engines with the SIMD and the scalar pair evaluator give bit-identical trajectories (2D)", "[fast]") {
  // The 2D blast with equal radii, and with a big impurity (unequal radii: the species lookup of
  // the contact distance, and the big particles' own scans).
  for (const Species impurity : {Species{0.5, 1.0}, Species{2.5, 1.0}}) {
    INFO("impurity radius " << impurity.radius);
    auto rng = realization_rng(11, 0);
    const double radius = 110.0;
    InitialState<2> s;
    s.host = {0.5, 1.0};
    s.impurity = impurity;
    const auto count = static_cast<std::size_t>(0.15 * M_PI * radius * radius);
    s.position = random_sequential_addition<2>(rng, count, 0.5, radius);
    s.velocity.assign(count, Vec<2>::Zero());
    s.species.assign(count, host_species);
    kick_impurities<2>(rng, s, 4, 5.7, radius);
    EngineConfig<2> simd;
    simd.region_radius = 140.0;
    simd.guard_radius = 138.0;
    simd.cell_width = 1.0;  // host-sized cells: the big impurity's wide stencil is in use
    EngineConfig<2> scalar = simd;
    scalar.simd = false;
    Engine<2, CalendarEventQueue> a(simd, s), b(scalar, s);
    a.run_until(400.0);
    b.run_until(400.0);
    testing::require_same_trajectory(a, b, 10000);
    REQUIRE(a.stale_count() == b.stale_count());
  }
}
