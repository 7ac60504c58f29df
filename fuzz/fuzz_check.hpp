#pragma once
// Shared by the fuzz targets (fuzz/README.md): what a target may end in. A reader of hostile input
// must either return a valid result or throw std::invalid_argument (the CLI's exit 2); any other
// exception, a non-finite number in a result, a crash, a hang or a sanitizer report is a finding.
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <stdexcept>
#include <string>

namespace coldblast::fuzz {

/// Ends the process with a message (libFuzzer then saves the input as a crash).
[[noreturn]] inline void finding(const std::string& what) {
  std::fprintf(stderr, "fuzz finding: %s\n", what.c_str());
  std::abort();
}

inline void require(bool condition, const std::string& what) {
  if (!condition) finding(what);
}

inline void require_finite(double value, const std::string& what) {
  if (!std::isfinite(value)) finding(what + " is not finite");
}

/// Runs `body`; std::invalid_argument is a clean rejection, any other exception a finding.
template <class Body>
void expect_clean(Body&& body) {
  try {
    body();
  } catch (const std::invalid_argument&) {
  } catch (const std::exception& e) {
    finding(std::string("not std::invalid_argument: ") + e.what());
  }
}

}  // namespace coldblast::fuzz

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size);
