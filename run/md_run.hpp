#pragma once
// `coldblast md run` as a library call shared by the CLI and the Python module (coldblast.md.run):
// the flag checks with the CLI's messages; the scene (a TOML file, its text or the embedded
// default) with `--set key=value` overrides and the typed options; or, with --resume OUT alone, the
// scene and shard of OUT's checkpoint, an option given again that contradicts it being an error
// naming the option and both values; and the run's end: its files, manifest.json, the checkpoint
// removed (docs/md-output.md).
#include <filesystem>
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
  std::optional<std::string> shard;       ///< "i/n" (--shard); none = 0/1, or the checkpoint's
  std::filesystem::path out;              ///< output folder; empty = no files and no checkpoint
  bool resume = false;                    ///< continue OUT's checkpoint (--resume OUT)
  bool overwrite = false;                 ///< replace another run's files in OUT (--overwrite)
  /// A realization running longer saves its state every this many seconds (--save-every;
  /// RunOptions::in_flight_seconds), in (0, 1e9].
  double save_every = 600.0;
  /// How to continue a stopped run, in messages (the CLI's "coldblast md run --resume OUT").
  std::string resume_hint;
};

/// The scene and options for run_blast (the caller adds progress).
struct MdRunPlan {
  md::BlastConfig config;  ///< validated; A_d = 0 when the scene leaves it to the A_d policy (run_blast)
  RunOptions options;      ///< threads, shard, OUT, resume, overwrite
};

/// Validates the request and builds the scene, or restores it from OUT's checkpoint when resuming;
/// throws std::invalid_argument naming the flag or scene key (the CLI's exit-2 messages). Reads
/// files only: the folder is claimed when the run starts (plan_ensemble).
MdRunPlan plan_md_run(const MdRunRequest& request);

/// The end of a run with an output folder: its files and manifest.json, then the checkpoint removed.
void finish_md_run(const BlastResult& result, const std::filesystem::path& out);

}  // namespace coldblast::run
