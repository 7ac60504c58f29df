#include "common/output.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <iostream>
#include <stdexcept>
#include <system_error>
#if defined(__GLIBC__) && defined(__GLIBCXX__)
#include <ext/stdio_sync_filebuf.h>
#define COLDBLAST_CHECKED_STDOUT 1
#endif

#include "coldblast/build_info.hpp"

namespace coldblast::common {

namespace fs = std::filesystem;

namespace {
std::string& command_line_storage() {
  static std::string line = "(library call)";
  return line;
}

std::runtime_error failure(const std::string& what, const fs::path& path, int error) {
  return std::runtime_error("cannot " + what + " " + path.string() + ": " + std::strerror(error));
}

/// write(2) until done, retrying on EINTR; false (errno set) on any failure.
bool write_all(int fd, const char* data, std::size_t left) {
  while (left > 0) {
    const ssize_t n = ::write(fd, data, left);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) {
      if (n == 0) errno = EIO;
      return false;
    }
    data += n;
    left -= static_cast<std::size_t>(n);
  }
  return true;
}
bool write_all(int fd, const std::string& content) {
  return write_all(fd, content.data(), content.size());
}

/// errno of the first failed write to standard output through the checked stream (0: none yet).
std::atomic<int> stdout_error{0};

#ifdef COLDBLAST_CHECKED_STDOUT
/// fopencookie's write function for the checked stdout: write(2) to descriptor 1, keeping the
/// first failure's errno, which later calls would overwrite before the exit check reads it.
ssize_t write_checked_stdout(void*, const char* data, std::size_t size) {
  if (write_all(STDOUT_FILENO, data, size)) return static_cast<ssize_t>(size);
  int expected = 0;
  stdout_error.compare_exchange_strong(expected, errno);
  return 0;  // fopencookie: 0 reports the error (the stream's error flag is set)
}
#endif

/// What a path is, for error messages ("a regular file", "a character device", ...).
std::string kind_of(const fs::file_status& status) {
  switch (status.type()) {
    case fs::file_type::regular:
      return "a regular file";
    case fs::file_type::directory:
      return "a folder";
    case fs::file_type::symlink:
      return "a symlink";
    case fs::file_type::block:
      return "a block device";
    case fs::file_type::character:
      return "a character device";
    case fs::file_type::fifo:
      return "a FIFO";
    case fs::file_type::socket:
      return "a socket";
    case fs::file_type::not_found:
      return "missing";
    default:
      return "of an unknown type";
  }
}

/// A device, FIFO or socket: opened as it is (never created, truncated or renamed onto).
void write_through(const fs::path& path, const std::string& content) {
  int fd;
  do fd = ::open(path.c_str(), O_WRONLY | O_NOCTTY | O_CLOEXEC);
  while (fd < 0 && errno == EINTR);
  if (fd < 0) throw failure("open", path, errno);
  if (!write_all(fd, content)) {
    const int error = errno;
    ::close(fd);
    throw failure("write", path, error);
  }
  if (::close(fd) != 0 && errno != EINTR) throw failure("write", path, errno);
}

/// "-", /dev/stdout, /dev/stderr, /dev/fd/N, /proc/self/fd/N: the descriptor this process already
/// holds (its offset and open mode are the caller's), or -1 for any other path.
int own_descriptor(const fs::path& path) {
  const std::string p = path.string();
  if (p == "-" || p == "/dev/stdout") return STDOUT_FILENO;
  if (p == "/dev/stderr") return STDERR_FILENO;
  for (const std::string prefix : {"/dev/fd/", "/proc/self/fd/"})
    if (p.size() > prefix.size() && p.size() < prefix.size() + 6 && p.compare(0, prefix.size(), prefix) == 0 &&
        p.find_first_not_of("0123456789", prefix.size()) == std::string::npos)
      return std::stoi(p.substr(prefix.size()));
  return -1;
}

void write_descriptor(int fd, const fs::path& path, const std::string& content) {
  std::cout.flush();  // keep the order of what this process printed before
  std::fflush(stdout);
  std::cerr.flush();
  std::fflush(stderr);
  if (!write_all(fd, content)) throw failure("write", path, errno);
}

/// A new path or a regular file: temporary file beside it, fsync, rename, fsync of the folder.
void write_atomically(const fs::path& path, const std::string& content) {
  std::error_code ec;
  const fs::path folder = path.has_parent_path() ? path.parent_path() : fs::path(".");
  if (path.has_parent_path()) {
    fs::create_directories(folder, ec);
    if (ec) throw std::runtime_error("cannot create folder " + folder.string() + ": " + ec.message());
  }
  mode_t mode = 0666;  // narrowed by the umask, as for any new file
  struct stat old;
  const bool replacing = ::stat(path.c_str(), &old) == 0;
  if (replacing) mode = old.st_mode & 07777;
  static std::atomic<unsigned> counter{0};
  const fs::path temporary =
      path.string() + ".tmp." + std::to_string(::getpid()) + "." + std::to_string(counter.fetch_add(1));
  const int fd = ::open(temporary.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, replacing ? 0600 : mode);
  if (fd < 0) throw failure("create", temporary, errno);
  const auto abandon = [&](const std::string& what, int error) {
    ::close(fd);
    ::unlink(temporary.c_str());
    return failure(what, path, error);
  };
  if (!write_all(fd, content)) throw abandon("write", errno);
  if (replacing && ::fchmod(fd, mode) != 0) throw abandon("set the permissions of", errno);
  if (::fsync(fd) != 0) throw abandon("write", errno);
  if (::close(fd) != 0) {
    const int error = errno;
    ::unlink(temporary.c_str());
    throw failure("write", path, error);
  }
  if (::rename(temporary.c_str(), path.c_str()) != 0) {
    const int error = errno;
    ::unlink(temporary.c_str());
    throw failure("rename a temporary file onto", path, error);
  }
  const int folder_fd = ::open(folder.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (folder_fd >= 0) {  // make the rename durable; a folder that cannot be opened still got the file
    ::fsync(folder_fd);
    ::close(folder_fd);
  }
}

/// Follows a chain of symlinks to the path it finally names (which need not exist yet).
fs::path final_target(fs::path path) {
  for (int hops = 0; hops < 40; ++hops) {
    struct stat s;
    if (::lstat(path.c_str(), &s) != 0 || !S_ISLNK(s.st_mode)) return path;
    std::error_code ec;
    const fs::path target = fs::read_symlink(path, ec);
    if (ec) throw std::runtime_error("cannot read the symlink " + path.string() + ": " + ec.message());
    path = target.is_absolute() ? target : path.parent_path() / target;
  }
  throw failure("resolve", path, ELOOP);
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

void write_file_atomic(const fs::path& path, const std::string& content) {
  if (path.empty()) throw std::runtime_error("cannot write an empty path");
  if (const int fd = own_descriptor(path); fd >= 0) return write_descriptor(fd, path, content);
  struct stat s;
  if (::stat(path.c_str(), &s) != 0) {  // new path, or a symlink to a path that does not exist yet
    if (errno != ENOENT) throw failure("write", path, errno);
    return write_atomically(final_target(path), content);
  }
  if (S_ISREG(s.st_mode)) return write_atomically(final_target(path), content);
  if (S_ISCHR(s.st_mode) || S_ISFIFO(s.st_mode) || S_ISSOCK(s.st_mode)) return write_through(path, content);
  if (S_ISDIR(s.st_mode)) throw std::runtime_error("cannot write " + path.string() + ": it is a folder");
  throw std::runtime_error("cannot write " + path.string() + ": not a regular file, device, FIFO or socket");
}

int remove_stale_temporaries(const fs::path& folder) {
  std::error_code ec;
  int removed = 0;
  for (fs::directory_iterator it(folder, ec), end; !ec && it != end; it.increment(ec)) {
    const std::string name = it->path().filename().string();
    const auto mark = name.rfind(".tmp.");
    if (mark == std::string::npos) continue;
    const std::string rest = name.substr(mark + 5);  // "PID.N"
    const auto dot = rest.find('.');
    if (dot == 0 || dot == std::string::npos || rest.find_first_not_of("0123456789.") != std::string::npos) continue;
    const long pid = std::strtol(rest.substr(0, dot).c_str(), nullptr, 10);
    if (pid <= 0 || pid > (1L << 30) || pid == ::getpid()) continue;
    if (::kill(static_cast<pid_t>(pid), 0) == 0 || errno != ESRCH) continue;  // its writer still runs
    std::error_code ignored;
    if (fs::remove(it->path(), ignored)) ++removed;
  }
  return removed;
}

void check_standard_output_writes() {
#ifdef COLDBLAST_CHECKED_STDOUT
  static bool installed = false;
  if (installed) return;
  cookie_io_functions_t io{};
  io.write = write_checked_stdout;
  FILE* stream = ::fopencookie(nullptr, "w", io);
  if (stream == nullptr) return;  // keep the plain stdout (the exit check may then lack the reason)
  std::fflush(stdout);
  std::setvbuf(stream, nullptr, ::isatty(STDOUT_FILENO) ? _IOLBF : _IOFBF, BUFSIZ);
  stdout = stream;  // glibc's stdout is an assignable variable (glibc manual, "Standard Streams")
  static __gnu_cxx::stdio_sync_filebuf<char> buffer(stream);  // std::cout stays in step with printf
  std::cout.rdbuf(&buffer);
  installed = true;
#endif
}

int finish_standard_streams() noexcept {
  errno = 0;
  try {
    std::cout.flush();  // synchronised with stdio: flushes stdout, whose failure sets errno
  } catch (...) {
  }
  const bool out_failed = std::fflush(stdout) != 0 || std::ferror(stdout) || !std::cout.good();
  // The first failed write's errno, kept by the checked stream; else errno of this flush (a flush of
  // an emptied buffer after an earlier failure succeeds and leaves errno 0: "write error").
  const int error = stdout_error.load() != 0 ? stdout_error.load() : errno;
  if (out_failed) {
    std::fprintf(stderr, "coldblast: error: cannot write standard output: %s\n",
                 error != 0 ? std::strerror(error) : "write error");
    std::fflush(stderr);
    return 1;
  }
  if (std::fflush(stderr) != 0 || std::ferror(stderr)) return 1;
  return 0;
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

void require_output_folder(const fs::path& path, const std::string& option) {
  const std::string named = option + " = " + path.string();
  const std::string allowed = " (allowed: a folder or a new path; nothing else is replaced)";
  if (path.empty()) throw std::invalid_argument(option + ": the output folder must not be empty");
  std::error_code error;
  const fs::file_status link = fs::symlink_status(path, error);
  if (fs::exists(link)) {
    const fs::file_status target = fs::status(path, error);
    if (fs::is_directory(target)) return;
    if (fs::is_symlink(link))
      throw std::invalid_argument(named + " is a symlink to " +
                                  (fs::exists(target) ? kind_of(target) : std::string("nothing")) + allowed);
    throw std::invalid_argument(named + " is " + kind_of(target) + allowed);
  }
  // A new path: the writers create it, so its nearest existing ancestor must be a folder.
  fs::path ancestor = path.parent_path();
  while (!ancestor.empty() && !fs::exists(fs::symlink_status(ancestor, error))) ancestor = ancestor.parent_path();
  if (ancestor.empty()) return;  // relative to the working folder
  const fs::file_status target = fs::status(ancestor, error);
  if (!fs::is_directory(target))
    throw std::invalid_argument(named + " cannot be created: " + ancestor.string() + " is " +
                                (fs::exists(target) ? kind_of(target) : std::string("a symlink to nothing")) +
                                ", not a folder");
}

}  // namespace coldblast::common
