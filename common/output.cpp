#include "common/output.hpp"

#include <unistd.h>

#include <fstream>
#include <stdexcept>
#include <system_error>

#include "coldblast/build_info.hpp"

namespace coldblast::common {

namespace {
std::string& command_line_storage() {
  static std::string line = "(library call)";
  return line;
}
}  // namespace

void set_command_line(int argc, const char* const* argv) {
  std::string line;
  for (int i = 0; i < argc; ++i) {
    if (i > 0) line += ' ';
    line += argv[i];
  }
  command_line_storage() = line;
}

const std::string& command_line() {
  return command_line_storage();
}

void write_file_atomic(const std::filesystem::path& path, const std::string& content) {
  namespace fs = std::filesystem;
  std::error_code ec;
  if (path.has_parent_path()) {
    fs::create_directories(path.parent_path(), ec);
    if (ec) throw std::runtime_error("cannot create folder " + path.parent_path().string() + ": " + ec.message());
  }
  const fs::path temporary = path.string() + ".tmp." + std::to_string(::getpid());
  {
    std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
    if (!out) throw std::runtime_error("cannot open " + temporary.string() + " for writing");
    out << content;
    out.flush();
    if (!out) {
      fs::remove(temporary, ec);
      throw std::runtime_error("write failed for " + temporary.string());
    }
  }
  fs::rename(temporary, path, ec);
  if (ec) {
    fs::remove(temporary, ec);
    throw std::runtime_error("cannot rename " + temporary.string() + " to " + path.string());
  }
}

std::string provenance_header(const HeaderFields& extra, const std::string& units) {
  std::string header;
  header += "# program: coldblast " + std::string(version) + "\n";
  header += "# commit: " + std::string(git_commit) + "\n";
  header += "# command: " + command_line() + "\n";
  header += "# units: " + units + "\n";
  for (const auto& [key, value] : extra) header += "# " + key + ": " + value + "\n";
  return header;
}

}  // namespace coldblast::common
