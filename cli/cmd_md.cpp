// coldblast md: event-driven MD of the cold-gas blast (paper Sec. V). `md run` maps flags onto a
// BlastConfig and calls run::run_blast; `md merge` combines shard directories exactly; `md
// equilibrium` runs periodic hard spheres (md::run_equilibrium). Output formats: docs/md-output.md.
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <mutex>
#include <sstream>

#include "cli/commands.hpp"
#include "common/input.hpp"
#include "common/interrupt.hpp"
#include "common/output.hpp"
#include "common/validate.hpp"
#include "md/equilibrium.hpp"
#include "run/ensemble.hpp"
#include "run/impurity_states.hpp"
#include "run/md_run.hpp"
#include "run/tracer_files.hpp"
#if COLDBLAST_HAVE_MPI
#include "run/mpi_ensemble.hpp"
#endif

namespace coldblast::cli {

namespace {

struct MdRunOptions {
  std::string scene_file;
  std::vector<std::string> set;
  long long realizations = 0;
  CLI::Option* realizations_option = nullptr;  // given or not: no value means "the scene's"
  int threads = 1;
  long long seed = 0;
  CLI::Option* seed_option = nullptr;
  std::string out = "md-output";
  std::string shard = "0/1";
  std::string resume;      // --resume DIR: continue the checkpoint in DIR/checkpoint
  bool out_given = false;  // --out on the command line (must then equal --resume)
  Format format = Format::table;
};

struct MdStatesOptions {
  MdRunOptions run;  // scene, --set, --realizations, --seed, --threads (no shards or checkpoints)
  double time = 0.0;
  std::string out = "md-states";
};

struct MdMergeOptions {
  std::vector<std::string> inputs;
  std::string out;
  Format format = Format::table;
};

struct MdEquilibriumOptions {
  md::EquilibriumConfig config;
  Format format = Format::table;
};

/// The status line of md run on stderr: realizations done with an ETA, at most every 0.5 s; while
/// none finishes for 2 s (a 3D paper-scene realization runs for minutes), the simulated time a
/// running realization has reached.
class Progress {
 public:
  explicit Progress(double t_max, const char* label = "md run") : t_max_(t_max), label_(label) {}
  void operator()(long long done, long long total) {
    std::lock_guard<std::mutex> lock(mutex_);
    done_ = done;
    total_ = total;
    const auto now = std::chrono::steady_clock::now();
    const double elapsed = std::chrono::duration<double>(now - start_).count();
    if (done < total && std::chrono::duration<double>(now - last_).count() < 0.5) return;
    last_ = now;
    shown_ = true;
    const double eta = done > 0 ? elapsed * (total - done) / done : 0.0;
    std::fprintf(stderr, "\r%s: %lld/%lld realizations, %.1f s elapsed, ETA %.1f s   ", label_, done, total, elapsed,
                 eta);
    if (done == total) std::fprintf(stderr, "\n");
    std::fflush(stderr);
  }
  void at(long long realization, double t) {
    std::lock_guard<std::mutex> lock(mutex_);
    const auto now = std::chrono::steady_clock::now();
    if (shown_ && std::chrono::duration<double>(now - last_).count() < 2.0) return;
    last_ = now;
    shown_ = true;
    const double elapsed = std::chrono::duration<double>(now - start_).count();
    const std::string done = std::to_string(done_) + (total_ > 0 ? "/" + std::to_string(total_) : "");
    if (t == 0.0)  // a realization starts: its initial state (random sequential addition) comes first
      std::fprintf(stderr, "\r%s: %s realizations done; realization %lld: placing the particles, %.1f s elapsed   ",
                   label_, done.c_str(), realization, elapsed);
    else
      std::fprintf(stderr, "\r%s: %s realizations done; realization %lld at t = %.4g of %.4g, %.1f s elapsed   ",
                   label_, done.c_str(), realization, t, t_max_, elapsed);
    std::fflush(stderr);
  }

 private:
  std::mutex mutex_;  // at() comes from the worker threads
  double t_max_;
  const char* label_;
  long long done_ = 0, total_ = 0;
  bool shown_ = false;  // a line was printed
  std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now(), last_ = start_;
};

void print_summary(const run::BlastResult& result, const std::string& out, Format format) {
  common::Json summary = run::blast_summary(result);
  summary.erase("scene_toml");
  summary["out"] = out;
  if (format == Format::json) {
    print_json(summary);
    return;
  }
  std::printf("scene %s (d = %d), %lld realizations, %llu collisions in %.2f s (%.3g collisions/s)\n",
              result.scene.config.name.c_str(), result.scene.config.d, result.realizations(),
              static_cast<unsigned long long>(result.collisions()), result.wall_seconds,
              summary["collisions_per_second"].get<double>());
  std::printf("max relative energy error %.2g; output in %s\n", result.energy_error_max(), out.c_str());
  print_final_estimates(result);
}

}  // namespace

void print_final_estimates(const run::BlastResult& ensemble) {
  const auto rows = run::estimate_observables(ensemble);
  const double t_last = rows.empty() ? 0.0 : rows.back().t;
  for (const auto& row : rows) {
    if (row.t != t_last) continue;
    if (std::isfinite(row.stderr_))
      std::printf("  t = %-10g %-6s %20s\n", row.t, row.observable.c_str(),
                  common::format_measurement(row.mean, row.stderr_).c_str());
    else  // one realization, or a flow below its noise (u_flow's mean <= 0; docs/md-output.md)
      std::printf("  t = %-10g %-6s %14.6g (no error: %s)\n", row.t, row.observable.c_str(), row.mean,
                  row.count < 2 ? "one realization" : "undefined at a zero mean");
  }
}

namespace {

// The ensemble (over MPI ranks when built with MPI); a SIGINT/SIGTERM stop says how to resume.
run::BlastResult run_ensemble(const md::BlastConfig& config, const run::RunOptions& options, const std::string& out) {
  try {
#if COLDBLAST_HAVE_MPI
    return run::run_blast_mpi(config, options);
#else
    return run::run_blast(config, options);
#endif
  } catch (const common::Interrupted&) {
    std::cerr << "\ncoldblast: the finished blocks are saved in "
              << (std::filesystem::path(out) / "checkpoint").string()
              << "; continue with the same command and --resume " << out << '\n';
    throw;
  }
}

void run_md(const MdRunOptions& o) {
  run::MdRunRequest request;
  request.scene_file = o.scene_file;
  request.overrides = o.set;
  if (o.realizations_option->count() > 0) request.realizations = o.realizations;
  if (o.seed_option->count() > 0) request.seed = o.seed;
  request.threads = o.threads;
  const auto [shard_index, shard_count] = run::parse_shard(o.shard);
  run::MdRunPlan plan = run::plan_md_run(request);
  const md::BlastConfig& config = plan.config;
  run::RunOptions& options = plan.options;
  options.shard_index = shard_index;
  options.shard_count = shard_count;
  Progress progress(config.t_max);
  options.progress = [&progress](long long done, long long total) { progress(done, total); };
  options.realization_time = [&progress](long long realization, double t) { progress.at(realization, t); };
  // Every finished block is checkpointed in OUT/checkpoint (removed once the outputs are written);
  // --resume DIR continues there (DIR is the output directory).
  std::string out = o.out;
  if (!o.resume.empty()) {
    if (o.out_given &&
        std::filesystem::path(o.out).lexically_normal() != std::filesystem::path(o.resume).lexically_normal())
      throw std::invalid_argument("--resume = " + o.resume + " must be the output directory (--out = " + o.out + ")");
    out = o.resume;
    options.resume = true;
  }
  common::require_output_folder(out, o.resume.empty() ? "--out" : "--resume");
  options.checkpoint = std::filesystem::path(out) / "checkpoint";
#if COLDBLAST_HAVE_MPI
  // Under mpirun: blocks spread over ranks; rank 0 alone reports progress and writes the outputs.
  if (run::MpiSession::rank() != 0) {
    options.progress = nullptr;
    options.realization_time = nullptr;
  }
  run::BlastResult result = run_ensemble(config, options, out);
  if (run::MpiSession::rank() != 0) return;
#else
  run::BlastResult result = run_ensemble(config, options, out);
#endif
  run::write_blast_outputs(result, out);
  std::error_code ignored;
  std::filesystem::remove_all(options.checkpoint, ignored);
  print_summary(result, out, o.format);
}

/// md states: the impurities' state at one time in every realization (run/impurity_states.hpp).
void states_md(const MdStatesOptions& o) {
  run::MdRunRequest request;
  request.scene_file = o.run.scene_file;
  request.overrides = o.run.set;
  if (o.run.realizations_option->count() > 0) request.realizations = o.run.realizations;
  if (o.run.seed_option->count() > 0) request.seed = o.run.seed;
  request.threads = o.run.threads;
  const run::MdRunPlan plan = run::plan_md_run(request);
  common::require_output_folder(o.out, "--out");
  const md::ResolvedScene scene = run::resolve_blast_scene(plan.config);
  Progress progress(o.time, "md states");
  const auto states = run::impurity_states(scene, o.time, plan.config.realizations, o.run.threads,
                                           [&progress](long long done, long long total) { progress(done, total); });
  const std::filesystem::path file = std::filesystem::path(o.out) / "impurity_states.csv";
  common::write_file_atomic(file, run::impurity_states_csv(states, plan.config, o.time));
  std::printf("md states: %zu impurities of %lld realizations of scene %s at t = %s; written to %s\n", states.size(),
              plan.config.realizations, plan.config.name.c_str(), common::format_number(o.time).c_str(),
              file.string().c_str());
}

void merge_md(const MdMergeOptions& o) {
  common::require_output_folder(o.out, "--out");
  std::vector<std::filesystem::path> inputs(o.inputs.begin(), o.inputs.end());
  if (run::is_tracer_run(inputs.front())) {  // tracer shards: also moments.csv and the tracer's keys
    const run::TracerResult result = run::merge_tracer_outputs(inputs);
    if (const std::string note = run::partial_merge_note(result.ensemble); !note.empty()) std::cerr << note << '\n';
    write_tracer_run(result, o.out, o.format);
    return;
  }
  const run::BlastResult result = run::merge_blast_outputs(inputs);
  if (const std::string note = run::partial_merge_note(result); !note.empty()) std::cerr << note << '\n';
  run::write_blast_outputs(result, o.out);
  print_summary(result, o.out, o.format);
}

void equilibrium_md(const MdEquilibriumOptions& o) {
  // The library validates its fields; the messages name this command's flags.
  static const common::FieldNames flags = {{"d", "--d"},
                                           {"phi", "--phi"},
                                           {"particles", "--particles"},
                                           {"collisions", "--collisions"},
                                           {"blocks", "--blocks"},
                                           {"queue", "--queue"},
                                           {"diffusion_lag", "--diffusion-lag"},
                                           {"diffusion_windows", "--diffusion-windows"}};
  common::with_field_names(flags, [&] { o.config.validate(); });
  ProgressPacer pacer;
  const md::EquilibriumResult r =
      md::run_equilibrium(o.config, [&pacer](const char* stage, long long done, long long total) {
        if (pacer.due(done == 0 || done == total))
          std::fprintf(stderr, "md equilibrium: %s %lld/%lld\n", stage, done, total);
      });
  common::Json j;
  j["d"] = r.config.d;
  j["phi"] = r.config.phi;
  j["Z"] = r.Z;
  j["Z_error"] = r.Z_error;
  j["collision_rate"] = r.collision_rate;
  j["collision_rate_error"] = r.collision_rate_error;
  j["collisions_per_second"] = r.collisions_per_second;
  j["Z_from_collision_rate"] = r.Z_from_collision_rate;
  j["Z_from_collision_rate_error"] = r.Z_from_collision_rate_error;
  j["Z_reference"] = r.Z_reference;
  j["reference"] = r.reference_name;
  j["particles"] = r.config.particles;
  j["box_side"] = r.box_side;
  j["temperature"] = r.temperature;
  j["energy_error"] = r.energy_error;
  j["collisions_total"] = r.collisions_total;
  j["wall_seconds"] = r.wall_seconds;
  j["seed"] = r.config.seed;
  if (r.config.diffusion_lag > 0.0) {
    j["diffusion"] = r.diffusion;
    j["diffusion_error"] = r.diffusion_error;
    j["diffusion_lag"] = r.config.diffusion_lag;
    j["diffusion_windows"] = r.config.diffusion_windows;
    j["msd_lag"] = r.msd_lag;
    j["msd_lag_error"] = r.msd_lag_error;
    j["diffusion_sample_interval"] = r.diffusion_sample_interval;
    j["center_of_mass_error"] = r.center_of_mass_error;
  }
  if (o.format == Format::json) {
    print_json(j);
    return;
  }
  std::printf("hard %s, d = %d, phi = %g, N = %lld (periodic, T = 1)\n", r.config.d == 2 ? "discs" : "spheres",
              r.config.d, r.config.phi, r.config.particles);
  std::printf("  Z = beta P / n (virial)        %s\n", common::format_measurement(r.Z, r.Z_error).c_str());
  std::printf("  Z from collision rate          %s\n",
              common::format_measurement(r.Z_from_collision_rate, r.Z_from_collision_rate_error).c_str());
  std::printf("  %-30s %.6f\n", r.reference_name.c_str(), r.Z_reference);
  std::printf("  collision rate per particle    %s\n",
              common::format_measurement(r.collision_rate, r.collision_rate_error).c_str());
  if (r.config.diffusion_lag > 0.0)
    std::printf("  self-diffusion D (MSD, lag %g) %s\n", r.config.diffusion_lag,
                common::format_measurement(r.diffusion, r.diffusion_error).c_str());
  std::printf("  %.3g collisions in %.2f s: %.3g collisions/s\n", static_cast<double>(r.collisions_total),
              r.wall_seconds, r.collisions_per_second);
}

}  // namespace

void add_md_command(CLI::App& app) {
  CLI::App* md =
      app.add_subcommand("md", "Event-driven MD of the blast in a zero-temperature hard-sphere gas (paper Sec. V)");
  md->require_subcommand(1);

  auto run = std::make_shared<MdRunOptions>();
  CLI::App* run_command =
      md->add_subcommand("run", "Run an ensemble of blast realizations of a TOML scene (default: the embedded scene)");
  run_command->add_option("SCENE", run->scene_file, "Scene file (TOML); keys in docs/md-output.md");
  run_command->add_option("--set", run->set,
                          "Override a scene key: key=value (repeatable; e.g. --set E=20 --set impurities.count=2)");
  run->realizations_option =
      run_command->add_option("--realizations", run->realizations, "Number of realizations (overrides the scene)");
  run_command->add_option("--threads", run->threads, "Worker threads (results are identical for any count)")
      ->capture_default_str();
  run->seed_option = run_command->add_option("--seed", run->seed, "Master seed (overrides the scene; >= 0)");
  CLI::Option* out_option =
      run_command
          ->add_option("--out", run->out,
                       "Output directory (finished blocks are checkpointed in OUT/checkpoint until the run ends)")
          ->capture_default_str();
  run_command->add_option("--shard", run->shard, "Run only blocks i, i+n, ... of the ensemble: i/n")
      ->capture_default_str();
  run_command->add_option("--resume", run->resume,
                          "Continue a killed run in output directory DIR: load its checkpoint (same scene required) "
                          "and run only the missing blocks");
  add_format_option(*run_command, run->format);
  run_command->callback([run, out_option] {
    run->out_given = out_option->count() > 0;
    common::install_stop_handlers();  // SIGINT/SIGTERM end the run between realizations, blocks saved
    run_md(*run);
  });

  auto states = std::make_shared<MdStatesOptions>();
  CLI::App* states_command = md->add_subcommand(
      "states",
      "Write the impurities' positions, velocities and collision counts at one time in every realization "
      "(the realizations of md run; to start coldblast tracer --start states from)");
  states_command->add_option("SCENE", states->run.scene_file, "Scene file (TOML); keys in docs/md-output.md");
  states_command->add_option("--set", states->run.set, "Override a scene key: key=value (repeatable)");
  states->run.realizations_option =
      states_command->add_option("--realizations", states->run.realizations, "Realizations (overrides the scene)");
  states->run.seed_option = states_command->add_option("--seed", states->run.seed, "Master seed (overrides the scene)");
  states_command->add_option("--threads", states->run.threads, "Worker threads (results are identical for any count)")
      ->capture_default_str();
  states_command->add_option("--time", states->time, "Time of the states, in (0, t_max] of the scene")->required();
  states_command->add_option("--out", states->out, "Output directory (impurity_states.csv)")->capture_default_str();
  states_command->callback([states] {
    common::install_stop_handlers();
    states_md(*states);
  });

  auto merge = std::make_shared<MdMergeOptions>();
  CLI::App* merge_command = md->add_subcommand("merge", "Combine the output directories of shards exactly");
  merge_command->add_option("DIR", merge->inputs, "Shard output directories")->required();
  merge_command->add_option("--out", merge->out, "Output directory")->required();
  add_format_option(*merge_command, merge->format);
  merge_command->callback([merge] { merge_md(*merge); });

  auto eq = std::make_shared<MdEquilibriumOptions>();
  CLI::App* eq_command = md->add_subcommand(
      "equilibrium", "Equilibrium hard spheres in a periodic box: Z = beta P/n, the collision rate, self-diffusion");
  eq_command->add_option("--d", eq->config.d, "Dimension (2 or 3)")->capture_default_str();
  eq_command->add_option("--phi", eq->config.phi, "Packing fraction (0..0.7 in 2D, 0..0.5 in 3D)")
      ->capture_default_str();
  eq_command->add_option("--particles", eq->config.particles, "Number of particles N")->capture_default_str();
  eq_command->add_option("--collisions", eq->config.collisions, "Collisions measured after equilibration")
      ->capture_default_str();
  eq_command->add_option("--blocks", eq->config.blocks, "Blocks for the error bars")->capture_default_str();
  eq_command->add_option("--seed", eq->config.seed, "Random seed")->capture_default_str();
  eq_command->add_option("--queue", eq->config.queue, "Event calendar: calendar or heap")->capture_default_str();
  eq_command
      ->add_option("--diffusion-lag", eq->config.diffusion_lag,
                   "Self-diffusion from the mean squared displacement over windows of 2 x this lag (0: off)")
      ->capture_default_str();
  eq_command->add_option("--diffusion-windows", eq->config.diffusion_windows, "Windows for the self-diffusion")
      ->capture_default_str();
  add_format_option(*eq_command, eq->format);
  eq_command->callback([eq] { equilibrium_md(*eq); });
}

}  // namespace coldblast::cli
