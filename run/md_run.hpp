#pragma once
// What `coldblast md run` does before the ensemble starts, as a library call shared by the CLI and
// the Python module (coldblast.md.run): the flag checks with the CLI's messages, the scene (a TOML
// file, its text or the embedded default) with `--set key=value` overrides and the typed options,
// and the run options (docs/md-output.md).
#include <optional>
#include <string>
#include <vector>

#include "md/blast_config.hpp"
#include "run/ensemble.hpp"

namespace coldblast::run {

struct MdRunRequest {
  std::string scene_file;                 ///< TOML scene file; empty = scene_text, or the embedded default
  std::string scene_text;                 ///< TOML text used when scene_file is empty (empty = default scene)
  std::vector<std::string> overrides;     ///< "key=value" (--set)
  std::optional<long long> realizations;  ///< none = the scene's; else [1, 1e9] (--realizations)
  std::optional<long long> seed;          ///< none = the scene's; else >= 0 (--seed)
  int threads = 1;                        ///< worker threads, [1, 1024] (--threads)
};

/// The scene and options for run_blast (the caller adds shards, progress and checkpoints).
struct MdRunPlan {
  md::BlastConfig config;  ///< validated; A_d = 0 when the scene leaves it to the A_d policy (run_blast)
  RunOptions options;      ///< threads
};

/// Validates the request and builds the scene; throws std::invalid_argument naming the flag or
/// scene key (the CLI's exit-2 messages).
MdRunPlan plan_md_run(const MdRunRequest& request);

}  // namespace coldblast::run
