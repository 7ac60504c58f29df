#include "run/md_run.hpp"

#include "common/validate.hpp"
#include "run/scene_file.hpp"

namespace coldblast::run {

MdRunPlan plan_md_run(const MdRunRequest& request) {
  SceneRequest scene;
  scene.file = request.scene_file;
  scene.text = request.scene_text;
  scene.overrides = request.overrides;
  scene.realizations = request.realizations;
  scene.seed = request.seed;
  MdRunPlan plan;
  plan.config = load_scene(scene);
  common::require_integer_in_range("--threads", request.threads, 1, 1024);
  plan.options.threads = request.threads;
  return plan;
}

}  // namespace coldblast::run
