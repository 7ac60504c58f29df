// Stop requests for long work (common/interrupt.hpp).
#include "common/interrupt.hpp"

#include <unistd.h>

#include <atomic>
#include <csignal>
#include <cstring>
#include <string>

namespace coldblast::common {
namespace {
std::atomic<int> pending_signal{0};
static_assert(std::atomic<int>::is_always_lock_free, "request_stop must be async-signal-safe");

std::string signal_name(int signal_number) {
  switch (signal_number) {
    case SIGINT:
      return "SIGINT";
    case SIGTERM:
      return "SIGTERM";
    default:
      return "signal " + std::to_string(signal_number);
  }
}

extern "C" void on_stop_signal(int signal_number) {
  if (pending_signal.load() == signal_number) {  // asked twice: stop now, as the default action would
    std::signal(signal_number, SIG_DFL);
    std::raise(signal_number);
    return;
  }
  request_stop(signal_number);
  // At once, so that a stop that waits for a long realization is not taken for a hang (write(2) is
  // async-signal-safe; a failed write changes nothing).
  static const char note[] =
      "\ncoldblast: stopping after the work in flight (an MD run with an output folder saves a long realization "
      "where it is, within seconds; other work runs to its end and is saved); the same signal again stops at once "
      "and loses it\n";
  [[maybe_unused]] const ssize_t written = write(STDERR_FILENO, note, sizeof note - 1);
}
}  // namespace

Interrupted::Interrupted(int signal_number)
    : std::runtime_error("interrupted by " + signal_name(signal_number)), signal_(signal_number) {}

void request_stop(int signal_number) noexcept {
  pending_signal.store(signal_number > 0 ? signal_number : SIGINT);
}
bool stop_requested() noexcept {
  return pending_signal.load() != 0;
}
int stop_signal() noexcept {
  return pending_signal.load();
}
void clear_stop() noexcept {
  pending_signal.store(0);
}

void throw_if_stop_requested() {
  const int signal_number = pending_signal.load();
  if (signal_number != 0) throw Interrupted(signal_number);
}

void install_stop_handlers() {
  struct sigaction action;
  std::memset(&action, 0, sizeof action);
  action.sa_handler = on_stop_signal;
  sigemptyset(&action.sa_mask);
  action.sa_flags = SA_RESTART;
  sigaction(SIGINT, &action, nullptr);
  sigaction(SIGTERM, &action, nullptr);
}

}  // namespace coldblast::common
