// Ensembles: bit-identical results for 1 and 2 threads, shards merged equal to the unsharded run,
// and the realizations' progress.
#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <mutex>
#include <sstream>
#include <string>
#include <vector>

#include "md/blast_config.hpp"
#include "run/ensemble.hpp"
#include "run/merge.hpp"
#include "run/scene_file.hpp"
#include "tests/temp_path.hpp"

using namespace coldblast::run;
using coldblast::md::BlastConfig;
using coldblast::md::ResolvedScene;
namespace fs = std::filesystem;

namespace {
BlastConfig small_scene() {
  return parse_scene(default_scene_toml(),
                     {"t_max=60", "realizations=7", "block_size=2", "A_d=0.351935906848599",
                      R"(observables=["R_imp","V_imp","C_imp","u_imp","n0","T0","R","profiles","p_imp"])"});
}
std::string data_lines(const fs::path& file) {
  std::ifstream in(file);
  std::string line, out;
  while (std::getline(in, line))
    if (!line.empty() && line[0] != '#') out += line + "\n";
  return out;
}
}  // namespace

TEST_CASE("1 thread and 2 threads give bit-identical block sums", "[slow]") {
  const BlastConfig scene = small_scene();
  RunOptions one, two;
  two.threads = 2;
  const BlastResult a = run_blast(scene, one), b = run_blast(scene, two);
  REQUIRE(a.blocks.size() == 4);
  REQUIRE(a.realizations() == 7);
  for (const auto& [block, sums] : a.blocks) {
    REQUIRE(b.blocks.at(block).sum == sums.sum);
    REQUIRE(b.blocks.at(block).sum_squares == sums.sum_squares);
    REQUIRE(b.blocks.at(block).collisions == sums.collisions);
  }
  CHECK(a.energy_error_max() < 1e-12);
  CHECK(a.collisions() > 1000);
}

TEST_CASE("shards merged equal the unsharded run", "[slow]") {
  const BlastConfig scene = small_scene();
  const fs::path root = coldblast::test::unique_temp_path("coldblast_test_shards");
  fs::remove_all(root);
  RunOptions all, first, second;
  first.shard_count = second.shard_count = 2;
  second.shard_index = 1;
  write_blast_outputs(run_blast(scene, all), root / "all");
  write_blast_outputs(run_blast(scene, first), root / "s0");
  write_blast_outputs(run_blast(scene, second), root / "s1");
  const BlastResult merged = merge_blast_outputs({root / "s1", root / "s0"});
  write_blast_outputs(merged, root / "merged");
  for (const char* file : {"observables.csv", "blocks.csv", "profiles.csv", "p_imp.csv", "accumulators.csv"}) {
    INFO(file);
    CHECK(data_lines(root / "all" / file) == data_lines(root / "merged" / file));
  }
  CHECK(data_lines(root / "all" / "observables.csv").size() > 100);
  CHECK_THROWS_WITH(merge_blast_outputs({root / "s0", root / "s0"}), Catch::Contains("appears twice"));
  // One shard alone merges (a progress check), with a note naming what is missing; both: none.
  CHECK(partial_merge_note(merged).empty());
  const BlastResult half = merge_blast_outputs({root / "s1"});
  REQUIRE((scene.realizations == 7 && scene.block_size == 2));  // blocks 0..3; shard 1/2 ran 1 and 3
  CHECK(half.realizations() == 3);
  CHECK(partial_merge_note(half) ==
        "md merge: 3 of the scene's 7 realizations (blocks 0, 2 missing): a partial ensemble");
  fs::remove_all(root);
}

TEST_CASE("shards of different counts, and merged folders, merge exactly; a copy without accumulators.csv is refused",
          "[slow]") {
  // The deep campaigns' layout (scripts/campaigns.sh): one coarse shard plus finer ones that fill its
  // gaps, kept as folders and merged later, possibly with an earlier merge among the inputs.
  const BlastConfig scene = small_scene();  // blocks 0..3
  const fs::path root = coldblast::test::unique_temp_path("coldblast_test_mixed_shards");
  fs::remove_all(root);
  const auto shard = [&](int index, int count, const char* name) {
    RunOptions o;
    o.shard_index = index;
    o.shard_count = count;
    write_blast_outputs(run_blast(scene, o), root / name);
  };
  write_blast_outputs(run_blast(scene, RunOptions{}), root / "all");
  shard(0, 2, "coarse");  // blocks 0, 2
  shard(1, 4, "fine1");   // block 1
  shard(3, 4, "fine3");   // block 3
  write_blast_outputs(merge_blast_outputs({root / "fine1", root / "coarse"}), root / "partial");
  write_blast_outputs(merge_blast_outputs({root / "partial", root / "fine3"}), root / "merged");
  for (const char* file : {"observables.csv", "blocks.csv", "profiles.csv", "p_imp.csv", "accumulators.csv"}) {
    INFO(file);
    CHECK(data_lines(root / "all" / file) == data_lines(root / "merged" / file));
  }
  CHECK(partial_merge_note(merge_blast_outputs({root / "merged"})).empty());
  // A block in two inputs (the coarse shard and a merge that holds it) is refused.
  CHECK_THROWS(merge_blast_outputs({root / "partial", root / "coarse", root / "fine3"}));
  // data/ once kept a campaign without its accumulators.csv: the error says what is missing and why.
  fs::remove(root / "fine3" / "accumulators.csv");
  CHECK_THROWS_WITH(merge_blast_outputs({root / "partial", root / "fine3"}),
                    Catch::Contains((root / "fine3" / "accumulators.csv").string()) && Catch::Contains("is missing") &&
                        Catch::Contains("cannot be merged"));
  fs::remove_all(root);
}

TEST_CASE("shard specs are validated", "[fast]") {
  CHECK(parse_shard("1/3") == std::pair<int, int>{1, 3});
  CHECK_THROWS_WITH(parse_shard("3/2"), Catch::Contains("--shard"));
  CHECK_THROWS_WITH(parse_shard("x"), Catch::Contains("--shard"));
}

TEST_CASE("realization_time reports each realization's start and recorded times, and changes nothing", "[slow]") {
  const BlastConfig scene = small_scene();
  RunOptions quiet, watched;
  watched.threads = 2;
  std::mutex mutex;
  std::map<long long, std::vector<double>> seen;
  watched.realization_time = [&](long long realization, double t) {
    std::lock_guard<std::mutex> lock(mutex);
    seen[realization].push_back(t);
  };
  const BlastResult a = run_blast(scene, quiet), b = run_blast(scene, watched);
  REQUIRE(seen.size() == 7);
  for (const auto& [realization, times] : seen) {
    INFO("realization " << realization);
    REQUIRE(times.size() == b.scene.times.size() + 1);
    CHECK(times.front() == 0.0);  // the start, before the initial state is built
    CHECK(std::vector<double>(times.begin() + 1, times.end()) == b.scene.times);
  }
  for (const auto& [block, sums] : a.blocks) {
    CHECK(b.blocks.at(block).sum == sums.sum);
    CHECK(b.blocks.at(block).collisions == sums.collisions);
  }
}
