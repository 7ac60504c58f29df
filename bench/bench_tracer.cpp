// The kinetic tracer's hot path (kinetic/trajectory.hpp, paper Eq. (36)): collisions per second of
// kinetic::advance in a uniform bath and in the late core of the paper's 2D and 3D blasts at
// R/λ ≈ 10⁶ (the regime of issue 13's second performance target), and the cost of one host-state
// lookup in the Navier–Stokes background (a direct time slice, or one derived from an anchor);
// the same late core in the vector lanes of kinetic/batch.hpp, once per kernel this CPU runs.
// Counters: collisions/s (items), candidates per collision. Results: docs/benchmarks.md.
#include <benchmark/benchmark.h>

#include <cmath>
#include <fstream>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "kinetic/background.hpp"
#include "kinetic/batch.hpp"
#include "kinetic/tracer.hpp"
#include "kinetic/trajectory.hpp"
#include "run/scene_file.hpp"

namespace {

using namespace coldblast;
constexpr double pi = 3.14159265358979323846;

kinetic::TracerConfig paper_scene(int d, double t_max) {
  std::ifstream in(std::string(COLDBLAST_SCENES_DIR) + (d == 2 ? "/paper-2d.toml" : "/paper-3d.toml"));
  std::ostringstream text;
  text << in.rdbuf();
  kinetic::TracerConfig c;
  c.scene = coldblast::run::parse_scene(text.str(), {"t_max=" + std::to_string(t_max)});
  c.transport = "enskog";
  return c;
}

/// The paper scene's dense Navier–Stokes background up to R/λ ≈ 10⁶, solved once per d (≈ 2 s).
struct LateScene {
  kinetic::TracerConfig config;
  std::unique_ptr<kinetic::Background> background;
};
const LateScene& late_scene(int d) {
  static const auto make = [](int dim) {
    LateScene s{paper_scene(dim, dim == 2 ? 3.7e12 : 7.9e15), nullptr};
    s.background = kinetic::make_background(s.config);
    return s;
  };
  static const LateScene two = make(2), three = make(3);
  return d == 2 ? two : three;
}

void report(benchmark::State& state, const kinetic::TracerCounters& counters) {
  state.SetItemsProcessed(static_cast<std::int64_t>(counters.collisions));
  state.counters["candidates_per_collision"] =
      static_cast<double>(counters.candidates) / static_cast<double>(counters.collisions);
  state.counters["segments_per_collision"] =
      static_cast<double>(counters.segments) / static_cast<double>(counters.collisions);
}

/// An equal-mass impurity in a uniform bath at the MD's φ = 0.118 (2D) or 0.1 (3D), T = 1, Enskog χ:
/// 1000 mean free times per iteration.
template <int D>
void equilibrium(benchmark::State& state) {
  const double phi = D == 2 ? 0.118 : 0.1, a = 0.5;
  const double n = D == 2 ? phi / (pi * a * a) : phi / (4.0 / 3.0 * pi * a * a * a);
  const kinetic::ContactModel contact{D, a, a, true};
  const kinetic::EquilibriumBackground bath(D, n, 1.0, contact);
  const kinetic::ImpurityModel impurity{D, 1.0, 2 * a};
  kinetic::Random rng(1, 0);
  kinetic::TracerState<D> s;
  s.v[0] = 1.0;
  kinetic::TracerCounters counters;
  for (auto _ : state) kinetic::advance<D>(bath, impurity, s, s.t + 1000.0 / (n * 4.0), rng, counters);
  report(state, counters);
}

/// A thermal impurity at the blast's centre, advanced through the core from t_max/2 to t_max of the
/// R/λ ≈ 10⁶ scene (≈ 10⁴ collisions per iteration): the per-collision cost of the late regime.
template <int D>
void late_core(benchmark::State& state) {
  const LateScene& scene = late_scene(D);
  const double t_max = scene.config.scene.t_max;
  const kinetic::ImpurityModel impurity{D, 1.0, 2 * scene.config.scene.a};
  kinetic::Random rng(2, 0);
  kinetic::TracerCounters counters;
  for (auto _ : state) {
    kinetic::TracerState<D> s;
    s.t = 0.5 * t_max;
    const kinetic::WindowBound window = scene.background->bound(s.t);
    const double T = scene.background->at(0.0, s.t, window).T;
    for (int k = 0; k < D; ++k) s.v[k] = std::sqrt(T) * rng.normal();
    kinetic::advance<D>(*scene.background, impurity, s, t_max, rng, counters);
  }
  report(state, counters);
}

/// late_core with batch_lanes (16) trajectories at once in the vector lanes of `kernel`
/// (kinetic/batch.hpp); per iteration 16 × the trajectories of late_core.
template <int D>
void late_core_batch(benchmark::State& state, const std::string& kernel) {
  const LateScene& scene = late_scene(D);
  const kinetic::GridBackground* grid = kinetic::batch_background(*scene.background);
  const double t_max = scene.config.scene.t_max;
  const kinetic::ImpurityModel impurity{D, 1.0, 2 * scene.config.scene.a};
  std::vector<kinetic::Random> rngs;
  for (int l = 0; l < kinetic::batch_lanes; ++l) rngs.emplace_back(2, l);
  kinetic::TracerCounters counters;
  for (auto _ : state) {
    kinetic::TracerState<D> s[kinetic::batch_lanes];
    for (int l = 0; l < kinetic::batch_lanes; ++l) {
      s[l].t = 0.5 * t_max;
      const kinetic::WindowBound window = scene.background->bound(s[l].t);
      const double T = scene.background->at(0.0, s[l].t, window).T;
      for (int k = 0; k < D; ++k) s[l].v[k] = std::sqrt(T) * rngs[l].normal();
    }
    kinetic::advance_batch<D>(*grid, impurity, kernel, s, rngs.data(), (1u << kinetic::batch_lanes) - 1, t_max,
                              counters);
  }
  report(state, counters);
}

/// One host-state lookup at a random radius inside the core at t ≈ 0.7 t_max (2D scene): the time
/// slice computed directly (a log and an exp), or derived from an anchor (series), then `at`.
void lookup(benchmark::State& state) {
  const bool derived = state.range(0) != 0;
  const LateScene& scene = late_scene(2);
  const kinetic::Background& background = *scene.background;
  const double t0 = 0.7 * scene.config.scene.t_max;
  const kinetic::WindowBound window = background.bound(t0);
  kinetic::TimeSlice anchor = background.slice(window, t0);
  const double core = 0.3 * anchor.scale;
  kinetic::Random rng(3, 0);
  double sink = 0.0;
  for (auto _ : state) {
    const double t = t0 * (1.0 + 1e-6 * rng.uniform());
    const kinetic::TimeSlice slice = derived ? background.slice_near(window, anchor, t) : background.slice(window, t);
    sink += background.at(core * rng.uniform(), slice).n;
  }
  benchmark::DoNotOptimize(sink);
  state.SetItemsProcessed(state.iterations());
}

}  // namespace

BENCHMARK_TEMPLATE(equilibrium, 2)->Unit(benchmark::kMillisecond);
BENCHMARK_TEMPLATE(equilibrium, 3)->Unit(benchmark::kMillisecond);
BENCHMARK_TEMPLATE(late_core, 2)->Unit(benchmark::kMillisecond);
BENCHMARK_TEMPLATE(late_core, 3)->Unit(benchmark::kMillisecond);
BENCHMARK(lookup)->Arg(0)->Arg(1);

// late_core_batch<D>/KERNEL for every vector kernel this CPU runs (kinetic::batch_kernels()).
int main(int argc, char** argv) {
  for (const std::string& kernel : kinetic::batch_kernels()) {
    benchmark::RegisterBenchmark(("late_core_batch<2>/" + kernel).c_str(), late_core_batch<2>, kernel)
        ->Unit(benchmark::kMillisecond);
    benchmark::RegisterBenchmark(("late_core_batch<3>/" + kernel).c_str(), late_core_batch<3>, kernel)
        ->Unit(benchmark::kMillisecond);
  }
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
