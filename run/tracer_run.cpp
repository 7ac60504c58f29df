#include "run/tracer_run.hpp"

#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <memory>
#include <mutex>
#include <sstream>
#include <stdexcept>
#include <vector>

#include "common/validate.hpp"
#include "run/checkpoint.hpp"
#include "run/ensemble.hpp"
#include "run/impurity_states.hpp"
#include "run/md_fields.hpp"
#include "run/run_directory.hpp"
#include "run/scene_file.hpp"
#include "run/tracer_files.hpp"
#include "run/worker_pool.hpp"

namespace coldblast::run {

std::uint64_t TracerResult::collisions() const {
  return kinetic::total_collisions(blocks);
}
std::uint64_t TracerResult::candidates() const {
  return kinetic::total_candidates(blocks);
}
long long TracerResult::trajectories() const {
  return kinetic::total_trajectories(blocks);
}
double TracerResult::collision_rate() const {
  return kinetic::collision_rate(blocks, config.scene.t_max - start_time);
}
double TracerResult::collision_rate_error() const {
  return kinetic::collision_rate_error(blocks, config.scene.t_max - start_time);
}
double TracerResult::temperature_final() const {
  return kinetic::temperature_final(blocks, config.scene.impurities.mass, config.scene.d);
}
double TracerResult::temperature_final_error() const {
  return kinetic::temperature_final_error(blocks, config.scene.impurities.mass, config.scene.d);
}
double TracerResult::rejection_rate() const {
  return kinetic::rejection_rate(blocks);
}

std::string md_run_path(const std::string& md_run) {
  if (md_run.empty()) return md_run;
  std::filesystem::path path = std::filesystem::absolute(md_run).lexically_normal();
  if (path.filename().empty()) path = path.parent_path();  // "DIR/": the folder itself
  return path.string();
}

kinetic::TracerConfig with_input_files(kinetic::TracerConfig config) {
  if (config.start == "states" && !config.states && !config.start_states.empty())
    config.states = std::make_shared<const md::ImpurityStates>(
        read_impurity_states(config.start_states, config.scene.d, "--start-states"));
  if (config.background == "md" && !config.md_profiles && !config.md_run.empty()) {
    config.md_run = md_run_path(config.md_run);
    MdRunFields fields = read_md_run_fields(config.md_run, "--md-run");
    const std::string named = "--md-run = " + config.md_run;
    const std::string difference = scene_physics_difference(fields.scene, config.scene);
    if (!difference.empty())
      throw std::invalid_argument(named + " is of another scene: " + difference +
                                  " (leave SCENE and --set of these keys out to take the MD run's scene)");
    if (!config.md_run_id.empty() && config.md_run_id != fields.run_id)
      throw std::invalid_argument(named + " now holds run " + fields.run_id + ", not run " + config.md_run_id +
                                  " whose fields the checkpoint's blocks ran in");
    if (config.scene.t_max > fields.scene.t_max)
      throw std::invalid_argument(named + " ran to t_max = " + common::format_number(fields.scene.t_max) +
                                  " (recorded up to t = " + common::format_number(fields.profiles.frames.back().t) +
                                  "); the tracer's t_max = " + common::format_number(config.scene.t_max) +
                                  " is beyond it");
    config.md_run_id = fields.run_id;
    config.md_profiles = std::make_shared<const kinetic::MeasuredProfiles>(std::move(fields.profiles));
  }
  return config;
}

TracerResult tracer_result(const kinetic::TracerRunInfo& info, double wall_seconds, int ranks) {
  TracerResult result;
  result.config = info.config;
  result.ensemble.kind = "tracer";
  result.ensemble.scene = info.scene;
  result.ensemble.threads = info.config.threads;
  result.ensemble.shard_index = info.config.shard_index;
  result.ensemble.shard_count = info.config.shard_count;
  result.ensemble.ranks = ranks;
  result.ensemble.wall_seconds = wall_seconds;
  result.background_description = info.background_description;
  result.background_frames = info.background_frames;
  result.kernel = info.kernel;
  result.n = info.n;
  result.chi = info.chi;
  result.start_time = info.start_time;
  result.wall_seconds = wall_seconds;
  return result;
}

namespace {

std::string hex(double value) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%a", value);
  return buffer;
}

/// A tracer block's own sums as checkpoint lines (after md's sums): counts in decimal, sums in
/// C99 hex floats (an exact round trip).
std::string tracer_block_text(const kinetic::TracerBlock& t) {
  std::ostringstream out;
  out << "tracer " << t.count << ' ' << t.candidates << ' ' << t.collisions << '\n'
      << hex(t.collisions_squares) << ' ' << hex(t.v2_final) << ' ' << hex(t.v2_final_squares) << '\n'
      << "moments " << t.moments.size() << '\n';
  for (const double m : t.moments) out << hex(m) << '\n';
  return out.str();
}

kinetic::TracerBlock parse_tracer_block(const std::string& text, std::size_t moments, const std::string& source) {
  const auto bad = [&] { return std::invalid_argument("--resume: malformed tracer sums in checkpoint " + source); };
  std::istringstream in(text);
  kinetic::TracerBlock t;
  std::string word, a, b, c;
  std::size_t size = 0;
  if (!(in >> word >> t.count >> t.candidates >> t.collisions) || word != "tracer") throw bad();
  if (!(in >> a >> b >> c >> word >> size) || word != "moments" || size != moments) throw bad();
  const auto number = [&](const std::string& v) {
    char* end = nullptr;
    const double x = std::strtod(v.c_str(), &end);
    if (v.empty() || *end != '\0' || !std::isfinite(x)) throw bad();
    return x;
  };
  t.collisions_squares = number(a);
  t.v2_final = number(b);
  t.v2_final_squares = number(c);
  for (std::size_t k = 0; k < moments; ++k) {
    if (!(in >> a)) throw bad();
    t.moments.push_back(number(a));
  }
  return t;
}

std::string option_text(double value) {
  return common::format_number(value);
}

}  // namespace

std::map<std::string, std::string> tracer_option_values(const kinetic::TracerConfig& c) {
  return {{"--background", c.background},
          {"--transport", c.transport},
          {"--trajectories", std::to_string(c.trajectories)},
          {"--T", option_text(c.T)},
          {"--phi", c.phi ? option_text(*c.phi) : ""},
          {"--start", c.start},
          {"--r0", option_text(c.r0)},
          {"--start-time", option_text(c.start_time)},
          {"--start-states", c.start_states},
          {"--md-run", md_run_path(c.md_run)},
          {"md_run_id", c.md_run_id},
          {"--frames-per-decade", std::to_string(c.frames_per_decade)},
          {"--cells", std::to_string(c.cells)},
          {"--kernel", c.kernel},
          {"--shard", std::to_string(c.shard_index) + "/" + std::to_string(c.shard_count)}};
}

kinetic::TracerConfig resume_tracer_config(const std::filesystem::path& out, const kinetic::TracerConfig& requested,
                                           const std::vector<std::string>& given) {
  const std::filesystem::path checkpoint = checkpoint_folder(out);
  checkpoint_scene_text(checkpoint);  // throws, naming --resume, without a checkpoint
  const CheckpointRun run = checkpoint_run(checkpoint);
  if (run.kind != "tracer")
    throw std::invalid_argument("--resume: the checkpoint in " + checkpoint.string() + " is of a " + run.kind +
                                ", not of a tracer run; continue it with `coldblast md run --resume " + out.string() +
                                "`");
  const std::string where = " contradicts the checkpoint in " + checkpoint.string();
  kinetic::TracerConfig c = requested;
  c.scene = parse_scene(run.scene_toml, {}, (checkpoint / "run.json").string());
  const auto value = [&](const char* key) {
    if (!run.options.contains(key) || !run.options.at(key).is_string())
      throw std::invalid_argument("--resume: " + (checkpoint / "run.json").string() + " has no option " + key);
    return run.options.at(key).get<std::string>();
  };
  try {
    c.background = value("--background");
    c.transport = value("--transport");
    c.trajectories = std::stoll(value("--trajectories"));
    c.T = std::stod(value("--T"));
    const std::string phi = value("--phi");
    c.phi = phi.empty() ? std::nullopt : std::optional<double>(std::stod(phi));
    c.start = value("--start");
    c.r0 = run.options.contains("--r0") ? std::stod(value("--r0")) : 0.0;  // absent before the hot-spot start
    c.start_time = std::stod(value("--start-time"));
    c.start_states = value("--start-states");
    // Absent from checkpoints made before --background md: no MD run.
    c.md_run = run.options.contains("--md-run") ? value("--md-run") : "";
    c.md_run_id = run.options.contains("md_run_id") ? value("md_run_id") : "";
    c.frames_per_decade = std::stoi(value("--frames-per-decade"));
    c.cells = std::stoi(value("--cells"));
    c.kernel = value("--kernel");
    std::tie(c.shard_index, c.shard_count) = parse_shard(value("--shard"));
  } catch (const std::logic_error&) {  // std::stod and friends: not a number
    throw std::invalid_argument("--resume: " + (checkpoint / "run.json").string() + " holds a malformed option");
  }
  const auto asked = tracer_option_values(requested), saved = tracer_option_values(c);
  for (const std::string& flag : given) {
    if (flag == "SCENE" || flag == "--set" || flag == "--seed") {
      const std::string difference = scene_difference(scene_toml(c.scene), scene_toml(requested.scene));
      if (!difference.empty())
        throw std::invalid_argument(flag + where + ": " + difference + "; leave it out to resume");
    } else if (asked.count(flag) && asked.at(flag) != saved.at(flag)) {
      throw std::invalid_argument(flag + " = " + asked.at(flag) + where + ", which has " + flag + " = " +
                                  saved.at(flag) + "; leave it out to resume");
    }
  }
  return c;
}

TracerPlan plan_tracer(const kinetic::TracerRun& run, const TracerRunFiles& files) {
  const kinetic::TracerRunInfo& info = run.info();
  TracerPlan plan;
  plan.result = tracer_result(info, 0.0);
  TracerResult& result = plan.result;
  result.ensemble.run_id = new_run_id();
  if (!files.out.empty()) {
    const std::filesystem::path checkpoint = checkpoint_folder(files.out);
    if (files.resume) {
      Checkpoint saved = load_checkpoint(checkpoint, info.scene);
      result.ensemble.run_id = saved.run.run_id;
      require_own_files(files.out, "--resume", result.ensemble.run_id);
      for (auto& [b, sums] : saved.blocks) {
        if (!saved.extra.count(b))
          throw std::invalid_argument("--resume: block " + std::to_string(b) + " of " + checkpoint.string() +
                                      " has no tracer sums");
        result.blocks[b] = parse_tracer_block(saved.extra.at(b), 4 * info.scene.times.size(),
                                              (checkpoint / ("block_" + std::to_string(b) + ".txt")).string());
        result.ensemble.resumed_realizations += sums.count;
        result.ensemble.resumed_collisions += sums.collisions;
        result.ensemble.blocks[b] = std::move(sums);
      }
    } else {
      claim_output_folder(files.out, files.out_option, files.overwrite,
                          files.resume_hint.empty() ? "--resume " + files.out.string() : files.resume_hint);
      common::Json options = common::Json::object();
      for (const auto& [flag, value] : tracer_option_values(info.config)) options[flag] = value;
      start_checkpoint(checkpoint, info.scene,
                       {result.ensemble.run_id, "tracer", info.config.shard_index, info.config.shard_count,
                        scene_toml(info.input_scene), options});
    }
  }
  for (const long long b : run.blocks())
    if (!result.blocks.count(b)) plan.pending.push_back(b);
  return plan;
}

void save_tracer_block(const TracerRunFiles& files, long long block, const kinetic::TracerBlockSums& sums) {
  if (!files.out.empty())
    save_checkpoint_block(checkpoint_folder(files.out), block, sums.sums, {}, tracer_block_text(sums.tracer));
}

TracerResult run_tracer(const kinetic::TracerConfig& config, const TracerProgress& progress,
                        const TracerRunFiles& files) {
  const auto started = std::chrono::steady_clock::now();
  config.validate();  // before the states are read: a missing --start-states is named as such
  const kinetic::TracerRun run(with_input_files(config), progress.background);
  TracerPlan plan = plan_tracer(run, files);
  const std::vector<long long>& owned = plan.pending;
  std::vector<kinetic::TracerBlockSums> outputs(owned.size());
  std::mutex mutex;
  long long done = 0;
  run_slots_in_parallel(owned.size(), config.threads, [&](std::size_t slot, const std::atomic<bool>& stop) {
    outputs[slot] = run.run_block(owned[slot], stop);
    if (stop) return;
    save_tracer_block(files, owned[slot], outputs[slot]);
    std::lock_guard<std::mutex> lock(mutex);
    ++done;
    if (progress.blocks) progress.blocks(done, static_cast<long long>(owned.size()));
  });
  TracerResult& result = plan.result;
  result.wall_seconds = result.ensemble.wall_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  for (std::size_t slot = 0; slot < owned.size(); ++slot) {
    result.ensemble.blocks[owned[slot]] = std::move(outputs[slot].sums);
    result.blocks[owned[slot]] = std::move(outputs[slot].tracer);
  }
  return std::move(plan.result);
}

void finish_tracer_run(const TracerResult& result, const std::filesystem::path& out) {
  write_tracer_outputs(result, out);
  remove_checkpoint(out);
}

}  // namespace coldblast::run
