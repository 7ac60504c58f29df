// Reading an MD run directory: blocks.csv parsing, ensemble values, and loud errors.
#include <catch2/catch.hpp>
#include <filesystem>

#include "common/output.hpp"
#include "compare/run_data.hpp"
#include "tests/temp_path.hpp"

using namespace coldblast::compare;
namespace fs = std::filesystem;

TEST_CASE("blocks.csv is parsed into dense block series with count-weighted means", "[fast]") {
  const std::string text =
      "# program: coldblast\n"
      "block,t,observable,sum,count\n"
      "0,10,R_imp,8,2\n"
      "1,10,R_imp,10,3\n"
      "0,20,R_imp,18,2\n"
      "1,20,R_imp,27,3\n"
      "0,10,C_imp,4,2\n"
      "1,10,C_imp,6,3\n";
  const auto series = parse_blocks_csv(text, "test");
  REQUIRE(series.size() == 2);
  const BlockSeries& r = series.at("R_imp");
  CHECK(r.transform == Transform::sqrt);
  REQUIRE(r.t == std::vector<double>{10, 20});
  const auto all = r.ensemble_values();
  CHECK(all[0] == Approx(std::sqrt(18.0 / 5.0)));
  CHECK(all[1] == Approx(3.0));
  const auto without_first = r.ensemble_values(0);
  CHECK(without_first[0] == Approx(std::sqrt(10.0 / 3.0)));
  CHECK(r.realizations_at(1) == 5.0);
  CHECK(series.at("C_imp").ensemble_values()[0] == Approx(2.0));
}

TEST_CASE("malformed blocks.csv names the file, the line and the problem", "[fast]") {
  CHECK_THROWS_WITH(parse_blocks_csv("t,observable\n", "f.csv"),
                    Catch::Contains("f.csv line 1") && Catch::Contains("header"));
  CHECK_THROWS_WITH(parse_blocks_csv("block,t,observable,sum,count\n0,1,speed,1,1\n", "f.csv"),
                    Catch::Contains("speed"));
  CHECK_THROWS_WITH(parse_blocks_csv("block,t,observable,sum,count\n0,x,R_imp,1,1\n", "f.csv"),
                    Catch::Contains("f.csv line 2"));
  CHECK_THROWS_WITH(parse_blocks_csv("block,t,observable,sum,count\n0,1,R_imp,1\n", "f.csv"),
                    Catch::Contains("expected 5 fields"));
  CHECK_THROWS_WITH(parse_blocks_csv("", "f.csv"), Catch::Contains("empty"));
}

TEST_CASE("read_run rejects a missing or incomplete directory", "[fast]") {
  CHECK_THROWS_WITH(read_run("/nonexistent/run"), Catch::Contains("RUN_DIR"));
  const fs::path dir = coldblast::test::unique_temp_path("coldblast_test_run");
  fs::remove_all(dir);
  fs::create_directories(dir);
  CHECK_THROWS_WITH(read_run(dir), Catch::Contains("summary.json"));
  // A run still going holds only its checkpoint: the error says how to look at it now.
  coldblast::common::write_file_atomic(dir / "checkpoint" / "scene.toml", "d = 2\n");
  CHECK_THROWS_WITH(read_run(dir), Catch::Contains("is a run in progress") &&
                                       Catch::Contains("coldblast md merge " + dir.string() + " --out DIR"));
  coldblast::common::write_file_atomic(dir / "summary.json", "{\"scene\": {\"d\": 2}}");
  CHECK_THROWS_WITH(read_run(dir), Catch::Contains("blocks.csv"));
  coldblast::common::write_file_atomic(dir / "blocks.csv", "block,t,observable,sum,count\n0,1,n0,0.1,1\n");
  const RunData run = read_run(dir);
  CHECK(run.d == 2);
  CHECK(run.series.count("n0") == 1);
  fs::remove_all(dir);
}
