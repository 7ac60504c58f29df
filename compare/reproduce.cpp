#include "compare/reproduce.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <thread>

#include "coldblast/paper_scene.hpp"
#include "common/output.hpp"
#include "common/validate.hpp"
#include "compare/hydro_reference.hpp"
#include "compare/report.hpp"
#include "compare/reproduce_report.hpp"
#include "compare/run_data.hpp"
#include "hydro/navier_stokes.hpp"
#include "hydro/result_files.hpp"
#include "hydro/tvns.hpp"
#include "md/blast_config.hpp"
#include "run/ensemble.hpp"
#include "run/scene_file.hpp"
#include "run/tracer_files.hpp"
#include "run/tracer_run.hpp"
#include "theory/exponents.hpp"
#include "theory/prefactors.hpp"

namespace coldblast::compare {

namespace fs = std::filesystem;

ReproduceScale parse_scale(const std::string& text) {
  if (text == "quick") return ReproduceScale::quick;
  if (text == "paper") return ReproduceScale::paper;
  throw std::invalid_argument("--scale = " + text + " is not one of quick, paper");
}

void ReproduceConfig::validate() const {
  common::require_integer_in_range("--threads", threads, 0, 1024);
  // The seed goes into the scene's TOML (a signed 64-bit integer), as md run's --seed.
  common::require_integer_in_range("--seed", seed, 0, std::numeric_limits<long long>::max());
  common::require_integer_in_range("--realizations", realizations, 0, 100000000,
                                   " (0 = the scale's default; at least 2, for error bars)");
  if (realizations == 1)
    throw std::invalid_argument("--realizations = 1: an error bar needs at least 2 (0 = the scale's default)");
  if (hydro_until != 0)
    common::require_in_range("--hydro-until", hydro_until, 20.0, 1e8, common::Bound::closed, common::Bound::closed);
  common::require_integer_in_range("--tracer-trajectories", tracer_trajectories, 0, 100000000,
                                   " (0 = the scale's default; at least 2, for error bars)");
  if (tracer_trajectories == 1)
    throw std::invalid_argument("--tracer-trajectories = 1: an error bar needs at least 2 (0 = the scale's default)");
  common::require_output_folder(out, "--out");
  if (fs::is_directory(out))  // the reports replace these folders whole: checked before the work
    for (const char* report : {"report-theory", "report-paper", "report-hydro", "report-tracer"})
      report_folder(out / report);
  if (!md_run.empty()) check_paper_md_run(md_run);
}

namespace {
/// The first key of the paper scene's physics and recording (whatever the ensemble's size, seed and
/// blocks) that the run's summary.json "scene" object does not share, as "key is X, the paper
/// scene's Y"; empty when it is the paper scene.
std::string paper_scene_difference(const common::Json& scene) {
  const md::BlastConfig paper = run::parse_scene(paper_scene_toml, {}, "scenes/paper-2d.toml");
  const std::pair<const char*, double> keys[] = {{"/d", paper.d},
                                                 {"/n", paper.n},
                                                 {"/a", paper.a},
                                                 {"/E", paper.E},
                                                 {"/t_min", paper.t_min},
                                                 {"/t_max", paper.t_max},
                                                 {"/p_imp_bins", paper.p_imp_bins},
                                                 {"/impurities/count", paper.impurities.count},
                                                 {"/impurities/mass", paper.impurities.mass},
                                                 {"/impurities/radius", paper.impurities.radius}};
  for (const auto& [pointer, value] : keys) {
    const common::Json::json_pointer key(pointer);
    const bool present = scene.is_object() && scene.contains(key);
    if (present && scene.at(key).is_number() && scene.at(key).get<double>() == value) continue;
    std::string name = std::string(pointer).substr(1);
    std::replace(name.begin(), name.end(), '/', '.');
    return name + " is " + (present ? scene.at(key).dump() : std::string("missing")) + ", the paper scene's " +
           common::format_number(value);
  }
  // The no-recollision experiment is not hard-sphere dynamics (md/blast_config.hpp): not the paper's MD.
  const common::Json::json_pointer recollide("/impurities/recollide");
  if (scene.is_object() && scene.contains(recollide) && scene.at(recollide) != true)
    return "impurities.recollide is " + scene.at(recollide).dump() + ", the paper scene's true";
  return {};
}
}  // namespace

void check_paper_md_run(const fs::path& directory) {
  RunData run;
  try {
    run = read_run(directory);
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument(std::string("--md-run: ") + e.what());
  }
  if (is_tracer_run(run))
    throw std::invalid_argument("--md-run = " + directory.string() +
                                " is a tracer run; it must be an MD run (coldblast md run)");
  // Table 1 and the tracer step (which runs the embedded paper scene) compare the paper's 2D scene.
  const std::string difference = paper_scene_difference(run.summary.value("scene", common::Json::object()));
  if (!difference.empty())
    throw std::invalid_argument("--md-run = " + directory.string() + " is not a run of the paper's 2D scene: its " +
                                difference +
                                " (reproduce compares scenes/paper-2d.toml; coldblast compare judges other runs)");
}

namespace {

void say(const ReproduceProgress& progress, const std::string& line) {
  if (progress) progress(line);
}

common::Json hydro_json(const hydro::NavierStokesResult& result) {
  return {{"d", result.config.physics.d},
          {"R_over_lambda", result.final_exponents().R_over_lambda},
          {"exponents", hydro::exponents_json(result)},
          {"energy_error", result.max_energy_error},
          {"wall_seconds", result.statistics.wall_seconds}};
}

/// Step 1: A_2, A_3 (Eq. (1), ideal gas) and A_2 at the MD's packing fraction, into r and tvns.json.
void tvns_step(const ReproduceConfig& config, const md::BlastConfig& scene, ReproduceResult& r) {
  const hydro::TvnsSolution a2 = hydro::solve_tvns({2, 0.0, hydro::Eos::ideal, 0.0, 1e-13});
  const hydro::TvnsSolution a3 = hydro::solve_tvns({3, 0.0, hydro::Eos::ideal, 0.0, 1e-13});
  r.phi_md = theory::packing_fraction(scene.d, scene.n, scene.a);
  // the amplitude of hydro::md_amplitude, reported with its error (step 2's box takes it from there)
  const hydro::TvnsSolution a2_md = hydro::solve_tvns_for_md(2, r.phi_md);
  r.A2 = a2.A();
  r.A2_error = a2.A_error();
  r.A3 = a3.A();
  r.A3_error = a3.A_error();
  r.A2_md = a2_md.A();
  r.A2_md_error = a2_md.A_error();
  const common::Json tvns{{"A_2", r.A2},
                          {"A_2_error", r.A2_error},
                          {"A_3", r.A3},
                          {"A_3_error", r.A3_error},
                          {"phi_md", r.phi_md},
                          {"A_2_phi_md", r.A2_md},
                          {"A_2_phi_md_error", r.A2_md_error}};
  common::write_file_atomic(config.out / "tvns.json", tvns.dump(2) + "\n");
}

/// A (done, total) callback of a step's workers that says "  LABEL: done/total UNIT" about `lines`
/// times in all and at the end.
std::function<void(long long, long long)> count_lines(const ReproduceProgress& progress, const std::string& label,
                                                      const std::string& unit, long long lines) {
  return [&progress, label, unit, lines](long long done, long long total) {
    if (progress && (done % std::max<long long>(1, total / lines) == 0 || done == total))
      progress("  " + label + ": " + std::to_string(done) + "/" + std::to_string(total) + " " + unit);
  };
}

/// --threads, 0 resolved to every hardware thread (the MD's and the tracer's workers).
int worker_threads(const ReproduceConfig& config) {
  return config.threads > 0 ? config.threads : static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
}

/// Step 2: the paper scene's MD ensemble (as `coldblast md run`, bit for bit) into out/md, or the
/// given --md-run; r.md is its summary. Returns the run's folder.
fs::path md_step(const ReproduceConfig& config, md::BlastConfig scene, const ReproduceProgress& progress,
                 ReproduceResult& r) {
  if (!config.md_run.empty()) {
    say(progress, "step 2/6: MD ensemble taken from " + config.md_run.string());
    r.md = read_run(config.md_run).summary;
    return config.md_run;
  }
  say(progress, "step 2/6: MD ensemble of the paper's 2D scene");
  scene.seed = static_cast<std::uint64_t>(config.seed);
  scene.realizations =
      config.realizations > 0 ? config.realizations : (config.scale == ReproduceScale::quick ? 384 : 30000);
  scene.block_size = static_cast<int>(std::max<long long>(1, scene.realizations / 64));
  run::RunOptions options;
  options.threads = worker_threads(config);
  options.progress = count_lines(progress, "md", "realizations", 20);
  const run::BlastResult blast = run::run_blast(scene, options);
  const fs::path md_dir = config.out / "md";
  run::write_blast_outputs(blast, md_dir);
  r.md = run::blast_summary(blast);
  return md_dir;
}

/// Step 4: the impurity from kinetic theory, Eq. (36) [LB-full]: `coldblast tracer` of the paper
/// scene in the dense Navier–Stokes background (Enskog χ at contact, the MD's φ; the model of
/// step 3), the MD's kick, into out/tracer. r.tracer is its summary. Returns the run's folder.
fs::path tracer_step(const ReproduceConfig& config, const ReproduceProgress& progress, ReproduceResult& r) {
  kinetic::TracerConfig tracer;
  run::SceneRequest scene;
  scene.text = paper_scene_toml;
  scene.md_snapshots = false;  // the tracer records no particles
  tracer.scene = run::load_scene(scene);
  tracer.scene.seed = static_cast<std::uint64_t>(config.seed);
  tracer.background = "ns";
  tracer.transport = "enskog";
  tracer.trajectories = config.tracer_trajectories > 0 ? config.tracer_trajectories
                                                       : (config.scale == ReproduceScale::quick ? 100000 : 1000000);
  tracer.threads = worker_threads(config);
  say(progress, "step 4/6: the impurity from kinetic theory (paper Eq. (36)): " + std::to_string(tracer.trajectories) +
                    " tracer trajectories in the dense Navier–Stokes background");
  run::TracerProgress tracer_progress;
  tracer_progress.blocks = count_lines(progress, "tracer", "blocks", 10);
  const run::TracerResult result = run::run_tracer(tracer, tracer_progress);
  const fs::path tracer_dir = config.out / "tracer";
  run::write_tracer_outputs(result, tracer_dir);
  r.tracer = run::tracer_summary(result);
  r.tracer.erase("scene_toml");
  return tracer_dir;
}
}  // namespace

ReproduceResult run_reproduce(const ReproduceConfig& config, const ReproduceProgress& progress) {
  config.validate();
  ReproduceResult r;
  r.out = config.out;
  fs::create_directories(config.out);

  say(progress, "step 1/6: exact TvNS amplitudes A_2, A_3 and A_2 at the MD's packing fraction");
  const md::BlastConfig scene = run::parse_scene(paper_scene_toml, {}, "scenes/paper-2d.toml");
  tvns_step(config, scene, r);
  const fs::path md_dir = md_step(config, scene, progress, r);

  // One continuum solve serves the NS exponent table, the hydro verdicts and all three reports' figures.
  const RunData run = read_run(md_dir);
  const HydroModel model = with_run_start(resolve_hydro_model({}, run.d, run_packing_fraction(run)), run);
  const double until =
      config.hydro_until > 0 ? config.hydro_until : (config.scale == ReproduceScale::quick ? 1e4 : 1e6);
  say(progress, "step 3/6: Navier–Stokes blast, " + model.describe() +
                    ", at the MD's R/lambda and up to R/lambda = " + common::format_number(until));
  std::string solving;
  const auto continuum = solve_continuum(
      run, model, hydro::default_core_cells, until,
      [&](const std::string& solve, double) {
        if (solve != solving) say(progress, "  Navier–Stokes " + solve);
        solving = solve;
      },
      /*history=*/true);
  r.hydro = hydro_json(continuum->ns);
  r.hydro["model"] = model.describe();
  common::write_file_atomic(config.out / "hydro" / "core.json", r.hydro.dump(2) + "\n");
  const fs::path tracer_dir = tracer_step(config, progress, r);

  say(progress,
      "step 5/6: comparisons against theory, the paper's Table 1, the Navier–Stokes prediction and (the tracer) the "
      "MD");
  CompareConfig compare_config;
  compare_config.run_dir = md_dir;
  compare_config.against = Reference::theory;
  r.against_theory = run_compare(compare_config, continuum);
  compare_config.against = Reference::paper;
  r.against_paper = run_compare(compare_config);
  r.against_paper.continuum = continuum;
  compare_config.against = Reference::hydro;
  r.against_hydro = run_compare(compare_config, continuum);
  CompareConfig tracer_config;
  tracer_config.run_dir = tracer_dir;
  tracer_config.against = Reference::theory;
  tracer_config.md_run = md_dir;
  r.tracer_vs_md = run_compare(tracer_config, continuum);  // the same scene: the MD run's continuum

  say(progress, "step 6/6: reports");
  write_report(r.against_theory, {config.out / "report-theory", config.figures});
  // The same MD run's Fig. 1 in each report: drawn once (its PDF alone takes gnuplot 15 s).
  const fs::path drawn = config.out / "report-theory" / "figures";
  write_report(r.against_paper, {config.out / "report-paper", config.figures}, drawn);
  write_report(r.against_hydro, {config.out / "report-hydro", config.figures}, drawn);
  write_report(r.tracer_vs_md, {config.out / "report-tracer", config.figures});
  common::write_file_atomic(config.out / "REPORT.md", reproduce_markdown(r, config.figures));
  common::write_file_atomic(config.out / "table1.md", table1_markdown(r));
  common::write_file_atomic(config.out / "summary.json", reproduce_summary(r).dump(2) + "\n");
  return r;
}

}  // namespace coldblast::compare
