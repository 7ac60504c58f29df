// run_tracer: bit-identical ensembles for any thread count and sharding, the equilibrium summary
// (collision rate against the exact value), the run directory, and bad input naming the option.
#include <catch2/catch.hpp>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "kinetic/kinetic_theory.hpp"
#include "kinetic/tracer.hpp"
#include "tests/temp_path.hpp"

using namespace coldblast::kinetic;

namespace {
TracerConfig small_config(const std::string& background) {
  TracerConfig c;
  c.scene = coldblast::md::parse_scene(coldblast::md::default_scene_toml());
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

TEST_CASE("tracer: bit-identical for any thread count and sharding") {
  TracerConfig c = small_config("tvns");
  const TracerResult one = run_tracer(c);
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
}
