#include "run/tracer_files.hpp"

#include <sstream>
#include <stdexcept>

#include "common/input.hpp"
#include "common/output.hpp"
#include "common/validate.hpp"
#include "kinetic/kinetic_theory.hpp"
#include "kinetic/prefactors.hpp"
#include "run/merge.hpp"
#include "run/run_directory.hpp"

namespace coldblast::run {

using common::format_number;

std::string prefactors_csv(const TracerResult& result) {
  const md::ResolvedScene& scene = result.ensemble.scene;
  std::ostringstream out;
  out << common::provenance_header({{"run_id", result.ensemble.run_id},
                                    {"scene", scene.config.name},
                                    {"seed", std::to_string(scene.config.seed)},
                                    {"background", result.background_description},
                                    {"A_d", format_number(scene.A_d)}},
                                   "m = 1 (host mass), k_B = 1, lengths and times in the scene's units")
      << "# X_prefactor = X / (the paper's estimate of X with its O(1) factor set to 1: theory::scaling_estimates,\n"
         "#   Eqs. (6), (8), (10)), R/lambda from Eq. (1) with A_d; X_exponent = d ln X / d ln(R/lambda) over\n"
         "#   [t/"
      << format_number(kinetic::prefactor_window)
      << ", t]; errors: block jackknife\n"
         "t,R_over_lambda";
  for (const std::string& name : kinetic::prefactor_observables())
    out << ',' << name << "_prefactor," << name << "_prefactor_stderr," << name << "_exponent," << name
        << "_exponent_stderr";
  out << '\n';
  for (const kinetic::PrefactorRow& row : kinetic::prefactor_rows(scene, result.ensemble.blocks)) {
    out << format_number(row.t) << ',' << format_number(row.R_over_lambda);
    for (std::size_t j = 0; j < row.prefactor.size(); ++j)
      out << ',' << format_number(row.prefactor[j]) << ',' << format_number(row.prefactor_error[j]) << ','
          << format_number(row.exponent[j]) << ',' << format_number(row.exponent_error[j]);
    out << '\n';
  }
  return out.str();
}

common::Json tracer_summary(const TracerResult& result) {
  common::Json j = blast_summary(result.ensemble);
  const kinetic::TracerConfig& c = result.config;
  j["engine"] = "tracer (Lorentz-Boltzmann Monte Carlo, paper Eq. (36))";
  j["background"] = c.background;
  j["background_description"] = result.background_description;
  j["background_frames"] = result.background_frames;
  if (c.background == "md") {  // the MD run whose measured fields the tracer ran in
    j["md_run"] = c.md_run;
    j["md_run_id"] = c.md_run_id;
  }
  j["transport"] = c.transport;
  j["kernel"] = result.kernel;
  j["start"] = c.start;
  if (c.start == "states") j["start_states"] = c.start_states;
  if (c.start == "hotspot") j["r0"] = c.hot_spot_radius();  // the hot spot's radius (length)
  j["start_time"] = result.start_time;
  j["trajectories"] = result.trajectories();
  j["impurity_mass"] = c.scene.impurities.mass;
  j["impurity_radius"] = result.ensemble.scene.impurity_radius;
  j["collision_rate"] = result.collision_rate();
  j["collision_rate_error"] = result.collision_rate_error();
  j["chi"] = result.chi;
  j["n_ambient"] = result.n;
  j["temperature_final"] = result.temperature_final();
  j["temperature_final_error"] = result.temperature_final_error();
  j["candidates_total"] = result.candidates();
  j["rejection_rate"] = result.rejection_rate();
  j["trajectories_per_second"] =
      result.wall_seconds > 0 ? static_cast<double>(result.trajectories()) / result.wall_seconds : 0.0;
  if (c.background == "equilibrium") {
    const auto& s = result.ensemble.scene;
    j["T"] = c.T;
    j["collision_rate_exact"] = kinetic::equilibrium_collision_rate(
        s.config.d, result.n, result.chi, s.config.a + s.impurity_radius, c.T, s.config.impurities.mass);
  }
  return j;
}

namespace {

constexpr const char* tracer_blocks_header =
    "block,count,candidates,collisions,collisions_squares,v2_final,v2_final_squares";
constexpr const char* moment_sums_header = "block,t,r2_sum,r4_sum,v2_sum,v4_sum";

/// tracer_blocks.csv (per block: the counters and the end-state sums) and moment_sums.csv (per
/// block and recording time: the sums of r², r⁴, v², v⁴): the exact sums behind the summary's
/// tracer keys and moments.csv, shortest round-trip decimals, read back by merge_tracer_outputs.
void add_tracer_blocks(const TracerResult& result, NamedFiles& files) {
  const std::string header =
      run_file_header(result.ensemble.scene, result.ensemble.run_id, {{"background", result.background_description}});
  const auto& times = result.ensemble.scene.times;
  std::ostringstream blocks, moments;
  blocks << header << "# sums over the block's trajectories; v2_final: |v|^2 at t_max\n"
         << tracer_blocks_header << '\n';
  moments << header << "# sums over the block's trajectories; r: displacement from the start\n"
          << moment_sums_header << '\n';
  for (const auto& [b, s] : result.blocks) {
    blocks << b << ',' << s.count << ',' << s.candidates << ',' << s.collisions << ','
           << format_number(s.collisions_squares) << ',' << format_number(s.v2_final) << ','
           << format_number(s.v2_final_squares) << '\n';
    for (std::size_t k = 0; k < times.size(); ++k)
      moments << b << ',' << format_number(times[k]) << ',' << format_number(s.moments[4 * k]) << ','
              << format_number(s.moments[4 * k + 1]) << ',' << format_number(s.moments[4 * k + 2]) << ','
              << format_number(s.moments[4 * k + 3]) << '\n';
  }
  files.emplace_back("tracer_blocks.csv", blocks.str());
  files.emplace_back("moment_sums.csv", moments.str());
}

/// Reads a tracer shard's tracer_blocks.csv and moment_sums.csv (bad input names the file and line).
kinetic::TracerBlocks read_tracer_blocks(const std::filesystem::path& dir, std::size_t times) {
  kinetic::TracerBlocks blocks;
  const std::filesystem::path totals_path = dir / "tracer_blocks.csv", moments_path = dir / "moment_sums.csv";
  const common::CsvTable totals = common::parse_csv(common::read_text(totals_path, "md merge DIR file"),
                                                    totals_path.string(), tracer_blocks_header);
  for (const common::CsvRow& row : totals.rows) {
    const std::string where = totals.where(row);
    kinetic::TracerBlock s;
    s.count = common::parse_count(row.fields[1], where);
    s.candidates = static_cast<std::uint64_t>(common::parse_count(row.fields[2], where));
    s.collisions = static_cast<std::uint64_t>(common::parse_count(row.fields[3], where));
    s.collisions_squares = common::parse_finite(row.fields[4], where);
    s.v2_final = common::parse_finite(row.fields[5], where);
    s.v2_final_squares = common::parse_finite(row.fields[6], where);
    s.moments.assign(4 * times, 0.0);
    blocks[common::parse_count(row.fields[0], where)] = std::move(s);
  }
  const common::CsvTable moments = common::parse_csv(common::read_text(moments_path, "md merge DIR file"),
                                                     moments_path.string(), moment_sums_header);
  std::map<long long, std::size_t> next_time;  // rows come in time order per block
  for (const common::CsvRow& row : moments.rows) {
    const std::string where = moments.where(row);
    const long long b = common::parse_count(row.fields[0], where);
    const auto block = blocks.find(b);
    const std::size_t k = next_time[b]++;
    if (block == blocks.end() || k >= times)
      throw std::invalid_argument("md merge: " + where + " does not match tracer_blocks.csv and the scene's times");
    for (int q = 0; q < 4; ++q) block->second.moments[4 * k + q] = common::parse_finite(row.fields[2 + q], where);
  }
  for (const auto& [b, s] : blocks)
    if (next_time[b] != times)
      throw std::invalid_argument("md merge: " + moments_path.string() + " holds " + std::to_string(next_time[b]) +
                                  " times of block " + std::to_string(b) + ", the scene " + std::to_string(times));
  return blocks;
}

/// The run-wide keys of a tracer shard's summary.json (equal in every shard of one run).
common::Json read_tracer_summary(const std::filesystem::path& path) {
  const auto bad = [&](const std::string& what) {
    return std::invalid_argument("md merge: " + path.string() + ": " + what);
  };
  common::Json s;
  try {
    s = common::Json::parse(common::read_text(path, "md merge DIR file"));
  } catch (const common::Json::exception& e) {
    throw bad(e.what());
  }
  if (!s.is_object()) throw bad("not a JSON object");
  common::Json keys = common::Json::object();
  const auto take = [&](const char* key, bool number) {
    if (!s.contains(key) || (number ? !s.at(key).is_number() : !s.at(key).is_string()))
      throw bad(std::string("no ") + (number ? "number" : "string") + " '" + key + "' (a tracer shard)");
    keys[key] = s.at(key);
  };
  for (const char* key : {"engine", "background", "background_description", "transport", "start"}) take(key, false);
  for (const char* key : {"background_frames", "start_time", "chi", "n_ambient", "impurity_mass", "impurity_radius"})
    take(key, true);
  if (!keys.at("background_frames").is_number_unsigned()) throw bad("'background_frames' is not a count");
  if (keys.at("background") == "equilibrium") take("T", true);
  if (keys.at("background") == "md") {
    take("md_run", false);
    take("md_run_id", false);
  }
  if (s.contains("kernel"))
    take("kernel", false);
  else
    keys["kernel"] = "scalar";  // runs before the vector kernels
  return keys;
}

}  // namespace

namespace {
/// moments.csv: r², <r⁴>/<r²>² and the same of the speed per recording time, block-jackknife errors.
std::string moments_csv(const TracerResult& result) {
  std::ostringstream out;
  out << common::provenance_header({{"run_id", result.ensemble.run_id},
                                    {"scene", result.ensemble.scene.config.name},
                                    {"seed", std::to_string(result.ensemble.scene.config.seed)},
                                    {"background", result.background_description}},
                                   "m = 1 (host mass), k_B = 1, lengths and times in the scene's units")
      << "# r: impurity displacement from its start; errors: block jackknife\n"
      << "t,r2,r2_stderr,r4_over_r2_squared,r4_over_r2_squared_stderr,v2,v2_stderr,v4_over_v2_squared,"
         "v4_over_v2_squared_stderr\n";
  for (const kinetic::MomentRow& m : kinetic::moment_rows(result.ensemble.scene.times, result.blocks))
    out << format_number(m.t) << ',' << format_number(m.r2) << ',' << format_number(m.r2_error) << ','
        << format_number(m.r_ratio) << ',' << format_number(m.r_ratio_error) << ',' << format_number(m.v2) << ','
        << format_number(m.v2_error) << ',' << format_number(m.v_ratio) << ',' << format_number(m.v_ratio_error)
        << '\n';
  return out.str();
}
}  // namespace

NamedFiles tracer_files(const TracerResult& result) {
  NamedFiles files = blast_data_files(result.ensemble);
  files.emplace_back("moments.csv", moments_csv(result));
  files.emplace_back("prefactors.csv", prefactors_csv(result));
  add_tracer_blocks(result, files);
  files.emplace_back("summary.json", tracer_summary(result).dump(2) + "\n");
  return files;
}

void write_tracer_outputs(const TracerResult& result, const std::filesystem::path& directory) {
  write_run_files(tracer_files(result), result.ensemble.run_id, result.ensemble.kind, directory);
}

bool is_tracer_run(const std::filesystem::path& directory) {
  try {
    const common::Json s = common::Json::parse(common::read_text(directory / "summary.json"));
    return s.is_object() && s.contains("engine") && s.at("engine").is_string() &&
           s.at("engine").get<std::string>().rfind("tracer", 0) == 0;
  } catch (const std::exception&) {
    return false;  // md merge reports the unreadable file
  }
}

TracerResult merge_tracer_outputs(const std::vector<std::filesystem::path>& directories) {
  TracerResult merged;
  merged.ensemble = merge_blast_outputs(directories);  // checks scenes and duplicate blocks
  const md::ResolvedScene& scene = merged.ensemble.scene;
  const common::Json first = read_tracer_summary(directories.front() / "summary.json");
  for (const auto& dir : directories) {
    const common::Json summary = read_tracer_summary(dir / "summary.json");
    for (const auto& [key, value] : first.items())
      if (summary.at(key) != value)
        throw std::invalid_argument("md merge: " + dir.string() + " ran a different tracer than " +
                                    directories.front().string() + ": " + key + " = " + summary.at(key).dump() +
                                    " there, " + value.dump() + " in the first");
    for (auto& [b, block] : read_tracer_blocks(dir, scene.times.size())) {
      if (!merged.ensemble.blocks.count(b) || merged.ensemble.blocks.at(b).count != block.count)
        throw std::invalid_argument("md merge: " + (dir / "tracer_blocks.csv").string() + ": block " +
                                    std::to_string(b) + " does not match block_totals.csv");
      merged.blocks[b] = std::move(block);
    }
  }
  if (merged.blocks.size() != merged.ensemble.blocks.size())
    throw std::invalid_argument("md merge: the tracer shards' tracer_blocks.csv hold " +
                                std::to_string(merged.blocks.size()) + " blocks, block_totals.csv " +
                                std::to_string(merged.ensemble.blocks.size()));
  kinetic::TracerConfig& c = merged.config;
  c.scene = scene.config;
  c.background = first.at("background").get<std::string>();
  c.transport = first.at("transport").get<std::string>();
  c.start = first.at("start").get<std::string>();
  if (first.contains("start_states")) c.start_states = first.at("start_states").get<std::string>();
  if (first.contains("r0")) c.r0 = first.at("r0").get<double>();
  if (first.contains("T")) c.T = first.at("T").get<double>();
  if (first.contains("md_run")) {
    c.md_run = first.at("md_run").get<std::string>();
    c.md_run_id = first.at("md_run_id").get<std::string>();
  }
  c.trajectories = scene.config.realizations;
  c.threads = merged.ensemble.threads;
  merged.start_time = c.start_time = first.at("start_time").get<double>();
  merged.background_description = first.at("background_description").get<std::string>();
  merged.background_frames = first.at("background_frames").get<std::uint64_t>();
  merged.kernel = first.at("kernel").get<std::string>();
  merged.chi = first.at("chi").get<double>();
  merged.n = first.at("n_ambient").get<double>();
  merged.wall_seconds = merged.ensemble.wall_seconds;
  return merged;
}

}  // namespace coldblast::run
