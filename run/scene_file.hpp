#pragma once
// Scene files (docs/md-output.md): the TOML form of a blast scene (md::BlastConfig), `--set
// key=value` overrides, the typed options of the front ends (--realizations, --seed), the embedded
// default scene, and the scene's TOML text that checkpoints, merges and summary.json compare.
#include <optional>
#include <string>
#include <vector>

#include "md/blast_config.hpp"

namespace coldblast::run {

/// The embedded default scene (small: a few seconds on one core).
const std::string& default_scene_toml();

/// Parses a scene from TOML text and applies "key=value" overrides (dotted keys such as
/// impurities.count allowed); unknown keys are rejected; validates. Throws std::invalid_argument.
md::BlastConfig parse_scene(const std::string& toml_text, const std::vector<std::string>& overrides = {},
                            const std::string& source = "scene");

/// The scene as TOML (every key, so that parse_scene reads it back to the same scene).
std::string scene_toml(const md::BlastConfig& config);

/// A scene as a front end asks for it: a file, a text or the default, `--set` overrides, and the
/// typed options given on the command line or in Python (none = the scene's value).
struct SceneRequest {
  std::string file;                       ///< TOML scene file (SCENE); empty = text, or the embedded default
  std::string text;                       ///< TOML text used when file is empty (empty = the default scene)
  std::vector<std::string> overrides;     ///< "key=value" (--set), applied in order after the scene
  std::optional<long long> realizations;  ///< --realizations: [1, 1e9]
  std::optional<long long> seed;          ///< --seed: >= 0
  /// false: the scene's md snapshot keys are dropped (the tracer records no particles, and a
  /// snapshot time beyond a shorter t_max would refuse the scene); an override of them still applies.
  bool md_snapshots = true;
};

/// Reads and validates the scene of `request`; std::invalid_argument names the file, key or option.
md::BlastConfig load_scene(const SceneRequest& request);

}  // namespace coldblast::run
