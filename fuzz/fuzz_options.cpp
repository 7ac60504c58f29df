// Fuzz target: the numeric option parsers. The first byte picks the parser, the rest is the text:
// `--shard i/n` (md::parse_shard), number and count fields (common::parse_finite, parse_count,
// parse_number_or_nan), and `--set key=value` scene overrides (md::parse_scene with overrides on the
// default scene, resolved as md run does).
#include <string>
#include <vector>

#include "common/input.hpp"
#include "fuzz/fuzz_check.hpp"
#include "md/ensemble.hpp"
#include "md/scenes.hpp"

using namespace coldblast;

namespace {
// A scene with A_d = 0 needs an amplitude policy (md/scenes.hpp); the ideal-gas value keeps the
// fuzzers free of hydro's solver.
theory::AmplitudeChoice fuzz_amplitude(int d, double) {
  return {theory::ideal_gas_amplitude(d), "ideal gas"};
}
}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  const std::string text(reinterpret_cast<const char*>(data) + 1, size - 1);
  switch (data[0] % 5) {
    case 0:
      fuzz::expect_clean([&] {
        const auto [i, n] = md::parse_shard(text);
        fuzz::require(n >= 1 && i >= 0 && i < n, "parse_shard accepted " + text);
      });
      break;
    case 1:
      fuzz::expect_clean(
          [&] { fuzz::require_finite(common::parse_finite(text, "fuzz"), "parse_finite(" + text + ")"); });
      break;
    case 2:
      fuzz::expect_clean([&] { fuzz::require(common::parse_count(text, "fuzz") >= 0, "negative count " + text); });
      break;
    case 3:
      fuzz::expect_clean([&] {
        const double x = common::parse_number_or_nan(text, "fuzz");
        fuzz::require(std::isfinite(x) || std::isnan(x), "parse_number_or_nan gave an infinity for " + text);
      });
      break;
    default: {
      std::vector<std::string> overrides;  // one override per line, as repeated --set options
      std::string::size_type start = 0;
      while (start <= text.size() && overrides.size() < 8) {
        const auto end = text.find('\n', start);
        overrides.push_back(text.substr(start, end == std::string::npos ? std::string::npos : end - start));
        if (end == std::string::npos) break;
        start = end + 1;
      }
      fuzz::expect_clean([&] {
        const md::ResolvedScene scene =
            md::resolve_scene(md::parse_scene(md::default_scene_toml(), overrides, "default scene"), fuzz_amplitude);
        fuzz::require_finite(scene.region_radius, "region_radius");
        fuzz::require_finite(scene.phi, "phi");
      });
    }
  }
  return 0;
}
