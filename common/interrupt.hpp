#pragma once
// Cooperative interruption of long work: a signal handler (SIGINT, SIGTERM) or a host such as the
// Python module requests a stop; long loops poll stop_requested() between units of work (an MD
// realization) and throw Interrupted, so completed checkpoints stay and nothing is half-written.
#include <stdexcept>

namespace coldblast::common {

/// Thrown by throw_if_stop_requested(); signal() is the requesting signal number (0 if none).
class Interrupted : public std::runtime_error {
 public:
  explicit Interrupted(int signal_number);
  int signal() const noexcept { return signal_; }
  /// Conventional shell exit status of a process ended by the signal: 128 + signal (130 SIGINT, 143 SIGTERM).
  int exit_code() const noexcept { return 128 + signal_; }

 private:
  int signal_;
};

/// Requests a stop; async-signal-safe (one lock-free atomic store). signal_number > 0.
void request_stop(int signal_number) noexcept;
/// True once a stop was requested and not cleared.
bool stop_requested() noexcept;
/// The signal number of the pending request, 0 when none.
int stop_signal() noexcept;
/// Forgets a pending request (a host that handled it, or a test).
void clear_stop() noexcept;
/// Throws Interrupted when a stop is pending.
void throw_if_stop_requested();
/// Routes SIGINT and SIGTERM to request_stop (sigaction, SA_RESTART), saying so on stderr at once
/// (long loops stop at their next unit; an MD realization in flight saves its state when its run has an
/// output folder, else runs to its end); a second
/// signal of the same kind while the first is pending ends the process at once with the default action.
void install_stop_handlers();

}  // namespace coldblast::common
