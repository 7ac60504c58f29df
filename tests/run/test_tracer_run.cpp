// run_tracer: bit-identical ensembles for any thread count and sharding, the equilibrium summary
// (collision rate against the exact value), the run directory, and bad input naming the option.
#include <catch2/catch.hpp>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <vector>

#include "common/output.hpp"
#include "kinetic/batch.hpp"
#include "kinetic/kinetic_theory.hpp"
#include "kinetic/tracer_config.hpp"
#include "kinetic/tracer_statistics.hpp"
#include "run/ensemble.hpp"
#include "run/impurity_states.hpp"
#include "run/run_files.hpp"
#include "run/scene_file.hpp"
#include "run/tracer_files.hpp"
#include "run/tracer_run.hpp"
#include "tests/temp_path.hpp"

using namespace coldblast::kinetic;
using namespace coldblast::run;

namespace {
TracerConfig small_config(const std::string& background) {
  TracerConfig c;
  c.scene = parse_scene(default_scene_toml());
  c.scene.t_max = 100.0;
  c.scene.t_min = 1.0;
  c.background = background;
  c.trajectories = 600;
  c.scene.block_size = 16;
  return c;
}

std::string read(const std::filesystem::path& path) {
  std::ifstream in(path);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}
}  // namespace

TEST_CASE("tracer: equilibrium summary rate equals n chi S ⟨|g|⟩, and T_final the bath's") {
  TracerConfig c = small_config("equilibrium");
  c.start = "thermal";
  c.T = 2.0;
  c.phi = 0.2;
  c.transport = "enskog";
  c.scene.impurities.mass = 3.0;
  c.scene.impurities.radius = 1.0;
  const TracerResult r = run_tracer(c);
  const double exact = r.collision_rate() > 0 ? tracer_summary(r).at("collision_rate_exact").get<double>() : 0.0;
  CHECK(exact == Approx(equilibrium_collision_rate(2, r.n, r.chi, 1.5, 2.0, 3.0)).epsilon(1e-14));
  CHECK(r.chi == Approx(pair_contact_value(2, 0.2, 0.5, 1.0)).epsilon(1e-12));
  CHECK(std::abs(r.collision_rate() - exact) < 4 * r.collision_rate_error());
  CHECK(std::abs(r.temperature_final() - 2.0) < 4 * r.temperature_final_error());
  CHECK(r.trajectories() == 600);
}

TEST_CASE("tracer: the single-host start leaves the impurity at rest near the centre until the blast moves it") {
  // At the start time (the first recording time t_min) every trajectory is at rest where it
  // started: <v^2> and <r^2> (from its start) exactly 0, where the kick's <v^2> is 2E/(k M) on average.
  TracerConfig c = small_config("tvns");
  c.start = "single";
  const TracerResult single = run_tracer(c);
  REQUIRE(single.start_time == c.scene.t_min);
  const auto at_rest = moment_rows(single.ensemble.scene.times, single.blocks).front();
  CHECK(at_rest.t == c.scene.t_min);
  CHECK(at_rest.v2 == 0.0);
  CHECK(at_rest.r2 == 0.0);
  c.start = "kick";
  const TracerResult kick = run_tracer(c);
  CHECK(moment_rows(kick.ensemble.scene.times, kick.blocks).front().v2 > 0.0);
  // The blast picks it up: it collides, and its <v^2> grows from 0.
  CHECK(single.collisions() > 0);
  CHECK(moment_rows(single.ensemble.scene.times, single.blocks).back().v2 > 0.0);
  // In an equilibrium bath it reaches the bath's temperature (equipartition, M <v^2>/d = T).
  c = small_config("equilibrium");
  c.start = "single";
  c.T = 2.0;
  c.phi = 0.2;
  c.scene.impurities.mass = 3.0;
  const TracerResult bath = run_tracer(c);
  CHECK(std::abs(bath.temperature_final() - 2.0) < 4 * bath.temperature_final_error());
}

TEST_CASE("tracer: bit-identical for any thread count and sharding, with every kernel") {
  TracerConfig c = small_config("tvns");
  std::vector<std::string> kernels = batch_kernels();
  kernels.insert(kernels.end(), {"scalar", "auto"});
  c.kernel = GENERATE_COPY(from_range(kernels));
  const TracerResult one = run_tracer(c);
  CHECK(one.kernel == (c.kernel != "auto" ? c.kernel : batch_kernels().empty() ? "scalar" : batch_kernels().front()));
  c.threads = 3;
  const TracerResult three = run_tracer(c);
  REQUIRE(one.ensemble.blocks.size() == three.ensemble.blocks.size());
  for (const auto& [b, s] : one.ensemble.blocks) {
    CHECK(s.sum == three.ensemble.blocks.at(b).sum);
    CHECK(s.sum_squares == three.ensemble.blocks.at(b).sum_squares);
    CHECK(one.blocks.at(b).moments == three.blocks.at(b).moments);
  }
  c.threads = 1;
  c.shard_count = 2;
  for (int shard = 0; shard < 2; ++shard) {
    c.shard_index = shard;
    const TracerResult part = run_tracer(c);
    for (const auto& [b, s] : part.ensemble.blocks) CHECK(s.sum == one.ensemble.blocks.at(b).sum);
  }
  CHECK(one.collisions() > 0);
  CHECK(one.rejection_rate() > 0.0);
  CHECK(one.rejection_rate() < 1.0);
}

TEST_CASE("tracer: the run directory has md run's files and the tracer's summary keys") {
  TracerConfig c = small_config("tvns");
  c.trajectories = 64;
  const TracerResult r = run_tracer(c);
  const auto dir = coldblast::test::unique_temp_path("coldblast-test-tracer-out");
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  write_tracer_outputs(r, dir);
  for (const char* name :
       {"observables.csv", "blocks.csv", "p_imp.csv", "summary.json", "moments.csv", "prefactors.csv"})
    CHECK(std::filesystem::exists(dir / name));
  const auto summary = coldblast::common::Json::parse(read(dir / "summary.json"));
  for (const char* key : {"collision_rate", "collision_rate_error", "chi", "temperature_final", "rejection_rate", "d"})
    CHECK(summary.contains(key));
  CHECK(read(dir / "blocks.csv").find(",R_imp,") != std::string::npos);
  std::filesystem::remove_all(dir);
}

TEST_CASE("tracer: bad input names the option") {
  const auto message = [](TracerConfig c) {
    try {
      c.validate();
    } catch (const std::invalid_argument& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  TracerConfig c = small_config("equilibrium");
  c.background = "plasma";
  CHECK(message(c).find("--background") != std::string::npos);
  c = small_config("equilibrium");
  c.T = 0.0;
  CHECK(message(c).find("--T") != std::string::npos);
  c.T = 1.0;
  c.phi = 0.8;
  CHECK(message(c).find("--phi") != std::string::npos);
  c = small_config("tvns");
  c.transport = "enskog";
  CHECK(message(c).find("--transport") != std::string::npos);
  c = small_config("ns");
  c.scene.t_max = 2.0;  // before the Navier–Stokes start at R/λ = 2: no background solution
  c.scene.t_min = 1.0;
  CHECK_THROWS_WITH(run_tracer(c), Catch::Contains("t_max"));
  c = small_config("ns");
  c.kernel = "simd";
  CHECK(message(c).find("--kernel") != std::string::npos);
  c = small_config("equilibrium");
  c.kernel = "avx512";
  CHECK(message(c).find("--kernel") != std::string::npos);
  c.kernel = "auto";  // the equilibrium background runs the scalar loop
  c.trajectories = 8;
  CHECK(run_tracer(c).kernel == "scalar");
}

TEST_CASE("tracer: every vector kernel and the scalar loop sample the same process (dense NS background)") {
  std::vector<std::string> kernels = batch_kernels();
  if (kernels.empty()) {
    WARN("this CPU (or build) runs no vector kernel: only the scalar loop runs here");
    return;
  }
  const std::string kernel = GENERATE_COPY(from_range(kernels));
  CAPTURE(kernel);
  // Different deviates, so different trajectories: every observable at every recorded time, the
  // collision rate and T_final agree within 4 combined standard errors.
  TracerConfig c = small_config("ns");
  c.transport = "enskog";
  c.scene.t_max = 400.0;
  c.trajectories = 4000;
  c.scene.block_size = 64;
  c.threads = 2;
  c.kernel = "scalar";
  const TracerResult scalar = run_tracer(c);
  c.kernel = kernel;
  const TracerResult vector = run_tracer(c);
  REQUIRE(scalar.kernel == "scalar");
  REQUIRE(vector.kernel == kernel);
  const auto z = [](double a, double ea, double b, double eb) { return std::abs(a - b) / std::hypot(ea, eb); };
  CHECK(z(scalar.collision_rate(), scalar.collision_rate_error(), vector.collision_rate(),
          vector.collision_rate_error()) < 4);
  CHECK(z(scalar.temperature_final(), scalar.temperature_final_error(), vector.temperature_final(),
          vector.temperature_final_error()) < 4);
  const auto a = estimate_observables(scalar.ensemble);
  const auto b = estimate_observables(vector.ensemble);
  REQUIRE(a.size() == b.size());
  int compared = 0;
  for (std::size_t k = 0; k < a.size(); ++k) {
    const auto &x = a[k], &y = b[k];
    REQUIRE(x.observable == y.observable);
    REQUIRE(x.t == y.t);
    if (!(x.stderr_ > 0 || y.stderr_ > 0)) continue;
    INFO(x.observable << " at t = " << x.t << ": " << x.mean << " ± " << x.stderr_ << " vs " << y.mean << " ± "
                      << y.stderr_);
    CHECK(z(x.mean, x.stderr_, y.mean, y.stderr_) < 4);
    ++compared;
  }
  CHECK(compared > 100);
}

TEST_CASE("tracer: --start states starts trajectory i from the MD's impurity state i at the file's time") {
  TracerConfig c = small_config("tvns");
  c.scene.A_d = 0.3;  // sizes the MD's region; not a key the states file checks
  c.scene.realizations = 5;
  const double t0 = 16.0;  // a recording time: t_min 2^(k/4), k = 16
  const auto states = impurity_states(resolve_blast_scene(c.scene), t0, 5, 2);
  REQUIRE(states.size() == 20);
  const auto dir = coldblast::test::unique_temp_path("coldblast_test_tracer_states");
  const auto file = dir / "impurity_states.csv";
  coldblast::common::write_file_atomic(file, impurity_states_csv(states, c.scene, t0, "test-run"));
  c.start = "states";
  c.start_states = file.string();
  c.trajectories = 0;  // one per state
  const TracerResult r = run_tracer(c);
  CHECK(r.trajectories() == 20);
  CHECK(r.start_time == t0);
  CHECK(tracer_summary(r).at("start") == "states");
  // At the start time every observable is the states' own: R_imp from the MD's start positions,
  // C_imp the MD's collisions so far.
  double r2 = 0.0, v2 = 0.0, collisions = 0.0;
  for (const auto& s : states) {
    for (int k = 0; k < 2; ++k) {
      r2 += 0.5 * (s.r[k] - s.r0[k]) * (s.r[k] - s.r0[k]);
      v2 += 0.5 * s.v[k] * s.v[k];
    }
    collisions += static_cast<double>(s.collisions);
  }
  std::map<std::string, std::map<double, double>> mean;
  for (const auto& e : estimate_observables(r.ensemble)) mean[e.observable][e.t] = e.mean;
  CHECK(mean["R_imp"].at(t0) == Approx(std::sqrt(r2 / 20)).epsilon(1e-12));
  CHECK(mean["V_imp"].at(t0) == Approx(std::sqrt(v2 / 20)).epsilon(1e-12));
  CHECK(mean["C_imp"].at(t0) == Approx(collisions / 20).epsilon(1e-12));
  CHECK(mean["C_imp"].at(mean["C_imp"].rbegin()->first) > collisions / 20);  // and it collides on from there
  CHECK(r.collisions() > 0);

  // Bad input: named options, nothing run.
  TracerConfig bad = c;
  bad.trajectories = 21;
  CHECK_THROWS_WITH(run_tracer(bad), Catch::Contains("--trajectories = 21 exceeds the 20 states"));
  bad = c;
  bad.scene.impurities.mass = 10.0;
  CHECK_THROWS_WITH(run_tracer(bad), Catch::Contains("is of another scene: its impurities.mass is 1, 10 here"));
  bad = c;
  bad.scene.t_max = 10.0;
  bad.scene.t_min = 1.0;
  CHECK_THROWS_WITH(run_tracer(bad), Catch::Contains("the time of --start-states"));
  bad = c;
  bad.start_states.clear();
  CHECK_THROWS_WITH(bad.validate(), Catch::Contains("--start = states needs --start-states"));
  bad = c;
  bad.start = "kick";
  CHECK_THROWS_WITH(bad.validate(), Catch::Contains("--start-states is only for --start states"));
  bad = c;
  bad.start_time = 20.0;
  CHECK_THROWS_WITH(bad.validate(), Catch::Contains("--start-time is the states file's time"));
  bad = c;
  bad.background = "equilibrium";
  CHECK_THROWS_WITH(bad.validate(), Catch::Contains("not equilibrium"));
  std::filesystem::remove_all(dir);
}

TEST_CASE("tracer: md merge of shard directories equals one run, summary keys and moments included") {
  TracerConfig c = small_config("equilibrium");  // the equilibrium keys (T, collision_rate_exact) too
  c.trajectories = 96;
  c.scene.block_size = 8;
  c.T = 2.0;
  c.phi = 0.2;
  c.transport = "enskog";
  c.threads = 2;
  const TracerResult one = run_tracer(c);
  const auto root = coldblast::test::unique_temp_path("coldblast-test-tracer-merge");
  std::vector<std::filesystem::path> shards;
  c.threads = 1;
  c.shard_count = 3;
  for (int i = 0; i < 3; ++i) {
    c.shard_index = i;
    shards.push_back(root / ("s" + std::to_string(i)));
    write_tracer_outputs(run_tracer(c), shards.back());
  }
  REQUIRE(is_tracer_run(shards[0]));
  const TracerResult merged = merge_tracer_outputs(shards);
  CHECK(merged.trajectories() == 96);
  CHECK(merged.collisions() == one.collisions());
  CHECK(merged.candidates() == one.candidates());
  // Exact equality: the merge rebuilds the block sums and totals them in block order.
  CHECK(merged.collision_rate() == one.collision_rate());
  CHECK(merged.collision_rate_error() == one.collision_rate_error());
  CHECK(merged.temperature_final() == one.temperature_final());
  CHECK(merged.temperature_final_error() == one.temperature_final_error());
  CHECK(merged.rejection_rate() == one.rejection_rate());
  const auto a = moment_rows(one.ensemble.scene.times, one.blocks),
             b = moment_rows(merged.ensemble.scene.times, merged.blocks);
  REQUIRE(a.size() == b.size());
  for (std::size_t k = 0; k < a.size(); ++k) {
    CHECK(a[k].r2 == b[k].r2);
    CHECK(a[k].r_ratio == b[k].r_ratio);
    CHECK(a[k].r_ratio_error == b[k].r_ratio_error);
    CHECK(a[k].v_ratio == b[k].v_ratio);
    CHECK(a[k].v2_error == b[k].v2_error);
  }
  auto x = tracer_summary(one), y = tracer_summary(merged);
  CHECK(y.at("merged_from").size() == 3);  // the shards' run ids; the merge is a run of its own
  CHECK(y.at("run_id") != x.at("run_id"));
  for (const char* key : {"wall_seconds", "collisions_per_second", "seconds_per_realization", "threads",
                          "trajectories_per_second", "run_id", "merged_from"}) {
    x.erase(key);
    y.erase(key);
  }
  CHECK(x == y);  // every other key, the tracer's included (collision_rate_exact, T, chi, ...)
  CHECK(y.at("collision_rate_exact") == x.at("collision_rate_exact"));

  // A shard of another tracer run is refused, naming the differing key.
  TracerConfig other = c;
  other.shard_index = 1;
  other.T = 3.0;
  write_tracer_outputs(run_tracer(other), shards[1]);
  CHECK_THROWS_WITH(merge_tracer_outputs(shards),
                    Catch::Contains("background_description") || Catch::Contains("T = 3"));
  // So is a shard of another kernel (its trajectories are not those of the run).
  {
    const auto path = shards[2] / "summary.json";
    auto summary = coldblast::common::Json::parse(read(path));
    REQUIRE(summary.at("kernel") == "scalar");
    summary["kernel"] = "avx512";
    std::ofstream(path) << summary.dump(2);
    c.shard_index = 1;
    write_tracer_outputs(run_tracer(c), shards[1]);
    CHECK_THROWS_WITH(merge_tracer_outputs(shards), Catch::Contains("kernel"));
    summary["kernel"] = "scalar";
    std::ofstream(path) << summary.dump(2);
  }
  // A shard without its tracer sums is bad input naming the file.
  c.shard_index = 1;
  write_tracer_outputs(run_tracer(c), shards[1]);
  CHECK_NOTHROW(merge_tracer_outputs(shards));
  std::filesystem::remove(shards[1] / "tracer_blocks.csv");
  CHECK_THROWS_AS(merge_tracer_outputs(shards), std::invalid_argument);
  CHECK_THROWS_WITH(merge_tracer_outputs(shards), Catch::Contains("tracer_blocks.csv"));
  std::filesystem::remove_all(root);
}

TEST_CASE("tracer: --start hotspot runs in the NS hot spot, records r0, and resume refuses another start or r0") {
  const std::filesystem::path root = coldblast::test::unique_temp_path("coldblast_test_tracer_hotspot");
  TracerConfig c = small_config("ns");
  c.trajectories = 64;
  c.start = "hotspot";
  c.r0 = 5.0;
  const TracerRunFiles files{root / "out", "--out", false, false, "resume"};
  const TracerResult first = run_tracer(c, {}, files);  // the checkpoint stays (no finish_tracer_run)
  CHECK(first.start_time == c.scene.t_min / 1024);      // from the deposition, to 0.1 % of t_min
  CHECK(first.background_description.find("hot-spot start r0 = ") != std::string::npos);
  const auto summary = tracer_summary(first);
  CHECK(summary.at("start") == "hotspot");
  CHECK(summary.at("r0") == 5.0);
  TracerConfig requested = small_config("ns");
  const TracerConfig resumed = resume_tracer_config(files.out, requested, {});
  CHECK(resumed.start == "hotspot");
  CHECK(resumed.r0 == 5.0);
  requested.start = "hotspot";
  requested.r0 = 6.0;
  CHECK_THROWS_WITH(resume_tracer_config(files.out, requested, {"--r0"}),
                    Catch::Contains("--r0 = 6 contradicts the checkpoint") && Catch::Contains("which has --r0 = 5"));
  requested.start = "kick";
  CHECK_THROWS_WITH(resume_tracer_config(files.out, requested, {"--start"}),
                    Catch::Contains("--start = kick contradicts the checkpoint"));
  std::filesystem::remove_all(root);
}
