#include "compare/md_run.hpp"

#include <limits>
#include <stdexcept>

#include "common/input.hpp"
#include "common/validate.hpp"
#include "hydro/tvns.hpp"

namespace coldblast::compare {

MdRunPlan plan_md_run(const MdRunRequest& request) {
  std::vector<std::string> overrides = request.overrides;
  if (request.realizations) {
    common::require_integer_in_range("--realizations", *request.realizations, 1, 1000000000);
    overrides.push_back("realizations=" + std::to_string(*request.realizations));
  }
  md::add_seed_override(overrides, request.seed);
  common::require_integer_in_range("--threads", request.threads, 1, 1024);
  std::string text, source;
  if (!request.scene_file.empty()) {
    text = common::read_text(request.scene_file, "SCENE", common::text_size_limit);
    source = request.scene_file;
  } else if (!request.scene_text.empty()) {
    text = request.scene_text;
    source = "scene";
  } else {
    text = md::default_scene_toml();
    source = "default scene";
  }
  MdRunPlan plan;
  plan.config = md::parse_scene(text, overrides, source);
  plan.options.threads = request.threads;
  plan.options.amplitude = hydro::md_amplitude;
  return plan;
}

}  // namespace coldblast::compare
