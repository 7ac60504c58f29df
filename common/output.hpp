#pragma once
// Output plumbing shared by every module: atomic file writes (nothing is ever half-written),
// commented provenance headers for CSV/TSV files, and the JSON type used for summaries.
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <utility>
#include <vector>

namespace coldblast::common {

using Json = nlohmann::ordered_json;

/// Writes `content` to `path` through a temporary file in the same folder and an atomic rename.
/// Creates missing parent folders. Throws std::runtime_error naming the path on failure.
void write_file_atomic(const std::filesystem::path& path, const std::string& content);

/// Key/value lines written as "# key: value" at the top of every table file.
using HeaderFields = std::vector<std::pair<std::string, std::string>>;

/// The standard provenance block: program version, git commit, command line, units, then `extra`.
std::string provenance_header(const HeaderFields& extra, const std::string& units);

/// The command line of this process, recorded by main() for provenance headers.
void set_command_line(int argc, const char* const* argv);
const std::string& command_line();

}  // namespace coldblast::common
