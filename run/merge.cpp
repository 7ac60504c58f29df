#include "run/merge.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <optional>
#include <stdexcept>

#include "common/input.hpp"
#include "md/observers.hpp"
#include "run/checkpoint.hpp"
#include "run/ensemble.hpp"
#include "run/run_directory.hpp"
#include "run/scene_file.hpp"
#include "run/snapshot_files.hpp"

namespace coldblast::run {

using md::BlockSums;
using md::ObservableLayout;

namespace {
namespace fs = std::filesystem;
}  // namespace

namespace {

/// The block sums of one shard directory, read back exactly from block_totals.csv and accumulators.csv.
std::map<long long, BlockSums> read_block_sums(const fs::path& dir, const ObservableLayout& layout) {
  std::map<long long, BlockSums> blocks;
  const common::CsvTable totals = common::parse_csv(common::read_text(dir / "block_totals.csv", "md merge DIR file"),
                                                    (dir / "block_totals.csv").string(), block_totals_header);
  for (const common::CsvRow& row : totals.rows) {
    const std::string where = totals.where(row);
    BlockSums s;
    s.count = common::parse_count(row.fields[1], where);
    s.collisions = static_cast<std::uint64_t>(common::parse_count(row.fields[2], where));
    s.energy_error_max = common::parse_number_or_nan(row.fields[3], where);
    s.sum.assign(layout.size(), 0.0);
    s.sum_squares.assign(layout.size(), 0.0);
    blocks[common::parse_count(row.fields[0], where)] = s;
  }
  if (!fs::exists(dir / "accumulators.csv"))
    throw std::invalid_argument("md merge DIR file = " + (dir / "accumulators.csv").string() +
                                " is missing: md merge adds the blocks' sums it holds, so a copy of a run that kept "
                                "only observables, blocks and profiles cannot be merged (rerun its realizations)");
  const common::CsvTable accumulators =
      common::parse_csv(common::read_text(dir / "accumulators.csv", "md merge DIR file"),
                        (dir / "accumulators.csv").string(), accumulator_header);
  for (const common::CsvRow& row : accumulators.rows) {
    const std::string where = accumulators.where(row);
    const auto block = blocks.find(common::parse_count(row.fields[0], where));
    const auto e = static_cast<std::size_t>(common::parse_count(row.fields[1], where));
    if (block == blocks.end() || e >= layout.size() || row.fields[2] != layout.channel(e))
      throw std::invalid_argument("md merge: " + where + " does not match the scene layout");
    block->second.sum[e] = common::parse_number_or_nan(row.fields[5], where);
    block->second.sum_squares[e] = common::parse_number_or_nan(row.fields[6], where);
  }
  return blocks;
}

}  // namespace

namespace {
/// What md merge takes from a shard's summary.json.
struct MergedSummary {
  std::string run_id;  ///< empty for a run made before run ids
  std::string scene_toml;
  double wall_seconds = 0.0;
  long long resumed_realizations = 0, resumed_collisions = 0;
  int threads = 1;
  // As the shards resolved the scene (absent in old files): where A_d came from, and the region
  // (the tracer's has no particles), which md's resolve_scene would otherwise size anew.
  std::optional<std::string> A_d_source;
  std::optional<long long> particles;
  std::optional<double> region_radius;
};

/// Reads summary.json of a shard: a malformed file or field is bad input (std::invalid_argument
/// naming the file and the key), not a runtime failure (found by fuzz/fuzz_run_directory.cpp).
MergedSummary read_merged_summary(const std::filesystem::path& path) {
  const std::string text = common::read_text(path, "md merge DIR file");
  const auto bad = [&](const std::string& what) {
    return std::invalid_argument("md merge: " + path.string() + ": " + what);
  };
  try {
    const common::Json s = common::Json::parse(text);
    if (!s.is_object()) throw bad("not a JSON object");
    const auto count = [&](const char* key, long long fallback, long long most) {
      if (!s.contains(key)) {
        if (fallback < 0) throw bad(std::string("no '") + key + "'");
        return fallback;
      }
      const common::Json& v = s.at(key);
      if (!v.is_number_integer() || v.get<long long>() < 0 || v.get<long long>() > most)
        throw bad(std::string("'") + key + "' = " + v.dump() + " is not a count in [0, " + std::to_string(most) + "]");
      return v.get<long long>();
    };
    MergedSummary m;
    if (!s.contains("scene_toml") || !s.at("scene_toml").is_string()) throw bad("no 'scene_toml' string");
    m.scene_toml = s.at("scene_toml").get<std::string>();
    if (s.contains("run_id")) {
      if (!s.at("run_id").is_string()) throw bad("'run_id' is not a string");
      m.run_id = s.at("run_id").get<std::string>();
    }
    if (!s.contains("wall_seconds") || !s.at("wall_seconds").is_number() ||
        !(s.at("wall_seconds").get<double>() >= 0.0) || !std::isfinite(s.at("wall_seconds").get<double>()))
      throw bad("no finite 'wall_seconds' >= 0");
    m.wall_seconds = s.at("wall_seconds").get<double>();
    m.resumed_realizations = count("resumed_realizations", 0, std::numeric_limits<long long>::max());
    m.resumed_collisions = count("resumed_collisions", 0, std::numeric_limits<long long>::max());
    m.threads = static_cast<int>(count("threads", -1, 1 << 20));
    if (s.contains("A_d_source")) {
      if (!s.at("A_d_source").is_string()) throw bad("'A_d_source' is not a string");
      m.A_d_source = s.at("A_d_source").get<std::string>();
    }
    if (s.contains("particles")) m.particles = count("particles", -1, std::numeric_limits<long long>::max());
    if (s.contains("region_radius")) {
      const common::Json& v = s.at("region_radius");
      if (!v.is_number() || !(v.get<double>() > 0.0) || !std::isfinite(v.get<double>()))
        throw bad("'region_radius' = " + v.dump() + " is not a finite number > 0");
      m.region_radius = v.get<double>();
    }
    return m;
  } catch (const common::Json::exception& e) {
    throw bad(e.what());
  }
}
}  // namespace

std::string partial_merge_note(const BlastResult& merged) {
  const long long expected = merged.scene.config.realizations, got = merged.realizations();
  if (got >= expected) return "";
  const long long block_size = merged.scene.config.block_size;
  const long long blocks = (expected + block_size - 1) / block_size;
  std::string missing;
  int listed = 0;
  for (long long b = 0; b < blocks; ++b) {
    if (merged.blocks.count(b)) continue;
    if (listed++ == 8) {
      missing += ", ...";
      break;
    }
    missing += (missing.empty() ? "" : ", ") + std::to_string(b);
  }
  return "md merge: " + std::to_string(got) + " of the scene's " + std::to_string(expected) + " realizations (blocks " +
         missing + " missing): a partial ensemble";
}

namespace {

/// One input of md merge, as read from its folder.
struct MergeInput {
  MergedSummary summary;
  md::ResolvedScene scene;
  std::map<long long, BlockSums> blocks;
  NamedFiles files;  ///< its single realizations' files, with its own run id
};

/// The scene of a finished run's summary, as the run resolved it (its recorded A_d source and region
/// where present: md's resolve_scene would otherwise size them anew).
md::ResolvedScene summary_scene(const MergedSummary& summary, const fs::path& source) {
  md::ResolvedScene scene = md::resolve_scene(parse_scene(summary.scene_toml, {}, source.string()));
  if (summary.A_d_source) scene.A_d_source = *summary.A_d_source;
  if (summary.particles) scene.particle_count = static_cast<std::size_t>(*summary.particles);
  if (summary.region_radius) scene.region_radius = *summary.region_radius;
  return scene;
}

MergeInput read_finished_run(const fs::path& dir) {
  require_one_run(dir, "md merge DIR");
  MergeInput input;
  input.summary = read_merged_summary(dir / "summary.json");
  input.scene = summary_scene(input.summary, dir / "summary.json");
  input.blocks = read_block_sums(dir, ObservableLayout(input.scene));
  for (const auto& entry : fs::directory_iterator(dir)) {
    const std::string name = entry.path().filename().string();
    if (is_realization_file_name(name)) input.files.push_back({name, common::read_text(entry.path())});
  }
  return input;
}

/// "md merge: DIR is a run in progress: ..." for the notes: what of it is merged and what is not.
std::string in_progress_note(const fs::path& dir, const Checkpoint& checkpoint) {
  long long done = 0, running = 0;
  for (const auto& [b, sums] : checkpoint.blocks) done += sums.count;
  for (const auto& [b, sums] : checkpoint.partial) running += sums.count;
  const auto count = [](long long n, const std::string& noun) {
    return std::to_string(n) + " " + noun + (n == 1 ? "" : "s");
  };
  return "md merge: " + dir.string() + " is a run in progress (its checkpoint): " +
         count(static_cast<long long>(checkpoint.blocks.size()), "finished block") + " (" + count(done, "realization") +
         ") merged" + (running > 0 ? "; " + count(running, "realization") + " of blocks in progress left out" : "");
}

/// A run still in progress: the finished blocks of its checkpoint, read without changing anything
/// in the folder (the running process keeps writing it). Its scene is the checkpoint's resolved
/// scene, with the A_d source of the scene as given (run.json) when that resolves to the same text.
MergeInput read_run_in_progress(const fs::path& dir, std::vector<std::string>* notes) {
  const fs::path folder = checkpoint_folder(dir);
  const CheckpointRun run = checkpoint_run(folder);
  if (run.kind != "md run")
    throw std::invalid_argument("md merge: " + dir.string() + " is a " + run.kind +
                                " in progress: only an md run's checkpoint can be merged before it ends");
  MergeInput input;
  // A checkpoint from before run ids (no run.json) names no run: checkpoint_run made one up.
  if (fs::exists(folder / "run.json")) input.summary.run_id = run.run_id;
  input.summary.scene_toml = checkpoint_scene_text(folder);
  input.scene = md::resolve_scene(parse_scene(input.summary.scene_toml, {}, (folder / "scene.toml").string()));
  if (!run.scene_toml.empty()) {
    const md::ResolvedScene given =
        resolve_blast_scene(parse_scene(run.scene_toml, {}, (folder / "run.json").string()));
    if (scene_toml(given.config) == input.summary.scene_toml) input.scene = given;
  }
  Checkpoint checkpoint = read_checkpoint(folder, input.scene, "md merge DIR");
  if (notes) notes->push_back(in_progress_note(dir, checkpoint));
  for (const auto& [b, sums] : checkpoint.blocks) input.summary.resumed_realizations += sums.count;
  for (const auto& [b, sums] : checkpoint.blocks)
    input.summary.resumed_collisions += static_cast<long long>(sums.collisions);
  input.blocks = std::move(checkpoint.blocks);
  for (auto& [name, text] : checkpoint.files)
    if (is_realization_file_name(name)) input.files.push_back({name, std::move(text)});
  return input;
}

/// A folder with summary.json is a finished run; one with only a checkpoint, a run in progress.
MergeInput read_merge_input(const fs::path& dir, std::vector<std::string>* notes) {
  const bool in_progress = !fs::exists(dir / "summary.json") && fs::exists(checkpoint_folder(dir) / "scene.toml");
  return in_progress ? read_run_in_progress(dir, notes) : read_finished_run(dir);
}

}  // namespace

BlastResult merge_blast_outputs(const std::vector<fs::path>& directories, std::vector<std::string>* notes) {
  if (directories.empty()) throw std::invalid_argument("md merge: no input directories");
  BlastResult merged;
  merged.run_id = new_run_id();
  merged.kind = "md merge";
  std::string scene_text;
  for (const auto& dir : directories) {
    MergeInput input = read_merge_input(dir, notes);
    if (scene_text.empty()) {
      scene_text = input.summary.scene_toml;
      merged.scene = input.scene;
    } else if (input.summary.scene_toml != scene_text) {
      throw std::invalid_argument("md merge: " + dir.string() + " ran a different scene than " +
                                  directories.front().string());
    }
    merged.wall_seconds += input.summary.wall_seconds;
    merged.resumed_realizations += input.summary.resumed_realizations;
    merged.resumed_collisions += static_cast<std::uint64_t>(input.summary.resumed_collisions);
    merged.threads = std::max(merged.threads, input.summary.threads);
    for (auto& [b, s] : input.blocks) {
      if (merged.blocks.count(b))
        throw std::invalid_argument("md merge: block " + std::to_string(b) + " appears twice (" + dir.string() + ")");
      merged.blocks[b] = std::move(s);
    }
    if (!input.summary.run_id.empty()) merged.merged_from.push_back(input.summary.run_id);
    for (auto& [name, text] : input.files)
      merged.realization_files.push_back(
          {name, input.summary.run_id.empty() ? std::move(text)
                                              : with_run_id(std::move(text), input.summary.run_id, merged.run_id)});
  }
  std::sort(merged.realization_files.begin(), merged.realization_files.end());
  return merged;
}

}  // namespace coldblast::run
