#pragma once
// Output plumbing shared by every module: the output path rules (atomic writes of regular files,
// straight-through writes of devices and pipes, `-` for stdout), the exit-time check of stdout and
// stderr, commented provenance headers for CSV/TSV files, and the JSON type used for summaries.
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <utility>
#include <vector>

namespace coldblast::common {

using Json = nlohmann::ordered_json;

/// Writes `content` to `path` by the output path rules (the one place every writer gets them):
/// - "-" or "/dev/stdout" (standard output), "/dev/stderr", "/dev/fd/N", "/proc/self/fd/N": the
///   descriptor this process holds, written after what it printed before, every write checked;
/// - a new path or a regular file: atomically, through a temporary file in the same folder
///   (write, fsync, rename, fsync of the folder); a replaced file keeps its permission bits;
///   missing parent folders are created;
/// - a symlink: atomically to the file it finally points to, so the link stays a link;
/// - a character device, FIFO or socket (/dev/null, /dev/full, a named pipe, /dev/fd/N): written
///   straight through with every write checked, never renamed onto;
/// - a folder or a block device: refused.
/// Throws std::runtime_error naming the path and the system's reason on any failure; a failed
/// atomic write leaves the old file untouched and no temporary behind.
void write_file_atomic(const std::filesystem::path& path, const std::string& content);

/// Checks an output folder before any work is done (`option` names it in the error, e.g. "--out"):
/// a folder, also through symlinks, or a new path whose nearest existing ancestor is a folder, is
/// accepted; a regular file, a device, a FIFO, a socket or a symlink to nothing throws
/// std::invalid_argument naming the option, the path and what it is. Creates and replaces nothing.
void require_output_folder(const std::filesystem::path& path, const std::string& option);

/// Removes the temporary files that atomic writes of killed processes left in `folder`
/// ("NAME.tmp.PID.N" whose process PID no longer runs); returns how many. Missing folder: 0.
int remove_stale_temporaries(const std::filesystem::path& folder);

/// Routes stdout and std::cout (both, so printf and << stay in order) through one stream that keeps
/// the errno of the first failed write, so that finish_standard_streams can name the reason ("No
/// space left on device") when the failure happened part-way through a large output rather than in
/// the exit flush, by which time errno is gone. Called by main() first; a no-op outside glibc and
/// libstdc++, and when called again.
void check_standard_output_writes();

/// The GNU close_stdout rule, called by main() before it returns: flushes stdout and stderr and
/// returns 1 after printing "coldblast: error: cannot write standard output: REASON" on stderr when
/// a write to stdout failed (a full disk, a closed descriptor, a pipe whose reader left while
/// SIGPIPE is ignored); returns 1 silently when stderr failed; else 0. A pipe whose reader left
/// ends the process by SIGPIPE's default action before this is reached (`| head` stays quiet).
int finish_standard_streams() noexcept;

/// Key/value lines written as "# key: value" at the top of every table file.
using HeaderFields = std::vector<std::pair<std::string, std::string>>;

/// The standard provenance block: program version, git commit, command line, units, then `extra`.
std::string provenance_header(const HeaderFields& extra, const std::string& units);

/// The command line of this process, recorded by main() for provenance headers.
void set_command_line(int argc, const char* const* argv);
const std::string& command_line();

}  // namespace coldblast::common
