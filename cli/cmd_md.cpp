// coldblast md: event-driven MD of the cold-gas blast (paper Sec. V). `md run` maps flags onto a
// BlastConfig and calls run::run_blast; `md merge` combines shard directories exactly; `md
// equilibrium` runs periodic hard spheres (md::run_equilibrium). Output formats: docs/md-output.md.
#include <atomic>
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
#include "run/checkpoint.hpp"
#include "run/ensemble.hpp"
#include "run/impurity_states.hpp"
#include "run/md_run.hpp"
#include "run/merge.hpp"
#include "run/progress.hpp"
#include "run/run_directory.hpp"
#include "run/tracer_files.hpp"
#if COLDBLAST_HAVE_MPI
#include "run/mpi_ensemble.hpp"
#endif

namespace coldblast::cli {

namespace {

/// md run's flags: the scene, ensemble and folder options bind straight into the library's request.
struct MdRunOptions {
  run::MdRunRequest request;
  std::string out = "md-output";
  std::string resume;      // --resume DIR: continue the checkpoint in DIR/checkpoint
  bool out_given = false;  // --out on the command line (must then equal --resume)
  Format format = Format::table;
};

struct MdStatesOptions {
  run::MdRunRequest request;  // scene, --set, --realizations, --seed, --threads (no shards or checkpoints)
  double time = 0.0;
  std::string out = "md-states";
  bool overwrite = false;
  Format format = Format::table;
};

struct MdMergeOptions {
  std::vector<std::string> inputs;
  std::string out;
  bool overwrite = false;
  Format format = Format::table;
};

struct MdEquilibriumOptions {
  md::EquilibriumConfig config;
  Format format = Format::table;
};

/// md run's progress (run/progress.hpp): realizations done with an ETA; while none finishes (a 3D
/// paper-scene realization runs for minutes), the simulated time a running realization has reached.
class Progress {
 public:
  explicit Progress(double t_max, const char* label = "md run") : t_max_(t_max), lines_(label, "realizations") {}
  void operator()(long long done, long long total) {
    done_ = done;
    total_ = total;
    lines_.update(done, total);
  }
  void at(long long realization, double t) {
    const std::string done = std::to_string(done_) + (total_ > 0 ? "/" + std::to_string(total_.load()) : "");
    char text[160];
    if (t == 0.0)  // a realization starts: its initial state (random sequential addition) comes first
      std::snprintf(text, sizeof text, "%s realizations done; realization %lld: placing the particles", done.c_str(),
                    realization);
    else
      std::snprintf(text, sizeof text, "%s realizations done; realization %lld at t = %.4g of %.4g", done.c_str(),
                    realization, t, t_max_);
    lines_.status(text);
  }

 private:
  double t_max_;
  std::atomic<long long> done_{0}, total_{0};  // at() comes from the worker threads
  run::Progress lines_;
};

void print_summary(const run::BlastResult& result, const std::string& out, Format format) {
  common::Json summary = run::blast_summary(result);
  summary.erase("scene_toml");
  summary["out"] = out;
  if (format == Format::json) {
    print_json(summary);
    return;
  }
  // A start other than the kick is named, with the hot spot's r0/λ (hydro core --start hotspot --r0).
  const md::StartConfig& start = result.scene.config.start;
  std::string start_text;
  if (start.kind == md::StartKind::single) start_text = ", start single";
  if (start.kind == md::StartKind::hotspot)
    start_text = ", start hotspot r0 = " + common::format_number(start.r0) + " = " +
                 common::format_number(start.r0 / result.scene.lambda) + " lambda";
  // Realizations loaded from checkpoints (a resume, a merge of a run in progress) were not timed here.
  char cost[96] = " (loaded, not run here: no timing)";
  if (result.realizations() > result.resumed_realizations)
    std::snprintf(cost, sizeof cost, " in %.2f s (%.3g collisions/s)", result.wall_seconds,
                  summary["collisions_per_second"].get<double>());
  std::printf("scene %s (d = %d%s), %lld realizations, %llu collisions%s\n", result.scene.config.name.c_str(),
              result.scene.config.d, start_text.c_str(), result.realizations(),
              static_cast<unsigned long long>(result.collisions()), cost);
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
run::BlastResult run_ensemble(const md::BlastConfig& config, const run::RunOptions& options) {
  try {
#if COLDBLAST_HAVE_MPI
    return run::run_blast_mpi(config, options);
#else
    return run::run_blast(config, options);
#endif
  } catch (const common::Interrupted&) {
    std::cerr << "\ncoldblast: every finished realization, and where each long one in flight stood, is saved in "
              << run::checkpoint_folder(options.out).string() << "; continue with `" << options.resume_hint << "`\n";
    throw;
  }
}

void run_md(const MdRunOptions& o) {
  run::MdRunRequest request = o.request;
  // Every finished realization is checkpointed in OUT/checkpoint (removed once the outputs are
  // written); --resume DIR continues there (DIR is the output directory) with its scene and shard.
  const std::string out = run_folder(o.out, o.out_given, o.resume);
  request.resume = !o.resume.empty();
  request.out = out;
  request.resume_hint = "coldblast md run --resume " + out;
  run::MdRunPlan plan = run::plan_md_run(request);
  const md::BlastConfig& config = plan.config;
  run::RunOptions& options = plan.options;
  Progress progress(config.t_max);
  options.progress = [&progress](long long done, long long total) { progress(done, total); };
  options.realization_time = [&progress](long long realization, double t) { progress.at(realization, t); };
  options.warning = [](const std::string& warning) { std::cerr << "md run: " << warning << '\n'; };
#if COLDBLAST_HAVE_MPI
  // Under mpirun: blocks spread over ranks; rank 0 alone reports progress and writes the outputs.
  if (run::MpiSession::rank() != 0) {
    options.progress = nullptr;
    options.realization_time = nullptr;
  }
  run::BlastResult result = run_ensemble(config, options);
  if (run::MpiSession::rank() != 0) return;
#else
  run::BlastResult result = run_ensemble(config, options);
#endif
  run::finish_md_run(result, out);
  print_summary(result, out, o.format);
}

/// md states: the impurities' state at one time in every realization (run/impurity_states.hpp).
void states_md(const MdStatesOptions& o) {
  const run::MdRunPlan plan = run::plan_md_run(o.request);
  common::require_output_folder(o.out, "--out");
  run::claim_output_folder(o.out, "--out", o.overwrite, "coldblast md run --resume " + o.out);
  const md::ResolvedScene scene = run::resolve_blast_scene(plan.config);
  Progress progress(o.time, "md states");
  const auto states = run::impurity_states(scene, o.time, plan.config.realizations, o.request.threads,
                                           [&progress](long long done, long long total) { progress(done, total); });
  const std::filesystem::path file = run::write_impurity_states(o.out, states, plan.config, o.time);
  if (o.format == Format::json) {
    common::Json j;
    j["impurities"] = states.size();
    j["realizations"] = plan.config.realizations;
    j["scene"] = plan.config.name;
    j["d"] = plan.config.d;
    j["t"] = o.time;
    j["seed"] = plan.config.seed;
    j["file"] = file.string();
    j["run_id"] = run::recorded_run_id(file);
    j["out"] = o.out;
    print_json(j);
    return;
  }
  std::printf("md states: %zu impurities of %lld realizations of scene %s at t = %s; written to %s\n", states.size(),
              plan.config.realizations, plan.config.name.c_str(), common::format_number(o.time).c_str(),
              file.string().c_str());
}

void merge_md(const MdMergeOptions& o) {
  common::require_output_folder(o.out, "--out");
  std::vector<std::filesystem::path> inputs(o.inputs.begin(), o.inputs.end());
  for (const auto& input : inputs)
    if (std::filesystem::weakly_canonical(input) == std::filesystem::weakly_canonical(o.out))
      throw std::invalid_argument("--out = " + o.out +
                                  " is one of the shard directories DIR; merge into another folder");
  run::claim_output_folder(o.out, "--out", o.overwrite, "");
  if (run::is_tracer_run(inputs.front())) {  // tracer shards: also moments.csv and the tracer's keys
    const run::TracerResult result = run::merge_tracer_outputs(inputs);
    if (const std::string note = run::partial_merge_note(result.ensemble); !note.empty()) std::cerr << note << '\n';
    write_tracer_run(result, o.out, o.format);
    return;
  }
  std::vector<std::string> notes;
  const run::BlastResult result = run::merge_blast_outputs(inputs, &notes);
  for (const std::string& note : notes) std::cerr << note << '\n';
  if (const std::string note = run::partial_merge_note(result); !note.empty()) std::cerr << note << '\n';
  run::write_blast_outputs(result, o.out);
  print_summary(result, o.out, o.format);
}

/// md equilibrium --format json (keys in docs/cli.md).
common::Json equilibrium_json(const md::EquilibriumResult& r) {
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
  return j;
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
  if (o.format == Format::json) {
    print_json(equilibrium_json(r));
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

/// SCENE, --set, --realizations, --seed, --threads of md run and md states, into the library's request.
void add_scene_options(CLI::App& command, run::MdRunRequest& request) {
  command.add_option("SCENE", request.scene_file, "Scene file (TOML); keys in docs/md-output.md");
  command.add_option("--set", request.overrides,
                     "Override a scene key: key=value (repeatable; e.g. --set E=20 --set impurities.count=2)");
  command.add_option_function<long long>(
      "--realizations", [&request](const long long& n) { request.realizations = n; },
      "Number of realizations (overrides the scene)");
  command.add_option_function<long long>(
      "--seed", [&request](const long long& seed) { request.seed = seed; }, "Master seed (overrides the scene; >= 0)");
  command.add_option("--threads", request.threads, "Worker threads (results are identical for any count)")
      ->capture_default_str();
}

void add_run_command(CLI::App& md) {
  auto run = std::make_shared<MdRunOptions>();
  CLI::App* command =
      md.add_subcommand("run", "Run an ensemble of blast realizations of a TOML scene (default: the embedded scene)");
  add_scene_options(*command, run->request);
  CLI::Option* out_option =
      command
          ->add_option("--out", run->out,
                       "Output directory: one run (files with its run id, manifest.json); finished realizations are "
                       "checkpointed in OUT/checkpoint until the run ends")
          ->capture_default_str();
  command->add_option_function<std::string>(
      "--shard", [run](const std::string& shard) { run->request.shard = shard; },
      "Run only blocks i, i+n, ... of the ensemble: i/n (default 0/1)");
  command->add_option("--resume", run->resume,
                      "Continue a stopped or killed run in output directory DIR with the scene, options and run id "
                      "of its checkpoint, running only the missing realizations (an option given again must "
                      "agree with the checkpoint)");
  command->add_flag("--overwrite", run->request.overwrite,
                    "Replace the files of another run (or an unfinished run's checkpoint) in --out: exactly "
                    "those of its manifest.json");
  command
      ->add_option("--save-every", run->request.save_every,
                   "Seconds: a realization running longer saves its state in OUT/checkpoint this often, so a kill "
                   "loses at most this much of it; a stop (SIGINT, SIGTERM) saves it at once")
      ->capture_default_str();
  add_format_option(*command, run->format);
  command->callback([run, out_option] {
    run->out_given = out_option->count() > 0;
    common::install_stop_handlers();  // SIGINT/SIGTERM end the run between realizations, blocks saved
    run_md(*run);
  });
}

void add_states_command(CLI::App& md) {
  auto states = std::make_shared<MdStatesOptions>();
  CLI::App* command = md.add_subcommand(
      "states",
      "Write the impurities' positions, velocities and collision counts at one time in every realization "
      "(the realizations of md run; to start coldblast tracer --start states from)");
  add_scene_options(*command, states->request);
  command->add_option("--time", states->time, "Time of the states, in (0, t_max] of the scene")->required();
  command->add_option("--out", states->out, "Output directory (impurity_states.csv, manifest.json)")
      ->capture_default_str();
  command->add_flag("--overwrite", states->overwrite,
                    "Replace the files of another run in --out (exactly those of its manifest.json)");
  add_format_option(*command, states->format);
  command->callback([states] {
    common::install_stop_handlers();
    states_md(*states);
  });
}

void add_merge_command(CLI::App& md) {
  auto merge = std::make_shared<MdMergeOptions>();
  CLI::App* merge_command = md.add_subcommand(
      "merge",
      "Combine the output directories of shards exactly; a run still in progress gives the finished blocks of its "
      "checkpoint (read only), to look at a long run while it goes on");
  merge_command->add_option("DIR", merge->inputs, "Shard output directories, finished or in progress")->required();
  merge_command->add_option("--out", merge->out, "Output directory (a new run: its own run id)")->required();
  merge_command->add_flag("--overwrite", merge->overwrite,
                          "Replace the files of another run in --out (exactly those of its manifest.json)");
  add_format_option(*merge_command, merge->format);
  merge_command->callback([merge] { merge_md(*merge); });
}

void add_equilibrium_command(CLI::App& md) {
  auto eq = std::make_shared<MdEquilibriumOptions>();
  CLI::App* eq_command = md.add_subcommand(
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

}  // namespace

void add_md_command(CLI::App& app) {
  CLI::App* md =
      app.add_subcommand("md", "Event-driven MD of the blast in a zero-temperature hard-sphere gas (paper Sec. V)");
  md->require_subcommand(1);
  add_run_command(*md);
  add_states_command(*md);
  add_merge_command(*md);
  add_equilibrium_command(*md);
}

}  // namespace coldblast::cli
