// Fuzz target: a TOML scene through parsing, validation and resolution (run::parse_scene,
// md::resolve_scene), as `md run SCENE` and `md merge` (summary.json's scene_toml) read it.
// A scene that resolves must be finite and must read back from its own run::scene_toml() unchanged
// (checkpoints and merges compare scenes by that text).
#include <string>

#include "fuzz/fuzz_check.hpp"
#include "md/blast_config.hpp"
#include "run/scene_file.hpp"

using namespace coldblast;

namespace {
// A scene with A_d = 0 needs an amplitude policy (md/blast_config.hpp); the ideal-gas value keeps the
// fuzzers free of hydro's solver.
theory::AmplitudeChoice fuzz_amplitude(int d, double) {
  return {theory::ideal_gas_amplitude(d), "ideal gas"};
}
}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  fuzz::expect_clean([&] {
    const md::BlastConfig config = run::parse_scene(text, {}, "fuzz.toml");
    const md::ResolvedScene scene = md::resolve_scene(config, fuzz_amplitude);
    fuzz::require_finite(scene.A_d, "A_d");
    fuzz::require_finite(scene.phi, "phi");
    fuzz::require_finite(scene.lambda, "lambda");
    fuzz::require_finite(scene.region_radius, "region_radius");
    fuzz::require_finite(scene.guard_radius, "guard_radius");
    fuzz::require(!scene.times.empty(), "no recording times");
    for (const double t : scene.times) fuzz::require_finite(t, "a recording time");
    const std::string toml = run::scene_toml(config);
    fuzz::require(run::scene_toml(run::parse_scene(toml, {}, "round trip")) == toml,
                  "scene_toml does not read back:\n" + toml);
  });
  return 0;
}
