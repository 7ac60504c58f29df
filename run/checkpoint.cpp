#include "run/checkpoint.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <system_error>
#include <vector>

#include "common/input.hpp"
#include "common/output.hpp"
#include "md/observers.hpp"
#include "run/scene_file.hpp"

namespace coldblast::run {

using md::BlockSums;

namespace fs = std::filesystem;

namespace {
const char* block_file_comment = "# coldblast checkpoint: one block's sums (hex floats, exact)";

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

std::string checkpoint_block_text(long long block, const BlockSums& sums) {
  std::ostringstream out;
  out << block_file_comment << '\n'
      << "block " << block << '\n'
      << "count " << sums.count << '\n'
      << "collisions " << sums.collisions << '\n'
      << "energy_error_max " << hex(sums.energy_error_max) << '\n'
      << "entries " << sums.sum.size() << '\n';
  for (std::size_t e = 0; e < sums.sum.size(); ++e) out << hex(sums.sum[e]) << ' ' << hex(sums.sum_squares[e]) << '\n';
  out << "end\n";
  return out.str();
}

BlockSums parse_checkpoint_block(const std::string& text, long long block, std::size_t entries, long long count,
                                 const std::string& source) {
  const auto bad = [&](const std::string& what) {
    return std::invalid_argument("--resume: malformed checkpoint " + source + ": " + what +
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
  if (s.count != count)
    throw bad("count = " + std::to_string(s.count) + ", the scene's block has " + std::to_string(count));
  s.collisions = integer("collisions");
  s.energy_error_max = number(field("energy_error_max"), "energy_error_max");
  if (integer("entries") != entries)
    throw bad("entries differ from the scene's " + std::to_string(entries) + " accumulated channels");
  s.sum.resize(entries);
  s.sum_squares.resize(entries);
  for (std::size_t e = 0; e < entries; ++e) {
    std::string a, b, extra;
    if (!std::getline(in, line)) throw bad("ends at entry " + std::to_string(e));
    std::istringstream ls(line);
    if (!(ls >> a >> b) || (ls >> extra)) throw bad("entry " + std::to_string(e) + " is '" + line + "'");
    s.sum[e] = number(a, "sum");
    s.sum_squares[e] = number(b, "sum_squares");
  }
  if (!std::getline(in, line) || line != "end") throw bad("no end line (truncated)");
  return s;
}

void start_checkpoint(const fs::path& directory, const md::ResolvedScene& scene) {
  std::error_code ec;
  if (fs::exists(directory, ec))
    for (const auto& entry : fs::directory_iterator(directory)) {
      const std::string name = entry.path().filename().string();
      if (name.rfind("block_", 0) == 0 || name.rfind("scene.toml", 0) == 0 || name == "realization0")
        fs::remove_all(entry.path());
    }
  common::write_file_atomic(directory / "scene.toml", scene_toml(scene.config));
}

void save_checkpoint_block(const fs::path& directory, long long block, const BlockSums& sums,
                           const NamedFiles* realization0_files) {
  if (realization0_files)
    for (const auto& [name, content] : *realization0_files)
      common::write_file_atomic(directory / "realization0" / name, content);
  common::write_file_atomic(block_path(directory, block), checkpoint_block_text(block, sums));
}

Checkpoint load_checkpoint(const fs::path& directory, const md::ResolvedScene& scene) {
  common::remove_stale_temporaries(directory);  // writes of a killed run
  common::remove_stale_temporaries(directory / "realization0");
  const fs::path scene_path = directory / "scene.toml";
  if (!fs::exists(scene_path)) {
    // The checkpoint is removed once a run's outputs are written: a finished run has nothing left.
    const bool finished = fs::exists(directory.parent_path() / "summary.json");
    throw std::invalid_argument(
        "--resume: no checkpoint in " + directory.string() + " (scene.toml missing); " +
        (finished ? directory.parent_path().string() + " holds a finished run (summary.json): nothing to resume"
                  : std::string("run without --resume to start")));
  }
  const std::string saved = common::read_text(scene_path, "--resume", common::text_size_limit),
                    current = scene_toml(scene.config);
  if (saved != current) {
    const auto a = toml_entries(saved), b = toml_entries(current);
    std::string key = "(formatting)", was = "", now = "";
    for (const auto& [k, v] : b) {
      const auto it = a.find(k);
      if (it == a.end() || it->second != v) {
        key = k, was = it == a.end() ? "(missing)" : it->second, now = v;
        break;
      }
    }
    if (key == "(formatting)")
      for (const auto& [k, v] : a)
        if (!b.count(k)) {
          key = k, was = v, now = "(missing)";
          break;
        }
    throw std::invalid_argument("--resume: the checkpoint in " + directory.string() + " ran a different scene: " + key +
                                " = " + was + " there, " + now + " now");
  }
  const md::ObservableLayout layout(scene);
  Checkpoint checkpoint;
  for (const auto& entry : fs::directory_iterator(directory)) {
    const std::string name = entry.path().filename().string();
    if (name.rfind("block_", 0) != 0 || name.size() <= 10 || name.substr(name.size() - 4) != ".txt") continue;
    const std::string digits = name.substr(6, name.size() - 10);
    if (digits.find_first_not_of("0123456789") != std::string::npos) continue;
    const long long block = std::stoll(digits);
    const long long count = md::block_realizations(scene.config, block);
    if (count == 0) throw std::invalid_argument("--resume: " + entry.path().string() + " is beyond the scene's blocks");
    checkpoint.blocks[block] = parse_checkpoint_block(common::read_text(entry.path(), "--resume"), block, layout.size(),
                                                      count, entry.path().string());
  }
  if (checkpoint.blocks.count(0) && fs::exists(directory / "realization0"))
    for (const auto& entry : fs::directory_iterator(directory / "realization0")) {
      const std::string name = entry.path().filename().string();
      if (name.find(".tmp.") == std::string::npos)
        checkpoint.realization0_files.push_back({name, common::read_text(entry.path(), "--resume")});
    }
  std::sort(checkpoint.realization0_files.begin(), checkpoint.realization0_files.end());
  return checkpoint;
}

}  // namespace coldblast::run
