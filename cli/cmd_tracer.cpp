// coldblast tracer: Monte Carlo of the impurity's Lorentz–Boltzmann equation (paper Eq. (36)
// [LB-full]) in a Navier–Stokes, TvNS, equilibrium or measured MD background. Maps flags onto a
// kinetic::TracerConfig, calls run::run_tracer and writes the `md run` run directory
// (docs/kinetic.md), over MPI ranks under mpirun (MPI build). Shards are combined with `coldblast md merge`.
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>

#include "cli/commands.hpp"
#include "common/input.hpp"
#include "common/interrupt.hpp"
#include "common/output.hpp"
#include "common/validate.hpp"
#include "kinetic/tracer_config.hpp"
#include "run/checkpoint.hpp"
#include "run/ensemble.hpp"
#include "run/md_fields.hpp"
#include "run/progress.hpp"
#include "run/scene_file.hpp"
#include "run/tracer_files.hpp"
#include "run/tracer_run.hpp"
#if COLDBLAST_HAVE_MPI
#include "run/mpi_ensemble.hpp"
#include "run/mpi_tracer.hpp"
#endif

namespace coldblast::cli {

namespace {

struct TracerOptions {
  std::string scene_file;
  std::vector<std::string> set;
  kinetic::TracerConfig config;
  long long seed = 0;
  CLI::Option* seed_option = nullptr;  // given or not: no value means "the scene's"
  std::optional<double> phi;
  std::string shard = "0/1";
  std::string out = "tracer-output";
  bool out_given = false;
  std::string resume;  // --resume DIR: continue the checkpoint in DIR/checkpoint
  bool overwrite = false;
  std::vector<std::string> given;  // the options on the command line (for --resume's checks)
  Format format = Format::table;
};

// The run (over MPI ranks when built with MPI); a SIGINT/SIGTERM stop says how to resume.
run::TracerResult run_tracer_blocks(const kinetic::TracerConfig& config, const run::TracerProgress& progress,
                                    const run::TracerRunFiles& files) {
  try {
#if COLDBLAST_HAVE_MPI
    return run::run_tracer_mpi(config, progress, files);
#else
    return run::run_tracer(config, progress, files);
#endif
  } catch (const common::Interrupted&) {
    std::cerr << "\ncoldblast: every finished block is saved in " << run::checkpoint_folder(files.out).string()
              << "; continue with `" << files.resume_hint << "`\n";
    throw;
  }
}

void run(TracerOptions& o) {
  if (!o.resume.empty() && o.overwrite)
    throw std::invalid_argument("--overwrite starts a new run; --resume continues the one in the folder: give one");
  const std::string out = run_folder(o.out, o.out_given, o.resume);
  run::SceneRequest scene;
  scene.file = o.scene_file;
  // --background md without SCENE: the MD run's own scene (its physics must be the tracer's).
  if (o.config.background == "md" && o.scene_file.empty() && !o.config.md_run.empty())
    scene.text = run::md_run_scene_toml(o.config.md_run, "--md-run");
  scene.overrides = o.set;
  if (o.seed_option->count() > 0) scene.seed = o.seed;
  scene.md_snapshots = false;  // the tracer records no particles
  kinetic::TracerConfig config = o.config;
  config.scene = run::load_scene(scene);
  config.phi = o.phi;
  std::tie(config.shard_index, config.shard_count) = run::parse_shard(o.shard);
  if (!o.resume.empty()) config = run::resume_tracer_config(out, config, o.given);
  run::TracerRunFiles files{out, "--out", !o.resume.empty(), o.overwrite, "coldblast tracer --resume " + out};
  run::TracerProgress progress;
  ProgressPacer pacer;
  progress.background = [&pacer](double R_over_lambda) {
    if (!pacer.due_at(R_over_lambda)) return;
    std::fprintf(stderr, "tracer: Navier-Stokes background, R/lambda = %.4g\n", R_over_lambda);
  };
  run::Progress blocks("tracer", "blocks");
  progress.blocks = [&blocks](long long done, long long total) { blocks.update(done, total); };
#if COLDBLAST_HAVE_MPI
  // Under mpirun: blocks spread over ranks (md's launcher); rank 0 alone reports and writes.
  if (run::MpiSession::rank() != 0) progress = {};
  const run::TracerResult result = run_tracer_blocks(config, progress, files);
  if (run::MpiSession::rank() != 0) return;
#else
  const run::TracerResult result = run_tracer_blocks(config, progress, files);
#endif
  write_tracer_run(result, out, o.format);
  run::remove_checkpoint(out);
}

}  // namespace

void write_tracer_run(const run::TracerResult& result, const std::string& out, Format format) {
  run::write_tracer_outputs(result, out);
  common::Json summary = run::tracer_summary(result);
  summary.erase("scene_toml");
  summary["out"] = out;
  if (format == Format::json) {
    print_json(summary);
    return;
  }
  std::printf("tracer (%s background), scene %s (d = %d): %lld trajectories, %llu collisions in %.2f s\n",
              result.config.background.c_str(), result.ensemble.scene.config.name.c_str(),
              result.ensemble.scene.config.d, result.trajectories(),
              static_cast<unsigned long long>(result.collisions()), result.wall_seconds);
  std::printf("  collision rate %s per impurity per time (chi = %.6g), null-collision rejection %.3f, %s kernel\n",
              common::format_measurement(result.collision_rate(), result.collision_rate_error()).c_str(), result.chi,
              result.rejection_rate(), result.kernel.c_str());
  if (summary.contains("collision_rate_exact")) {  // equilibrium: the exact n chi S <|g|> beside the measurement
    const double exact = summary["collision_rate_exact"].get<double>();
    std::printf("  exact equilibrium collision rate n chi S <|g|> = %s (measured %+.1f sigma from it)\n",
                common::format_significant(exact, 6).c_str(),
                (result.collision_rate() - exact) / result.collision_rate_error());
  }
  const std::string bath =
      result.config.background == "equilibrium" ? " (bath T = " + common::format_number(result.config.T) + ")" : "";
  std::printf("  impurity temperature at t_max %s%s; output in %s\n",
              common::format_measurement(result.temperature_final(), result.temperature_final_error()).c_str(),
              bath.c_str(), out.c_str());
  print_final_estimates(result.ensemble);
}

namespace {
/// The options of the run rather than of its physics: trajectories, threads, seed, shard and the
/// output folder (--out, returned, --resume, --overwrite).
CLI::Option* add_tracer_run_options(CLI::App& c, TracerOptions& o) {
  c.add_option("--trajectories", o.config.trajectories,
               "Impurity trajectories (0 = the scene's realizations x impurities.count)")
      ->capture_default_str();
  c.add_option("--threads", o.config.threads, "Worker threads (results are identical for any count)")
      ->capture_default_str();
  o.seed_option = c.add_option("--seed", o.seed, "Master seed (overrides the scene; >= 0)");
  c.add_option("--shard", o.shard, "Run only blocks i, i+n, ... (combine with coldblast md merge): i/n")
      ->capture_default_str();
  CLI::Option* out_option =
      c.add_option("--out", o.out,
                   "Output directory: one run (files with its run id, manifest.json); finished blocks are "
                   "checkpointed in OUT/checkpoint until the run ends")
          ->capture_default_str();
  c.add_option("--resume", o.resume,
               "Continue a stopped or killed run in output directory DIR with the scene, options and run id of its "
               "checkpoint, running only the missing blocks (an option given again must agree with the checkpoint)");
  c.add_flag("--overwrite", o.overwrite,
             "Replace the files of another run (or an unfinished run's checkpoint) in --out: exactly those of its "
             "manifest.json");
  return out_option;
}
}  // namespace

void add_tracer_command(CLI::App& app) {
  auto o = std::make_shared<TracerOptions>();
  CLI::App* c = app.add_subcommand(
      "tracer", "Monte Carlo of the impurity's Lorentz-Boltzmann equation (paper Eq. 36) in a hydrodynamic background");
  c->add_option("SCENE", o->scene_file, "Scene file (TOML, the keys of md run); default: the embedded scene");
  c->add_option("--set", o->set, "Override a scene key: key=value (repeatable)");
  c->add_option("--background", o->config.background,
                "Host background: ns, tvns, equilibrium, or md (the measured mean fields of an MD run: --md-run)")
      ->capture_default_str();
  c->add_option("--md-run", o->config.md_run,
                "--background md: an `md run` folder that recorded the observables profiles and R; its scene is the "
                "tracer's unless SCENE is given (d, n, a, E and impurities must agree)");
  c->add_option(
       "--transport", o->config.transport,
       "dilute (chi = 1; ideal-gas Navier-Stokes) or enskog (chi(n) at contact; dense Navier-Stokes at the scene's "
       "packing fraction: the prediction for its MD, as reproduce runs it; not with tvns)")
      ->capture_default_str();
  CLI::Option* out_option = add_tracer_run_options(*c, *o);
  c->add_option("--T", o->config.T, "Equilibrium background: bath temperature (> 0)")->capture_default_str();
  c->add_option("--phi", o->phi, "Equilibrium background: packing fraction (default: the scene's)");
  c->add_option("--start", o->config.start,
                "Initial state: kick (the MD's), hotspot (the MD's hot spot of radius --r0, in the Navier-Stokes hot "
                "spot; docs/kinetic.md), single (the MD's single kicked host: the impurity at rest near the centre, as "
                "the MD places it), "
                "thermal (local Maxwellian) or states (the MD's own impurities at a time: --start-states)")
      ->capture_default_str();
  c->add_option("--r0", o->config.r0,
                "--start hotspot: the hot spot's radius, a length as the scene's start.r0 (not hydro's r0/lambda); "
                "0 = the scene's start.r0")
      ->capture_default_str();
  c->add_option("--start-states", o->config.start_states,
                "--start states: impurity_states.csv of `coldblast md states` (or its --out directory) for the same "
                "scene; trajectory i "
                "starts from state i at the file's time (at most as many trajectories as states)");
  c->add_option("--start-time", o->config.start_time,
                "Start time (0 = the scene's t_min, t_min/1024 for hotspot; 0 for equilibrium)")
      ->capture_default_str();
  c->add_option("--frames-per-decade", o->config.frames_per_decade, "ns: stored frames per decade of R/lambda")
      ->capture_default_str();
  c->add_option("--cells", o->config.cells, "ns: Navier-Stokes cells")->capture_default_str();
  c->add_option("--kernel", o->config.kernel,
                "auto (the widest vector kernel this CPU runs, for ns and tvns; else scalar); avx512, avx2, sse4 or "
                "neon forces that vector kernel (avx512 and avx2 give the same paths); scalar one trajectory at a "
                "time: the same process with other deviates, so other sample paths (summary.json records it)")
      ->capture_default_str();
  add_format_option(*c, o->format);
  c->callback([o, c, out_option] {
    o->out_given = out_option->count() > 0;
    o->given.clear();
    for (const CLI::Option* option : c->get_options())
      if (option->count() > 0) o->given.push_back(option->get_name());
    common::install_stop_handlers();  // SIGINT/SIGTERM end the run between blocks, blocks saved
    run(*o);
  });
}

}  // namespace coldblast::cli
