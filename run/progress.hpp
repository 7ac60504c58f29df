#pragma once
// Progress of long runs on stderr (md run, md states, tracer), suited to where it goes: on a
// terminal one status line rewritten in place ("\r") at most twice a second; anywhere else (a log
// file, a pipe, a Slurm log) plain lines, each ending in a newline and never holding a carriage
// return, at most one per 10 % of the work or per 30 s, each with the elapsed time and the ETA.
#include <cstdio>
#include <functional>
#include <mutex>
#include <optional>
#include <string>

namespace coldblast::run {

class Progress {
 public:
  /// `label` starts every line ("md run"), `unit` names what is counted ("realizations").
  /// `terminal`: none = whether `stream` is a terminal (isatty). `clock`: seconds since any fixed
  /// moment (none = the steady clock; tests pass their own).
  Progress(std::string label, std::string unit, std::FILE* stream = stderr, std::optional<bool> terminal = {},
           std::function<double()> clock = {});
  /// `done` of `total` units finished. Thread-safe.
  void update(long long done, long long total);
  /// What a long unit is doing meanwhile ("realization 3 at t = 520 of 4000"): shown when no update
  /// came for 2 s (terminal) or 30 s (elsewhere). Thread-safe.
  void status(const std::string& text);
  bool terminal() const { return terminal_; }

 private:
  void show(const std::string& text, bool last);
  std::string label_, unit_;
  std::FILE* stream_;
  bool terminal_;
  std::function<double()> clock_;
  std::mutex mutex_;
  double start_ = 0.0, last_ = 0.0;  ///< clock at the start and at the last line
  long long done_ = 0, total_ = 0;
  int decile_ = 0;      ///< the last tenth of the work a plain line reported
  bool shown_ = false;  ///< a line was printed
};

}  // namespace coldblast::run
