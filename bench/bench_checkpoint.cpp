// The cost of checkpoints (run/checkpoint.hpp; docs/benchmarks.md, "Checkpoints"): one save of a
// block of the paper's 2D scene with every observable it records (the largest layout a shipped
// scene has: profiles and p_imp at every recording time), and an ensemble of short realizations run
// with a save after every realization against the default (a save per block, plus one every 60 s
// and at a stop).
#include <benchmark/benchmark.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "md/observers.hpp"
#include "run/checkpoint.hpp"
#include "run/ensemble.hpp"
#include "run/scene_file.hpp"

using namespace coldblast;
namespace fs = std::filesystem;

namespace {

md::BlastConfig paper_scene() {
  std::ifstream file(std::string(COLDBLAST_SCENES_DIR) + "/paper-2d.toml");
  std::stringstream text;
  text << file.rdbuf();
  return run::parse_scene(text.str(), {"A_d=0.22380034"});
}

void block_save(benchmark::State& state) {
  const md::ResolvedScene scene = md::resolve_scene(paper_scene());
  const md::ObservableLayout layout(scene);
  md::BlockSums sums;
  for (std::size_t e = 0; e < layout.size(); ++e) {
    sums.sum.push_back(1.0 / (1.0 + static_cast<double>(e)));
    sums.sum_squares.push_back(3.0 / (7.0 + static_cast<double>(e)));
  }
  sums.count = 16;
  const fs::path folder = fs::temp_directory_path() / "coldblast_bench_checkpoint";
  fs::create_directories(folder);
  for (auto _ : state) run::save_checkpoint_block(folder, 0, sums);
  state.counters["entries"] = static_cast<double>(layout.size());
  state.counters["bytes"] = static_cast<double>(fs::file_size(folder / "block_0.txt"));
  fs::remove_all(folder);
}

/// 64 realizations of the default scene to t_max = 100 (a few ms each: the worst case for a save per
/// realization) with saves every `seconds` (0: after every realization).
void ensemble(benchmark::State& state, double seconds) {
  const md::BlastConfig config =
      run::parse_scene(run::default_scene_toml(), {"t_max=100", "realizations=64", "block_size=64", "A_d=0.2238"});
  const fs::path folder = fs::temp_directory_path() / "coldblast_bench_checkpoint_ensemble";
  for (auto _ : state) {
    fs::remove_all(folder);
    run::RunOptions options;
    options.out = folder;
    options.checkpoint_seconds = seconds;
    benchmark::DoNotOptimize(run::run_blast(config, options).collisions());
  }
  fs::remove_all(folder);
}

}  // namespace

BENCHMARK(block_save)->Unit(benchmark::kMillisecond)->Repetitions(5)->ReportAggregatesOnly(true);
BENCHMARK_CAPTURE(ensemble, save_every_realization, 0.0)
    ->Unit(benchmark::kMillisecond)
    ->Iterations(3)
    ->Repetitions(5)
    ->ReportAggregatesOnly(true);
BENCHMARK_CAPTURE(ensemble, save_every_60_s, 60.0)
    ->Unit(benchmark::kMillisecond)
    ->Iterations(3)
    ->Repetitions(5)
    ->ReportAggregatesOnly(true);
BENCHMARK_MAIN();
