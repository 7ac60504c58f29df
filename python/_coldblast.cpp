// _coldblast: the pybind11 extension under the Python package `coldblast` (python/coldblast/).
// It calls the library functions the CLI calls (no second implementation): theory exponents, the
// exact TvNS solution, the Navier–Stokes core, MD ensembles, the kinetic tracer, run-directory
// reading and the verdicts. Long work runs on a worker thread with the GIL released while the calling thread polls
// for Ctrl-C every 0.1 s (common/interrupt.hpp stops the work between units) and reports progress.
// std::invalid_argument becomes ValueError with the CLI's message (pybind11's translation).
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <atomic>
#include <chrono>
#include <csignal>
#include <filesystem>
#include <functional>
#include <future>
#include <map>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include "common/input.hpp"
#include "common/interrupt.hpp"
#include "common/output.hpp"
#include "common/validate.hpp"
#include "compare/report.hpp"
#include "compare/reproduce.hpp"
#include "compare/reproduce_report.hpp"
#include "compare/run_data.hpp"
#include "compare/verdict.hpp"
#include "hydro/options.hpp"
#include "hydro/result_files.hpp"
#include "kinetic/tracer_config.hpp"
#include "run/ensemble.hpp"
#include "run/impurity_states.hpp"
#include "run/md_fields.hpp"
#include "run/md_run.hpp"
#include "run/run_directory.hpp"
#include "run/scene_file.hpp"
#include "run/snapshot_files.hpp"
#include "run/tracer_files.hpp"
#include "run/tracer_run.hpp"
#include "theory/computed_prefactors.hpp"
#include "theory/exponents.hpp"

namespace py = pybind11;
using namespace coldblast;

namespace {

// ---- running long work: GIL released, Ctrl-C polled, progress reported --------------------------

/// Progress shared between the worker (writes) and the polling thread (reads, calls Python).
class Progress {
 public:
  explicit Progress(py::object callback) : callback_(std::move(callback)) {}
  void set(double done, double total) {
    total_.store(total);
    done_.store(done);
  }
  /// With the GIL: calls callback(done, total) when the progress moved.
  void report() {
    if (callback_.is_none()) return;
    const double done = done_.load(), total = total_.load();
    if (done == reported_) return;
    reported_ = done;
    callback_(done, total);
  }

 private:
  py::object callback_;
  std::atomic<double> done_{-1.0}, total_{0.0};
  double reported_ = -1.0;
};

/// Text progress: lines from the worker, handed to callback(line) by the polling thread.
class LineProgress {
 public:
  explicit LineProgress(py::object callback) : callback_(std::move(callback)) {}
  void push(const std::string& line) {
    const std::lock_guard<std::mutex> lock(mutex_);
    pending_.push_back(line);
  }
  /// With the GIL: calls callback(line) for each line pushed since the last report.
  void report() {
    std::vector<std::string> lines;
    {
      const std::lock_guard<std::mutex> lock(mutex_);
      lines.swap(pending_);
    }
    if (callback_.is_none()) return;
    for (const std::string& line : lines) callback_(line);
  }

 private:
  py::object callback_;
  std::mutex mutex_;
  std::vector<std::string> pending_;
};

/// Runs `work` on a worker thread; the calling thread (holding the GIL between polls) checks for
/// pending Python signals every 0.1 s. On KeyboardInterrupt (or an exception from the progress
/// callback) it requests a stop, waits for the worker to leave at its next check, and re-raises.
template <class Result, class ProgressReport>
Result run_interruptible(const std::function<Result()>& work, ProgressReport& progress) {
  common::clear_stop();
  std::future<Result> future = std::async(std::launch::async, work);
  const auto stop_and_wait = [&future] {
    common::request_stop(SIGINT);
    {
      py::gil_scoped_release release;
      future.wait();
    }
    common::clear_stop();
  };
  for (;;) {
    std::future_status status;
    {
      py::gil_scoped_release release;
      status = future.wait_for(std::chrono::milliseconds(100));
    }
    try {
      progress.report();
    } catch (...) {
      stop_and_wait();
      throw;
    }
    if (status == std::future_status::ready) break;
    if (PyErr_CheckSignals() != 0) {
      py::error_already_set error;  // takes the pending KeyboardInterrupt
      stop_and_wait();
      throw error;
    }
  }
  return future.get();  // rethrows the library's exceptions
}

// ---- conversions ------------------------------------------------------------------------------

py::array_t<double> array(const std::vector<double>& values) {
  py::array_t<double> out(static_cast<py::ssize_t>(values.size()));
  std::copy(values.begin(), values.end(), out.mutable_data());
  return out;
}

template <class T, class Getter>
py::array_t<double> column(const std::vector<T>& rows, Getter get) {
  py::array_t<double> out(static_cast<py::ssize_t>(rows.size()));
  double* data = out.mutable_data();
  for (std::size_t i = 0; i < rows.size(); ++i) data[i] = get(rows[i]);
  return out;
}

py::tuple fraction(const theory::Rational& value) {
  return py::make_tuple(value.numerator(), value.denominator());
}

py::object json_to_python(const common::Json& document) {
  return py::module_::import("json").attr("loads")(document.dump());
}

// ---- theory -----------------------------------------------------------------------------------

/// theory::computed_prefactors(d) as a list of dicts, each with its source's command and trajectories.
py::list theory_computed_prefactors(int d) {
  common::require_integer_in_range("--d", d, theory::min_dimension, theory::max_dimension);
  py::list out;
  for (const theory::ComputedPrefactor& p : theory::computed_prefactors(d)) {
    const theory::PrefactorSource& s = theory::prefactor_sources().at(static_cast<std::size_t>(p.source));
    py::dict row;
    row["observable"] = p.observable;
    row["t"] = p.t;
    row["R_over_lambda"] = p.R_over_lambda;
    row["value"] = p.value;
    row["error"] = p.error;
    row["source"] = p.source;
    row["command"] = s.command;
    row["trajectories"] = s.trajectories;
    out.append(row);
  }
  return out;
}

py::dict theory_exponents(int d) {
  common::require_integer_in_range("--d", d, theory::min_dimension, theory::max_dimension);
  const theory::ScalingExponents s = theory::scaling_exponents(d);
  const theory::ConvectionDiffusionExponents c = theory::convection_diffusion_exponents(d);
  py::dict in_time, in_R;
  for (const auto& [name, e] : s.named()) {
    in_time[py::str(name)] = fraction(e.in_time);
    in_R[py::str(name)] = fraction(e.in_R_over_lambda);
  }
  py::dict convection;
  convection["drift"] = fraction(c.drift);
  convection["diffusion"] = fraction(c.diffusion);
  convection["spread"] = fraction(c.spread);
  convection["density"] = fraction(c.density);
  convection["gaussian_coefficient"] = fraction(c.gaussian_coefficient);
  py::dict out;
  out["d"] = d;
  out["pathological"] = s.pathological;
  out["h_d"] = fraction(s.h_d);
  out["omega_d"] = fraction(s.omega_d);
  out["in_time"] = in_time;
  out["in_R_over_lambda"] = in_R;
  out["convection_diffusion"] = convection;
  return out;
}

// ---- TvNS -------------------------------------------------------------------------------------

const char* case_name(hydro::TvnsCase c) {
  return c == hydro::TvnsCase::standard ? "standard" : c == hydro::TvnsCase::singular ? "singular" : "vacuum";
}

py::dict tvns_profile(const hydro::TvnsSolution& s,
                      const py::array_t<double, py::array::c_style | py::array::forcecast>& x) {
  std::vector<double> xs(x.data(), x.data() + x.size());
  std::vector<hydro::TvnsPoint> points;
  {
    py::gil_scoped_release release;
    points = s.profile(xs);
  }
  std::vector<py::ssize_t> shape(x.shape(), x.shape() + x.ndim());
  py::dict out;
  const auto field = [&](double hydro::TvnsPoint::*member) {
    py::array_t<double> a(shape);
    double* data = a.mutable_data();
    for (std::size_t i = 0; i < points.size(); ++i) data[i] = points[i].*member;
    return a;
  };
  out["r_over_R"] = field(&hydro::TvnsPoint::r_over_R);
  out["density"] = field(&hydro::TvnsPoint::density);
  out["velocity"] = field(&hydro::TvnsPoint::velocity);
  out["pressure"] = field(&hydro::TvnsPoint::pressure);
  out["temperature"] = field(&hydro::TvnsPoint::temperature);
  return out;
}

// ---- hydro ------------------------------------------------------------------------------------

/// A result table (hydro/result_files.hpp) as {column: float64 array}.
py::dict table_dict(const hydro::Table& table) {
  py::dict columns;
  for (const hydro::Column& c : table) columns[py::str(c.name)] = array(c.values);
  return columns;
}

/// The result's one schema (hydro/result_files.hpp): the summary the CLI prints as JSON, and the
/// tables of its files as arrays; python/coldblast/hydro.py makes the attributes from them.
py::dict hydro_result(const hydro::NavierStokesResult& r) {
  py::list profiles;
  for (const hydro::NavierStokesProfile& p : r.profiles) {
    py::dict profile = table_dict(hydro::profile_table(p));
    profile["t"] = p.t;
    profile["R"] = p.R;
    profiles.append(profile);
  }
  py::dict out;
  out["summary"] = json_to_python(hydro::result_summary(r));
  out["samples"] = table_dict(hydro::sample_table(r));
  out["exponents"] = table_dict(hydro::exponent_table(r));
  out["profiles"] = profiles;
  return out;
}

py::dict hydro_run(bool euler, int d, double until, int cells, bool viscosity, std::optional<double> kappa_prefactor,
                   const std::string& eos, double phi, const std::string& transport, const std::string& start,
                   double r0, const py::object& progress_callback) {
  hydro::HydroOptions options{d, until, cells, viscosity, kappa_prefactor, eos, phi, transport};
  options.start = start;
  options.r0 = r0;
  const hydro::NavierStokesConfig config = hydro::navier_stokes_config(options, euler);
  Progress progress(progress_callback);
  const std::function<hydro::NavierStokesResult()> work = [&] {
    return hydro::run_navier_stokes(config, [&](const hydro::NavierStokesSample& s) {
      progress.set(s.R_over_lambda, config.until_R_over_lambda);
      common::throw_if_stop_requested();  // Ctrl-C: leave the integrator (its handles are RAII)
    });
  };
  return hydro_result(run_interruptible(work, progress));
}

// ---- MD ---------------------------------------------------------------------------------------

/// A run's files as the run directory holds them (run::blast_files, run::tracer_files): [(name, text)],
/// in writing order. python/coldblast/_run.py parses them exactly as it parses the files on disk, so
/// md.run, tracer.run and read_run return the same object.
py::list file_list(const run::NamedFiles& files) {
  py::list list;
  for (const auto& [name, content] : files) list.append(py::make_tuple(name, py::bytes(content)));
  return list;
}

/// md run's and md states' scene and ensemble arguments (run/md_run.hpp).
run::MdRunRequest md_request(const std::string& scene_file, const std::string& scene_text,
                             const std::vector<std::string>& overrides, std::optional<long long> realizations,
                             std::optional<long long> seed, int threads) {
  run::MdRunRequest request;
  request.scene_file = scene_file;
  request.scene_text = scene_text;
  request.overrides = overrides;
  request.realizations = realizations;
  request.seed = seed;
  request.threads = threads;
  return request;
}

py::list md_run(const std::string& scene_file, const std::string& scene_text, const std::vector<std::string>& overrides,
                std::optional<long long> realizations, std::optional<long long> seed, int threads,
                const std::string& out, bool resume, bool overwrite, double save_every,
                const py::object& progress_callback) {
  if (!out.empty()) common::require_output_folder(out, resume ? "--resume" : "--out");
  run::MdRunRequest request = md_request(scene_file, scene_text, overrides, realizations, seed, threads);
  request.save_every = save_every;
  // As `md run --out DIR`: every finished realization is checkpointed in DIR/checkpoint until the
  // outputs are written (an interrupted run keeps them; resume=DIR or `coldblast md run --resume
  // DIR` continues).
  request.out = out;
  request.resume = resume;
  request.overwrite = overwrite;
  request.resume_hint = "coldblast.md.run(resume=\"" + out + "\")";
  run::MdRunPlan plan = run::plan_md_run(request);
  run::RunOptions& options = plan.options;
  if (const std::string warning = run::snapshot_size_warning(run::resolve_blast_scene(plan.config)); !warning.empty())
    py::module_::import("sys").attr("stderr").attr("write")("md.run: " + warning + "\n");
  Progress progress(progress_callback);
  options.progress = [&progress](long long done, long long total) {
    progress.set(static_cast<double>(done), static_cast<double>(total));
  };
  const std::function<run::BlastResult()> work = [&] { return run::run_blast(plan.config, options); };
  run::BlastResult result = run_interruptible(work, progress);
  if (!out.empty()) run::finish_md_run(result, out);
  return file_list(run::blast_files(result));
}

/// md states: the impurities at time t of every realization (run/impurity_states.hpp), as numpy arrays; with
/// `out`, also out/impurity_states.csv (for tracer --start states).
py::dict md_states(const std::string& scene_file, const std::string& scene_text,
                   const std::vector<std::string>& overrides, std::optional<long long> realizations,
                   std::optional<long long> seed, int threads, double time, const std::string& out, bool overwrite,
                   const py::object& progress_callback) {
  if (!out.empty()) {
    common::require_output_folder(out, "--out");
    run::claim_output_folder(out, "--out", overwrite, "coldblast.md.run(resume=\"" + out + "\")");
  }
  const run::MdRunPlan plan =
      run::plan_md_run(md_request(scene_file, scene_text, overrides, realizations, seed, threads));
  const md::ResolvedScene scene = run::resolve_blast_scene(plan.config);
  Progress progress(progress_callback);
  const std::function<std::vector<md::ImpurityState>()> work = [&] {
    return run::impurity_states(
        scene, time, plan.config.realizations, threads,
        [&progress](long long done, long long n) { progress.set(static_cast<double>(done), static_cast<double>(n)); });
  };
  const std::vector<md::ImpurityState> states = run_interruptible(work, progress);
  if (!out.empty()) run::write_impurity_states(out, states, plan.config, time);
  const int d = plan.config.d;
  const auto matrix = [&](auto member) {
    py::array_t<double> a({static_cast<py::ssize_t>(states.size()), static_cast<py::ssize_t>(d)});
    auto view = a.mutable_unchecked<2>();
    for (std::size_t i = 0; i < states.size(); ++i)
      for (int k = 0; k < d; ++k)
        view(static_cast<py::ssize_t>(i), k) = (states[i].*member)[static_cast<std::size_t>(k)];
    return a;
  };
  py::dict output;
  output["t"] = time;
  output["realization"] = column(states, [](const md::ImpurityState& s) { return static_cast<double>(s.realization); });
  output["impurity"] = column(states, [](const md::ImpurityState& s) { return static_cast<double>(s.impurity); });
  output["collisions"] = column(states, [](const md::ImpurityState& s) { return static_cast<double>(s.collisions); });
  output["r"] = matrix(&md::ImpurityState::r);
  output["v"] = matrix(&md::ImpurityState::v);
  output["r0"] = matrix(&md::ImpurityState::r0);
  return output;
}

// ---- kinetic tracer ---------------------------------------------------------------------------

/// The tracer's options beyond the scene (as `coldblast tracer`'s flags).
struct TracerOptions {
  std::string background, transport, start;
  long long trajectories = 0;
  int threads = 1;
  double T = 1.0;
  std::optional<double> phi;
  double start_time = 0.0;
  int frames_per_decade = 40, cells = hydro::default_core_cells;
  std::string start_states;
  std::string kernel = "auto";
  std::string md_run;
  double r0 = 0.0;
};

py::list tracer_run(const std::string& scene_file, const std::string& scene_text, std::vector<std::string> overrides,
                    std::optional<long long> seed, const TracerOptions& o, const std::string& out, bool resume,
                    bool overwrite, const std::vector<std::string>& given, const py::object& progress_callback) {
  if (!out.empty()) common::require_output_folder(out, resume ? "--resume" : "--out");
  run::SceneRequest scene;
  scene.file = scene_file;
  scene.text = scene_text;
  // background="md" without a scene: the MD run's own (as `tracer --background md --md-run DIR`).
  if (o.background == "md" && scene_file.empty() && scene_text.empty() && !o.md_run.empty())
    scene.text = run::md_run_scene_toml(o.md_run, "--md-run");
  scene.overrides = std::move(overrides);
  scene.seed = seed;
  scene.md_snapshots = false;  // the tracer records no particles
  kinetic::TracerConfig config;
  config.scene = run::load_scene(scene);
  config.background = o.background;
  config.transport = o.transport;
  config.start = o.start;
  config.r0 = o.r0;
  config.trajectories = o.trajectories;
  config.threads = o.threads;
  config.T = o.T;
  config.phi = o.phi;
  config.start_time = o.start_time;
  config.start_states = o.start_states;
  config.frames_per_decade = o.frames_per_decade;
  config.cells = o.cells;
  config.kernel = o.kernel;
  config.md_run = o.md_run;
  // resume=OUT: the checkpoint's scene and options; an argument given again must agree with them.
  if (resume) config = run::resume_tracer_config(out, config, given);
  Progress progress(progress_callback);
  const std::function<run::TracerResult()> work = [&] {
    run::TracerProgress report;
    report.blocks = [&progress](long long done, long long total) {
      progress.set(static_cast<double>(done), static_cast<double>(total));
    };
    // As `tracer --out DIR`: every finished block is checkpointed in DIR/checkpoint.
    const run::TracerRunFiles files{out, "--out", resume, overwrite, "coldblast.tracer.run(resume=\"" + out + "\")"};
    return run::run_tracer(config, report, files);
  };
  const run::TracerResult result = run_interruptible(work, progress);
  if (!out.empty()) run::finish_tracer_run(result, out);
  return file_list(run::tracer_files(result));
}

// ---- run directories and verdicts ---------------------------------------------------------------

py::object read_run_summary(const std::string& directory) {
  return json_to_python(compare::read_run(directory).summary);
}

py::object compare_run(const std::string& run_dir, const std::string& against, double sigma,
                       std::optional<double> allowance, double window_decades, double until,
                       const std::vector<std::string>& observables, int hydro_cells, const std::string& hydro_eos,
                       std::optional<double> hydro_phi, const std::string& hydro_transport,
                       std::optional<bool> hydro_viscosity, const std::string& md_run, const std::string& out,
                       bool figures, const py::object& progress_callback) {
  if (!out.empty()) compare::report_folder(out);
  compare::CompareConfig config;
  config.run_dir = run_dir;
  config.against = compare::parse_reference(against);
  config.sigma = sigma;
  config.allowance = allowance;
  config.window_decades = window_decades;
  config.until = until;
  config.observables = observables;
  config.hydro_cells = hydro_cells;
  if (!hydro_eos.empty()) config.hydro_model.eos = hydro::eos_from_string(hydro_eos, "--hydro-eos");
  if (!hydro_transport.empty())
    config.hydro_model.transport = hydro::transport_from_string(hydro_transport, "--hydro-transport");
  if (hydro_phi) config.hydro_model.phi = *hydro_phi;
  if (hydro_viscosity) config.hydro_model.viscosity = *hydro_viscosity;
  config.md_run = md_run;
  config.continuum_for_figures = !out.empty() && figures;
  Progress progress(progress_callback);
  const std::function<compare::CompareResult()> work = [&] {
    compare::CompareResult result = compare::run_compare(config);
    if (!out.empty()) compare::write_report(result, {out, figures});
    return result;
  };
  return json_to_python(compare::verdict_json(run_interruptible(work, progress)));
}

// ---- reproduce --------------------------------------------------------------------------------

py::object reproduce(const std::string& scale, const std::string& out, int threads, long long seed,
                     long long realizations, double hydro_until, const std::string& md_run,
                     long long tracer_trajectories, bool figures, const py::object& progress_callback) {
  compare::ReproduceConfig config;
  config.scale = compare::parse_scale(scale);
  config.out = out;
  config.threads = threads;
  config.seed = seed;
  config.realizations = realizations;
  config.hydro_until = hydro_until;
  config.md_run = md_run;
  config.tracer_trajectories = tracer_trajectories;
  config.figures = figures;
  config.validate();  // bad input raises before the worker starts
  LineProgress progress(progress_callback);
  const std::function<compare::ReproduceResult()> work = [&] {
    return compare::run_reproduce(config, [&progress](const std::string& line) { progress.push(line); });
  };
  return json_to_python(compare::reproduce_summary(run_interruptible(work, progress)));
}

/// Interrupted (SIGINT in a run) reaches Python as KeyboardInterrupt.
void bind_errors() {
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const common::Interrupted&) {
      PyErr_SetNone(PyExc_KeyboardInterrupt);
    }
  });
}

/// coldblast theory: the exact exponents and the prefactors.
void bind_theory(py::module_& m) {
  m.def("theory_exponents", &theory_exponents, py::arg("d"));
  m.def("theory_computed_prefactors", &theory_computed_prefactors, py::arg("d"));
}

/// The TvNS solution and the Navier–Stokes and Euler runs.
void bind_hydro(py::module_& m) {
  py::class_<hydro::TvnsSolution>(m, "TvnsSolution")
      .def_property_readonly("d", [](const hydro::TvnsSolution& s) { return s.config().d; })
      .def_property_readonly("eos", [](const hydro::TvnsSolution& s) { return hydro::to_string(s.config().eos); })
      .def_property_readonly("phi", [](const hydro::TvnsSolution& s) { return s.config().phi; })
      .def_property_readonly("tolerance", [](const hydro::TvnsSolution& s) { return s.config().tolerance; })
      .def_property_readonly("gamma", &hydro::TvnsSolution::gamma)
      .def_property_readonly("A", &hydro::TvnsSolution::A)
      .def_property_readonly("A_error", &hydro::TvnsSolution::A_error)
      .def_property_readonly("method_agreement", &hydro::TvnsSolution::method_agreement)
      .def_property_readonly("A_closed_form", &hydro::TvnsSolution::A_closed_form)
      .def_property_readonly("A_ode", &hydro::TvnsSolution::A_ode)
      .def_property_readonly("case", [](const hydro::TvnsSolution& s) { return case_name(s.solution_case()); })
      .def_property_readonly("shock_compression", &hydro::TvnsSolution::shock_compression)
      .def_property_readonly("shock_packing_fraction", &hydro::TvnsSolution::shock_packing_fraction)
      .def_property_readonly("cavity_radius", &hydro::TvnsSolution::cavity_radius)
      .def_property_readonly("density_exponent", &hydro::TvnsSolution::density_exponent)
      .def_property_readonly("temperature_exponent", &hydro::TvnsSolution::temperature_exponent)
      .def("profile", &tvns_profile, py::arg("r_over_R"));
  m.def(
      "tvns_solve",
      [](int d, double gamma, const std::string& eos, double phi, double tolerance) {
        const hydro::TvnsConfig config = hydro::tvns_config({d, gamma, eos, phi, tolerance});
        py::gil_scoped_release release;
        return hydro::solve_tvns(config);
      },
      py::arg("d"), py::arg("gamma"), py::arg("eos"), py::arg("phi"), py::arg("tolerance"));

  m.def("hydro_run", &hydro_run, py::arg("euler"), py::arg("d"), py::arg("until"), py::arg("cells"),
        py::arg("viscosity"), py::arg("kappa_prefactor"), py::arg("eos"), py::arg("phi"), py::arg("transport"),
        py::arg("start"), py::arg("r0"), py::arg("progress"));
  m.attr("default_core_cells") = hydro::default_core_cells;
  m.attr("default_euler_cells") = hydro::default_euler_cells;
}

/// MD runs, impurity states, the default scene and run summaries.
void bind_md(py::module_& m) {
  m.def("md_run", &md_run, py::arg("scene_file"), py::arg("scene_text"), py::arg("overrides"), py::arg("realizations"),
        py::arg("seed"), py::arg("threads"), py::arg("out"), py::arg("resume"), py::arg("overwrite"),
        py::arg("save_every"), py::arg("progress"));
  m.def("md_states", &md_states, py::arg("scene_file"), py::arg("scene_text"), py::arg("overrides"),
        py::arg("realizations"), py::arg("seed"), py::arg("threads"), py::arg("time"), py::arg("out"),
        py::arg("overwrite"), py::arg("progress"));
  m.def("default_scene_toml", [] { return run::default_scene_toml(); });
  m.def("read_run_summary", &read_run_summary, py::arg("directory"));
}

/// compare and reproduce.
void bind_compare(py::module_& m) {
  m.def("compare", &compare_run, py::arg("run_dir"), py::arg("against"), py::arg("sigma"), py::arg("allowance"),
        py::arg("window_decades"), py::arg("until"), py::arg("observables"), py::arg("hydro_cells"),
        py::arg("hydro_eos"), py::arg("hydro_phi"), py::arg("hydro_transport"), py::arg("hydro_viscosity"),
        py::arg("md_run"), py::arg("out"), py::arg("figures"), py::arg("progress"));
  m.def("reproduce", &reproduce, py::arg("scale"), py::arg("out"), py::arg("threads"), py::arg("seed"),
        py::arg("realizations"), py::arg("hydro_until"), py::arg("md_run"), py::arg("tracer_trajectories"),
        py::arg("figures"), py::arg("progress"));
}

/// The kinetic tracer.
void bind_tracer(py::module_& m) {
  m.def(
      "tracer_run",
      [](const std::string& scene_file, const std::string& scene_text, const std::vector<std::string>& overrides,
         std::optional<long long> seed, const std::string& background, const std::string& transport,
         const std::string& start, long long trajectories, int threads, double T, std::optional<double> phi,
         double start_time, int frames_per_decade, int cells, const std::string& start_states,
         const std::string& kernel, const std::string& md_run, double r0, const std::string& out, bool resume,
         bool overwrite, const std::vector<std::string>& given, const py::object& progress) {
        const TracerOptions options{background, transport,         start, trajectories, threads, T,      phi,
                                    start_time, frames_per_decade, cells, start_states, kernel,  md_run, r0};
        return tracer_run(scene_file, scene_text, overrides, seed, options, out, resume, overwrite, given, progress);
      },
      py::arg("scene_file"), py::arg("scene_text"), py::arg("overrides"), py::arg("seed"), py::arg("background"),
      py::arg("transport"), py::arg("start"), py::arg("trajectories"), py::arg("threads"), py::arg("T"), py::arg("phi"),
      py::arg("start_time"), py::arg("frames_per_decade"), py::arg("cells"), py::arg("start_states"), py::arg("kernel"),
      py::arg("md_run"), py::arg("r0"), py::arg("out"), py::arg("resume"), py::arg("overwrite"), py::arg("given"),
      py::arg("progress"));
}

}  // namespace

PYBIND11_MODULE(_coldblast, m) {
  m.doc() = "coldblast's C++ library (use the `coldblast` package, not this module directly)";
  bind_errors();
  bind_theory(m);
  bind_hydro(m);
  bind_md(m);
  bind_compare(m);
  bind_tracer(m);
}
