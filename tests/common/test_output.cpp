#include <sys/socket.h>
#include <sys/stat.h>
#include <sys/un.h>
#include <unistd.h>

#include <array>
#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <thread>

#include "common/output.hpp"
#include "tests/temp_path.hpp"

namespace fs = std::filesystem;
using namespace coldblast::common;

TEST_CASE("write_file_atomic creates folders, replaces content and leaves no temporary", "[fast]") {
  const fs::path dir = coldblast::test::unique_temp_path("coldblast_test_output");
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

namespace {
std::string slurp(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::stringstream content;
  content << in.rdbuf();
  return content.str();
}
fs::path fresh_folder(const std::string& name) {
  const fs::path dir = coldblast::test::unique_temp_path(name);
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}
int entries_in(const fs::path& dir) {
  int entries = 0;
  for ([[maybe_unused]] const auto& entry : fs::directory_iterator(dir)) ++entries;
  return entries;
}
}  // namespace

TEST_CASE("write_file_atomic writes a symlink's target and keeps the link", "[fast]") {
  const fs::path dir = fresh_folder("coldblast_test_output_symlink");
  fs::create_directories(dir / "scratch");
  write_file_atomic(dir / "scratch" / "table.csv", "old\n");
  fs::create_symlink("scratch/table.csv", dir / "link.csv");  // relative, as users make them
  fs::create_symlink(dir / "link.csv", dir / "link_to_link.csv");
  write_file_atomic(dir / "link_to_link.csv", "new\n");
  REQUIRE(fs::is_symlink(dir / "link.csv"));
  REQUIRE(fs::is_symlink(dir / "link_to_link.csv"));
  REQUIRE(slurp(dir / "scratch" / "table.csv") == "new\n");
  REQUIRE(entries_in(dir / "scratch") == 1);
  SECTION("a dangling link gets its target created") {
    fs::create_symlink("scratch/later.csv", dir / "dangling.csv");
    write_file_atomic(dir / "dangling.csv", "later\n");
    REQUIRE(fs::is_symlink(dir / "dangling.csv"));
    REQUIRE(slurp(dir / "scratch" / "later.csv") == "later\n");
  }
  fs::remove_all(dir);
}

TEST_CASE("write_file_atomic keeps a replaced file's permission bits", "[fast]") {
  const fs::path dir = fresh_folder("coldblast_test_output_mode");
  write_file_atomic(dir / "shared.csv", "a\n");
  fs::permissions(dir / "shared.csv", fs::perms::owner_read | fs::perms::owner_write | fs::perms::group_read);
  write_file_atomic(dir / "shared.csv", "b\n");
  REQUIRE(fs::status(dir / "shared.csv").permissions() ==
          (fs::perms::owner_read | fs::perms::owner_write | fs::perms::group_read));
  fs::remove_all(dir);
}

TEST_CASE("write_file_atomic writes devices straight through and never renames onto them", "[fast]") {
  write_file_atomic("/dev/null", "discarded\n");
  REQUIRE(fs::is_character_file("/dev/null"));
  try {
    write_file_atomic("/dev/full", "does not fit\n");
    FAIL("/dev/full accepted a write");
  } catch (const std::runtime_error& e) {
    REQUIRE(std::string(e.what()) == "cannot write /dev/full: No space left on device");
  }
  REQUIRE(fs::is_character_file("/dev/full"));
  for (const auto& entry : fs::directory_iterator("/dev"))  // no temporary left beside the device
    REQUIRE(entry.path().filename().string().rfind("full.tmp", 0) != 0);
}

TEST_CASE("write_file_atomic writes a FIFO straight through to its reader", "[fast]") {
  const fs::path dir = fresh_folder("coldblast_test_output_fifo");
  const fs::path fifo = dir / "pipe";
  REQUIRE(::mkfifo(fifo.c_str(), 0600) == 0);
  std::string received;
  std::thread reader([&] { received = slurp(fifo); });
  const std::string content(200000, 'x');  // more than a pipe's buffer: several checked writes
  write_file_atomic(fifo, content);
  reader.join();
  REQUIRE(received == content);
  REQUIRE(fs::is_fifo(fifo));
  REQUIRE(entries_in(dir) == 1);
  fs::remove_all(dir);
}

TEST_CASE("write_file_atomic refuses folders and sockets, naming the path", "[fast]") {
  const fs::path dir = fresh_folder("coldblast_test_output_refuse");
  REQUIRE_THROWS_WITH(write_file_atomic(dir, "x"), "cannot write " + dir.string() + ": it is a folder");
  const fs::path socket_path = dir / "socket";
  const int fd = ::socket(AF_UNIX, SOCK_STREAM, 0);
  REQUIRE(fd >= 0);
  sockaddr_un address{};
  address.sun_family = AF_UNIX;
  std::snprintf(address.sun_path, sizeof address.sun_path, "%s", socket_path.c_str());
  REQUIRE(::bind(fd, reinterpret_cast<const sockaddr*>(&address), sizeof address) == 0);
  // A listening socket cannot be opened as a file: a clear error, and the socket stays a socket.
  REQUIRE_THROWS_WITH(write_file_atomic(socket_path, "x"), Catch::Contains("cannot open " + socket_path.string()));
  REQUIRE(fs::is_socket(socket_path));
  ::close(fd);
  fs::remove_all(dir);
}

TEST_CASE("require_output_folder accepts folders and new paths, refuses the rest and changes nothing", "[fast]") {
  const fs::path dir = fresh_folder("coldblast_test_output_folder");
  fs::create_directories(dir / "folder");
  fs::create_directory_symlink("folder", dir / "link");
  std::ofstream(dir / "file") << "precious\n";
  fs::create_symlink("nowhere", dir / "dangling");
  fs::create_symlink("file", dir / "file_link");
  REQUIRE(::mkfifo((dir / "fifo").c_str(), 0600) == 0);
  REQUIRE_NOTHROW(require_output_folder(dir / "folder", "--out"));
  REQUIRE_NOTHROW(require_output_folder(dir / "link", "--out"));
  REQUIRE_NOTHROW(require_output_folder(dir / "new" / "deeper", "--out"));
  REQUIRE_NOTHROW(require_output_folder("relative-new-folder", "--out"));
  const auto refused = [&](const fs::path& path, const std::string& message) {
    REQUIRE_THROWS_AS(require_output_folder(path, "--out"), std::invalid_argument);
    REQUIRE_THROWS_WITH(require_output_folder(path, "--out"), Catch::StartsWith("--out = " + path.string() + message));
  };
  refused(dir / "file", " is a regular file (allowed: a folder or a new path");
  refused(dir / "fifo", " is a FIFO");
  refused(dir / "dangling", " is a symlink to nothing");
  refused(dir / "file_link", " is a symlink to a regular file");
  refused("/dev/null", " is a character device");
  refused(dir / "file" / "sub", " cannot be created: " + (dir / "file").string() + " is a regular file, not a folder");
  refused(dir / "dangling" / "sub", " cannot be created: " + (dir / "dangling").string() + " is a symlink to nothing");
  REQUIRE_THROWS_WITH(require_output_folder("", "out"), "out: the output folder must not be empty");
  REQUIRE(slurp(dir / "file") == "precious\n");  // nothing was created or replaced
  REQUIRE(fs::is_fifo(dir / "fifo"));
  REQUIRE(fs::is_character_file("/dev/null"));
  REQUIRE(fs::is_symlink(dir / "dangling"));
  REQUIRE(entries_in(dir) == 6);
  REQUIRE(!fs::exists("relative-new-folder"));
  fs::remove_all(dir);
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
