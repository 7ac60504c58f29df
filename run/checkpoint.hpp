#pragma once
// Checkpoints of an ensemble (OUT/checkpoint, `--resume OUT`; docs/md-output.md, docs/cluster.md):
// the resolved scene (scene.toml), the run's id, kind, shard and options (run.json), one file per
// block (block_<k>.txt, its sums as hex floats: an exact round trip) and the single realizations'
// files (files/). A block file is written atomically when the block ends, and for a block in
// progress with the realizations it has finished (at a stop, and at most every few seconds), so a
// stopped or killed run resumes without redoing finished realizations and ends with outputs
// identical to an uninterrupted run's. Nothing here deletes saved blocks, except a fresh run
// claiming its folder with --overwrite (run/run_directory.hpp).
#include <filesystem>
#include <map>
#include <string>

#include "common/output.hpp"
#include "md/blast_config.hpp"
#include "md/block_sums.hpp"
#include "run/run_files.hpp"

namespace coldblast::run {

/// The checkpoint folder of an output folder: OUT/checkpoint.
std::filesystem::path checkpoint_folder(const std::filesystem::path& out);

/// run.json: who is running, and how (restored by `--resume OUT` alone).
struct CheckpointRun {
  std::string run_id;
  std::string kind = "md run";  ///< "md run" or "tracer"
  int shard_index = 0, shard_count = 1;
  /// The scene as given (A_d = 0 left to the policy: its source is recorded as such); empty in
  /// checkpoints made before run.json, whose scene.toml then serves.
  std::string scene_toml;
  common::Json options = common::Json::object();  ///< the tracer's options (its run.json "options")
};

/// Blocks (and the single realizations' files) read from a checkpoint.
struct Checkpoint {
  CheckpointRun run;
  std::map<long long, md::BlockSums> blocks;   ///< finished blocks
  std::map<long long, md::BlockSums> partial;  ///< blocks in progress: their first `count` realizations
  NamedFiles files;                            ///< in name order
  /// Extra lines of the block files after the md sums (the tracer's sums), by block.
  std::map<long long, std::string> extra;
};

/// The text of block_<k>.txt: counts in decimal, sums in C99 hex floats ("%a"), then `extra`.
std::string checkpoint_block_text(long long block, const md::BlockSums& sums, const std::string& extra = "");
/// Parses checkpoint_block_text: checks the block index, the number of entries and a count in
/// [1, `count`] (below `count`: a block in progress); the lines after the sums go to `extra`.
/// Throws std::invalid_argument naming `option` and `source` when the text is malformed.
md::BlockSums parse_checkpoint_block(const std::string& text, long long block, std::size_t entries, long long count,
                                     const std::string& source, std::string* extra = nullptr,
                                     const std::string& option = "--resume");

/// Starts a fresh checkpoint in `directory`: scene.toml and run.json (the folder holds none yet:
/// run/run_directory.hpp's claim cleared it).
void start_checkpoint(const std::filesystem::path& directory, const md::ResolvedScene& scene, const CheckpointRun& run);
/// Saves one block, finished or in progress, atomically (thread-safe for distinct blocks): first
/// `files` (single realizations' files not saved yet), then its block file, so that a saved block
/// always has its files.
void save_checkpoint_block(const std::filesystem::path& directory, long long block, const md::BlockSums& sums,
                           const NamedFiles& files = {}, const std::string& extra = "");
/// The scene text and run.json of a checkpoint, for `--resume OUT` alone. Throws
/// std::invalid_argument naming --resume when the folder holds no checkpoint (saying so when it
/// holds a finished run instead).
std::string checkpoint_scene_text(const std::filesystem::path& directory);
CheckpointRun checkpoint_run(const std::filesystem::path& directory);
/// The first key whose value differs between two scenes' TOML texts, as "KEY = A there, B now";
/// empty when the texts are equal.
std::string scene_difference(const std::string& there, const std::string& now);
/// Reads every saved block. Throws std::invalid_argument naming --resume when the folder holds no
/// checkpoint, when its scene differs from `scene` (naming the first differing key) or when a file
/// is malformed.
Checkpoint load_checkpoint(const std::filesystem::path& directory, const md::ResolvedScene& scene);
/// load_checkpoint's reading alone, for a checkpoint another process may still be writing (md merge
/// of a run in progress): it changes nothing in `directory` (a killed write's temporaries are
/// skipped, not removed) and does not compare scenes. Errors name `option`.
Checkpoint read_checkpoint(const std::filesystem::path& directory, const md::ResolvedScene& scene,
                           const std::string& option);
/// The mid-run state of realization `realization` (md::InFlight), kept while it runs:
/// CHECKPOINT/in_flight/realization_<r>.bin. A binary file for this machine type (common/bytes.hpp),
/// dropped once the realization's block file counts it.
std::filesystem::path in_flight_path(const std::filesystem::path& directory, long long realization);
/// Its bytes, empty when there is none.
std::string read_in_flight(const std::filesystem::path& directory, long long realization);
/// Writes it atomically (a kill while writing keeps the previous save).
void save_in_flight(const std::filesystem::path& directory, long long realization, const std::string& bytes);
/// Removes it, if present.
void drop_in_flight(const std::filesystem::path& directory, long long realization);

/// Removes OUT/checkpoint once the run's outputs and manifest are written: renamed to
/// OUT/checkpoint.removed, then deleted, so that a kill meanwhile never leaves part of it.
void remove_checkpoint(const std::filesystem::path& out);

}  // namespace coldblast::run
