#include "kinetic/tracer.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <stdexcept>

#include "common/validate.hpp"
#include "hydro/tvns.hpp"
#include "kinetic/batch.hpp"
#include "kinetic/tracer_drivers.hpp"
#include "md/observers.hpp"
#include "theory/observables.hpp"
#include "theory/prefactors.hpp"

namespace coldblast::kinetic {

using common::Bound;
using common::format_number;

namespace {

double scene_phi(const md::BlastConfig& c) {
  return theory::packing_fraction(c.d, c.n, c.a);
}

/// The scene as the md writers need it, without md::resolve_scene's particle-region sizing (the
/// tracer has no particles, and R/λ = 1e6 would exceed its MD limits): A_d, φ, λ, radii, times.
md::ResolvedScene tracer_scene(md::BlastConfig c, long long trajectories, double A_d, const std::string& A_d_source) {
  c.observables = theory::observable_names(theory::is_tracer_recorded);  // what tracer_drivers.cpp records
  c.realizations = trajectories;
  // At most ~256 blocks: enough for jackknife errors, few enough for a small blocks.csv.
  c.block_size = static_cast<int>(std::max<long long>(c.block_size, (trajectories + 255) / 256));
  c.A_d = A_d;
  c.validate();
  md::ResolvedScene s;
  s.config = c;
  s.A_d = A_d;
  s.A_d_source = A_d_source;
  s.phi = scene_phi(c);
  s.lambda = theory::mean_free_path(c.d, c.n, c.a);
  s.impurity_radius = c.impurities.radius > 0.0 ? c.impurities.radius : c.a;
  const theory::BlastParameters p{c.d, c.n, c.a, c.E, A_d};
  s.shock_radius_at_t_max = theory::shock_radius(p, c.t_max);  // Eq. (1) [R-shock]
  s.region_radius = s.shock_radius_at_t_max;
  s.guard_radius = s.region_radius;
  s.particle_count = 0;
  for (int k = 0;; ++k) {
    const double t = c.t_min * std::pow(2.0, k / 4.0);
    if (t > c.t_max * (1.0 + 1e-12)) break;
    s.times.push_back(t);
  }
  return s;
}

/// start = "states": the states read from start_states, checked against the scene (its physics
/// keys, a time in (0, t_max) and at least `trajectories` states); `start_time` is set to their time.
std::vector<md::ImpurityState> start_states(const TracerConfig& c, long long trajectories, double& start_time) {
  const std::string named = "--start-states = " + c.start_states;
  if (!c.states) throw std::invalid_argument(named + ": the states were not read (run::read_impurity_states)");
  const md::ImpurityStates& file = *c.states;
  for (const auto& entry : md::states_scene_keys(c.scene)) {
    // Not a structured binding: clang does not let a lambda capture one (C++17).
    const std::string &key = entry.first, &value = entry.second;
    if (key == "impurities.recollide") continue;  // the tracer has none either way
    const auto found =
        std::find_if(file.header.begin(), file.header.end(), [&](const auto& f) { return f.first == key; });
    if (found == file.header.end() ||
        std::strtod(found->second.c_str(), nullptr) != std::strtod(value.c_str(), nullptr))
      throw std::invalid_argument(named + " is of another scene: its " + key + " is " +
                                  (found == file.header.end() ? std::string("missing") : found->second) + ", " + value +
                                  " here");
  }
  common::require_in_range("the time of --start-states", file.t, 0.0, c.scene.t_max, Bound::open, Bound::open,
                           " (within the scene's (0, t_max))");
  if (trajectories > static_cast<long long>(file.states.size()))
    throw std::invalid_argument("--trajectories = " + std::to_string(trajectories) + " exceeds the " +
                                std::to_string(file.states.size()) + " states of " + named +
                                " (each trajectory starts from its own state, so that the errors include the states' "
                                "scatter; allowed: 1 to " +
                                std::to_string(file.states.size()) + ")");
  start_time = file.t;
  return file.states;
}

double resolved_A_d(const md::BlastConfig& c, std::string& source) {
  if (c.A_d > 0.0) {
    source = "scene";
    return c.A_d;
  }
  // The A_d policy of `md run` (hydro::md_amplitude), so p_imp's bins match the MD's.
  theory::AmplitudeChoice choice = hydro::md_amplitude(c.d, scene_phi(c));
  source = std::move(choice.source);
  return choice.A_d;
}

}  // namespace

struct TracerRun::Context {
  TracerRunInfo info;
  std::unique_ptr<Background> background;
  std::unique_ptr<md::ObservableLayout> layout;
  std::unique_ptr<TracerContext> run;
  std::vector<md::ImpurityState> states;  ///< start = "states"
};

TracerRun::TracerRun(const TracerConfig& config, const BackgroundProgress& progress)
    : context_(std::make_unique<Context>()) {
  config.validate();
  Context& x = *context_;
  TracerRunInfo& result = x.info;
  result.config = config;
  result.input_scene = config.scene;
  md::BlastConfig scene_config = config.scene;
  double states_time = 0.0;
  if (config.start == "states") x.states = start_states(config, config.trajectories, states_time);
  const long long trajectories = config.trajectories > 0 ? config.trajectories
                                 : x.states.empty()      ? scene_config.realizations * scene_config.impurities.count
                                                         : static_cast<long long>(x.states.size());
  std::string A_d_source;
  const double A_d = resolved_A_d(scene_config, A_d_source);
  result.scene = tracer_scene(scene_config, trajectories, A_d, A_d_source);
  const md::ResolvedScene& scene = result.scene;
  result.config.scene = scene.config;
  result.start_time = config.start == "states" ? states_time : config.resolved_start_time();

  x.background = make_background(config, &result.background_description, progress);
  // A background of measured data (md) has nothing to continue before its first recorded time.
  const std::string source = config.background == "md" ? "--md-run = " + config.md_run + "'s first recorded time"
                                                       : "the " + config.background + " background's first time";
  if (result.start_time < x.background->t_first())
    throw std::invalid_argument("the tracer starts at t = " + format_number(result.start_time) +
                                " (--start-time, or the scene's t_min), before " + source +
                                ", t = " + format_number(x.background->t_first()));
  if (scene.config.t_max > x.background->t_last())
    throw std::invalid_argument("t_max = " + format_number(scene.config.t_max) + " is after the " + config.background +
                                " background's last time, t = " + format_number(x.background->t_last()));
  if (const auto* grid = dynamic_cast<const GridBackground*>(x.background.get()))
    result.background_frames = grid->frame_count();
  const ImpurityModel impurity{scene.config.d, scene.config.impurities.mass, scene.config.a + scene.impurity_radius};
  {
    const double t = std::max(result.start_time, 1e-300);
    const HostState ambient = x.background->at(1e300, t, x.background->bound(t));
    result.n = ambient.n;
    result.chi = ambient.chi;
  }
  x.layout = std::make_unique<md::ObservableLayout>(scene);
  const GridBackground* grid = batch_background(*x.background);
  result.kernel = resolve_kernel(config.kernel, grid != nullptr);
  x.run = std::make_unique<TracerContext>(TracerContext{
      result.config, scene, *x.layout, *x.background, impurity, result.start_time,
      config.start == "states" ? &x.states : nullptr, result.kernel != "scalar" ? grid : nullptr, result.kernel});
  const long long block_count = (trajectories + scene.config.block_size - 1) / scene.config.block_size;
  for (long long b = config.shard_index; b < block_count; b += config.shard_count) blocks_.push_back(b);
}

TracerRun::~TracerRun() = default;

const TracerRunInfo& TracerRun::info() const {
  return context_->info;
}

TracerBlockSums TracerRun::run_block(long long block, const std::atomic<bool>& stop) const {
  return run_tracer_block(*context_->run, block, stop);
}

}  // namespace coldblast::kinetic
