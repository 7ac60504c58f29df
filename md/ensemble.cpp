#include "md/ensemble.hpp"

#include <toml++/toml.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <exception>
#include <limits>
#include <mutex>
#include <sstream>
#include <stdexcept>
#include <thread>

#include "common/input.hpp"
#include "common/interrupt.hpp"
#include "common/validate.hpp"
#include "md/checkpoint.hpp"
#include "md/engine.hpp"
#include "md/initial_state.hpp"
#include "md/observers.hpp"
#include "theory/prefactors.hpp"

namespace coldblast::md {

namespace {
using common::format_number;

struct RealizationOutput {
  std::vector<double> record;
  std::uint64_t collisions = 0;
  double energy_error = 0.0;
  std::vector<std::pair<std::string, std::string>> files;
};

const char* units_text = "m = 1 (host mass), k_B = 1, lengths and times in the scene's units (a = host radius)";

common::HeaderFields scene_fields(const ResolvedScene& s) {
  return {{"scene", s.config.name},
          {"seed", std::to_string(s.config.seed)},
          {"A_d", format_number(s.A_d) + " (" + s.A_d_source + ")"},
          {"particles", std::to_string(s.particle_count)},
          {"region_radius", format_number(s.region_radius)}};
}

/// Provenance header: the standard block, the scene's derived sizes, then the resolved scene as
/// commented TOML lines ("#   key = value").
std::string header_for(const ResolvedScene& s, common::HeaderFields extra = {}) {
  common::HeaderFields fields = scene_fields(s);
  fields.insert(fields.end(), extra.begin(), extra.end());
  std::string header = common::provenance_header(fields, units_text) + "# resolved scene (TOML):\n";
  std::istringstream toml_lines(s.config.to_toml());
  std::string line;
  while (std::getline(toml_lines, line))
    if (!line.empty()) header += "#   " + line + "\n";
  return header;
}

template <int D, class Queue>
std::string snapshot_csv(const ResolvedScene& scene, const Engine<D, Queue>& engine) {
  std::ostringstream out;
  out << header_for(scene, {{"realization", "0"}, {"t", format_number(engine.now())}})
      << (D == 2 ? "id,x,y,moving,impurity\n" : "id,x,y,z,moving,impurity\n");
  for (std::size_t i = 0; i < engine.size(); ++i) {
    const auto id = static_cast<std::int32_t>(i);
    const Vec<D> x = engine.position(id);
    out << i;
    for (int k = 0; k < D; ++k) out << ',' << format_number(x[k]);
    out << ',' << (engine.is_moving(id) ? 1 : 0) << ',' << (engine.species(id) == impurity_species ? 1 : 0) << '\n';
  }
  return out.str();
}

template <int D, class Queue>
RealizationOutput run_realization(const ResolvedScene& scene, const ObservableLayout& layout, long long index) {
  const BlastConfig& c = scene.config;
  const InitialState<D> state = blast_initial_state<D>(scene, index);

  const bool first = index == 0;
  EngineConfig<D> config;
  config.periodic = false;
  config.region_radius = scene.region_radius;
  config.guard_radius = scene.guard_radius;
  config.guard_advice = "raise box_margin (now " + format_number(c.box_margin) + ") or give a smaller A_d (now " +
                        format_number(scene.A_d) + ")";
  config.cell_width = c.cell_width;
  config.overlap_check = c.overlap_check;
  config.record_impurity_trajectories = first && scene.wants("trajectories");
  Engine<D, Queue> engine(config, state);
  BlastObserver<D, Queue> observer(scene, layout, engine);

  RealizationOutput out;
  out.record.assign(layout.size(), 0.0);
  std::vector<std::pair<double, int>> stops;  // (time, k) with k = -1 for a snapshot
  for (std::size_t k = 0; k < scene.times.size(); ++k) stops.push_back({scene.times[k], static_cast<int>(k)});
  if (first && scene.wants("snapshots"))
    for (const double t : scene.snapshot_times) stops.push_back({t, -1});
  std::stable_sort(stops.begin(), stops.end(), [](const auto& x, const auto& y) { return x.first < y.first; });
  std::vector<Vec<D>> start;
  for (const std::int32_t id : observer.impurities()) start.push_back(engine.position(id));
  for (const auto& [t, k] : stops) {
    engine.run_until(t);
    if (k >= 0)
      observer.measure(k, out.record);
    else
      out.files.push_back({"snapshot_" + format_number(t) + ".csv", snapshot_csv(scene, engine)});
  }
  engine.run_until(c.t_max);
  out.collisions = engine.collision_count();
  out.energy_error = std::abs(engine.kinetic_energy() - c.E) / c.E;
  if (config.record_impurity_trajectories) {
    std::vector<TrajectoryPoint<D>> points;
    for (std::size_t m = 0; m < start.size(); ++m) points.push_back({0.0, observer.impurities()[m], start[m]});
    for (const auto& p : engine.trajectories()) points.push_back(p);
    for (const std::int32_t id : observer.impurities()) points.push_back({engine.now(), id, engine.position(id)});
    std::stable_sort(points.begin(), points.end(), [](const auto& x, const auto& y) { return x.id < y.id; });
    std::ostringstream file;
    file << header_for(scene, {{"realization", "0"}}) << (D == 2 ? "id,t,x,y\n" : "id,t,x,y,z\n");
    for (const auto& p : points) {
      file << p.id << ',' << format_number(p.t);
      for (int k = 0; k < D; ++k) file << ',' << format_number(p.position[k]);
      file << '\n';
    }
    out.files.push_back({"trajectories.csv", file.str()});
  }
  for (const double v : out.record)
    if (!std::isfinite(v)) throw std::runtime_error("non-finite observable in realization " + std::to_string(index));
  return out;
}

RealizationOutput dispatch(const ResolvedScene& scene, const ObservableLayout& layout, long long index) {
  const bool heap = scene.config.queue == "heap";
  if (scene.config.d == 2)
    return heap ? run_realization<2, HeapEventQueue>(scene, layout, index)
                : run_realization<2, CalendarEventQueue>(scene, layout, index);
  return heap ? run_realization<3, HeapEventQueue>(scene, layout, index)
              : run_realization<3, CalendarEventQueue>(scene, layout, index);
}

std::string number_or_nan(double v) {
  return std::isfinite(v) ? format_number(v) : "nan";
}

const char* accumulator_header = "block,entry,channel,t,bin,sum,sum_squares";
const char* block_totals_header = "block,count,collisions,energy_error_max";
}  // namespace

template <int D>
InitialState<D> blast_initial_state(const ResolvedScene& scene, long long index) {
  const BlastConfig& c = scene.config;
  auto rng = realization_rng(c.seed, static_cast<std::uint64_t>(index));
  InitialState<D> state;
  state.host = {c.a, 1.0};
  state.impurity = {scene.impurity_radius, c.impurities.mass};
  state.position = random_sequential_addition<D>(rng, scene.particle_count, c.a, scene.region_radius);
  state.velocity.assign(scene.particle_count, Vec<D>::Zero());
  state.species.assign(scene.particle_count, host_species);
  kick_impurities<D>(rng, state, static_cast<std::size_t>(c.impurities.count), c.E, scene.region_radius);
  return state;
}
template InitialState<2> blast_initial_state<2>(const ResolvedScene&, long long);
template InitialState<3> blast_initial_state<3>(const ResolvedScene&, long long);

long long BlastResult::realizations() const {
  long long n = 0;
  for (const auto& [b, s] : blocks) n += s.count;
  return n;
}

std::uint64_t BlastResult::collisions() const {
  std::uint64_t n = 0;
  for (const auto& [b, s] : blocks) n += s.collisions;
  return n;
}

double BlastResult::energy_error_max() const {
  double e = 0.0;
  for (const auto& [b, s] : blocks) e = std::max(e, s.energy_error_max);
  return e;
}

std::pair<int, int> parse_shard(const std::string& text) {
  const auto slash = text.find('/');
  int i = -1, n = -1;
  try {
    std::size_t u1 = 0, u2 = 0;
    if (slash == std::string::npos) throw std::invalid_argument("");
    i = std::stoi(text.substr(0, slash), &u1);
    n = std::stoi(text.substr(slash + 1), &u2);
    if (u1 != slash || u2 != text.size() - slash - 1) throw std::invalid_argument("");
  } catch (const std::exception&) {
    throw std::invalid_argument("--shard = " + text + " is not of the form i/n (0 <= i < n)");
  }
  common::require_integer_in_range("--shard n", n, 1, 1000000);
  common::require_integer_in_range("--shard i", i, 0, n - 1, " (0 <= i < n; --shard = " + text + ")");
  return {i, n};
}

long long block_realizations(const BlastConfig& config, long long block) {
  const long long R = config.realizations, B = config.block_size;
  return std::max(0LL, std::min(R, (block + 1) * B) - block * B);
}

BlockSums run_block(const ResolvedScene& scene, long long block, NamedFiles* realization0_files,
                    const std::function<void()>& realization_done, const std::atomic<bool>* stop) {
  const ObservableLayout layout(scene);
  const long long B = scene.config.block_size;
  BlockSums s;
  s.sum.assign(layout.size(), 0.0);
  s.sum_squares.assign(layout.size(), 0.0);
  for (long long r = block * B; r < block * B + block_realizations(scene.config, block); ++r) {
    if (stop && *stop) break;
    common::throw_if_stop_requested();  // SIGINT/SIGTERM or a host's Ctrl-C: finished blocks stay saved
    RealizationOutput out = dispatch(scene, layout, r);
    for (std::size_t e = 0; e < out.record.size(); ++e) {
      s.sum[e] += out.record[e];
      s.sum_squares[e] += out.record[e] * out.record[e];
    }
    ++s.count;
    s.collisions += out.collisions;
    s.energy_error_max = std::max(s.energy_error_max, out.energy_error);
    if (r == 0 && realization0_files) *realization0_files = std::move(out.files);
    if (realization_done) realization_done();
  }
  return s;
}

EnsemblePlan plan_ensemble(const BlastConfig& config, const RunOptions& options) {
  EnsemblePlan plan;
  BlastResult& result = plan.result;
  result.scene = resolve_scene(config);
  result.threads = options.threads;
  result.shard_index = options.shard_index;
  result.shard_count = options.shard_count;
  const long long block_count = (config.realizations + config.block_size - 1) / config.block_size;
  if (!options.checkpoint.empty()) {
    if (options.resume) {
      Checkpoint saved = load_checkpoint(options.checkpoint, result.scene);
      for (auto& [b, s] : saved.blocks)
        if (b % options.shard_count == options.shard_index) {
          result.resumed_realizations += s.count;
          result.resumed_collisions += s.collisions;
          result.blocks[b] = std::move(s);
        }
      if (result.blocks.count(0)) result.realization0_files = std::move(saved.realization0_files);
    } else {
      start_checkpoint(options.checkpoint, result.scene);
    }
  }
  for (long long b = options.shard_index; b < block_count; b += options.shard_count)
    if (!result.blocks.count(b)) plan.pending.push_back(b);
  for (const long long b : plan.pending) plan.pending_realizations += block_realizations(config, b);
  return plan;
}

BlastResult run_blast(const BlastConfig& config, const RunOptions& options) {
  common::require_integer_in_range("threads", options.threads, 1, 1024);
  common::require_integer_in_range("shard_count", options.shard_count, 1, 1000000);
  common::require_integer_in_range("shard_index", options.shard_index, 0, options.shard_count - 1);
  const auto started = std::chrono::steady_clock::now();
  EnsemblePlan plan = plan_ensemble(config, options);
  BlastResult& result = plan.result;
  const ResolvedScene& scene = result.scene;
  const std::vector<long long>& owned = plan.pending;  // blocks still to run
  const long long total = plan.pending_realizations;

  std::vector<BlockSums> sums(owned.size());
  std::atomic<std::size_t> next{0};
  std::atomic<bool> failed{false};
  std::exception_ptr error;
  std::mutex mutex;
  long long done = 0;
  const auto realization_done = [&] {
    std::lock_guard<std::mutex> lock(mutex);
    ++done;
    if (options.progress) options.progress(done, total);
  };
  auto worker = [&] {
    while (!failed) {
      const std::size_t slot = next++;
      if (slot >= owned.size()) return;
      try {
        NamedFiles files;
        sums[slot] = run_block(scene, owned[slot], &files, realization_done, &failed);
        if (failed) return;
        if (!options.checkpoint.empty())
          save_checkpoint_block(options.checkpoint, owned[slot], sums[slot], owned[slot] == 0 ? &files : nullptr);
        if (owned[slot] == 0) {
          std::lock_guard<std::mutex> lock(mutex);
          result.realization0_files = std::move(files);
        }
      } catch (...) {
        std::lock_guard<std::mutex> lock(mutex);
        if (!error) error = std::current_exception();
        failed = true;
      }
    }
  };
  std::vector<std::thread> pool;
  for (int t = 1; t < options.threads; ++t) pool.emplace_back(worker);
  worker();
  for (auto& t : pool) t.join();
  if (error) std::rethrow_exception(error);
  for (std::size_t slot = 0; slot < owned.size(); ++slot) result.blocks[owned[slot]] = std::move(sums[slot]);
  result.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  return std::move(plan.result);
}

std::vector<ObservableEstimate> estimate_observables(const BlastResult& result) {
  const ResolvedScene& scene = result.scene;
  const ObservableLayout layout(scene);
  std::vector<double> S(layout.size(), 0.0), Q(layout.size(), 0.0);
  long long N = 0;
  for (const auto& [b, s] : result.blocks) {  // block order: identical for any threads/shards
    for (std::size_t e = 0; e < layout.size(); ++e) {
      S[e] += s.sum[e];
      Q[e] += s.sum_squares[e];
    }
    N += s.count;
  }
  std::vector<ObservableEstimate> rows;
  for (std::size_t k = 0; k < scene.times.size(); ++k)
    for (const std::string& name : scalar_observable_names()) {
      const int e = layout.scalar(name, static_cast<int>(k));
      if (e < 0) continue;
      const double mean = S[e] / N;
      const double variance = N > 1 ? std::max(0.0, (Q[e] - S[e] * mean) / (N - 1)) : std::nan("");
      double value = mean, error = std::sqrt(variance / N);
      if (name == "R_imp" || name == "V_imp" || name == "u_flow") {
        // Eq. (38) (and u_flow): sqrt of the ensemble mean; delta method. u_flow's mean of
        // |ū|² − s²/N can be <= 0 when the flow is below the noise: reported as 0.
        value = mean > 0.0 ? std::sqrt(mean) : 0.0;
        error = value > 0.0 ? error / (2.0 * value) : std::nan("");
      }
      rows.push_back({scene.times[k], name, value, error, N});
    }
  return rows;
}

common::Json blast_summary(const BlastResult& result) {
  const ResolvedScene& s = result.scene;
  const BlastConfig& c = s.config;
  common::Json scene_json;
  {
    std::ostringstream json;
    json << toml::json_formatter{toml::parse(std::string_view(c.to_toml()))};
    scene_json = common::Json::parse(json.str());
  }
  // Cost figures count the work done in wall_seconds: without the blocks a resumed run loaded.
  const double collisions = static_cast<double>(result.collisions() - result.resumed_collisions);
  const long long realizations_run = result.realizations() - result.resumed_realizations;
  common::Json j;
  j["scene"] = scene_json;
  j["seed"] = c.seed;
  j["realizations"] = result.realizations();
  j["collisions_total"] = result.collisions();
  j["wall_seconds"] = result.wall_seconds;
  j["collisions_per_second"] = result.wall_seconds > 0.0 ? collisions / result.wall_seconds : 0.0;
  j["energy_error_max"] = result.energy_error_max();
  j["d"] = c.d;
  j["n"] = c.n;
  j["a"] = c.a;
  j["E"] = c.E;
  j["phi"] = s.phi;
  j["lambda"] = s.lambda;
  j["A_d"] = s.A_d;
  j["A_d_source"] = s.A_d_source;
  j["particles"] = s.particle_count;
  j["region_radius"] = s.region_radius;
  j["R_theory_at_t_max"] = s.shock_radius_at_t_max;
  j["R_over_lambda_at_t_max"] = s.shock_radius_at_t_max / s.lambda;
  j["recording_times"] = s.times.size();
  j["block_size"] = c.block_size;
  j["blocks"] = result.blocks.size();
  j["seconds_per_realization"] =
      realizations_run > 0 ? result.wall_seconds * result.threads * result.ranks / realizations_run : 0.0;
  j["resumed_realizations"] = result.resumed_realizations;
  j["resumed_collisions"] = result.resumed_collisions;
  j["threads"] = result.threads;
  j["ranks"] = result.ranks;
  j["shard"] = std::to_string(result.shard_index) + "/" + std::to_string(result.shard_count);
  j["scene_toml"] = c.to_toml();
  return j;
}

void write_blast_outputs(const BlastResult& result, const std::filesystem::path& directory) {
  common::remove_stale_temporaries(directory);  // writes of a killed earlier attempt
  const ResolvedScene& scene = result.scene;
  const ObservableLayout layout(scene);
  const std::string header = header_for(scene);
  {
    std::ostringstream out;
    out << header << "t,observable,mean,stderr,count\n";
    for (const auto& row : estimate_observables(result))
      out << format_number(row.t) << ',' << row.observable << ',' << number_or_nan(row.mean) << ','
          << number_or_nan(row.stderr_) << ',' << row.count << '\n';
    common::write_file_atomic(directory / "observables.csv", out.str());
  }
  {
    std::ostringstream out, acc, totals;
    out << header << "block,t,observable,sum,count\n";
    acc << header << accumulator_header << '\n';
    totals << header << block_totals_header << '\n';
    for (const auto& [b, s] : result.blocks) {
      for (std::size_t k = 0; k < scene.times.size(); ++k)
        for (const std::string& name : scalar_observable_names()) {
          const int e = layout.scalar(name, static_cast<int>(k));
          if (e >= 0)
            out << b << ',' << format_number(scene.times[k]) << ',' << name << ',' << format_number(s.sum[e]) << ','
                << s.count << '\n';
        }
      for (std::size_t e = 0; e < layout.size(); ++e)
        acc << b << ',' << e << ',' << layout.channel(e) << ',' << format_number(scene.times[layout.time_index(e)])
            << ',' << layout.bin(e) << ',' << format_number(s.sum[e]) << ',' << format_number(s.sum_squares[e]) << '\n';
      totals << b << ',' << s.count << ',' << s.collisions << ',' << format_number(s.energy_error_max) << '\n';
    }
    common::write_file_atomic(directory / "blocks.csv", out.str());
    common::write_file_atomic(directory / "accumulators.csv", acc.str());
    common::write_file_atomic(directory / "block_totals.csv", totals.str());
  }
  std::vector<double> S(layout.size(), 0.0), Q(layout.size(), 0.0);
  double N = 0.0;
  for (const auto& [b, s] : result.blocks) {
    for (std::size_t e = 0; e < layout.size(); ++e) {
      S[e] += s.sum[e];
      Q[e] += s.sum_squares[e];
    }
    N += s.count;
  }
  const auto stderr_of = [&](int e) {
    if (N < 2) return std::nan("");
    const double mean = S[e] / N;
    return std::sqrt(std::max(0.0, (Q[e] - S[e] * mean) / (N - 1)) / N);
  };
  if (layout.has_profiles() && N > 0) {
    std::ostringstream out;
    out << header
        << "t,bin,r_over_R_lo,r_over_R_hi,density_over_n,density_stderr,radial_velocity,temperature,particles\n";
    const int bins = scene.config.profile_bins;
    const double width = 1.5 / bins;
    for (std::size_t k = 0; k < scene.times.size(); ++k)
      for (int b = 0; b < bins; ++b) {
        const int e0 = layout.profile(static_cast<int>(k), b, 0);
        const double count = S[e0 + 3];
        const double u = count > 0 ? S[e0 + 1] / count : 0.0;
        const double T = count > 0 ? std::max(0.0, (S[e0 + 2] / count - u * u) / scene.config.d) : 0.0;
        out << format_number(scene.times[k]) << ',' << b << ',' << format_number(b * width) << ','
            << format_number((b + 1) * width) << ',' << format_number(S[e0] / N) << ',' << number_or_nan(stderr_of(e0))
            << ',' << format_number(u) << ',' << format_number(T) << ',' << format_number(count / N) << '\n';
      }
    common::write_file_atomic(directory / "profiles.csv", out.str());
  }
  if (layout.has_p_imp() && N > 0) {
    std::ostringstream out;
    out << header << "t,bin,r_lo,r_hi,r,p,p_stderr,count\n";
    const int bins = scene.config.p_imp_bins;
    const theory::BlastParameters p{scene.config.d, scene.config.n, scene.config.a, scene.config.E, scene.A_d};
    for (std::size_t k = 0; k < scene.times.size(); ++k) {
      const double width = theory::shock_radius(p, scene.times[k]) / bins;
      for (int b = 0; b < bins; ++b) {
        const int e = layout.p_imp(static_cast<int>(k), b);
        out << format_number(scene.times[k]) << ',' << b << ',' << format_number(b * width) << ','
            << format_number((b + 1) * width) << ',' << format_number((b + 0.5) * width) << ','
            << format_number(S[e] / N / width) << ',' << number_or_nan(stderr_of(e) / width) << ',' << N << '\n';
      }
    }
    common::write_file_atomic(directory / "p_imp.csv", out.str());
  }
  for (const auto& [name, content] : result.realization0_files) common::write_file_atomic(directory / name, content);
  common::write_file_atomic(directory / "summary.json", blast_summary(result).dump(2) + "\n");
}

namespace {
/// What md merge takes from a shard's summary.json.
struct MergedSummary {
  std::string scene_toml;
  double wall_seconds = 0.0;
  long long resumed_realizations = 0, resumed_collisions = 0;
  int threads = 1;
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
    if (!s.contains("wall_seconds") || !s.at("wall_seconds").is_number() ||
        !(s.at("wall_seconds").get<double>() >= 0.0) || !std::isfinite(s.at("wall_seconds").get<double>()))
      throw bad("no finite 'wall_seconds' >= 0");
    m.wall_seconds = s.at("wall_seconds").get<double>();
    m.resumed_realizations = count("resumed_realizations", 0, std::numeric_limits<long long>::max());
    m.resumed_collisions = count("resumed_collisions", 0, std::numeric_limits<long long>::max());
    m.threads = static_cast<int>(count("threads", -1, 1 << 20));
    return m;
  } catch (const common::Json::exception& e) {
    throw bad(e.what());
  }
}
}  // namespace

BlastResult merge_blast_outputs(const std::vector<std::filesystem::path>& directories) {
  if (directories.empty()) throw std::invalid_argument("md merge: no input directories");
  BlastResult merged;
  std::string scene_toml;
  for (const auto& dir : directories) {
    const MergedSummary summary = read_merged_summary(dir / "summary.json");
    const std::string& toml_text = summary.scene_toml;
    if (scene_toml.empty()) {
      scene_toml = toml_text;
      merged.scene = resolve_scene(parse_scene(toml_text, {}, (dir / "summary.json").string()));
    } else if (toml_text != scene_toml) {
      throw std::invalid_argument("md merge: " + dir.string() + " ran a different scene than " +
                                  directories.front().string());
    }
    merged.wall_seconds += summary.wall_seconds;
    merged.resumed_realizations += summary.resumed_realizations;
    merged.resumed_collisions += static_cast<std::uint64_t>(summary.resumed_collisions);
    merged.threads = std::max(merged.threads, summary.threads);
    const ObservableLayout layout(merged.scene);
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
    for (auto& [b, s] : blocks) {
      if (merged.blocks.count(b))
        throw std::invalid_argument("md merge: block " + std::to_string(b) + " appears twice (" + dir.string() + ")");
      merged.blocks[b] = std::move(s);
    }
    for (const auto& entry : std::filesystem::directory_iterator(dir)) {
      const std::string name = entry.path().filename().string();
      if (name == "trajectories.csv" ||
          (name.rfind("snapshot_", 0) == 0 && name.size() > 4 && name.substr(name.size() - 4) == ".csv"))
        merged.realization0_files.push_back({name, common::read_text(entry.path())});
    }
  }
  return merged;
}

}  // namespace coldblast::md
