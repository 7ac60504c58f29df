// The tracer in an MD run's measured fields (run/md_fields.*, `tracer --background md`): an md run
// folder read back exactly, the tracer in flat measured fields at the equilibrium collision rate
// n chi S <|g|> (kinetic/kinetic_theory.hpp, an independent closed form), the checkpoint's record of
// the MD run, and every bad folder named by --md-run. Seeds fixed.
#include <catch2/catch.hpp>
#include <cmath>
#include <filesystem>
#include <sstream>
#include <string>

#include "common/output.hpp"
#include "common/validate.hpp"
#include "kinetic/kinetic_theory.hpp"
#include "kinetic/tracer_config.hpp"
#include "run/checkpoint.hpp"
#include "run/md_fields.hpp"
#include "run/scene_file.hpp"
#include "run/tracer_files.hpp"
#include "run/tracer_run.hpp"
#include "tests/temp_path.hpp"
#include "theory/prefactors.hpp"

using namespace coldblast::run;
using coldblast::common::format_number;
using coldblast::common::write_file_atomic;
namespace fs = std::filesystem;

namespace {

/// The scene of the synthetic MD run: the default scene from t = 1 to 100 (recorded at 2^(k/4)).
coldblast::md::BlastConfig md_scene() {
  coldblast::md::BlastConfig c = parse_scene(default_scene_toml());
  c.t_min = 1.0;
  c.t_max = 100.0;
  c.block_size = 16;
  return c;
}

/// An `md run` folder of `scene` whose profiles are flat: n/n∞ = 1, u = 0 and T = T_host in 30 bins
/// of r/R over [0, 1.5) at every recorded time, R = R_scale t^(1/2) (observables.csv), written as
/// run/run_files.cpp writes them (the same columns).
fs::path write_md_run(const fs::path& dir, const coldblast::md::BlastConfig& scene, double T_host, double R_scale,
                      const std::string& run_id = "md-synthetic") {
  fs::create_directories(dir);
  std::ostringstream observables, profiles;
  observables << "# run_id: " << run_id << "\nt,observable,mean,stderr,count\n";
  profiles << "# run_id: " << run_id
           << "\nt,bin,r_over_R_lo,r_over_R_hi,density_over_n,density_stderr,radial_velocity,temperature,particles\n";
  for (int k = 0; k <= 26; ++k) {  // t = 2^(k/4) up to 90.5, then t_max = 100 = 2^(26.58/4) is not recorded
    const double t = std::pow(2.0, k / 4.0);
    observables << format_number(t) << ",R," << format_number(R_scale * std::sqrt(t)) << ",0.01,32\n";
    for (int b = 0; b < 30; ++b)
      profiles << format_number(t) << ',' << b << ',' << format_number(0.05 * b) << ',' << format_number(0.05 * (b + 1))
               << ",1,0.01,0," << format_number(T_host) << ",5\n";
  }
  coldblast::common::Json summary;
  summary["run_id"] = run_id;
  summary["scene_toml"] = scene_toml(scene);
  write_file_atomic(dir / "summary.json", summary.dump(2) + "\n");
  write_file_atomic(dir / "observables.csv", observables.str());
  write_file_atomic(dir / "profiles.csv", profiles.str());
  return dir;
}

coldblast::kinetic::TracerConfig md_config(const fs::path& md_run) {
  coldblast::kinetic::TracerConfig c;
  c.scene = md_scene();
  c.background = "md";
  c.md_run = md_run.string();
  c.trajectories = 512;
  return c;
}

}  // namespace

TEST_CASE("md fields: an md run folder read back exactly, its scene the MD's") {
  const fs::path dir = coldblast::test::unique_temp_path("coldblast_test_md_fields");
  const coldblast::md::BlastConfig scene = md_scene();
  write_md_run(dir, scene, 0.25, 3.0);
  const MdRunFields fields = read_md_run_fields(dir, "--md-run");
  CHECK(fields.run_id == "md-synthetic");
  CHECK(scene_physics_difference(fields.scene, scene).empty());
  CHECK(md_run_scene_toml(dir, "--md-run") == scene_toml(scene));
  const coldblast::kinetic::MeasuredProfiles& p = fields.profiles;
  CHECK(p.d == scene.d);
  CHECK(p.n == scene.n);
  REQUIRE(p.edges.size() == 31);
  CHECK(p.edges.front() == 0.0);
  CHECK(p.edges.back() == 1.5);
  REQUIRE(p.frames.size() == 27);
  for (std::size_t k = 0; k < p.frames.size(); ++k) {
    const double t = std::pow(2.0, static_cast<double>(k) / 4.0);
    CHECK(p.frames[k].t == t);  // shortest round-trip decimals: exact
    CHECK(p.frames[k].R == 3.0 * std::sqrt(t));
    CHECK(p.frames[k].temperature[29] == 0.25);
  }
  coldblast::md::BlastConfig other = scene;
  other.E *= 2.0;
  CHECK(scene_physics_difference(scene, other) ==
        "its E is " + format_number(scene.E) + ", " + format_number(other.E) + " here");
  fs::remove_all(dir);
}

TEST_CASE("tracer --background md: in flat measured fields the collision rate is n chi S <|g|>, T_final the hosts'") {
  // n = n∞, u = 0, T = 0.25 everywhere the impurity goes (R = 10^4 t^(1/2): it stays within
  // r/R < 1.5), so the impurity, started thermal (the local Maxwellian at T), stays in equilibrium.
  const fs::path dir = coldblast::test::unique_temp_path("coldblast_test_md_fields_flat");
  const double T = 0.25;
  coldblast::kinetic::TracerConfig c = md_config(dir);
  c.scene.t_max = std::pow(2.0, 26 / 4.0);  // the MD's last recorded time: no continuation after it
  c.start = "thermal";
  c.transport = "enskog";
  c.scene.impurities.mass = 3.0;
  c.scene.impurities.radius = 1.0;
  write_md_run(dir, c.scene, T, 1e4);  // an MD run with these impurities
  const TracerResult r = run_tracer(c);
  const auto& s = r.ensemble.scene.config;
  const double phi = coldblast::theory::packing_fraction(2, s.n, s.a);
  CHECK(r.chi == Approx(coldblast::kinetic::pair_contact_value(2, phi, s.a, 1.0)).epsilon(1e-12));
  const double exact = coldblast::kinetic::equilibrium_collision_rate(2, s.n, r.chi, s.a + 1.0, T, 3.0);
  INFO("rate " << r.collision_rate() << " ± " << r.collision_rate_error() << ", exact " << exact);
  CHECK(std::abs(r.collision_rate() - exact) < 4 * r.collision_rate_error());
  CHECK(r.collision_rate_error() < 0.01 * exact);
  CHECK(std::abs(r.temperature_final() - T) < 4 * r.temperature_final_error());
  const auto summary = tracer_summary(r);
  CHECK(summary.at("background") == "md");
  CHECK(summary.at("md_run") == md_run_path(dir.string()));
  CHECK(summary.at("md_run_id") == "md-synthetic");
  fs::remove_all(dir);
}

TEST_CASE("tracer --background md: the checkpoint records the MD run; resume refuses another") {
  const fs::path root = coldblast::test::unique_temp_path("coldblast_test_md_fields_resume");
  const fs::path md = write_md_run(root / "md", md_scene(), 0.25, 3.0);
  const fs::path other = write_md_run(root / "other", md_scene(), 0.25, 3.0, "md-other");
  coldblast::kinetic::TracerConfig c = md_config(md / "");  // a trailing separator: the same folder
  const TracerRunFiles files{root / "out", "--out", false, false, "resume"};
  const TracerResult first = run_tracer(c, {}, files);  // the checkpoint stays (no finish_tracer_run)
  REQUIRE(fs::exists(checkpoint_folder(files.out)));

  coldblast::kinetic::TracerConfig requested;
  requested.scene = md_scene();
  const coldblast::kinetic::TracerConfig resumed = resume_tracer_config(files.out, requested, {});
  CHECK(resumed.background == "md");
  CHECK(resumed.md_run == md_run_path(md.string()));
  CHECK(resumed.md_run_id == "md-synthetic");
  TracerRunFiles again = files;
  again.resume = true;
  const TracerResult second = run_tracer(resumed, {}, again);  // every block loaded: the same sums
  CHECK(second.collisions() == first.collisions());
  CHECK(second.ensemble.resumed_realizations == first.trajectories());

  requested.background = "md";
  requested.md_run = other.string();
  CHECK_THROWS_WITH(resume_tracer_config(files.out, requested, {"--md-run"}),
                    Catch::Contains("--md-run = " + md_run_path(other.string()) + " contradicts the checkpoint"));
  // The folder now holds another run than the one the checkpoint's blocks ran in.
  write_md_run(md, md_scene(), 0.25, 3.0, "md-replaced");
  CHECK_THROWS_WITH(run_tracer(resumed, {}, again), Catch::Contains("now holds run md-replaced, not run md-synthetic"));
  fs::remove_all(root);
}

TEST_CASE("tracer --background md: bad folders and options are named") {
  const fs::path root = coldblast::test::unique_temp_path("coldblast_test_md_fields_bad");
  const fs::path md = write_md_run(root / "md", md_scene(), 0.25, 3.0);
  const auto refuses = [](coldblast::kinetic::TracerConfig c, const std::string& words) {
    CHECK_THROWS_WITH(run_tracer(c), Catch::Contains(words));
  };
  coldblast::kinetic::TracerConfig c = md_config(md);
  refuses(md_config(root / "missing"), "--md-run = " + (root / "missing").string() + " is not a directory");
  fs::create_directories(root / "empty");
  refuses(md_config(root / "empty"), "is not an `md run` folder: it has no summary.json");
  // A tracer run's folder.
  fs::create_directories(root / "tracer");
  write_file_atomic(root / "tracer" / "summary.json",
                    R"json({"engine": "tracer (Lorentz-Boltzmann Monte Carlo)", "scene_toml": ""})json");
  refuses(md_config(root / "tracer"), "is a tracer run");
  // No profiles; no R.
  fs::copy(md, root / "no-profiles");
  fs::remove(root / "no-profiles" / "profiles.csv");
  refuses(md_config(root / "no-profiles"), "recorded no profiles (no profiles.csv)");
  fs::copy(md, root / "no-R");
  write_file_atomic(root / "no-R" / "observables.csv",
                    "# run_id: md-synthetic\nt,observable,mean,stderr,count\n1,R_imp,1,0.1,4\n");
  refuses(md_config(root / "no-R"), "observables.csv has no R at t = 1");
  // Another scene; times beyond the MD's.
  coldblast::kinetic::TracerConfig bad = c;
  bad.scene.impurities.mass = 10.0;
  refuses(bad, "--md-run = " + md_run_path(md.string()) + " is of another scene: its impurities.mass is 1, 10 here");
  bad = c;
  bad.scene.t_max = 120.0;
  refuses(bad, "ran to t_max = 100 (recorded up to t = " + format_number(std::pow(2.0, 6.5)) +
                   "); the tracer's t_max = 120 is beyond it");
  bad = c;
  bad.scene.t_min = 0.5;
  refuses(bad, "the tracer starts at t = 0.5 (--start-time, or the scene's t_min), before --md-run = " +
                   md_run_path(md.string()) + "'s first recorded time, t = 1");
  bad = c;
  bad.md_run.clear();
  CHECK_THROWS_WITH(bad.validate(), Catch::Contains("--background = md needs --md-run DIR"));
  bad = c;
  bad.background = "ns";
  CHECK_THROWS_WITH(bad.validate(), Catch::Contains("--md-run is only for --background md"));
  fs::remove_all(root);
}
