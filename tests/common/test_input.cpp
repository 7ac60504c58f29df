// common/input.*: whole-file reads and CSV tables whose errors name the file and the line.
#include <catch2/catch.hpp>
#include <cmath>
#include <filesystem>
#include <stdexcept>

#include "common/input.hpp"
#include "common/output.hpp"
#include "tests/temp_path.hpp"

namespace fs = std::filesystem;
using namespace coldblast::common;
using Catch::Matchers::Contains;

TEST_CASE("read_text returns the bytes written and names the path it cannot read", "[fast]") {
  const fs::path dir = coldblast::test::unique_temp_path("coldblast_test_input");
  fs::remove_all(dir);
  const std::string content = std::string("a,b\r\n1,2\n") + '\0' + "tail";
  write_file_atomic(dir / "x.csv", content);
  REQUIRE(read_text(dir / "x.csv") == content);
  const std::string missing = (dir / "missing.csv").string();
  REQUIRE_THROWS_WITH(read_text(missing, "SCENE"), "SCENE = " + missing + " cannot be read");
  REQUIRE_THROWS_WITH(read_text(missing), "cannot read " + missing);
  fs::remove_all(dir);
}

TEST_CASE("read_text refuses folders and stops an endless device at its size limit", "[fast]") {
  const fs::path dir = coldblast::test::unique_temp_path("coldblast_test_input_limits");
  fs::remove_all(dir);
  const std::string content(200000, 'x');  // several chunks of the reading loop
  write_file_atomic(dir / "big.toml", content);
  REQUIRE(read_text(dir / "big.toml", "SCENE", content.size()) == content);  // exactly at the limit
  REQUIRE_THROWS_WITH(
      read_text(dir / "big.toml", "SCENE", content.size() - 1),
      "SCENE = " + (dir / "big.toml").string() + " is longer than 199999 bytes, the limit for this input");
  REQUIRE_THROWS_AS(read_text(dir, "SCENE"), std::invalid_argument);
  REQUIRE_THROWS_WITH(read_text(dir, "SCENE"), "SCENE = " + dir.string() + " is a folder, not a file");
  REQUIRE_THROWS_WITH(read_text(dir), "cannot read " + dir.string() + ": it is a folder, not a file");
  REQUIRE_THROWS_WITH(read_text("/dev/zero", "--config", text_size_limit),
                      "--config = /dev/zero is longer than 16 MiB, the limit for this input");
  REQUIRE(read_text("/dev/null", "SCENE").empty());
  fs::remove_all(dir);
}

TEST_CASE("split_fields keeps empty fields, including a trailing one", "[fast]") {
  REQUIRE(split_fields("a,,b") == std::vector<std::string>{"a", "", "b"});
  REQUIRE(split_fields("a,b,") == std::vector<std::string>{"a", "b", ""});
  REQUIRE(split_fields("") == std::vector<std::string>{});
}

TEST_CASE("parse_csv skips comments, keeps line numbers and checks field counts", "[fast]") {
  const CsvTable table = parse_csv("# provenance\n\nt,x\r\n1,2\n# note\n3,4\n", "f.csv", "t,x");
  REQUIRE(table.columns == std::vector<std::string>{"t", "x"});
  REQUIRE(table.rows.size() == 2);
  REQUIRE(table.rows[0].line == 4);
  REQUIRE(table.rows[1].line == 6);
  REQUIRE(table.rows[1].fields == std::vector<std::string>{"3", "4"});
  REQUIRE(table.where(table.rows[1]) == "f.csv line 6");
  REQUIRE(table.column("x") == 1);
  REQUIRE_THROWS_WITH(table.column("y"), "f.csv: no column 'y'");
  REQUIRE_THROWS_WITH(parse_csv("t,x\n1,2\n3\n", "f.csv"), "f.csv line 3: expected 2 fields, found 1");
  REQUIRE_THROWS_WITH(parse_csv("t,y\n", "f.csv", "t,x"), "f.csv line 1: header must be 't,x', found 't,y'");
  REQUIRE_THROWS_WITH(parse_csv("# only\n", "f.csv"), Contains("f.csv: empty"));
}

TEST_CASE("number parsers take whole fields and name where they fail", "[fast]") {
  REQUIRE(parse_finite("0.25", "w") == 0.25);
  REQUIRE(parse_finite("-1e-3", "w") == -1e-3);
  REQUIRE_THROWS_WITH(parse_finite("1.5x", "f.csv line 2"), "f.csv line 2: '1.5x' is not a finite number");
  REQUIRE_THROWS_AS(parse_finite("inf", "w"), std::invalid_argument);
  REQUIRE_THROWS_AS(parse_finite("nan", "w"), std::invalid_argument);
  REQUIRE(std::isnan(parse_number_or_nan("nan", "w")));
  REQUIRE(parse_number_or_nan("2", "w") == 2.0);
  REQUIRE(parse_count("17", "w") == 17);
  REQUIRE_THROWS_WITH(parse_count("-1", "w"), "w: '-1' is not a non-negative integer");
  REQUIRE_THROWS_AS(parse_count("3.5", "w"), std::invalid_argument);
}
