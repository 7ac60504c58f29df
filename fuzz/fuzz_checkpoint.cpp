// Fuzz target: the checkpoint reader of `md run --resume`. The input is split at lines "@@" into a
// checkpoint folder of a small default scene: part 0 is scene.toml, parts 1.. are block_0.txt,
// block_1.txt, ... (so both the scene comparison and the block parser see hostile text). A block
// that parses must round-trip exactly through checkpoint_block_text.
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "fuzz/fuzz_check.hpp"
#include "run/checkpoint.hpp"
#include "run/scene_file.hpp"

using namespace coldblast;
namespace fs = std::filesystem;

namespace {
std::vector<std::string> parts(const std::string& text) {
  std::vector<std::string> out(1);
  std::string::size_type start = 0;
  while (true) {
    const auto cut = text.find("\n@@\n", start);
    out.back() += text.substr(start, cut == std::string::npos ? std::string::npos : cut - start + 1);
    if (cut == std::string::npos) return out;
    out.emplace_back();
    start = cut + 4;
  }
}
}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  // The scene of the seeds in fuzz/corpus/checkpoint (small blocks keep the inputs short).
  static const md::ResolvedScene scene = md::resolve_scene(run::parse_scene(
      run::default_scene_toml(), {"realizations=4", "block_size=1", "observables=[\"R_imp\"]", "t_max=8", "A_d=0.35"}));
  static const fs::path folder = fs::temp_directory_path() / ("coldblast_fuzz_checkpoint." + std::to_string(getpid()));
  const std::vector<std::string> files = parts(std::string(reinterpret_cast<const char*>(data), size));
  fs::remove_all(folder);
  fs::create_directories(folder);
  std::ofstream(folder / "scene.toml", std::ios::binary) << files[0];
  for (std::size_t k = 1; k < files.size() && k < 6; ++k)
    std::ofstream(folder / ("block_" + std::to_string(k - 1) + ".txt"), std::ios::binary) << files[k];
  fuzz::expect_clean([&] {
    const run::Checkpoint checkpoint = run::load_checkpoint(folder, scene);
    for (const auto& [block, sums] : checkpoint.blocks) {
      const std::string text = run::checkpoint_block_text(block, sums);
      const md::BlockSums again = run::parse_checkpoint_block(text, block, sums.sum.size(), sums.count, "round trip");
      fuzz::require(run::checkpoint_block_text(block, again) == text, "block text does not round-trip");
      for (std::size_t e = 0; e < sums.sum.size(); ++e) {
        fuzz::require_finite(sums.sum[e], "a checkpoint sum");
        fuzz::require_finite(sums.sum_squares[e], "a checkpoint sum of squares");
      }
    }
  });
  // The block parser alone, with the text as one block of the default scene's layout.
  if (files.size() > 1)
    fuzz::expect_clean([&] {
      const md::BlockSums s = run::parse_checkpoint_block(files[1], 0, 13, 1, "fuzz");
      fuzz::require(s.sum.size() == 13 && s.count == 1, "parse_checkpoint_block ignored the expected shape");
    });
  return 0;
}
