// The 8-lane kernel (kinetic/batch.hpp) against the same exact references as the scalar loop
// (test_trajectory.cpp): the equilibrium collision rate n chi S ⟨|g|⟩ and thermalisation in a
// uniform bath given as a grid, the collision count of a heavy impurity against the integral of
// its exact rate in an evolving background, no majorant violation in a steep one; and a lane's
// independence of the other lanes (bit for bit). On a CPU without AVX-512 the cases say so and
// check that advance_batch refuses to run. Tolerances are 4 estimated standard errors; seeds fixed.
#include <catch2/catch.hpp>
#include <cmath>
#include <functional>
#include <vector>

#include "kinetic/batch.hpp"
#include "kinetic/kinetic_theory.hpp"
#include "tests/kinetic/support.hpp"

using namespace coldblast::kinetic;
using coldblast::md::Vec;

namespace {
using namespace coldblast::kinetic_test;

/// False (with a warning) where the CPU has no AVX-512; then advance_batch must refuse.
bool kernel_here() {
  if (batch_available()) return true;
  WARN("this CPU has no AVX-512 F and DQ: the 8-lane kernel's checks do not run here");
  const GridBackground bg = uniform_grid(2, 0.1, 1.0, ContactModel{2, 0.5, 0.5, false});
  TracerState<2> s[batch_lanes];
  std::vector<Random> rngs(batch_lanes, Random(1, 0));
  TracerCounters counters;
  CHECK_THROWS_AS(advance_batch<2>(bg, ImpurityModel{2, 1.0, 1.0}, s, rngs.data(), 1u, 2.0, counters),
                  std::logic_error);
  return false;
}

/// Trajectories 0..count-1, eight at a time: start(i, state, rng) sets the state, then the kernel
/// advances it to t_end, then finish(i, state) reads it.
template <int D>
void run_batches(const GridBackground& bg, const ImpurityModel& impurity, int count, std::uint64_t seed, double t_end,
                 const std::function<void(int, TracerState<D>&, Random&)>& start,
                 const std::function<void(int, const TracerState<D>&)>& finish, TracerCounters& counters) {
  for (int first = 0; first < count; first += batch_lanes) {
    TracerState<D> s[batch_lanes];
    std::vector<Random> rngs;
    unsigned lanes = 0;
    for (int l = 0; l < batch_lanes; ++l) {
      rngs.emplace_back(seed, static_cast<std::uint64_t>(first + l));
      if (first + l >= count) continue;
      start(first + l, s[l], rngs.back());
      lanes |= 1u << l;
    }
    advance_batch<D>(bg, impurity, s, rngs.data(), lanes, t_end, counters);
    for (int l = 0; l < batch_lanes && first + l < count; ++l) finish(first + l, s[l]);
  }
}

template <int D>
void check_collision_rate(double n, bool enskog, double a_imp, double M, double T) {
  const ContactModel contact{D, 0.5, a_imp, enskog};
  const GridBackground bg = uniform_grid(D, n, T, contact);
  const ImpurityModel impurity{D, M, 0.5 + a_imp};
  const double exact = equilibrium_collision_rate(D, n, contact.chi(n), 0.5 + a_imp, T, M);
  const double t0 = 1.0, t1 = t0 + 400.0 / exact;
  Mean rate;
  TracerCounters counters;
  run_batches<D>(
      bg, impurity, 2000, 7, t1,
      [&](int, TracerState<D>& s, Random& rng) {
        s.t = t0;
        s.v = maxwellian<D>(T, M, rng);
      },
      [&](int, const TracerState<D>& s) {
        REQUIRE(s.t == t1);
        rate.add(static_cast<double>(s.collisions) / (t1 - t0));
      },
      counters);
  INFO("d = " << D << ", M = " << M << ", a_imp = " << a_imp << ", Enskog " << enskog << ": rate " << rate.mean()
              << " ± " << rate.error() << ", exact " << exact);
  CHECK(std::abs(rate.mean() - exact) < 4 * rate.error());
  CHECK(rate.error() < 2e-3 * exact);
  CHECK(counters.collisions == static_cast<std::uint64_t>(std::llround(rate.sum * (t1 - t0))));
}

template <int D>
void check_thermalisation(double M) {
  const double T = 1.3;
  const GridBackground bg = uniform_grid(D, 0.2, T, ContactModel{D, 0.5, 0.5, false});
  const ImpurityModel impurity{D, M, 1.0};
  const double nu = equilibrium_collision_rate(D, 0.2, 1.0, 1.0, T, M);
  const double t1 = 1.0 + 25.0 * (M + 1) * (M + 1) / (2 * M) / nu;
  const int samples = 20000;
  MaxwellianCheck maxwellian_check{D, M, T};
  TracerCounters counters;
  run_batches<D>(
      bg, impurity, samples, 11, t1,
      [&](int, TracerState<D>& s, Random&) {
        s.t = 1.0;
        s.v[0] = std::sqrt(2 * 30 * T / M);  // 30 T hot: it must forget the start
      },
      [&](int, const TracerState<D>& s) { maxwellian_check.add(s.v.squaredNorm()); }, counters);
  REQUIRE(maxwellian_check.temperature.count == samples);
  maxwellian_check.check();
}
}  // namespace

TEST_CASE("batch: equilibrium collision rate = n chi S ⟨|g|⟩ in a uniform grid bath") {
  if (!kernel_here()) return;
  check_collision_rate<2>(0.15, false, 0.5, 1.0, 1.0);  // 2 n σ √(πT)
  check_collision_rate<3>(0.1, false, 0.5, 1.0, 1.0);   // 4 n σ² √(πT)
  check_collision_rate<2>(0.15, false, 1.5, 10.0, 2.0);
  check_collision_rate<3>(0.1, false, 0.2, 0.1, 0.5);
  check_collision_rate<2>(0.3, true, 0.5, 1.0, 1.0);  // Enskog chi(n) (Henderson) at phi = 0.236
  check_collision_rate<3>(0.5, true, 1.0, 3.0, 1.0);  // Enskog, unequal radii
}

TEST_CASE("batch: thermalisation to the bath's Maxwellian for any mass ratio") {
  if (!kernel_here()) return;
  for (const double M : {0.1, 1.0, 10.0}) {
    check_thermalisation<2>(M);
    check_thermalisation<3>(M);
  }
}

TEST_CASE("batch: a heavy impurity in a cold, steep, evolving background collides at rate S n |v − u|") {
  if (!kernel_here()) return;
  // As the scalar case of test_trajectory.cpp: the velocity stays v0, so the mean count is the
  // integral of the exact rate along the straight path (composite Simpson, 2e5 intervals).
  const GridBackground bg = cold_inflow_background();
  const ImpurityModel impurity{2, 1e12, 1.0};
  const Vec<2> v0(0.3, 0.1);
  const double t0 = 1.0, t1 = 7.5;
  const double integral = straight_path_collisions(bg, impurity.cross_section(), v0, t0, t1);
  Mean count;
  TracerCounters counters;
  run_batches<2>(
      bg, impurity, 4000, 17, t1,
      [&](int, TracerState<2>& s, Random&) {
        s.t = t0;
        s.v = v0;
      },
      [&](int, const TracerState<2>& s) {
        REQUIRE((s.v - v0).norm() < 1e-9);
        count.add(static_cast<double>(s.collisions));
      },
      counters);
  INFO("collisions " << count.mean() << " ± " << count.error() << ", integral " << integral);
  CHECK(std::abs(count.mean() - integral) < 4 * count.error());
  CHECK(count.error() < 0.005 * integral);
  CHECK(counters.segments < counters.collisions / 2);
}

TEST_CASE("batch: a light impurity in a steep, evolving background never finds a rate above its majorant") {
  if (!kernel_here()) return;
  const double density = GENERATE(2.0, 40.0);
  const GridBackground bg = evolving_background([&](double x, double) {
    return HostState{density * (1 + 199 * std::pow(x, 4)), 0.3 * x, 0.01 * (1 + x)};
  });
  const ImpurityModel impurity{2, 1.0, 1.0};
  TracerCounters counters;
  REQUIRE_NOTHROW(run_batches<2>(
      bg, impurity, density > 10 ? 500 : 4000, 19, 7.9,
      [&](int, TracerState<2>& s, Random& rng) {
        s.t = 1.0;
        s.r = Vec<2>(0.5 * rng.uniform(), 0.0);
        s.v = maxwellian<2>(density > 10 ? 0.02 : 1.0, 1.0, rng);
      },
      [](int, const TracerState<2>& s) { REQUIRE(s.t == 7.9); }, counters));
  INFO(counters.collisions << " collisions, " << counters.segments << " segments");
  CHECK(counters.collisions > 100000);
  if (density > 10) CHECK(counters.segments < counters.collisions / 4);
}

TEST_CASE("batch: a trajectory does not depend on its lane or on the other lanes, bit for bit") {
  if (!kernel_here()) return;
  const GridBackground bg = evolving_background([](double x, double t) {
    return HostState{20 * (1 + 19 * x * x), 0.1 * x / t, 0.02 * (1 + x)};
  });
  const ImpurityModel impurity{2, 2.0, 1.0};
  const auto start = [](int i, TracerState<2>& s) {
    s.t = 1.0 + 0.01 * i;
    s.r = Vec<2>(0.05 * i, 0.02);
    s.v = Vec<2>(0.1, -0.05 * i);
  };
  // Eight trajectories in one batch, advanced to t = 3, then 6.5 (two calls, as the tracer's
  // recording times); lane 3 left out of the second call.
  TracerState<2> together[batch_lanes];
  std::vector<Random> rngs;
  for (int l = 0; l < batch_lanes; ++l) {
    start(l, together[l]);
    rngs.emplace_back(23, static_cast<std::uint64_t>(l));
  }
  TracerCounters counters;
  advance_batch<2>(bg, impurity, together, rngs.data(), 0xffu, 3.0, counters);
  const TracerState<2> lane3 = together[3];
  const auto lane3_stream = rngs[3].state();
  advance_batch<2>(bg, impurity, together, rngs.data(), 0xffu & ~(1u << 3), 6.5, counters);
  CHECK(together[3].t == lane3.t);
  CHECK(together[3].r == lane3.r);
  CHECK(rngs[3].state() == lane3_stream);
  // Each trajectory alone, in lane 5 of an otherwise empty batch.
  for (int i = 0; i < batch_lanes; ++i) {
    TracerState<2> alone[batch_lanes];
    std::vector<Random> own(batch_lanes, Random(99, 99));
    start(i, alone[5]);
    own[5] = Random(23, static_cast<std::uint64_t>(i));
    advance_batch<2>(bg, impurity, alone, own.data(), 1u << 5, 3.0, counters);
    if (i != 3) advance_batch<2>(bg, impurity, alone, own.data(), 1u << 5, 6.5, counters);
    INFO("trajectory " << i);
    CHECK(alone[5].t == together[i].t);
    CHECK(alone[5].r == together[i].r);
    CHECK(alone[5].v == together[i].v);
    CHECK(alone[5].collisions == together[i].collisions);
    CHECK(own[5].state() == rngs[static_cast<std::size_t>(i)].state());
    CHECK(own[0].state() == Random(99, 99).state());  // lanes outside the mask are not touched
  }
  CHECK(counters.collisions > 1000);
}
