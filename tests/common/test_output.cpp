#include <array>
#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "common/output.hpp"

namespace fs = std::filesystem;
using namespace coldblast::common;

TEST_CASE("write_file_atomic creates folders, replaces content and leaves no temporary", "[fast]") {
  const fs::path dir = fs::temp_directory_path() / "coldblast_test_output";
  fs::remove_all(dir);
  const fs::path file = dir / "sub" / "table.csv";
  write_file_atomic(file, "first\n");
  write_file_atomic(file, "second\n");
  std::ifstream in(file);
  std::stringstream content;
  content << in.rdbuf();
  REQUIRE(content.str() == "second\n");
  int entries = 0;
  for ([[maybe_unused]] const auto& entry : fs::directory_iterator(dir / "sub")) ++entries;
  REQUIRE(entries == 1);
  fs::remove_all(dir);
}

TEST_CASE("write_file_atomic fails loudly on an unwritable path", "[fast]") {
  REQUIRE_THROWS_AS(write_file_atomic("/proc/coldblast_cannot_write/x.csv", "x"), std::runtime_error);
}

TEST_CASE("provenance_header carries version, commit, command and units", "[fast]") {
  set_command_line(2, std::array<const char*, 2>{"coldblast", "theory"}.data());
  const std::string header = provenance_header({{"seed", "42"}}, "m = 1, k_B = 1");
  REQUIRE(header.find("# program: coldblast ") == 0);
  REQUIRE(header.find("# commit: ") != std::string::npos);
  REQUIRE(header.find("# command: coldblast theory\n") != std::string::npos);
  REQUIRE(header.find("# units: m = 1, k_B = 1\n") != std::string::npos);
  REQUIRE(header.find("# seed: 42\n") != std::string::npos);
}
