#include "run/progress.hpp"

#include <unistd.h>

#include <chrono>
#include <cstdint>

namespace coldblast::run {

namespace {

double steady_seconds() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

/// "12.3 s", "4.5 min", "2.1 h".
std::string duration(double seconds) {
  char text[32];
  if (seconds < 120.0)
    std::snprintf(text, sizeof text, "%.1f s", seconds);
  else if (seconds < 7200.0)
    std::snprintf(text, sizeof text, "%.1f min", seconds / 60.0);
  else
    std::snprintf(text, sizeof text, "%.1f h", seconds / 3600.0);
  return text;
}

}  // namespace

Progress::Progress(std::string label, std::string unit, std::FILE* stream, std::optional<bool> terminal,
                   std::function<double()> clock)
    : label_(std::move(label)),
      unit_(std::move(unit)),
      stream_(stream),
      terminal_(terminal ? *terminal : isatty(fileno(stream)) == 1),
      clock_(clock ? std::move(clock) : steady_seconds) {
  start_ = last_ = clock_();
}

void Progress::update(long long done, long long total) {
  const std::lock_guard<std::mutex> lock(mutex_);
  done_ = done;
  total_ = total;
  const double now = clock_();
  const bool last = done >= total;
  if (terminal_) {
    if (!last && now - last_ < 0.5) return;
  } else {
    const int decile = total > 0 ? static_cast<int>(10 * done / total) : 10;
    if (!last && decile <= decile_ && now - last_ < 30.0) return;
    decile_ = decile;
  }
  const double elapsed = now - start_, eta = done > 0 ? elapsed * static_cast<double>(total - done) / done : 0.0;
  const int percent = total > 0 ? static_cast<int>(100 * done / total) : 100;
  show(label_ + ": " + std::to_string(done) + "/" + std::to_string(total) + " " + unit_ + " (" +
           std::to_string(percent) + " %), " + duration(elapsed) + " elapsed, ETA " + duration(eta),
       last);
}

void Progress::status(const std::string& text) {
  const std::lock_guard<std::mutex> lock(mutex_);
  const double now = clock_();
  if (shown_ && now - last_ < (terminal_ ? 2.0 : 30.0)) return;
  show(label_ + ": " + text + ", " + duration(now - start_) + " elapsed", false);
}

void Progress::show(const std::string& text, bool last) {
  last_ = clock_();
  shown_ = true;
  if (terminal_) {
    std::fprintf(stream_, "\r%s   ", text.c_str());
    if (last) std::fputc('\n', stream_);
  } else {
    std::fprintf(stream_, "%s\n", text.c_str());
  }
  std::fflush(stream_);
}

}  // namespace coldblast::run
