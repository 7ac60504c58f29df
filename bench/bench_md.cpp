// MD engine benchmarks (docs/benchmarks.md, "MD engine"): collisions per second and seconds per
// realization of the paper's 2D blast and its set-up share, 3D equilibrium hard spheres at phi = 0.1, 0.3, 0.45 with
// N = 10^5 (the EDMD reference point), heap versus bucketed calendar, memory for N = 10^6, and the
// growth of the cost with t_max over a decade.
#include <benchmark/benchmark.h>
#include <sys/resource.h>

#include <cmath>
#include <map>
#include <memory>

#include "md/engine.hpp"
#include "md/initial_state.hpp"
#include "md/realization.hpp"
#include "run/ensemble.hpp"
#include "run/scene_file.hpp"

using namespace coldblast::md;
using coldblast::run::BlastResult;
using coldblast::run::default_scene_toml;
using coldblast::run::parse_scene;
using coldblast::run::run_blast;

namespace {
// The paper's 2D scene (scenes/paper-2d.toml) with hydro's A_2(phi = 0.118) = 0.2238 given
// explicitly (md must not call hydro).
BlastConfig paper_2d(double t_max, const std::string& queue, double margin) {
  BlastConfig c =
      parse_scene(default_scene_toml(),
                  {"name=\"paper-2d\"", "E=5.7", "A_d=0.22380034", "t_min=0.9765625", "t_max=" + std::to_string(t_max),
                   "box_margin=" + std::to_string(margin), "realizations=1", "queue=\"" + queue + "\""});
  c.observables = default_observable_names();  // the catalogue's MD defaults (no u_flow)
  return c;
}

void blast(benchmark::State& state, const std::string& queue, double t_max, double margin) {
  long long index = 0;
  std::uint64_t collisions = 0;
  double seconds = 0.0;
  for (auto _ : state) {
    BlastConfig c = paper_2d(t_max, queue, margin);
    c.seed = static_cast<std::uint64_t>(++index);  // a different realization each iteration
    const BlastResult r = run_blast(c);
    collisions += r.collisions();
    seconds += r.wall_seconds;
  }
  state.counters["collisions_per_second"] =
      benchmark::Counter(static_cast<double>(collisions), benchmark::Counter::kIsRate);
  state.counters["collisions_per_realization"] = static_cast<double>(collisions) / state.iterations();
  state.counters["seconds_per_realization"] = seconds / state.iterations();
}

// Set-up share of a paper-scene realization: RSA placement, impurity kick and engine construction
// (cell list, calendar), without the event loop (same steps as md/realization.cpp's run_realization).
void paper_2d_setup(benchmark::State& state) {
  const ResolvedScene scene = resolve_scene(paper_2d(4000.0, "calendar", 1.6));
  long long index = 0;
  for (auto _ : state) {
    const InitialState<2> initial = blast_initial_state<2>(scene, ++index);
    const EngineConfig<2> config = blast_engine_config<2>(scene);
    Engine<2, CalendarEventQueue> engine(config, initial);
    benchmark::DoNotOptimize(engine.size());
  }
}

template <class Queue>
struct EquilibriumSystem {
  std::unique_ptr<Engine<3, Queue>> engine;
};

template <class Queue>
Engine<3, Queue>& equilibrium_engine(double phi, std::size_t count) {
  static std::map<std::pair<double, std::size_t>, std::unique_ptr<Engine<3, Queue>>> cache;
  auto& slot = cache[{phi, count}];
  if (!slot) {
    auto rng = realization_rng(1, 0);
    EngineConfig<3> config;
    config.periodic = true;
    config.box = Vec<3>::Constant(std::cbrt(count * (M_PI / 6.0) / phi));
    slot = std::make_unique<Engine<3, Queue>>(config, lattice_start<3>(rng, count, 0.5, config.box, 1.0));
    slot->run_collisions(5 * count);  // melt the lattice
  }
  return *slot;
}

template <class Queue>
void equilibrium(benchmark::State& state) {
  const double phi = state.range(0) / 100.0;
  Engine<3, Queue>& engine = equilibrium_engine<Queue>(phi, 100000);
  const std::uint64_t start = engine.collision_count();
  for (auto _ : state) engine.run_collisions(1000000);
  state.counters["collisions_per_second"] =
      benchmark::Counter(static_cast<double>(engine.collision_count() - start), benchmark::Counter::kIsRate);
}

void memory_1e6(benchmark::State& state) {
  std::size_t bytes = 0;
  for (auto _ : state) {
    auto rng = realization_rng(2, 0);
    EngineConfig<3> config;
    config.periodic = true;
    const std::size_t count = 1000000;
    config.box = Vec<3>::Constant(std::cbrt(count * (M_PI / 6.0) / 0.3));
    Engine<3, CalendarEventQueue> engine(config, lattice_start<3>(rng, count, 0.5, config.box, 1.0));
    engine.run_collisions(1000000);
    bytes = engine.bytes();
  }
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  state.counters["engine_bytes_per_particle"] = static_cast<double>(bytes) / 1e6;
  state.counters["peak_rss_MB"] = usage.ru_maxrss / 1024.0;  // whole process, includes the initial state
}
}  // namespace

// The t_max scan uses box_margin = 3: below t ~ 1000 a few fast particles run well ahead of Eq. (1).
BENCHMARK_CAPTURE(blast, paper_2d_calendar, std::string("calendar"), 4000.0, 1.6)
    ->Unit(benchmark::kMillisecond)
    ->Iterations(3);
BENCHMARK(paper_2d_setup)->Unit(benchmark::kMillisecond)->Iterations(5);
BENCHMARK_CAPTURE(blast, paper_2d_heap, std::string("heap"), 4000.0, 1.6)->Unit(benchmark::kMillisecond)->Iterations(3);
BENCHMARK_CAPTURE(blast, t_max_400, std::string("calendar"), 400.0, 3.0)->Unit(benchmark::kMillisecond)->Iterations(10);
BENCHMARK_CAPTURE(blast, t_max_1265, std::string("calendar"), 1264.9110640673518, 3.0)
    ->Unit(benchmark::kMillisecond)
    ->Iterations(5);
BENCHMARK_CAPTURE(blast, t_max_4000, std::string("calendar"), 4000.0, 3.0)
    ->Unit(benchmark::kMillisecond)
    ->Iterations(3);
BENCHMARK_TEMPLATE(equilibrium, CalendarEventQueue)
    ->Arg(10)
    ->Arg(30)
    ->Arg(45)
    ->Unit(benchmark::kMillisecond)
    ->Iterations(1);
BENCHMARK_TEMPLATE(equilibrium, HeapEventQueue)
    ->Arg(10)
    ->Arg(30)
    ->Arg(45)
    ->Unit(benchmark::kMillisecond)
    ->Iterations(1);
BENCHMARK(memory_1e6)->Unit(benchmark::kMillisecond)->Iterations(1)->Repetitions(1);

BENCHMARK_MAIN();
