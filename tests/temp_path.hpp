#pragma once
// Scratch paths for tests that write files. A fixed name under /tmp collides when two test
// processes run at once (ctest -j, two build trees, two checkouts on one machine): one test's
// remove_all deletes the other's files. unique_temp_path gives a name no other live process uses.
#include <unistd.h>

#include <atomic>
#include <filesystem>
#include <string>

namespace coldblast::test {

/// <temp dir>/<stem>_<pid>_<k>, k counting the calls in this process; the path is not created
/// (tests that need the directory create it, as the code under test does).
inline std::filesystem::path unique_temp_path(const std::string& stem) {
  static std::atomic<long> calls{0};
  return std::filesystem::temp_directory_path() /
         (stem + "_" + std::to_string(::getpid()) + "_" + std::to_string(calls++));
}

}  // namespace coldblast::test
