// Wall time and RHS evaluations per Navier–Stokes blast solve (hydro/navier_stokes.hpp, paper Sec. III):
// the core runs of acceptance item 4 (R/λ = 2 -> 1e6 in 2D and 3D) at several resolutions, with the
// error of the final H, n0, T0 exponents against the paper's rationals as a counter (work–precision),
// the dense gas of issue 12 (hard-particle EOS, Enskog transport) likewise, and the Euler run against the
// exact TvNS amplitude. Results: docs/benchmarks.md.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>

#include "hydro/navier_stokes.hpp"
#include "theory/exponents.hpp"

namespace {

using namespace coldblast;

void core(benchmark::State& state) {
  const int d = static_cast<int>(state.range(0));
  const int cells = static_cast<int>(state.range(1));
  const double until = std::pow(10.0, static_cast<double>(state.range(2)));
  hydro::NavierStokesConfig config;
  config.physics.d = d;
  config.numerics.cells = cells;
  config.until_R_over_lambda = until;
  hydro::NavierStokesResult result;
  for (auto _ : state) result = hydro::run_navier_stokes(config);
  const auto theory_exponents = theory::scaling_exponents(d);
  const auto e = result.final_exponents();
  const double error = std::max({std::abs(e.H - theory::to_double(theory_exponents.H.in_time)),
                                 std::abs(e.n0 - theory::to_double(theory_exponents.n0.in_time)),
                                 std::abs(e.T0 - theory::to_double(theory_exponents.T0.in_time))});
  state.counters["rhs_evaluations"] = static_cast<double>(result.statistics.rhs_evaluations);
  state.counters["steps"] = static_cast<double>(result.statistics.steps);
  state.counters["exponent_error"] = error;
  state.counters["energy_error"] = result.max_energy_error;
}

/// The dense gas at the MD's packing fraction (issue 12): Henderson (2D) / Carnahan–Starling (3D) at
/// φ∞ = 0.118, Enskog transport, viscosity on; the amplitudes at R/λ = until as counters (their
/// error: the difference to the finest resolution, docs/benchmarks.md).
void dense_core(benchmark::State& state) {
  const int d = static_cast<int>(state.range(0));
  hydro::NavierStokesConfig config;
  config.physics.d = d;
  config.physics.eos = d == 2 ? hydro::Eos::henderson : hydro::Eos::carnahan_starling;
  config.physics.transport = hydro::Transport::enskog;
  config.physics.viscosity = true;
  config.numerics.cells = static_cast<int>(state.range(1));
  config.until_R_over_lambda = std::pow(10.0, static_cast<double>(state.range(2)));
  hydro::NavierStokesResult result;
  for (auto _ : state) result = hydro::run_navier_stokes(config);
  const auto theory_exponents = theory::scaling_exponents(d);
  const auto e = result.final_exponents();
  const auto& s = result.final_sample();
  state.counters["rhs_evaluations"] = static_cast<double>(result.statistics.rhs_evaluations);
  state.counters["exponent_error"] = std::max({std::abs(e.H - theory::to_double(theory_exponents.H.in_time)),
                                               std::abs(e.n0 - theory::to_double(theory_exponents.n0.in_time)),
                                               std::abs(e.T0 - theory::to_double(theory_exponents.T0.in_time))});
  state.counters["H_prefactor"] = s.H_prefactor;
  state.counters["n0_prefactor"] = s.n0_prefactor;
  state.counters["T0_prefactor"] = s.T0_prefactor;
  state.counters["energy_drift"] = result.energy_projected;
}

void euler(benchmark::State& state) {
  const int d = static_cast<int>(state.range(0));
  hydro::NavierStokesConfig config;
  config.physics.d = d;
  config.physics.heat_conduction = false;
  config.numerics.cells = static_cast<int>(state.range(1));
  config.until_R_over_lambda = 500;
  hydro::NavierStokesResult result;
  for (auto _ : state) result = hydro::run_navier_stokes(config);
  const hydro::TvnsComparison c = hydro::compare_to_tvns(result);
  state.counters["rhs_evaluations"] = static_cast<double>(result.statistics.rhs_evaluations);
  state.counters["A_error"] = std::abs(c.A_relative_error);
  state.counters["L1_density"] = c.L1_density;
}

}  // namespace

// (d, cells, log10 of R/λ at the end)
BENCHMARK(core)
    ->Args({2, 64, 6})
    ->Args({2, 128, 6})
    ->Args({2, 256, 6})
    ->Args({3, 64, 6})
    ->Args({3, 128, 6})
    ->Args({3, 256, 6})
    ->Args({2, 256, 8})
    ->Unit(benchmark::kSecond)
    ->Iterations(1);
// (d, cells, log10 of R/λ at the end)
BENCHMARK(dense_core)
    ->Args({2, 128, 6})
    ->Args({2, 256, 6})
    ->Args({2, 512, 6})
    ->Args({3, 128, 6})
    ->Args({3, 256, 6})
    ->Args({3, 512, 6})
    ->Unit(benchmark::kSecond)
    ->Iterations(1);
// (d, cells), R/λ = 500 with the hot region at 0.4
BENCHMARK(euler)
    ->Args({2, 128})
    ->Args({2, 256})
    ->Args({3, 128})
    ->Args({3, 256})
    ->Unit(benchmark::kSecond)
    ->Iterations(1);

BENCHMARK_MAIN();
