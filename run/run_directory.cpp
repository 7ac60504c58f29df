#include "run/run_directory.hpp"

#include <chrono>
#include <cstdio>
#include <ctime>
#include <fstream>
#include <random>
#include <set>
#include <stdexcept>
#include <system_error>

#include "common/input.hpp"
#include "common/output.hpp"

namespace coldblast::run {

namespace fs = std::filesystem;

namespace {

bool starts_with(const std::string& s, const std::string& prefix) {
  return s.rfind(prefix, 0) == 0;
}
bool ends_with(const std::string& s, const std::string& suffix) {
  return s.size() >= suffix.size() && s.compare(s.size() - suffix.size(), suffix.size(), suffix) == 0;
}

/// The value of `key` in an extended XYZ comment line (key=value, no quotes in ours), or "".
std::string extxyz_value(const std::string& line, const std::string& key) {
  for (std::size_t at = line.find(key + "="); at != std::string::npos; at = line.find(key + "=", at + 1)) {
    if (at > 0 && line[at - 1] != ' ') continue;
    const std::size_t begin = at + key.size() + 1, end = line.find(' ', begin);
    return line.substr(begin, end == std::string::npos ? std::string::npos : end - begin);
  }
  return "";
}

std::string listed(const std::vector<std::string>& names, std::size_t most = 4) {
  std::string text;
  for (std::size_t i = 0; i < names.size() && i < most; ++i) text += (i ? ", " : "") + names[i];
  if (names.size() > most) text += ", ...";
  return text;
}

/// What a checkpoint holds that a resume would continue: block files and mid-run states.
struct SavedWork {
  long long blocks = 0, states = 0;
  bool any() const { return blocks > 0 || states > 0; }
};

SavedWork saved_work(const fs::path& folder) {
  SavedWork work;
  std::error_code error;
  for (const auto& entry : fs::directory_iterator(folder / "checkpoint", error)) {
    const std::string name = entry.path().filename().string();
    if (starts_with(name, "block_") && ends_with(name, ".txt")) ++work.blocks;
  }
  for (const auto& entry : fs::directory_iterator(folder / "checkpoint" / "in_flight", error)) {
    const std::string name = entry.path().filename().string();
    if (starts_with(name, "realization_") && ends_with(name, ".bin")) ++work.states;
  }
  return work;
}

std::string checkpoint_description(const fs::path& folder) {
  const SavedWork work = saved_work(folder);
  std::string text = std::to_string(work.blocks) + (work.blocks == 1 ? " block" : " blocks");
  if (work.states > 0)
    text += " and " + std::to_string(work.states) + " mid-run realization state" + (work.states == 1 ? "" : "s");
  return text + " saved in " + (folder / "checkpoint").string();
}

}  // namespace

std::string new_run_id() {
  const std::time_t now = std::chrono::system_clock::to_time_t(std::chrono::system_clock::now());
  std::tm utc{};
  gmtime_r(&now, &utc);
  char stamp[32];
  std::strftime(stamp, sizeof stamp, "%Y%m%dT%H%M%SZ", &utc);
  std::random_device entropy;
  char id[48];
  std::snprintf(id, sizeof id, "%s-%08x", stamp, static_cast<unsigned>(entropy()));
  return id;
}

void write_manifest(const fs::path& folder, const RunManifest& manifest) {
  common::Json j;
  j["run_id"] = manifest.run_id;
  j["kind"] = manifest.kind;
  j["files"] = manifest.files;
  common::write_file_atomic(folder / manifest_file, j.dump(2) + "\n");
}

std::optional<RunManifest> read_manifest(const fs::path& folder) {
  const fs::path path = folder / manifest_file;
  std::error_code error;
  if (!fs::exists(path, error)) return std::nullopt;
  const auto bad = [&](const std::string& what) {
    return std::invalid_argument(path.string() + ": " + what + " (a coldblast run's manifest.json)");
  };
  try {
    const common::Json j = common::Json::parse(common::read_text(path, "manifest"));
    if (!j.is_object() || !j.contains("run_id") || !j.at("run_id").is_string() || !j.contains("files") ||
        !j.at("files").is_array())
      throw bad("no 'run_id' string and 'files' list");
    RunManifest m;
    m.run_id = j.at("run_id").get<std::string>();
    if (j.contains("kind") && j.at("kind").is_string()) m.kind = j.at("kind").get<std::string>();
    for (const auto& name : j.at("files")) {
      if (!name.is_string()) throw bad("a file name that is not a string");
      const std::string text = name.get<std::string>();
      if (text.empty() || text.find('/') != std::string::npos || text == "." || text == "..")
        throw bad("file name '" + text + "' is not a plain name");
      m.files.push_back(text);
    }
    return m;
  } catch (const common::Json::exception& e) {
    throw bad(std::string("malformed JSON (") + e.what() + ")");
  }
}

bool is_run_file_name(const std::string& name) {
  static const std::set<std::string> names{
      "observables.csv", "blocks.csv",        "accumulators.csv", "block_totals.csv",    "profiles.csv",
      "p_imp.csv",       "summary.json",      "snapshots.extxyz", "trajectories.csv",    "moments.csv",
      "prefactors.csv",  "tracer_blocks.csv", "moment_sums.csv",  "impurity_states.csv", manifest_file};
  if (names.count(name)) return true;
  return (starts_with(name, "snapshot_") && ends_with(name, ".csv")) ||
         (starts_with(name, "snapshots_realization_") && ends_with(name, ".extxyz")) ||
         (starts_with(name, "trajectories_realization_") && ends_with(name, ".csv"));
}

std::string recorded_run_id(const fs::path& file) {
  const std::string name = file.filename().string();
  if (name == "summary.json" || name == manifest_file) {
    try {
      const common::Json j = common::Json::parse(common::read_text(file, "run file"));
      if (j.is_object() && j.contains("run_id") && j.at("run_id").is_string()) return j.at("run_id").get<std::string>();
    } catch (const std::exception&) {
      // An unreadable or malformed file records no run; its reader names it.
    }
    return "";
  }
  std::ifstream in(file);
  std::string line;
  if (ends_with(name, ".extxyz")) {
    std::getline(in, line);  // the particle count
    return std::getline(in, line) ? extxyz_value(line, "run_id") : "";
  }
  const std::string key = "# run_id: ";
  while (std::getline(in, line) && !line.empty() && line[0] == '#')
    if (starts_with(line, key)) return line.substr(key.size());
  return "";
}

std::string with_run_id(std::string text, const std::string& from, const std::string& to) {
  if (from.empty()) return text;
  for (std::size_t at = text.find(from); at != std::string::npos; at = text.find(from, at + to.size()))
    text.replace(at, from.size(), to);
  return text;
}

FolderRuns inspect_folder(const fs::path& folder) {
  FolderRuns runs;
  std::error_code error;
  if (!fs::is_directory(folder, error)) return runs;
  runs.manifest = read_manifest(folder);
  for (const auto& entry : fs::directory_iterator(folder, error)) {
    const std::string name = entry.path().filename().string();
    if (name == manifest_file || !is_run_file_name(name) || !entry.is_regular_file(error)) continue;
    runs.files[name] = recorded_run_id(entry.path());
  }
  runs.checkpoint = fs::exists(folder / "checkpoint" / "scene.toml", error);
  return runs;
}

void require_one_run(const fs::path& folder, const std::string& option) {
  const FolderRuns runs = inspect_folder(folder);
  std::string run_id, source;
  if (runs.manifest) {
    run_id = runs.manifest->run_id;
    source = manifest_file;
  } else if (runs.files.count("summary.json") && !runs.files.at("summary.json").empty()) {
    run_id = runs.files.at("summary.json");
    source = "summary.json";
  } else {
    for (const auto& [name, id] : runs.files)
      if (!id.empty()) {
        run_id = id;
        source = name;
        break;
      }
  }
  if (run_id.empty()) return;  // no file records a run: a folder written before run ids
  for (const auto& [name, id] : runs.files) {
    if (id == run_id) continue;
    throw std::invalid_argument(
        option + ": " + (folder / name).string() + (id.empty() ? " records no run id" : " belongs to run " + id) +
        ", the folder's " + source + " to run " + run_id +
        ": the folder mixes the files of different runs; rerun into an empty folder (or with --overwrite)");
  }
}

void claim_output_folder(const fs::path& folder, const std::string& option, bool overwrite,
                         const std::string& resume_hint) {
  FolderRuns runs = inspect_folder(folder);
  if (!runs.checkpoint || !saved_work(folder).any()) {
    // Nothing to resume: a run that failed before its first block (and saved no realization's
    // state), or the remains of one killed while starting or deleting its checkpoint (no
    // scene.toml), whose blocks must not be resumed.
    std::error_code ignored;
    fs::remove_all(folder / "checkpoint", ignored);
    fs::remove_all(folder / "checkpoint.removed", ignored);
    runs.checkpoint = false;
  }
  if (runs.empty()) return;
  const std::string named = option + " = " + folder.string();
  std::vector<std::string> names;
  for (const auto& [name, id] : runs.files) names.push_back(name);
  if (!overwrite) {
    if (runs.checkpoint)
      throw std::invalid_argument(named + " holds the checkpoint of an unfinished run (" +
                                  checkpoint_description(folder) + "): continue it with `" + resume_hint +
                                  "`, or start anew with --overwrite (which deletes the saved blocks)");
    const std::string what = runs.manifest ? "the files of run " + runs.manifest->run_id + " (" + runs.manifest->kind +
                                                 (names.empty() ? "" : ": " + listed(names)) + ")"
                                           : "run files of an earlier run (" + listed(names) + ")";
    throw std::invalid_argument(named + " holds " + what + ": choose another " + option +
                                ", or give --overwrite to replace them");
  }
  std::set<std::string> remove;
  if (runs.manifest) {
    remove.insert(runs.manifest->files.begin(), runs.manifest->files.end());
    for (const auto& [name, id] : runs.files)
      if (!remove.count(name) && id != runs.manifest->run_id)
        throw std::invalid_argument(named + ": --overwrite removes only the files of run " + runs.manifest->run_id +
                                    " (manifest.json); " + (folder / name).string() +
                                    " belongs to another run: move or delete it by hand");
  } else {
    remove.insert(names.begin(), names.end());  // a folder written before manifests: its run files
  }
  for (const std::string& name : remove) fs::remove(folder / name);
  fs::remove(folder / manifest_file);
  if (runs.checkpoint) fs::remove_all(folder / "checkpoint");
}

void require_own_files(const fs::path& folder, const std::string& option, const std::string& run_id) {
  const FolderRuns runs = inspect_folder(folder);
  const auto foreign = [&](const std::string& name, const std::string& id) {
    return std::invalid_argument(option + " = " + folder.string() + ": " + (folder / name).string() +
                                 (id.empty() ? " records no run id" : " belongs to run " + id) +
                                 ", not to the resumed run " + run_id +
                                 ": move it away, or start anew with --overwrite");
  };
  if (runs.manifest && runs.manifest->run_id != run_id) throw foreign(manifest_file, runs.manifest->run_id);
  for (const auto& [name, id] : runs.files)
    if (id != run_id) throw foreign(name, id);
}

}  // namespace coldblast::run
