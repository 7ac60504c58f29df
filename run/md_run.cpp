#include "run/md_run.hpp"

#include <stdexcept>

#include "common/validate.hpp"
#include "run/checkpoint.hpp"
#include "run/scene_file.hpp"

namespace coldblast::run {

namespace {

SceneRequest scene_request(const MdRunRequest& request) {
  SceneRequest scene;
  scene.file = request.scene_file;
  scene.text = request.scene_text;
  scene.overrides = request.overrides;
  scene.realizations = request.realizations;
  scene.seed = request.seed;
  return scene;
}

std::string resolved_toml(const md::BlastConfig& config) {
  return scene_toml(resolve_blast_scene(config).config);
}

/// --resume OUT: the checkpoint's scene and shard; an option given again must agree with them.
void restore_from_checkpoint(const MdRunRequest& request, MdRunPlan& plan) {
  if (request.out.empty()) throw std::invalid_argument("--resume needs the output folder of the run to continue");
  const std::filesystem::path checkpoint = checkpoint_folder(request.out);
  const std::string saved = checkpoint_scene_text(checkpoint);  // the resolved scene; throws without one
  const CheckpointRun run = checkpoint_run(checkpoint);
  const std::string given = run.scene_toml.empty() ? saved : run.scene_toml;
  const std::string where = " contradicts the checkpoint in " + checkpoint.string();
  const std::string leave = "; leave it out to resume";
  plan.config = parse_scene(given, {}, (checkpoint / "run.json").string());
  for (const std::string& assignment : request.overrides) {
    const std::string difference = scene_difference(saved, resolved_toml(parse_scene(given, {assignment}, "--set")));
    if (!difference.empty()) throw std::invalid_argument("--set " + assignment + where + ": " + difference + leave);
  }
  const auto check = [&](const char* option, long long value, long long there) {
    if (value != there)
      throw std::invalid_argument(std::string(option) + " = " + std::to_string(value) + where + ", which has " +
                                  std::to_string(there) + leave);
  };
  if (request.realizations) check("--realizations", *request.realizations, plan.config.realizations);
  if (request.seed) check("--seed", *request.seed, static_cast<long long>(plan.config.seed));
  if (!request.scene_file.empty() || !request.scene_text.empty()) {
    const std::string difference = scene_difference(saved, resolved_toml(load_scene(scene_request(request))));
    if (!difference.empty())
      throw std::invalid_argument("SCENE" + (request.scene_file.empty() ? "" : " = " + request.scene_file) + where +
                                  ": " + difference + leave);
  }
  plan.options.shard_index = run.shard_index;
  plan.options.shard_count = run.shard_count;
  if (request.shard) {
    const auto [index, count] = parse_shard(*request.shard);
    if (index != run.shard_index || count != run.shard_count)
      throw std::invalid_argument("--shard = " + *request.shard + where + ", which runs shard " +
                                  std::to_string(run.shard_index) + "/" + std::to_string(run.shard_count) + leave);
  }
}

}  // namespace

MdRunPlan plan_md_run(const MdRunRequest& request) {
  common::require_integer_in_range("--threads", request.threads, 1, 1024);
  common::require_in_range("--save-every", request.save_every, 0.0, 1e9, common::Bound::open, common::Bound::closed);
  MdRunPlan plan;
  plan.options.in_flight_seconds = request.save_every;
  plan.options.threads = request.threads;
  plan.options.out = request.out;
  plan.options.resume = request.resume;
  plan.options.overwrite = request.overwrite;
  plan.options.resume_hint = request.resume_hint;
  if (request.resume && request.overwrite)
    throw std::invalid_argument("--overwrite starts a new run; --resume continues the one in the folder: give one");
  if (request.resume) {
    restore_from_checkpoint(request, plan);
    return plan;
  }
  plan.config = load_scene(scene_request(request));
  if (request.shard) std::tie(plan.options.shard_index, plan.options.shard_count) = parse_shard(*request.shard);
  return plan;
}

void finish_md_run(const BlastResult& result, const std::filesystem::path& out) {
  write_blast_outputs(result, out);
  remove_checkpoint(out);
}

}  // namespace coldblast::run
