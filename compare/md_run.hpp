#pragma once
// What `coldblast md run` does before the ensemble starts, as a library call shared by the CLI and
// the Python module (coldblast.md.run): the flag checks with the CLI's messages, the scene (a TOML
// file, its text or the embedded default) with `--set key=value` overrides, and A_d = 0 resolved
// to hydro's hard-particle TvNS amplitude A_d(phi) (it sizes the box; docs/md-output.md).
#include <string>
#include <vector>

#include "md/scenes.hpp"

namespace coldblast::compare {

struct MdRunRequest {
  std::string scene_file;              ///< TOML scene file; empty = scene_text, or the embedded default
  std::string scene_text;              ///< TOML text used when scene_file is empty (empty = default scene)
  std::vector<std::string> overrides;  ///< "key=value" (--set)
  long long realizations = 0;          ///< 0 = the scene's; else [1, 1e9] (--realizations)
  long long seed = -1;                 ///< -1 = the scene's; else >= 0 (--seed)
  int threads = 1;                     ///< worker threads, [1, 1024] (--threads)
};

/// The scene to run, ready for md::run_blast.
struct MdRunPlan {
  md::BlastConfig config;  ///< validated, with A_d resolved
  std::string A_d_source;  ///< how A_d was obtained when the scene left it 0 (empty: the scene gave it)
};

/// Validates the request and builds the scene; throws std::invalid_argument naming the flag or
/// scene key (the CLI's exit-2 messages).
MdRunPlan plan_md_run(const MdRunRequest& request);

}  // namespace coldblast::compare
