// The vector lanes (kinetic/batch.hpp), in every kernel this CPU runs (AVX-512, AVX2 and SSE4
// here; NEON on AArch64), against the same exact references as the scalar loop
// (test_trajectory.cpp): the equilibrium collision rate n chi S ⟨|g|⟩ and thermalisation in a
// uniform bath given as a grid, the collision count of a heavy impurity against the integral of
// its exact rate in an evolving background, no majorant violation in a steep one; a lane's
// independence of the other lanes (bit for bit); the kernels' vector log, exp, sin and cos against
// long-double references; and the choice of --kernel. Tolerances are 4 estimated standard errors;
// seeds fixed.
#include <hwy/targets.h>

#include <catch2/catch.hpp>
#include <cmath>
#include <functional>
#include <string>
#include <vector>

#include "kinetic/batch.hpp"
#include "kinetic/kinetic_theory.hpp"
#include "tests/kinetic/support.hpp"

using namespace coldblast::kinetic;
using coldblast::md::Vec;

namespace {
using namespace coldblast::kinetic_test;

constexpr unsigned all_lanes = (1u << batch_lanes) - 1;

/// The kernels this CPU runs; where there is none, {""} (a warning), and a kernel is refused.
std::vector<std::string> kernels_here() {
  const std::vector<std::string> kernels = batch_kernels();
  if (kernels.empty()) {
    WARN("this CPU (or build) runs no vector kernel: the lanes' checks do not run here");
    const GridBackground bg = uniform_grid(2, 0.1, 1.0, ContactModel{2, 0.5, 0.5, false});
    TracerState<2> s[batch_lanes];
    std::vector<Random> rngs(batch_lanes, Random(1, 0));
    TracerCounters counters;
    CHECK_THROWS_AS(advance_batch<2>(bg, ImpurityModel{2, 1.0, 1.0}, "avx2", s, rngs.data(), 1u, 2.0, counters),
                    std::invalid_argument);
    return {""};
  }
  return kernels;
}

/// Trajectories 0..count-1, batch_lanes at a time: start(i, state, rng) sets the state, then the kernel
/// advances it to t_end, then finish(i, state) reads it.
template <int D>
void run_batches(const std::string& kernel, const GridBackground& bg, const ImpurityModel& impurity, int count,
                 std::uint64_t seed, double t_end, const std::function<void(int, TracerState<D>&, Random&)>& start,
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
    advance_batch<D>(bg, impurity, kernel, s, rngs.data(), lanes, t_end, counters);
    for (int l = 0; l < batch_lanes && first + l < count; ++l) finish(first + l, s[l]);
  }
}

template <int D>
void check_collision_rate(const std::string& kernel, double n, bool enskog, double a_imp, double M, double T) {
  const ContactModel contact{D, 0.5, a_imp, enskog};
  const GridBackground bg = uniform_grid(D, n, T, contact);
  const ImpurityModel impurity{D, M, 0.5 + a_imp};
  const double exact = equilibrium_collision_rate(D, n, contact.chi(n), 0.5 + a_imp, T, M);
  const double t0 = 1.0, t1 = t0 + 400.0 / exact;
  Mean rate;
  TracerCounters counters;
  run_batches<D>(
      kernel, bg, impurity, 2000, 7, t1,
      [&](int, TracerState<D>& s, Random& rng) {
        s.t = t0;
        s.v = maxwellian<D>(T, M, rng);
      },
      [&](int, const TracerState<D>& s) {
        REQUIRE(s.t == t1);
        rate.add(static_cast<double>(s.collisions) / (t1 - t0));
      },
      counters);
  INFO(kernel << ": d = " << D << ", M = " << M << ", a_imp = " << a_imp << ", Enskog " << enskog << ": rate "
              << rate.mean() << " ± " << rate.error() << ", exact " << exact);
  CHECK(std::abs(rate.mean() - exact) < 4 * rate.error());
  CHECK(rate.error() < 2e-3 * exact);
  CHECK(counters.collisions == static_cast<std::uint64_t>(std::llround(rate.sum * (t1 - t0))));
}

template <int D>
void check_thermalisation(const std::string& kernel, double M) {
  const double T = 1.3;
  const GridBackground bg = uniform_grid(D, 0.2, T, ContactModel{D, 0.5, 0.5, false});
  const ImpurityModel impurity{D, M, 1.0};
  const double nu = equilibrium_collision_rate(D, 0.2, 1.0, 1.0, T, M);
  const double t1 = 1.0 + 25.0 * (M + 1) * (M + 1) / (2 * M) / nu;
  const int samples = 20000;
  MaxwellianCheck maxwellian_check{D, M, T};
  TracerCounters counters;
  run_batches<D>(
      kernel, bg, impurity, samples, 11, t1,
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
  const std::string kernel = GENERATE(from_range(kernels_here()));
  if (kernel.empty()) return;
  CAPTURE(kernel);
  check_collision_rate<2>(kernel, 0.15, false, 0.5, 1.0, 1.0);  // 2 n σ √(πT)
  check_collision_rate<3>(kernel, 0.1, false, 0.5, 1.0, 1.0);   // 4 n σ² √(πT)
  check_collision_rate<2>(kernel, 0.15, false, 1.5, 10.0, 2.0);
  check_collision_rate<3>(kernel, 0.1, false, 0.2, 0.1, 0.5);
  check_collision_rate<2>(kernel, 0.3, true, 0.5, 1.0, 1.0);  // Enskog chi(n) (Henderson) at phi = 0.236
  check_collision_rate<3>(kernel, 0.5, true, 1.0, 3.0, 1.0);  // Enskog, unequal radii
}

TEST_CASE("batch: thermalisation to the bath's Maxwellian for any mass ratio") {
  const std::string kernel = GENERATE(from_range(kernels_here()));
  if (kernel.empty()) return;
  CAPTURE(kernel);
  for (const double M : {0.1, 1.0, 10.0}) {
    check_thermalisation<2>(kernel, M);
    check_thermalisation<3>(kernel, M);
  }
}

TEST_CASE("batch: a heavy impurity in a cold, steep, evolving background collides at rate S n |v − u|") {
  const std::string kernel = GENERATE(from_range(kernels_here()));
  if (kernel.empty()) return;
  CAPTURE(kernel);
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
      kernel, bg, impurity, 4000, 17, t1,
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
  const std::string kernel = GENERATE(from_range(kernels_here()));
  if (kernel.empty()) return;
  CAPTURE(kernel);
  const double density = GENERATE(2.0, 40.0);
  const GridBackground bg = evolving_background([&](double x, double) {
    return HostState{density * (1 + 199 * std::pow(x, 4)), 0.3 * x, 0.01 * (1 + x)};
  });
  const ImpurityModel impurity{2, 1.0, 1.0};
  TracerCounters counters;
  REQUIRE_NOTHROW(run_batches<2>(
      kernel, bg, impurity, density > 10 ? 500 : 4000, 19, 7.9,
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

namespace {
/// batch_lanes trajectories of a dense, evolving background (every process of a step: segment ends,
/// rejections, both partner laws, collisions, reused and fresh segments), started in lane l.
template <int D>
void start_lane(int l, TracerState<D>& s, Random& rng) {
  s.t = 1.0 + 0.01 * l;
  s.r[0] = 0.05 * l;
  s.r[1] = 0.02;
  s.v[0] = 0.1;
  s.v[1] = -0.05 * l;
  if constexpr (D == 3) s.v[2] = 0.03;
  rng = Random(23, static_cast<std::uint64_t>(l));
}

template <int D>
GridBackground dense_background() {
  return evolving_background(
      [](double x, double t) {
        return HostState{20 * (1 + 19 * x * x), 0.1 * x / t, 0.02 * (1 + x)};
      },
      D);
}

/// The batch_lanes trajectories of start_lane in one batch of `kernel` to t = 3, then 6.5 (two calls, as
/// the tracer's recording times), lane 3 left out of the second call.
template <int D>
void run_batch(const std::string& kernel, TracerState<D>* states, std::vector<Random>& rngs, TracerCounters& counters) {
  const GridBackground bg = dense_background<D>();
  const ImpurityModel impurity{D, 2.0, 1.0};
  rngs.assign(batch_lanes, Random(0, 0));
  for (int l = 0; l < batch_lanes; ++l) start_lane<D>(l, states[l], rngs[static_cast<std::size_t>(l)]);
  advance_batch<D>(bg, impurity, kernel, states, rngs.data(), all_lanes, 3.0, counters);
  advance_batch<D>(bg, impurity, kernel, states, rngs.data(), all_lanes & ~(1u << 3), 6.5, counters);
}

template <int D>
void check_lane_independence(const std::string& kernel) {
  const GridBackground bg = dense_background<D>();
  const ImpurityModel impurity{D, 2.0, 1.0};
  TracerState<D> together[batch_lanes];
  std::vector<Random> rngs;
  TracerCounters counters;
  run_batch<D>(kernel, together, rngs, counters);
  // Each trajectory alone, in lane 5 of an otherwise empty batch (another vector than most).
  for (int i = 0; i < batch_lanes; ++i) {
    TracerState<D> alone[batch_lanes];
    std::vector<Random> own(batch_lanes, Random(99, 99));
    start_lane<D>(i, alone[5], own[5]);
    advance_batch<D>(bg, impurity, kernel, alone, own.data(), 1u << 5, 3.0, counters);
    if (i == 3) {  // left out of the second call: where the first left it
      CHECK(together[3].t == 3.0);
    } else {
      advance_batch<D>(bg, impurity, kernel, alone, own.data(), 1u << 5, 6.5, counters);
    }
    INFO("d = " << D << ", trajectory " << i);
    CHECK(alone[5].t == together[i].t);
    CHECK(alone[5].r == together[i].r);
    CHECK(alone[5].v == together[i].v);
    CHECK(alone[5].collisions == together[i].collisions);
    CHECK(own[5].state() == rngs[static_cast<std::size_t>(i)].state());
    CHECK(own[0].state() == Random(99, 99).state());  // lanes outside the mask are not touched
  }
  CHECK(counters.collisions > 1000);
}
}  // namespace

TEST_CASE("batch: a trajectory does not depend on its lane or on the other lanes, bit for bit") {
  const std::string kernel = GENERATE(from_range(kernels_here()));
  if (kernel.empty()) return;
  CAPTURE(kernel);
  check_lane_independence<2>(kernel);
  check_lane_independence<3>(kernel);
}

TEST_CASE("batch: the AVX-512 and AVX2 kernels (both with FMA) give the same trajectories, bit for bit") {
  if (!batch_available("avx512") || !batch_available("avx2")) {
    WARN("this CPU does not run both the avx512 and the avx2 kernel");
    return;
  }
  const auto check = [](auto dimension) {
    constexpr int D = decltype(dimension)::value;
    TracerState<D> wide[batch_lanes], narrow[batch_lanes];
    std::vector<Random> wide_rngs, narrow_rngs;
    TracerCounters wide_counters, narrow_counters;
    run_batch<D>("avx512", wide, wide_rngs, wide_counters);
    run_batch<D>("avx2", narrow, narrow_rngs, narrow_counters);
    for (int l = 0; l < batch_lanes; ++l) {
      INFO("d = " << D << ", trajectory " << l);
      CHECK(wide[l].t == narrow[l].t);
      CHECK(wide[l].r == narrow[l].r);
      CHECK(wide[l].v == narrow[l].v);
      CHECK(wide[l].collisions == narrow[l].collisions);
      CHECK(wide_rngs[static_cast<std::size_t>(l)].state() == narrow_rngs[static_cast<std::size_t>(l)].state());
    }
    CHECK(wide_counters.collisions == narrow_counters.collisions);
    CHECK(wide_counters.candidates == narrow_counters.candidates);
    CHECK(wide_counters.collisions > 400);
  };
  check(std::integral_constant<int, 2>());
  check(std::integral_constant<int, 3>());
}

namespace {
/// Checks that `kernel`'s vector f is within `bound` units in the last place of the double
/// nearest the long-double reference at every x.
void check_ulps(const std::string& kernel, BatchMath f, long double (*reference)(long double),
                const std::vector<double>& x, double bound) {
  std::vector<double> y(x.size());
  batch_math(kernel, f, x.data(), y.data(), x.size());
  double worst = 0.0, worst_x = 0.0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    const long double exact = reference(x[i]);
    const long double ulp =  // the spacing of doubles at |exact|, 2^-1074 among the subnormals
        exact == 0 ? 0x1p-1074L : std::max(std::ldexp(1.0L, std::ilogb(static_cast<double>(exact)) - 52), 0x1p-1074L);
    const double error = static_cast<double>(std::abs(static_cast<long double>(y[i]) - exact) / ulp);
    if (error > worst) {
      worst = error;
      worst_x = x[i];
    }
  }
  INFO("function " << static_cast<int>(f) << ": " << worst << " ulp at x = " << worst_x << " (of " << x.size()
                   << " points from " << x.front() << ")");
  CHECK(worst <= bound);
}
}  // namespace

TEST_CASE(
    "batch: the kernels' vector log and exp are within Highway's stated ulp bounds, cos 2πu and sin 2πu within 2") {
  const std::string kernel = GENERATE(from_range(kernels_here()));
  if (kernel.empty()) return;
  CAPTURE(kernel);
  // The kernel's arguments (−ln U with U = 1 − k 2^-53, the background's times and scales,
  // Box–Muller's U) and log's and exp's whole valid ranges (Highway: (0, DBL_MAX] and
  // [−DBL_MAX, 706]); 2^16 random points each (seed 1), and the quarter turns of cos and sin.
  Random rng(1, 0);
  const int count = 1 << 16;
  std::vector<double> uniform_positive, times, positive, exponents, wide_exponents, turns;
  for (int i = 0; i < count; ++i) {
    uniform_positive.push_back(rng.uniform_positive());
    times.push_back(std::pow(10.0, -3.0 + 19.0 * rng.uniform()));
    positive.push_back(std::ldexp(1.0 + rng.uniform(), static_cast<int>(rng.next() % 2045) - 1022));
    exponents.push_back(-2.0 + 4.0 * rng.uniform());
    wide_exponents.push_back(-700.0 + 1406.0 * rng.uniform());
    turns.push_back(rng.uniform());
  }
  for (int k = 0; k < 8; ++k) turns.insert(turns.end(), {k / 8.0, std::nextafter(k / 8.0, 1.0)});
  turns.push_back(std::nextafter(1.0, 0.0));
  const auto logl_ = [](long double x) { return std::log(x); };
  const auto expl_ = [](long double x) { return std::exp(x); };
  // In long double from u's nearest quarter turn (exact), so that the references stay accurate
  // near the zeros of cos 2πu and sin 2πu.
  const auto cos_2pi = [](long double u) {
    const long double q = std::nearbyint(4 * u), x = 6.283185307179586476925286766559L * (u - q / 4);
    const int quarter = static_cast<int>(q) % 4;
    return quarter == 0 ? std::cos(x) : quarter == 1 ? -std::sin(x) : quarter == 2 ? -std::cos(x) : std::sin(x);
  };
  const auto sin_2pi = [](long double u) {
    const long double q = std::nearbyint(4 * u), x = 6.283185307179586476925286766559L * (u - q / 4);
    const int quarter = static_cast<int>(q) % 4;
    return quarter == 0 ? std::sin(x) : quarter == 1 ? std::cos(x) : quarter == 2 ? -std::sin(x) : -std::cos(x);
  };
  for (const auto* x : {&uniform_positive, &times, &positive}) check_ulps(kernel, BatchMath::log, logl_, *x, 4);
  for (const auto* x : {&exponents, &wide_exponents}) check_ulps(kernel, BatchMath::exp, expl_, *x, 1);
  check_ulps(kernel, BatchMath::cos_2pi, cos_2pi, turns, 2);
  check_ulps(kernel, BatchMath::sin_2pi, sin_2pi, turns, 2);
  // The array's tail (fewer values than a vector holds) is computed too.
  double tail[3] = {0, 0, 0};
  batch_math(kernel, BatchMath::exp, exponents.data(), tail, 3);
  for (int i = 0; i < 3; ++i)  // within Highway's 1 ulp and glibc's 1 ulp
    CHECK(std::abs(tail[i] - std::exp(exponents[static_cast<std::size_t>(i)])) <= 0x1p-51 * tail[i]);
}

TEST_CASE("batch: --kernel auto takes the widest kernel this CPU runs; one it lacks is refused naming those it runs") {
  const std::vector<std::string> here = batch_kernels();
  CHECK(resolve_kernel("scalar", true) == "scalar");
  CHECK(resolve_kernel("auto", false) == "scalar");  // the equilibrium background: the scalar loop
  CHECK(resolve_kernel("auto", true) == (here.empty() ? "scalar" : here.front()));
  for (const std::string& kernel : here) {
    CHECK(resolve_kernel(kernel, true) == kernel);
    CHECK_THROWS_WITH(resolve_kernel(kernel, false), Catch::Contains("--kernel = " + kernel) &&
                                                         Catch::Contains("allowed with equilibrium: auto, scalar"));
  }
  CHECK_THROWS_WITH(resolve_kernel("simd", true), Catch::Contains("--kernel = simd is not one of: auto, avx512, avx2, "
                                                                  "sse4, neon, scalar; allowed on this CPU: auto"));
  if (here.empty() || here.front() != "avx512") {
    WARN("the refusal of a kernel the CPU lacks is checked on a CPU with AVX-512");
    return;
  }
  // An x86-64 CPU with AVX2 but no AVX-512, as Highway's mock of the CPU's targets.
  hwy::SetSupportedTargetsForTest(HWY_AVX2 | HWY_SSE4 | HWY_SCALAR);
  const std::vector<std::string> without = batch_kernels();
  const std::string chosen = resolve_kernel("auto", true);
  std::string refusal, batch_refusal;
  try {
    resolve_kernel("avx512", true);
  } catch (const std::invalid_argument& e) {
    refusal = e.what();
  }
  const GridBackground bg = uniform_grid(2, 0.1, 1.0, ContactModel{2, 0.5, 0.5, false});
  try {
    Batch<2> batch(bg, ImpurityModel{2, 1.0, 1.0}, "avx512");
  } catch (const std::invalid_argument& e) {
    batch_refusal = e.what();
  }
  hwy::SetSupportedTargetsForTest(0);  // the real CPU again
  CHECK(without == std::vector<std::string>{"avx2", "sse4"});
  CHECK(chosen == "avx2");
  CHECK(refusal ==
        "--kernel = avx512: this CPU (or build) does not run it; allowed on this CPU: auto, avx2, sse4, scalar");
  CHECK_THAT(batch_refusal, Catch::Contains("avx512") && Catch::Contains("allowed: avx2, sse4"));
  CHECK(batch_kernels() == here);
}
