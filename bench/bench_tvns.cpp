// Time to compute the TvNS amplitude A_d (paper Eq. (1) [R-shock]) at requested relative tolerances
// 1e-6 ... 1e-13 by each method, with the actual error against the most accurate result (closed form
// at 1e-14) and each method's own error estimate as counters. Results: docs/benchmarks.md.
#include <benchmark/benchmark.h>

#include <cmath>
#include <string>

#include "hydro/tvns.hpp"

namespace {

using namespace coldblast::hydro;

struct Scene {
  int d;
  Eos eos;
  double phi;
};

// 0: the paper's 2D blast (gamma = 2); 1: 3D, gamma = 5/3; 2: hard discs at the MD's phi = 0.118.
constexpr Scene scenes[] = {{2, Eos::ideal, 0.0}, {3, Eos::ideal, 0.0}, {2, Eos::henderson, 0.118}};

TvnsConfig config_for(int scene, double tolerance) {
  TvnsConfig config;
  config.d = scenes[scene].d;
  config.eos = scenes[scene].eos;
  config.phi = scenes[scene].phi;
  config.tolerance = tolerance;
  return config;
}

double reference(int scene) {
  // Ideal gas: the closed form at the tightest tolerance; hard discs: Bulirsch-Stoer at 1e-14.
  TvnsConfig config = config_for(scene, 1e-14);
  return tvns_amplitude(config, config.eos == Eos::ideal ? TvnsMethod::closed_form : TvnsMethod::ode).A;
}

void run(benchmark::State& state, TvnsMethod method) {
  const int scene = static_cast<int>(state.range(0));
  const double tolerance = std::pow(10.0, -static_cast<double>(state.range(1)));
  const TvnsConfig config = config_for(scene, tolerance);
  const double exact = reference(scene);
  TvnsAmplitude result;
  for (auto _ : state) {
    result = tvns_amplitude(config, method);
    benchmark::DoNotOptimize(result);
  }
  state.counters["tolerance"] = tolerance;
  state.counters["actual_error"] = std::abs(result.A - exact) / exact;
  state.counters["estimated_error"] = result.A_error / result.A;
  state.counters["evaluations"] = static_cast<double>(result.evaluations);
}

void BM_closed_form(benchmark::State& state) {
  run(state, TvnsMethod::closed_form);
}
void BM_ode_bulirsch_stoer(benchmark::State& state) {
  run(state, TvnsMethod::ode);
}
void BM_ode_dormand_prince(benchmark::State& state) {
  run(state, TvnsMethod::ode_check);
}

/// The whole solve_tvns() at the default tolerance 1e-13: both methods and their comparison.
void BM_solve_tvns(benchmark::State& state) {
  const TvnsConfig config = config_for(static_cast<int>(state.range(0)), 1e-13);
  const double exact = reference(static_cast<int>(state.range(0)));
  double A = 0.0, A_error = 0.0;
  for (auto _ : state) {
    TvnsSolution solution = solve_tvns(config);
    benchmark::DoNotOptimize(solution);  // not on a double: benchmark 1.7.1's "+r" constraint corrupts it
    A = solution.A();
    A_error = solution.A_error();
  }
  state.counters["actual_error"] = std::abs(A - exact) / exact;
  state.counters["estimated_error"] = A_error / A;
}

void tolerances_ideal(benchmark::internal::Benchmark* b) {
  for (int scene : {0, 1})
    for (int k = 6; k <= 13; ++k) b->Args({scene, k});
}
void tolerances_all(benchmark::internal::Benchmark* b) {
  for (int scene : {0, 1, 2})
    for (int k = 6; k <= 13; ++k) b->Args({scene, k});
}

}  // namespace

BENCHMARK(BM_closed_form)->Apply(tolerances_ideal)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_ode_bulirsch_stoer)->Apply(tolerances_all)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_ode_dormand_prince)->Apply(tolerances_all)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_solve_tvns)->Arg(0)->Arg(1)->Arg(2)->Unit(benchmark::kMicrosecond);

BENCHMARK_MAIN();
