// Fuzz target: the run-directory readers of `coldblast compare` (compare::read_run and the
// exponent analysis on top) and `md merge` (run::merge_blast_outputs). The input is split at lines
// "@@" into summary.json, blocks.csv, block_totals.csv and accumulators.csv of one run folder.
// What reads must give a finite merged summary and finite block sums.
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "compare/run_data.hpp"
#include "fuzz/fuzz_check.hpp"
#include "run/merge.hpp"

using namespace coldblast;
namespace fs = std::filesystem;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const fs::path folder = fs::temp_directory_path() / ("coldblast_fuzz_run." + std::to_string(getpid()));
  static const char* names[] = {"summary.json", "blocks.csv", "block_totals.csv", "accumulators.csv"};
  const std::string text(reinterpret_cast<const char*>(data), size);
  fs::remove_all(folder);
  fs::create_directories(folder);
  std::string::size_type start = 0;
  for (int k = 0; k < 4 && start != std::string::npos; ++k) {
    const auto cut = text.find("\n@@\n", start);
    std::ofstream(folder / names[k], std::ios::binary)
        << text.substr(start, cut == std::string::npos ? std::string::npos : cut - start + 1);
    start = cut == std::string::npos ? cut : cut + 4;
  }
  fuzz::expect_clean([&] {
    compare::RunData run = compare::read_run(folder);
    for (const auto& [name, series] : run.series) {
      fuzz::require(series.sums.size() == series.counts.size(), name + ": sums and counts differ in blocks");
      for (std::size_t k = 0; k < series.time_count(); ++k) fuzz::require_finite(series.t[k], name + " t");
      if (series.time_count() >= 2) compare::truncate_run(run, series.t[series.time_count() - 1]);
      break;
    }
  });
  fuzz::expect_clean([&] {
    const run::BlastResult merged = run::merge_blast_outputs({folder});
    for (const auto& [block, sums] : merged.blocks)
      for (std::size_t e = 0; e < sums.sum.size(); ++e) fuzz::require(!std::isinf(sums.sum[e]), "an infinite sum");
    const std::string summary = run::blast_summary(merged).dump(2);
    fuzz::require(!summary.empty(), "empty summary");
  });
  return 0;
}
