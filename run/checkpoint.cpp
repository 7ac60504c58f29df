#include "run/checkpoint.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <system_error>
#include <tuple>
#include <vector>

#include "common/input.hpp"
#include "common/output.hpp"
#include "md/observers.hpp"
#include "run/ensemble.hpp"
#include "run/run_directory.hpp"
#include "run/scene_file.hpp"

namespace coldblast::run {

using md::BlockSums;

namespace fs = std::filesystem;

namespace {
const char* block_file_comment = "# coldblast checkpoint: one block's sums (hex floats, exact)";
const char* extra_end = "extra end";

std::string hex(double value) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%a", value);
  return buffer;
}

fs::path block_path(const fs::path& directory, long long block) {
  return directory / ("block_" + std::to_string(block) + ".txt");
}

/// "key = value" lines of a resolved scene's TOML, by key (tables prefix their keys).
std::map<std::string, std::string> toml_entries(const std::string& toml) {
  std::map<std::string, std::string> entries;
  std::istringstream in(toml);
  std::string line, table;
  while (std::getline(in, line)) {
    if (line.empty()) continue;
    if (line.front() == '[') {
      table = line.substr(1, line.find(']') - 1) + ".";
      continue;
    }
    const auto eq = line.find(" = ");
    if (eq == std::string::npos) continue;
    entries[table + line.substr(0, eq)] = line.substr(eq + 3);
  }
  return entries;
}
}  // namespace

std::string checkpoint_block_text(long long block, const BlockSums& sums, const std::string& extra) {
  std::ostringstream out;
  out << block_file_comment << '\n'
      << "block " << block << '\n'
      << "count " << sums.count << '\n'
      << "collisions " << sums.collisions << '\n'
      << "energy_error_max " << hex(sums.energy_error_max) << '\n'
      << "entries " << sums.sum.size() << '\n';
  for (std::size_t e = 0; e < sums.sum.size(); ++e) out << hex(sums.sum[e]) << ' ' << hex(sums.sum_squares[e]) << '\n';
  out << "end\n";
  if (!extra.empty()) out << extra << (extra.back() == '\n' ? "" : "\n") << extra_end << '\n';
  return out.str();
}

BlockSums parse_checkpoint_block(const std::string& text, long long block, std::size_t entries, long long count,
                                 const std::string& source, std::string* extra, const std::string& option) {
  const auto bad = [&](const std::string& what) {
    return std::invalid_argument(option + ": malformed checkpoint " + source + ": " + what +
                                 " (delete the file to rerun its block)");
  };
  std::istringstream in(text);
  std::string line;
  if (!std::getline(in, line) || line != block_file_comment) throw bad("missing its first line");
  const auto field = [&](const std::string& key) {
    std::string name, value;
    if (!std::getline(in, line)) throw bad("ends before " + key);
    std::istringstream ls(line);
    if (!(ls >> name >> value) || name != key) throw bad("expected " + key + ", found '" + line + "'");
    return value;
  };
  const auto integer = [&](const std::string& key) {
    const std::string v = field(key);
    char* end = nullptr;
    const unsigned long long x = std::strtoull(v.c_str(), &end, 10);
    if (v.empty() || *end != '\0' || v[0] == '-') throw bad(key + " = " + v + " is not a count");
    return x;
  };
  const auto number = [&](const std::string& v, const std::string& key) {
    char* end = nullptr;
    const double x = std::strtod(v.c_str(), &end);
    if (v.empty() || *end != '\0' || !std::isfinite(x)) throw bad(key + " = " + v + " is not a finite number");
    return x;
  };
  BlockSums s;
  if (static_cast<long long>(integer("block")) != block) throw bad("block index differs from the file name");
  s.count = static_cast<long long>(integer("count"));
  if (s.count < 1 || s.count > count)
    throw bad("count = " + std::to_string(s.count) + ", the scene's block has " + std::to_string(count));
  s.collisions = integer("collisions");
  s.energy_error_max = number(field("energy_error_max"), "energy_error_max");
  if (integer("entries") != entries)
    throw bad("entries differ from the scene's " + std::to_string(entries) + " accumulated channels");
  s.sum.resize(entries);
  s.sum_squares.resize(entries);
  for (std::size_t e = 0; e < entries; ++e) {
    std::string a, b, more;
    if (!std::getline(in, line)) throw bad("ends at entry " + std::to_string(e));
    std::istringstream ls(line);
    if (!(ls >> a >> b) || (ls >> more)) throw bad("entry " + std::to_string(e) + " is '" + line + "'");
    s.sum[e] = number(a, "sum");
    s.sum_squares[e] = number(b, "sum_squares");
  }
  if (!std::getline(in, line) || line != "end") throw bad("no end line (truncated)");
  std::string rest, tail;
  while (std::getline(in, line)) {
    tail = line;
    if (line != extra_end) rest += line + "\n";
  }
  if (!rest.empty() && tail != extra_end) throw bad("no end line of its extra sums (truncated)");
  if (extra) *extra = rest;
  return s;
}

fs::path checkpoint_folder(const fs::path& out) {
  return out / "checkpoint";
}

void start_checkpoint(const fs::path& directory, const md::ResolvedScene& scene, const CheckpointRun& run) {
  common::Json j;
  j["run_id"] = run.run_id;
  j["kind"] = run.kind;
  j["shard"] = std::to_string(run.shard_index) + "/" + std::to_string(run.shard_count);
  j["scene"] = run.scene_toml;
  j["options"] = run.options;
  // run.json first: scene.toml marks a checkpoint, so a kill between the two leaves none.
  common::write_file_atomic(directory / "run.json", j.dump(2) + "\n");
  common::write_file_atomic(directory / "scene.toml", scene_toml(scene.config));
}

void save_checkpoint_block(const fs::path& directory, long long block, const BlockSums& sums, const NamedFiles& files,
                           const std::string& extra) {
  for (const auto& [name, content] : files) common::write_file_atomic(directory / "files" / name, content);
  common::write_file_atomic(block_path(directory, block), checkpoint_block_text(block, sums, extra));
}

std::string checkpoint_scene_text(const fs::path& directory) {
  const fs::path scene_path = directory / "scene.toml";
  if (!fs::exists(scene_path)) {
    // The checkpoint is removed once a run's outputs are written: a finished run has nothing left.
    const fs::path out = directory.parent_path();
    const bool finished = fs::exists(out / "summary.json");
    throw std::invalid_argument("--resume: no checkpoint in " + directory.string() + " (scene.toml missing); " +
                                (finished ? out.string() + " holds a finished run (summary.json): nothing to resume"
                                          : std::string("run without --resume to start")));
  }
  return common::read_text(scene_path, "--resume", common::text_size_limit);
}

CheckpointRun checkpoint_run(const fs::path& directory) {
  const fs::path path = directory / "run.json";
  CheckpointRun run;
  if (!fs::exists(path)) {  // a checkpoint of a run before run ids: it becomes a run of its own
    run.run_id = new_run_id();
    return run;
  }
  const auto bad = [&](const std::string& what) {
    return std::invalid_argument("--resume: malformed checkpoint " + path.string() + ": " + what);
  };
  try {
    const common::Json j = common::Json::parse(common::read_text(path, "--resume"));
    if (!j.is_object() || !j.contains("run_id") || !j.at("run_id").is_string() || !j.contains("shard") ||
        !j.at("shard").is_string())
      throw bad("no 'run_id' and 'shard' strings");
    run.run_id = j.at("run_id").get<std::string>();
    if (j.contains("kind") && j.at("kind").is_string()) run.kind = j.at("kind").get<std::string>();
    std::tie(run.shard_index, run.shard_count) = parse_shard(j.at("shard").get<std::string>());
    if (j.contains("scene") && j.at("scene").is_string()) run.scene_toml = j.at("scene").get<std::string>();
    if (j.contains("options") && j.at("options").is_object()) run.options = j.at("options");
  } catch (const common::Json::exception& e) {
    throw bad(e.what());
  }
  return run;
}

std::string scene_difference(const std::string& there, const std::string& now) {
  if (there == now) return "";
  const auto a = toml_entries(there), b = toml_entries(now);
  for (const auto& [k, v] : b) {
    const auto it = a.find(k);
    if (it == a.end() || it->second != v)
      return k + " = " + (it == a.end() ? "(missing)" : it->second) + " there, " + v + " now";
  }
  for (const auto& [k, v] : a)
    if (!b.count(k)) return k + " = " + v + " there, (missing) now";
  return "(formatting) differs";
}

Checkpoint load_checkpoint(const fs::path& directory, const md::ResolvedScene& scene) {
  common::remove_stale_temporaries(directory);  // writes of a killed run
  common::remove_stale_temporaries(directory / "files");
  common::remove_stale_temporaries(directory / "in_flight");
  const std::string saved = checkpoint_scene_text(directory), current = scene_toml(scene.config);
  if (saved != current)
    throw std::invalid_argument("--resume: the checkpoint in " + directory.string() +
                                " ran a different scene: " + scene_difference(saved, current));
  return read_checkpoint(directory, scene, "--resume");
}

Checkpoint read_checkpoint(const fs::path& directory, const md::ResolvedScene& scene, const std::string& option) {
  const md::ObservableLayout layout(scene);
  Checkpoint checkpoint;
  checkpoint.run = checkpoint_run(directory);
  for (const auto& entry : fs::directory_iterator(directory)) {
    const std::string name = entry.path().filename().string();
    if (name.rfind("block_", 0) != 0 || name.size() <= 10 || name.substr(name.size() - 4) != ".txt") continue;
    const std::string digits = name.substr(6, name.size() - 10);
    if (digits.find_first_not_of("0123456789") != std::string::npos) continue;
    const long long block = std::stoll(digits);
    const long long count = md::block_realizations(scene.config, block);
    if (count == 0)
      throw std::invalid_argument(option + ": " + entry.path().string() + " is beyond the scene's blocks");
    std::string extra;
    BlockSums sums = parse_checkpoint_block(common::read_text(entry.path(), option), block, layout.size(), count,
                                            entry.path().string(), &extra, option);
    (sums.count == count ? checkpoint.blocks : checkpoint.partial)[block] = std::move(sums);
    if (!extra.empty()) checkpoint.extra[block] = std::move(extra);
  }
  // The files of single realizations; a run before run ids kept realization 0's in realization0/.
  for (const char* folder : {"files", "realization0"})
    if (fs::exists(directory / folder))
      for (const auto& entry : fs::directory_iterator(directory / folder)) {
        const std::string name = entry.path().filename().string();
        if (name.find(".tmp.") == std::string::npos)
          checkpoint.files.push_back({name, common::read_text(entry.path(), option)});
      }
  std::sort(checkpoint.files.begin(), checkpoint.files.end());
  return checkpoint;
}

fs::path in_flight_path(const fs::path& directory, long long realization) {
  return directory / "in_flight" / ("realization_" + std::to_string(realization) + ".bin");
}

std::string read_in_flight(const fs::path& directory, long long realization) {
  const fs::path path = in_flight_path(directory, realization);
  std::error_code ec;
  if (!fs::is_regular_file(path, ec)) return "";
  return common::read_text(path, "--resume", std::size_t{1} << 40);
}

void save_in_flight(const fs::path& directory, long long realization, const std::string& bytes) {
  common::write_file_atomic(in_flight_path(directory, realization), bytes);
}

void drop_in_flight(const fs::path& directory, long long realization) {
  std::error_code ignored;
  fs::remove(in_flight_path(directory, realization), ignored);
}

void remove_checkpoint(const fs::path& out) {
  // Renamed first (atomic), then deleted: a kill while deleting leaves either the whole checkpoint
  // (resumed, it rewrites the same files) or none, never some blocks without run.json (its run id).
  const fs::path doomed = out / "checkpoint.removed";
  std::error_code ignored;
  fs::remove_all(doomed, ignored);  // a leftover of a run killed while deleting it
  fs::rename(checkpoint_folder(out), doomed, ignored);
  fs::remove_all(doomed, ignored);
}

}  // namespace coldblast::run
