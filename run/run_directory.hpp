#pragma once
// One run per folder (docs/md-output.md, "Run ids"). Every run has an id, written into summary.json,
// into the provenance header of every file it writes ("# run_id: ID"; snapshots.extxyz: run_id=ID
// in each frame's comment line) and into manifest.json, written last, which lists the run's files.
// A new run refuses a folder that holds another run's files (or an unfinished run's checkpoint)
// unless told to overwrite, and then removes exactly the old run's files; every reader refuses a
// folder whose files belong to different runs, naming the file.
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace coldblast::run {

/// A new run id: the UTC time and 32 random bits, e.g. "20261124T101530Z-3f9a2c1d".
std::string new_run_id();

/// manifest.json: the run and every file it wrote into its folder (manifest.json aside).
struct RunManifest {
  std::string run_id;
  std::string kind;  ///< what wrote it: "md run", "tracer", "md merge", "md states"
  std::vector<std::string> files;
};
inline constexpr const char* manifest_file = "manifest.json";
/// Writes folder/manifest.json atomically (last, after the files it lists).
void write_manifest(const std::filesystem::path& folder, const RunManifest& manifest);
/// Reads folder/manifest.json; none when the folder has none. Throws std::invalid_argument naming
/// the file when it is malformed.
std::optional<RunManifest> read_manifest(const std::filesystem::path& folder);

/// Whether `name` is the name of a file that runs write (observables.csv, blocks.csv, ...,
/// snapshot_<t>.csv, snapshots.extxyz, moments.csv, impurity_states.csv, manifest.json).
bool is_run_file_name(const std::string& name);

/// The run id a run file records: its "# run_id: " header line, summary.json's "run_id", an extended
/// XYZ frame's run_id=; empty when it records none (a file of a run made before run ids).
std::string recorded_run_id(const std::filesystem::path& file);

/// The run files of a folder and the run each belongs to.
struct FolderRuns {
  std::optional<RunManifest> manifest;
  std::map<std::string, std::string> files;  ///< run file name (manifest.json aside) → recorded run id
  bool checkpoint = false;                   ///< folder/checkpoint holds an unfinished run's checkpoint
  bool empty() const { return !manifest && files.empty() && !checkpoint; }
};
/// What `folder` holds (nothing for a missing folder).
FolderRuns inspect_folder(const std::filesystem::path& folder);

/// `text` (a run file) with the run id `from` replaced by `to` wherever it is recorded (md merge's
/// copies of its shards' realization files belong to the merged run).
std::string with_run_id(std::string text, const std::string& from, const std::string& to);

/// For a reader of the run in `folder` (`option` names it in errors, e.g. "RUN_DIR"): throws
/// std::invalid_argument naming the first file that belongs to another run than the folder's (the
/// manifest's run, else summary.json's, else the first file's), or that the manifest lists and the
/// folder lacks. Files of runs made before run ids (none records one) pass.
void require_one_run(const std::filesystem::path& folder, const std::string& option);

/// For a new run writing into `folder` (`option` names it, e.g. "--out"), before any work: nothing
/// when the folder holds no run's files. Otherwise, without `overwrite`, std::invalid_argument
/// naming the option, what the folder holds and how to proceed (`resume_hint`, e.g. "coldblast md
/// run --resume DIR", for a folder with a checkpoint); with `overwrite`, removes exactly the old
/// run's files (its manifest's; for a folder written before manifests, the files with run file
/// names) and its checkpoint, and nothing else.
void claim_output_folder(const std::filesystem::path& folder, const std::string& option, bool overwrite,
                         const std::string& resume_hint);

/// For a resumed run `run_id` finishing in `folder`: std::invalid_argument naming `option` and the
/// file when the folder holds files of another run (written there while it was stopped).
void require_own_files(const std::filesystem::path& folder, const std::string& option, const std::string& run_id);

}  // namespace coldblast::run
