#include "kinetic/tracer.hpp"

#include <toml++/toml.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <chrono>
#include <cmath>
#include <map>
#include <memory>
#include <mutex>
#include <sstream>
#include <stdexcept>

#include "common/input.hpp"
#include "common/validate.hpp"
#include "hydro/tvns.hpp"
#include "kinetic/batch.hpp"
#include "kinetic/hydro_backgrounds.hpp"
#include "kinetic/kinetic_theory.hpp"
#include "kinetic/prefactors.hpp"
#include "kinetic/trajectory.hpp"
#include "md/ensemble.hpp"
#include "md/observers.hpp"
#include "theory/prefactors.hpp"

namespace coldblast::kinetic {

using common::Bound;
using common::format_number;

namespace {

/// Largest packing fraction of the equilibrium background (the fluid range of the EOS used for chi).
double max_equilibrium_phi(int d) {
  return d == 2 ? 0.7 : 0.5;
}

double scene_phi(const md::BlastConfig& c) {
  return theory::packing_fraction(c.d, c.n, c.a);
}

/// The scene as the md writers need it, without md::resolve_scene's particle-region sizing (the
/// tracer has no particles, and R/λ = 1e6 would exceed its MD limits): A_d, φ, λ, radii, times.
md::ResolvedScene tracer_scene(md::BlastConfig c, long long trajectories, double A_d, const std::string& A_d_source) {
  c.observables = {"R_imp", "V_imp", "C_imp", "u_imp", "p_imp"};
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

/// Initial velocity: the MD's kick (k Gaussian vectors shifted to zero mean and scaled to total
/// kinetic energy E; this impurity is the first of them, md/initial_state.cpp) or the local
/// Maxwellian at the origin.
template <int D>
md::Vec<D> initial_velocity(const TracerConfig& c, const Background& background, double t0, Random& rng) {
  const double M = c.scene.impurities.mass;
  md::Vec<D> v;
  if (c.start == "kick") {
    const int k = c.scene.impurities.count;
    std::vector<md::Vec<D>> kicks(k);
    md::Vec<D> mean = md::Vec<D>::Zero();
    for (auto& x : kicks) {
      for (int i = 0; i < D; ++i) x[i] = rng.normal();
      mean += x;
    }
    if (k == 1) mean.setZero();  // one impurity: energy E in a random direction (md/initial_state.cpp)
    mean /= static_cast<double>(k);
    double energy = 0.0;
    for (auto& x : kicks) {
      x -= mean;
      energy += 0.5 * M * x.squaredNorm();
    }
    return std::sqrt(c.scene.E / energy) * kicks[0];
  }
  const HostState h = background.at(0.0, t0, background.bound(t0));
  for (int i = 0; i < D; ++i) v[i] = std::sqrt(h.T / M) * rng.normal();
  return v;  // u = 0 at the centre of a radial flow
}

struct RunContext {
  const TracerConfig& config;
  const md::ResolvedScene& scene;
  const md::ObservableLayout& layout;
  const Background& background;
  ImpurityModel impurity;
  double start_time;
  const std::vector<md::ImpurityState>* states;  ///< start = "states": trajectory i starts from states[i]
  const GridBackground* batch;                   ///< the 8-lane kernel's background, or nullptr (scalar loop)
};

/// start = "states": the file's states, checked against the scene (its physics keys, a time in
/// (0, t_max) and at least `trajectories` states); `start_time` is set to the file's time.
std::vector<md::ImpurityState> load_start_states(const TracerConfig& c, long long trajectories, double& start_time) {
  md::ImpurityStatesFile file = md::read_impurity_states(c.start_states, c.scene.d, "--start-states");
  const std::string named = "--start-states = " + c.start_states;
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
  return std::move(file.states);
}

/// One trajectory in flight: its stream, state, start position and counters.
template <int D>
struct Trajectory {
  Random rng;
  TracerState<D> s;
  md::Vec<D> r0 = md::Vec<D>::Zero();  ///< where the impurity started (r is from the blast centre)
  std::uint64_t collisions_before = 0;
  long long index = 0;
};

template <int D>
Trajectory<D> start_trajectory(const RunContext& ctx, long long index) {
  Trajectory<D> x{Random(ctx.scene.config.seed, static_cast<std::uint64_t>(index)), {}, md::Vec<D>::Zero(), 0, index};
  TracerState<D>& s = x.s;
  s.t = ctx.start_time;
  if (ctx.states != nullptr) {
    const md::ImpurityState& state = (*ctx.states)[static_cast<std::size_t>(index)];
    for (int k = 0; k < D; ++k) {
      s.r[k] = state.r[k];
      s.v[k] = state.v[k];
      x.r0[k] = state.r0[k];
    }
    s.collisions = state.collisions;  // C_imp counts from the MD's start, as the MD's does
  } else {
    s.v = initial_velocity<D>(ctx.config, ctx.background, s.t, x.rng);
  }
  x.collisions_before = s.collisions;
  return x;
}

/// The observables of recording time k (x advanced to it) into `record`, and |Δr|², |Δr|⁴, |v|²,
/// |v|⁴ into moments[4k..4k+3] (the trajectory's terms of TracerBlock::moments).
template <int D>
void record_time(const RunContext& ctx, std::size_t k, const Trajectory<D>& x, std::vector<double>& record,
                 std::vector<double>& moments) {
  const md::BlastConfig& c = ctx.scene.config;
  const TracerState<D>& s = x.s;
  const double t = ctx.scene.times[k];
  const double r2 = (s.r - x.r0).squaredNorm(), v2 = s.v.squaredNorm();
  const int kk = static_cast<int>(k);
  record[ctx.layout.scalar("R_imp", kk)] = 0.5 * r2;
  record[ctx.layout.scalar("V_imp", kk)] = 0.5 * v2;
  record[ctx.layout.scalar("C_imp", kk)] = static_cast<double>(s.collisions);
  const double time = std::max(t, s.t);
  record[ctx.layout.scalar("u_imp", kk)] = std::abs(ctx.background.at(s.r.norm(), time, ctx.background.bound(time)).u);
  // Eq. (39) [eq:pr]: |Δr| in bins of width R(t)/bins, R(t) from Eq. (1), as md/observers.cpp.
  const theory::BlastParameters p{D, c.n, c.a, c.E, ctx.scene.A_d};
  const int bins = c.p_imp_bins;
  const double width = theory::shock_radius(p, t) / bins;
  const int b = static_cast<int>(std::sqrt(r2) / width);
  if (b < bins) record[ctx.layout.p_imp(kk, b)] = 1.0;
  double* m = &moments[4 * k];
  m[0] = r2;
  m[1] = r2 * r2;
  m[2] = v2;
  m[3] = v2 * v2;
}

/// The end state at t_max (x advanced to it) and the moments' terms into the block; checks the record.
template <int D>
void finish_trajectory(const Trajectory<D>& x, const std::vector<double>& record, const std::vector<double>& moments,
                       TracerBlock& block) {
  for (std::size_t i = 0; i < moments.size(); ++i) block.moments[i] += moments[i];
  const double v2 = x.s.v.squaredNorm();
  block.v2_final += v2;
  block.v2_final_squares += v2 * v2;
  const auto made = static_cast<double>(x.s.collisions - x.collisions_before);  // in [start, t_max]
  block.collisions_squares += made * made;
  ++block.count;
  for (const double value : record)
    if (!std::isfinite(value))
      throw std::runtime_error("non-finite observable in trajectory " + std::to_string(x.index));
}

void add_record(const std::vector<double>& record, md::BlockSums& sums) {
  for (std::size_t e = 0; e < record.size(); ++e) {
    sums.sum[e] += record[e];
    sums.sum_squares[e] += record[e] * record[e];
  }
  ++sums.count;
}

/// Trajectories [first, first + count) one after the other (kinetic::advance).
template <int D>
void run_scalar(const RunContext& ctx, long long first, long long count, const std::atomic<bool>& stop,
                TracerBlockSums& out) {
  std::vector<double> record(ctx.layout.size(), 0.0), moments(out.tracer.moments.size(), 0.0);
  for (long long i = first; i < first + count && !stop; ++i) {
    Trajectory<D> x = start_trajectory<D>(ctx, i);
    TracerCounters counters;
    std::fill(record.begin(), record.end(), 0.0);
    for (std::size_t k = 0; k < ctx.scene.times.size(); ++k) {
      if (ctx.scene.times[k] > x.s.t)
        advance<D>(ctx.background, ctx.impurity, x.s, ctx.scene.times[k], x.rng, counters);
      record_time<D>(ctx, k, x, record, moments);
    }
    const double t_max = ctx.scene.config.t_max;
    if (t_max > x.s.t) advance<D>(ctx.background, ctx.impurity, x.s, t_max, x.rng, counters);
    out.tracer.collisions += counters.collisions;
    out.tracer.candidates += counters.candidates;
    finish_trajectory<D>(x, record, moments, out.tracer);
    add_record(record, out.sums);
  }
}

/// The same trajectories in the 8-lane kernel (kinetic/batch.hpp): a lane that reaches a
/// recording time is recorded and sent on at once, and a finished lane takes the next trajectory,
/// so no lane waits for another. Finished trajectories enter the block's sums in index order, as
/// in run_scalar, so the sums do not depend on the lanes' timing; the sample paths are the kernel's.
template <int D>
void run_batched(const RunContext& ctx, long long first, long long count, const std::atomic<bool>& stop,
                 TracerBlockSums& out) {
  struct Flight {
    Trajectory<D> x;
    std::size_t next = 0;  ///< the next recording time; times.size(): bound for t_max
    std::vector<double> record, moments;
  };
  const std::vector<double>& times = ctx.scene.times;
  const double t_max = ctx.scene.config.t_max;
  const auto target = [&](const Flight& f) { return f.next < times.size() ? times[f.next] : t_max; };
  Batch<D> batch(*ctx.batch, ctx.impurity);
  TracerCounters counters;
  std::vector<std::unique_ptr<Flight>> lanes(batch_lanes);
  std::map<long long, std::unique_ptr<Flight>> finished;  // waiting for an earlier trajectory
  long long next_load = first, next_sum = first;
  const auto load = [&](int l) {
    if (next_load >= first + count || stop) return;
    auto f = std::make_unique<Flight>(Flight{start_trajectory<D>(ctx, next_load++), 0,
                                             std::vector<double>(ctx.layout.size(), 0.0),
                                             std::vector<double>(out.tracer.moments.size(), 0.0)});
    batch.load(l, f->x.s, f->x.rng, target(*f), counters);
    lanes[static_cast<std::size_t>(l)] = std::move(f);
  };
  for (int l = 0; l < batch_lanes; ++l) load(l);
  for (unsigned arrived; (arrived = batch.run(counters)) != 0;) {
    for (; arrived != 0; arrived &= arrived - 1) {
      const int l = __builtin_ctz(arrived);
      Flight& f = *lanes[static_cast<std::size_t>(l)];
      f.x.s = batch.state(l);
      for (; f.next < times.size() && times[f.next] <= f.x.s.t; ++f.next)
        record_time<D>(ctx, f.next, f.x, f.record, f.moments);
      if (f.next < times.size() || t_max > f.x.s.t) {
        batch.retarget(l, target(f), counters);
        continue;
      }
      batch.unload(l);
      finished[f.x.index] = std::move(lanes[static_cast<std::size_t>(l)]);
      load(l);
    }
    for (auto it = finished.find(next_sum); it != finished.end(); it = finished.find(++next_sum)) {
      finish_trajectory<D>(it->second->x, it->second->record, it->second->moments, out.tracer);
      add_record(it->second->record, out.sums);
      finished.erase(it);
    }
  }
  out.tracer.collisions += counters.collisions;
  out.tracer.candidates += counters.candidates;
}

TracerBlockSums run_block(const RunContext& ctx, long long block, const std::atomic<bool>& stop) {
  const md::BlastConfig& c = ctx.scene.config;
  TracerBlockSums out;
  out.sums.sum.assign(ctx.layout.size(), 0.0);
  out.sums.sum_squares.assign(ctx.layout.size(), 0.0);
  out.tracer.moments.assign(4 * ctx.scene.times.size(), 0.0);
  const long long first = block * c.block_size, count = md::block_realizations(c, block);
  if (ctx.batch != nullptr)
    c.d == 2 ? run_batched<2>(ctx, first, count, stop, out) : run_batched<3>(ctx, first, count, stop, out);
  else
    c.d == 2 ? run_scalar<2>(ctx, first, count, stop, out) : run_scalar<3>(ctx, first, count, stop, out);
  out.sums.collisions = out.tracer.collisions;
  return out;
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

void TracerConfig::validate() const {
  scene.validate();
  if (background != "ns" && background != "tvns" && background != "equilibrium")
    throw std::invalid_argument("--background = " + background + " is not one of: ns, tvns, equilibrium");
  if (transport != "dilute" && transport != "enskog")
    throw std::invalid_argument("--transport = " + transport + " is not one of: dilute, enskog");
  if (transport == "enskog" && background == "tvns")
    throw std::invalid_argument(
        "--transport = enskog is not available with --background tvns (the ideal-gas "
        "Euler solution); allowed: dilute");
  if (start != "kick" && start != "thermal" && start != "states")
    throw std::invalid_argument("--start = " + start + " is not one of: kick, thermal, states");
  if ((start == "states") != !start_states.empty())
    throw std::invalid_argument(start == "states" ? "--start = states needs --start-states FILE (md states' output)"
                                                  : "--start-states is only for --start states");
  if (start == "states" && (background == "equilibrium" || start_time != 0.0))
    throw std::invalid_argument(background == "equilibrium"
                                    ? "--start = states is for the blast backgrounds ns and tvns, not equilibrium"
                                    : "--start-time is the states file's time with --start = states; leave it out");
  common::require_integer_in_range("--trajectories", trajectories, 0, 1000000000000LL, "(0 = scene default)");
  common::require_integer_in_range("--threads", threads, 1, 1024);
  common::require_integer_in_range("shard_count", shard_count, 1, 1000000);
  common::require_integer_in_range("shard_index", shard_index, 0, shard_count - 1);
  common::require_in_range("--T", T, 0.0, std::numeric_limits<double>::infinity());
  if (phi)
    common::require_in_range("--phi", *phi, 0.0, max_equilibrium_phi(scene.d), Bound::open, Bound::open,
                             "for d = " + std::to_string(scene.d));
  if (phi && background != "equilibrium")
    throw std::invalid_argument("--phi is only for --background equilibrium (the blast uses the scene's n)");
  common::require_in_range("--start-time", start_time, 0.0, scene.t_max, Bound::closed, Bound::open);
  common::require_integer_in_range("--frames-per-decade", frames_per_decade, 4, 400);
  common::require_integer_in_range("--cells", cells, 64, 4096);
  if (kernel != "auto" && kernel != "avx512" && kernel != "scalar")
    throw std::invalid_argument("--kernel = " + kernel + " is not one of: auto, avx512, scalar");
  if (kernel == "avx512" && !batch_available())
    throw std::invalid_argument(
        "--kernel = avx512: this CPU (or build) has no AVX-512 F and DQ; allowed here: auto, scalar");
  if (kernel == "avx512" && background == "equilibrium")
    throw std::invalid_argument(
        "--kernel = avx512 is for the grid backgrounds ns and tvns; allowed with equilibrium: auto, scalar");
}

double TracerConfig::resolved_start_time() const {
  if (start_time > 0.0 || background == "equilibrium") return start_time;
  return scene.t_min;
}

md::BlastConfig parse_tracer_scene(const std::string& toml_text, const std::vector<std::string>& overrides,
                                   const std::string& source) {
  std::vector<std::string> all{"snapshot_times=[]"};
  all.insert(all.end(), overrides.begin(), overrides.end());
  return md::parse_scene(toml_text, all, source);
}

std::unique_ptr<Background> make_background(const TracerConfig& config, std::string* description,
                                            const BackgroundProgress& progress) {
  const md::BlastConfig& c = config.scene;
  ContactModel contact{c.d, c.a, c.impurities.radius > 0.0 ? c.impurities.radius : c.a, config.transport == "enskog"};
  if (config.background == "equilibrium") {
    const double phi = config.phi ? *config.phi : scene_phi(c);
    const double n = theory::number_density(c.d, phi, c.a);
    if (description)
      *description = "equilibrium: n = " + format_number(n) + " (phi = " + common::format_significant(phi, 6) +
                     "), T = " + format_number(config.T) + ", u = 0, chi " + (contact.enskog ? "Enskog" : "= 1");
    return std::make_unique<EquilibriumBackground>(c.d, n, config.T, contact);
  }
  if (config.background == "tvns") return make_tvns_background(c, contact, description);
  return make_navier_stokes_background(c, contact, config.frames_per_decade, config.cells, description, progress);
}

std::uint64_t TracerResult::collisions() const {
  std::uint64_t total = 0;
  for (const auto& [b, s] : blocks) total += s.collisions;
  return total;
}
std::uint64_t TracerResult::candidates() const {
  std::uint64_t total = 0;
  for (const auto& [b, s] : blocks) total += s.candidates;
  return total;
}
long long TracerResult::trajectories() const {
  long long total = 0;
  for (const auto& [b, s] : blocks) total += s.count;
  return total;
}
double TracerResult::collision_rate() const {
  const double N = static_cast<double>(trajectories());
  return static_cast<double>(collisions()) / N / (config.scene.t_max - start_time);
}
double TracerResult::collision_rate_error() const {
  const double N = static_cast<double>(trajectories());
  double squares = 0.0;
  for (const auto& [b, s] : blocks) squares += s.collisions_squares;
  const double mean = static_cast<double>(collisions()) / N;
  const double variance = std::max(0.0, (squares - N * mean * mean) / (N - 1));
  return std::sqrt(variance / N) / (config.scene.t_max - start_time);
}
double TracerResult::temperature_final() const {
  double sum = 0.0;
  for (const auto& [b, s] : blocks) sum += s.v2_final;
  return config.scene.impurities.mass * sum / trajectories() / config.scene.d;
}
double TracerResult::temperature_final_error() const {
  const double N = static_cast<double>(trajectories());
  double sum = 0.0, squares = 0.0;
  for (const auto& [b, s] : blocks) {
    sum += s.v2_final;
    squares += s.v2_final_squares;
  }
  const double mean = sum / N;
  const double variance = std::max(0.0, (squares - N * mean * mean) / (N - 1));
  return config.scene.impurities.mass * std::sqrt(variance / N) / config.scene.d;
}
double TracerResult::rejection_rate() const {
  const double candidates_total = static_cast<double>(candidates());
  return candidates_total > 0 ? 1.0 - static_cast<double>(collisions()) / candidates_total : 0.0;
}

struct TracerRun::Context {
  TracerResult result;  ///< config, scene, background description, ambient n and chi, start time
  std::unique_ptr<Background> background;
  std::unique_ptr<md::ObservableLayout> layout;
  std::unique_ptr<RunContext> run;
  std::vector<md::ImpurityState> states;  ///< start = "states"
  std::chrono::steady_clock::time_point started;
};

TracerRun::TracerRun(const TracerConfig& config, const BackgroundProgress& progress)
    : context_(std::make_unique<Context>()) {
  config.validate();
  Context& x = *context_;
  x.started = std::chrono::steady_clock::now();
  TracerResult& result = x.result;
  result.config = config;
  md::BlastConfig scene_config = config.scene;
  double states_time = 0.0;
  if (config.start == "states") x.states = load_start_states(config, config.trajectories, states_time);
  const long long trajectories = config.trajectories > 0 ? config.trajectories
                                 : x.states.empty()      ? scene_config.realizations * scene_config.impurities.count
                                                         : static_cast<long long>(x.states.size());
  std::string A_d_source;
  const double A_d = resolved_A_d(scene_config, A_d_source);
  md::BlastResult& ensemble = result.ensemble;
  ensemble.scene = tracer_scene(scene_config, trajectories, A_d, A_d_source);
  ensemble.threads = config.threads;
  ensemble.shard_index = config.shard_index;
  ensemble.shard_count = config.shard_count;
  const md::ResolvedScene& scene = ensemble.scene;
  result.config.scene = scene.config;
  result.start_time = config.start == "states" ? states_time : config.resolved_start_time();

  x.background = make_background(config, &result.background_description, progress);
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
  const GridBackground* batch =
      config.kernel != "scalar" && batch_available() ? batch_background(*x.background) : nullptr;
  result.kernel = batch != nullptr ? "avx512" : "scalar";
  x.run = std::make_unique<RunContext>(RunContext{result.config, scene, *x.layout, *x.background, impurity,
                                                  result.start_time, config.start == "states" ? &x.states : nullptr,
                                                  batch});
  const long long block_count = (trajectories + scene.config.block_size - 1) / scene.config.block_size;
  for (long long b = config.shard_index; b < block_count; b += config.shard_count) blocks_.push_back(b);
}

TracerRun::~TracerRun() = default;

TracerBlockSums TracerRun::run_block(long long block, const std::atomic<bool>& stop) const {
  return kinetic::run_block(*context_->run, block, stop);
}

void TracerRun::add(long long block, TracerBlockSums&& sums) {
  context_->result.ensemble.blocks[block] = std::move(sums.sums);
  context_->result.blocks[block] = std::move(sums.tracer);
}

TracerResult TracerRun::result(int ranks) const {
  TracerResult result = context_->result;
  result.ensemble.ranks = ranks;
  result.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - context_->started).count();
  result.ensemble.wall_seconds = result.wall_seconds;
  return result;
}

TracerResult run_tracer(const TracerConfig& config, const TracerProgress& progress) {
  TracerRun run(config, progress.background);
  const std::vector<long long>& owned = run.blocks();
  std::vector<TracerBlockSums> outputs(owned.size());
  std::mutex mutex;
  long long done = 0;
  md::run_slots_in_parallel(owned.size(), config.threads, [&](std::size_t slot, const std::atomic<bool>& stop) {
    outputs[slot] = run.run_block(owned[slot], stop);
    std::lock_guard<std::mutex> lock(mutex);
    ++done;
    if (progress.blocks) progress.blocks(done, static_cast<long long>(owned.size()));
  });
  for (std::size_t slot = 0; slot < owned.size(); ++slot) run.add(owned[slot], std::move(outputs[slot]));
  return run.result();
}

std::vector<MomentRow> moment_rows(const TracerResult& result) {
  const auto& times = result.ensemble.scene.times;
  std::vector<MomentRow> rows;
  // Totals, then leave-one-block-out values for the jackknife.
  const std::size_t K = times.size();
  std::vector<double> total(4 * K, 0.0);
  double N = 0.0;
  for (const auto& [b, s] : result.blocks) {
    for (std::size_t e = 0; e < total.size(); ++e) total[e] += s.moments[e];
    N += static_cast<double>(s.count);
  }
  const auto values = [&](const std::vector<double>& sums, double count, std::size_t k) {
    const double r2 = sums[4 * k] / count, r4 = sums[4 * k + 1] / count;
    const double v2 = sums[4 * k + 2] / count, v4 = sums[4 * k + 3] / count;
    return std::array<double, 4>{r2, r2 > 0 ? r4 / (r2 * r2) : 0.0, v2, v2 > 0 ? v4 / (v2 * v2) : 0.0};
  };
  const double B = static_cast<double>(result.blocks.size());
  for (std::size_t k = 0; k < K; ++k) {
    const auto full = values(total, N, k);
    std::array<double, 4> mean{}, square{};
    for (const auto& [b, s] : result.blocks) {
      std::vector<double> rest(total);
      for (std::size_t e = 4 * k; e < 4 * k + 4; ++e) rest[e] -= s.moments[e];
      const auto leave = values(rest, N - static_cast<double>(s.count), k);
      for (int q = 0; q < 4; ++q) {
        mean[q] += leave[q] / B;
        square[q] += leave[q] * leave[q] / B;
      }
    }
    std::array<double, 4> error{};
    for (int q = 0; q < 4; ++q)
      error[q] = B > 1 ? std::sqrt(std::max(0.0, (B - 1) * (square[q] - mean[q] * mean[q]))) : std::nan("");
    rows.push_back({times[k], full[0], error[0], full[1], error[1], full[2], error[2], full[3], error[3]});
  }
  return rows;
}

common::Json tracer_summary(const TracerResult& result) {
  common::Json j = md::blast_summary(result.ensemble);
  const TracerConfig& c = result.config;
  j["engine"] = "tracer (Lorentz-Boltzmann Monte Carlo, paper Eq. (36))";
  j["background"] = c.background;
  j["background_description"] = result.background_description;
  j["background_frames"] = result.background_frames;
  j["transport"] = c.transport;
  j["kernel"] = result.kernel;
  j["start"] = c.start;
  if (c.start == "states") j["start_states"] = c.start_states;
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
    j["collision_rate_exact"] = equilibrium_collision_rate(
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
void write_tracer_blocks(const TracerResult& result, const std::filesystem::path& directory) {
  const std::string header =
      md::run_file_header(result.ensemble.scene, {{"background", result.background_description}});
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
  common::write_file_atomic(directory / "tracer_blocks.csv", blocks.str());
  common::write_file_atomic(directory / "moment_sums.csv", moments.str());
}

/// Reads a tracer shard's tracer_blocks.csv and moment_sums.csv (bad input names the file and line).
std::map<long long, TracerBlock> read_tracer_blocks(const std::filesystem::path& dir, std::size_t times) {
  std::map<long long, TracerBlock> blocks;
  const std::filesystem::path totals_path = dir / "tracer_blocks.csv", moments_path = dir / "moment_sums.csv";
  const common::CsvTable totals = common::parse_csv(common::read_text(totals_path, "md merge DIR file"),
                                                    totals_path.string(), tracer_blocks_header);
  for (const common::CsvRow& row : totals.rows) {
    const std::string where = totals.where(row);
    TracerBlock s;
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
  if (s.contains("kernel"))
    take("kernel", false);
  else
    keys["kernel"] = "scalar";  // runs before the 8-lane kernel
  return keys;
}

}  // namespace

void write_tracer_outputs(const TracerResult& result, const std::filesystem::path& directory) {
  md::write_blast_outputs(result.ensemble, directory);
  std::ostringstream out;
  out << common::provenance_header({{"scene", result.ensemble.scene.config.name},
                                    {"seed", std::to_string(result.ensemble.scene.config.seed)},
                                    {"background", result.background_description}},
                                   "m = 1 (host mass), k_B = 1, lengths and times in the scene's units")
      << "# r: impurity displacement from its start; errors: block jackknife\n"
      << "t,r2,r2_stderr,r4_over_r2_squared,r4_over_r2_squared_stderr,v2,v2_stderr,v4_over_v2_squared,"
         "v4_over_v2_squared_stderr\n";
  for (const MomentRow& m : moment_rows(result))
    out << format_number(m.t) << ',' << format_number(m.r2) << ',' << format_number(m.r2_error) << ','
        << format_number(m.r_ratio) << ',' << format_number(m.r_ratio_error) << ',' << format_number(m.v2) << ','
        << format_number(m.v2_error) << ',' << format_number(m.v_ratio) << ',' << format_number(m.v_ratio_error)
        << '\n';
  common::write_file_atomic(directory / "moments.csv", out.str());
  common::write_file_atomic(directory / "prefactors.csv", prefactors_csv(result));
  write_tracer_blocks(result, directory);
  common::write_file_atomic(directory / "summary.json", tracer_summary(result).dump(2) + "\n");
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
  merged.ensemble = md::merge_blast_outputs(directories);  // checks scenes and duplicate blocks
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
  TracerConfig& c = merged.config;
  c.scene = scene.config;
  c.background = first.at("background").get<std::string>();
  c.transport = first.at("transport").get<std::string>();
  c.start = first.at("start").get<std::string>();
  if (first.contains("start_states")) c.start_states = first.at("start_states").get<std::string>();
  if (first.contains("T")) c.T = first.at("T").get<double>();
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

}  // namespace coldblast::kinetic
